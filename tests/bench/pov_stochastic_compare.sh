#!/usr/bin/env bash
# pov_stochastic_compare.sh HEXANT SCENE... : the distribution sweep's
# comparison for scenes whose POV-Ray image is itself sampled (jittered area
# lights, focal blur) or aliased (fine detail at 80x60), where one ray per
# pixel centre in each renderer compares two different noises. POV-Ray
# renders at 640x480 (8x8 points per pixel, -A) and is box-filtered to
# 80x60 in linear light; hexant renders at 80x60 with --spp 64 (jittered).
# Both at clock 0, shutter 0. Prints each scene's mean error (idiff) and
# keeps the images in $OUT (default a temporary folder). SCALE (default 8)
# sets POV-Ray's points per pixel side and SPP (default 64) hexant's
# samples, to tell noise from a difference that stays.
# Needs povray, povray-includes, povray-examples, idiff and oiiotool.
# (Issue 42's seventh step: docs/benchmarks.md.)
set -u
[ $# -ge 2 ] || { echo "usage: $0 HEXANT SCENE... (paths under the examples folder)" >&2; exit 2; }
HX=$(realpath "$1"); shift
EX=${EXAMPLES:-/usr/share/doc/povray/examples}
INC=${INCLUDES:-/usr/share/povray-3.7/include}
OUT=${OUT:-$(mktemp -d -t hexant_stochastic.XXXXXX)}
SCALE=${SCALE:-8}; SPP=${SPP:-64}
# The working space the samples are averaged in, as each renderer averages
# them: linear light, or a scene's assumed_gamma G (WORKING_GAMMA=G;
# isocacti's 1.3), where averaging fine detail in the wrong space alone
# shifts the mean by several steps.
WG=${WORKING_GAMMA:-1}
mkdir -p "$OUT"
for s in "$@"; do
  n=${s//\//__}; d=$(dirname "$s"); f=$(basename "$s")
  ( cd "$EX/$d" && timeout 1200 nice povray +I"$f" +O"$OUT/$n.big.png" +W$((80 * SCALE)) +H$((60 * SCALE)) -D -A +K0 \
      +L"$INC" +FN -GA >/dev/null 2>&1 )
  oiiotool "$OUT/$n.big.png" --colorconvert sRGB linear --powc "$(python3 -c "print(1 / $WG)")" \
      --resize:filter=box 80x60 --powc "$WG" \
      --colorconvert linear sRGB -o "$OUT/$n.pov.png"
  ( cd "$EX/$d" && timeout 1200 "$HX" render "$f" -L "$INC" -W 80 -H 60 --clock 0 --spp "$SPP" \
      --shutter 0 -o "$OUT/$n.hx.png" >/dev/null 2>"$OUT/$n.err" )
  m=$(idiff -v "$OUT/$n.pov.png" "$OUT/$n.hx.png" 2>/dev/null | awk '/Mean error/{print $4}')
  printf '%s\t%s\n' "$s" "${m:-failed}"
done
