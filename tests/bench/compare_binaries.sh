#!/usr/bin/env bash
# compare_binaries.sh OLD NEW [OUT]: whether a change that is meant to leave
# every image as it was did so. Renders every example (three frames in
# spacetime and in frames mode; atom also in brute mode and adaptive) and
# every .pov under tests/ (a still at clock 0.5) with two hexant binaries,
# from this checkout, and compares the files byte for byte; exit codes too.
# Prints each run that differs and the totals; exit 1 if any differs.
# (Issue 41 ran it after each step: docs/benchmarks.md.)
set -u
[ $# -ge 2 ] || { echo "usage: $0 OLD NEW [OUT]" >&2; exit 2; }
OLD=$(realpath "$1") NEW=$(realpath "$2")
SRC=$(cd "$(dirname "$0")/../.." && pwd)
OUT=${3:-$(mktemp -d -t hexant_compare.XXXXXX)}
mkdir -p "$OUT"; OUT=$(realpath "$OUT")
rm -rf "$OUT/old" "$OUT/new"; mkdir -p "$OUT/old" "$OUT/new"
n=0; same=0; differ=0; failed=0
run() {  # tag, args...
  local tag=$1; shift
  for side in old new; do
    bin=$OLD; [ $side = new ] && bin=$NEW
    mkdir -p "$OUT/$side/$tag"
    ( cd "$SRC" && timeout 120 "$bin" render "$@" -o "$OUT/$side/$tag/f_####.png" --threads 2 ) > "$OUT/$side/$tag.log" 2>&1
    echo $? > "$OUT/$side/$tag.rc"
  done
  n=$((n+1))
  if ! cmp -s "$OUT/old/$tag.rc" "$OUT/new/$tag.rc"; then echo "RC DIFFERS $tag"; differ=$((differ+1)); return; fi
  if [ "$(cat $OUT/old/$tag.rc)" != 0 ]; then failed=$((failed+1)); fi
  if diff -rq "$OUT/old/$tag" "$OUT/new/$tag" >/dev/null; then same=$((same+1)); else echo "IMAGES DIFFER $tag"; differ=$((differ+1)); fi
}
for pov in "$SRC"/examples/*.pov; do
  name=$(basename "$pov" .pov)
  ini="examples/$name.ini"
  for mode in spacetime frames; do
    run "ex_${name}_$mode" "examples/$name.pov" "$ini" -W 48 -H 36 --spp 4 --frames 1:3 --mode $mode
  done
done
run ex_atom_brute examples/atom.pov examples/atom.ini -W 32 -H 24 --spp 2 --frames 1:2 --mode brute
run ex_atom_adaptive examples/atom.pov examples/atom.ini -W 48 -H 36 --frames 1:2
while IFS= read -r pov; do
  rel=${pov#$SRC/}
  tag=$(echo "$rel" | tr '/.' '__')
  run "t_$tag" "$rel" -W 40 -H 30 --spp 1 --no-jitter --clock 0.5
done < <(find "$SRC/tests" -name '*.pov' | sort)
echo "compared $n runs: $same identical, $differ differ ($failed failed the same way in both); files in $OUT"
[ "$differ" = 0 ]
