#!/bin/bash
# The Debian package CPack builds (`make package`): its control fields
# (Package, Version, Depends from dpkg-shlibdeps, Recommends for the
# dlopened FFmpeg libraries) and its files. Built into a temporary folder
# from the build tree; skipped (77) without dpkg-deb, dpkg-shlibdeps or file.
# Usage: deb_package_test.sh BUILD_DIR VERSION
set -u
build=$1
version=$2
for tool in cpack dpkg-deb dpkg-shlibdeps file; do
  command -v $tool >/dev/null || { echo "SKIP: no $tool"; exit 77; }
done
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

start=$SECONDS
cpack -G DEB --config "$build/CPackConfig.cmake" -B "$tmp" >"$tmp/cpack.log" 2>&1 ||
  { cat "$tmp/cpack.log"; fail "cpack failed"; }
echo "cpack took $((SECONDS - start)) s"
debs=("$tmp"/hexant_*.deb)
[ -f "${debs[0]}" ] || { cat "$tmp/cpack.log"; fail "no hexant_*.deb in $tmp"; }
deb=${debs[0]}
echo "$deb"

field() { dpkg-deb -f "$deb" "$1"; }
dpkg-deb -I "$deb"
[ "$(field Package)" = hexant ] || fail "Package is '$(field Package)'"
[ "$(field Version)" = "$version-1" ] || fail "Version is '$(field Version)', not $version-1"
[ "$(field Section)" = graphics ] || fail "Section is '$(field Section)'"
depends=$(field Depends)
# By prefix: Debian's names carry sonames and suffixes (libpng16-16t64).
for library in libc6 libstdc++6 libtbb libpng16 libfreetype; do
  [[ ", $depends" == *", $library"* ]] || fail "Depends lacks $library: $depends"
done
[[ "$depends" == *libavcodec* ]] && fail "Depends names FFmpeg, which is dlopened: $depends"
recommends=$(field Recommends)
for package in povray-includes fonts-povray libavcodec libavformat libswscale libavutil; do
  [[ "$recommends" == *"$package"* ]] || fail "Recommends lacks $package: $recommends"
done

dpkg-deb -c "$deb" >"$tmp/files"
for file in ./usr/bin/hexant ./usr/share/man/man1/hexant.1.gz \
            ./usr/share/hexant/include/colors.inc ./usr/share/doc/hexant/README.md; do
  grep -q " $file\$" "$tmp/files" || { cat "$tmp/files"; fail "the package lacks $file"; }
done
grep -q "/hexant/libhexant_oiio.so\$" "$tmp/files" ||
  { cat "$tmp/files"; fail "the package lacks the OpenImageIO module libhexant_oiio.so"; }
echo "PASS: $(basename "$deb"): Depends: $depends"
