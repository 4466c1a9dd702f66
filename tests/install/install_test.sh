#!/bin/bash
# An installed hexant, staged with DESTDIR (so not where it was configured
# to live): `--version` prints the project's version, and a scene that
# includes "colors.inc" reads the installed copy, not the source tree's.
# The installed copy gets a marker the source's lacks, so the same scene
# checked by the build tree's hexant must fail: the test can tell them apart.
# Usage: install_test.sh BUILD_DIR VERSION
set -u
build=$1
version=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

DESTDIR="$tmp/stage" cmake --install "$build" --prefix /usr >"$tmp/install.log" 2>&1 ||
  { cat "$tmp/install.log"; fail "cmake --install failed"; }
root="$tmp/stage/usr"
for file in bin/hexant share/man/man1/hexant.1.gz share/hexant/include/colors.inc \
            share/doc/hexant/README.md share/doc/hexant/examples/atom.pov; do
  [ -f "$root/$file" ] || fail "$file not installed"
done
[ -x "$root/bin/hexant" ] || fail "bin/hexant is not executable"
# The OpenImageIO module, where the installed hexant looks for it.
compgen -G "$root/lib*/hexant/libhexant_oiio.so" >/dev/null ||
  compgen -G "$root/lib/*/hexant/libhexant_oiio.so" >/dev/null ||
  fail "libhexant_oiio.so not installed under lib/.../hexant"

out=$("$root/bin/hexant" --version) || fail "hexant --version exited $?"
echo "$out"
[[ "$out" =~ ^hexant\ ${version//./\\.}(\ \(git\ [0-9a-f]+(-dirty)?\))?$ ]] ||
  fail "--version printed '$out', not 'hexant $version [(git COMMIT)]'"

echo '#declare Hexant_Installed_Copy = 1;' >>"$root/share/hexant/include/colors.inc"
mkdir "$tmp/scene"
cat >"$tmp/scene/scene.pov" <<'POV'
#include "colors.inc"
#ifndef (Hexant_Installed_Copy)
#error "colors.inc was not the installed copy"
#end
camera { location <0, 0, -3> look_at 0 }
light_source { <2, 4, -3> color White }
sphere { 0, 1 pigment { color Red } }
POV
cd "$tmp/scene" || fail "no scene folder"
"$root/bin/hexant" check scene.pov >"$tmp/check.log" 2>&1 ||
  { cat "$tmp/check.log"; fail "the installed hexant did not read its installed colors.inc"; }
"$build/hexant" check scene.pov >"$tmp/build_check.log" 2>&1 &&
  fail "the build tree's hexant read the marked installed colors.inc: the test cannot tell"
grep -q "not the installed copy" "$tmp/build_check.log" ||
  { cat "$tmp/build_check.log"; fail "the build tree's hexant failed for another reason"; }
echo "PASS: installed hexant $version reads $root/share/hexant/include"
