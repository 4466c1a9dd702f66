# The two set-up commands: `make run` and `make test`. Each installs the
# Debian packages hexant needs (as root; otherwise it prints the command),
# configures, builds into build/, then renders the atom example (frames,
# contact sheet, animated GIF and H.264 video under out/atom/) or runs the
# whole test suite. (file: dpkg-shlibdeps under `make package`; man-db:
# the install.man_page test formats hexant.1 with man -l.)
PACKAGES := build-essential cmake ninja-build pkg-config tao-pegtl-dev libglm-dev catch2 libcli11-dev \
            libpng-dev libjpeg-dev libopenexr-dev libgif-dev libopenimageio-dev libtbb-dev libhwy-dev libfreetype-dev fonts-povray povray-includes \
            nlohmann-json3-dev libavcodec-dev libavformat-dev libswscale-dev libavutil-dev nettle-dev file man-db
JOBS := $(shell nproc 2>/dev/null || echo 2)
# Ninja, not Make: Make's generator holds every file of a library until the
# libraries it links are whole, so one core idled through the grammar's
# three-minute file (language/interpreter.cpp). A build folder first made
# with another generator is configured afresh (cmake refuses to switch).
CONFIGURE := if [ -f build/CMakeCache.txt ] && ! grep -qx 'CMAKE_GENERATOR:INTERNAL=Ninja' build/CMakeCache.txt; \
	  then rm -rf build/CMakeCache.txt build/CMakeFiles; fi; \
	cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release

.PHONY: run test install package golden bench fuzz fuzz-long sanitize format format-check clang-format-installed build deps clean

run: build
	./build/hexant render examples/atom.pov examples/atom.ini \
	  --contact-sheet out/atom/contact_sheet.png --animation out/atom/atom.gif \
	  --video out/atom/atom.mp4

# --timeout: a test that hangs fails after 10 minutes instead of holding
# the run (the slowest takes a minute; the whole suite about four on 2 cores).
test: build
	cd build && ctest --output-on-failure -j$(JOBS) --timeout 600

# The install (README.md, "Install"): hexant, its man page and include
# files under PREFIX (staged under DESTDIR when set), and the Debian package
# build/hexant_VERSION-1_ARCH.deb. Both build only what is installed.
PREFIX ?= /usr/local
install: deps
	$(CONFIGURE)
	cmake --build build --target hexant hexant_man_page -j$(JOBS)
	DESTDIR="$(DESTDIR)" cmake --install build --prefix "$(PREFIX)"

package: deps
	$(CONFIGURE)
	cmake --build build --target hexant hexant_man_page -j$(JOBS)
	cd build && cpack -G DEB

# Renders the golden-test frames anew and stores them in tests/golden/: run by
# hand after a change that is meant to change the images, then look at them.
golden: build
	cmake --build build --target update_golden

# The peer benchmark against Embree 3 (tests/bench/embree_peer.cpp): Embree
# is needed for it alone, so it is installed here and not by `deps`; prints
# hexant's and Embree's times and errors on atom, bounce and the swarm at 10^3 to
# 10^5 spheres (about a quarter of an hour; --scene and --swarm-n pick fewer).
bench: deps
	@dpkg-query -W -f='$${Status}' libembree-dev 2>/dev/null | grep -q "install ok installed" || { \
	  if [ "$$(id -u)" = 0 ]; then \
	    echo "Installing: libembree-dev"; \
	    apt-get update && DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends libembree-dev; \
	  else \
	    echo "The benchmark needs this Debian package. Run:"; \
	    echo "  sudo apt-get install -y libembree-dev"; \
	    exit 1; \
	  fi; \
	}
	$(CONFIGURE)
	cmake --build build --target hexant_embree_peer -j$(JOBS)
	./build/tests/bench/hexant_embree_peer

# libFuzzer over reading a scene and rendering an 8 by 8 frame, over fonts
# and over image files, with AddressSanitizer and UndefinedBehaviorSanitizer
# (tests/fuzz/; README.md, "Fuzzing"): needs clang, so it is not part of
# `make test`. Builds into build-fuzz and runs each fuzzer for FUZZ_SECONDS;
# a crash fails with its input saved as build-fuzz/tests/fuzz/*crash-*.
FUZZ_SECONDS ?= 600
FUZZ_TARGETS := hexant_fuzz hexant_font_fuzz hexant_image_fuzz
fuzz: deps
	@command -v clang++ >/dev/null 2>&1 || { \
	  echo "make fuzz needs clang. Run:"; echo "  sudo apt-get install -y clang"; exit 1; }
	CC=clang CXX=clang++ cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo \
	  -DHEXANT_FUZZ=ON -DHEXANT_FUZZ_SECONDS=$(FUZZ_SECONDS)
	cmake --build build-fuzz --target $(FUZZ_TARGETS) -j$(JOBS)
	cd build-fuzz && ctest -L fuzz --output-on-failure

# A campaign: the three fuzzers one after the other (one process at a time),
# each for FUZZ_LONG_SECONDS (default 4 hours: 12 in all), the corpora they
# grow kept in build-fuzz/tests/fuzz/ for the next run.
FUZZ_LONG_SECONDS ?= 14400
fuzz-long:
	$(MAKE) fuzz FUZZ_SECONDS=$(FUZZ_LONG_SECONDS)

# The whole test suite under AddressSanitizer and UndefinedBehaviorSanitizer,
# in the fuzz build's folder (clang; README.md, "Tests"): about 15 minutes to
# build and 25 to run on a shared 2-core machine. Any report fails its test.
sanitize: deps
	@command -v clang++ >/dev/null 2>&1 || { \
	  echo "make sanitize needs clang. Run:"; echo "  sudo apt-get install -y clang"; exit 1; }
	CC=clang CXX=clang++ cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DHEXANT_FUZZ=ON
	cmake --build build-fuzz -j$(JOBS)
	cd build-fuzz && ctest -LE fuzz --output-on-failure -j$(JOBS)

# The tree as clang-format writes it (.clang-format; Debian's clang-format
# package, installed here and not by `deps`: users need it not). `make
# format` rewrites every C++ file; `make format-check` fails, naming each
# file, where one differs (.ci/run runs it before the tests). The commit
# that first applied it is in .git-blame-ignore-revs.
CXX_FILES = $(shell git ls-files '*.cpp' '*.hpp' 2>/dev/null || find app image language runtime tracer tests -name '*.[ch]pp')
format: clang-format-installed
	clang-format -i $(CXX_FILES)
format-check: clang-format-installed
	@clang-format --dry-run --Werror $(CXX_FILES) && \
	  echo "format-check: $(words $(CXX_FILES)) files as clang-format writes them"
clang-format-installed:
	@command -v clang-format >/dev/null 2>&1 || { \
	  if [ "$$(id -u)" = 0 ]; then \
	    echo "Installing: clang-format"; \
	    apt-get update && DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends clang-format; \
	  else \
	    echo "make format needs clang-format. Run:"; echo "  sudo apt-get install -y clang-format"; exit 1; \
	  fi; \
	}

build: deps
	$(CONFIGURE)
	cmake --build build -j$(JOBS)

deps:
	@missing=""; for p in $(PACKAGES); do \
	  dpkg-query -W -f='$${Status}' $$p 2>/dev/null | grep -q "install ok installed" || missing="$$missing $$p"; \
	done; \
	if [ -n "$$missing" ]; then \
	  if [ "$$(id -u)" = 0 ]; then \
	    echo "Installing:$$missing"; \
	    apt-get update && DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends $$missing; \
	  else \
	    echo "hexant needs these Debian packages. Run:"; \
	    echo "  sudo apt-get install -y$$missing"; \
	    exit 1; \
	  fi; \
	fi

clean:
	rm -rf build
