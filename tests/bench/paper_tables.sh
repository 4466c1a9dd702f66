#!/bin/sh
# The paper's Tables 1 and 2, measured: `hexant render --compare` on atom
# (Table 1's settings: 64 frames, 126 x 126, 32 samples per pixel) and on
# dino (Table 2's: 64 frames, 126 x 126, 4 samples per pixel), once with each
# split criterion (cost, the default, and the paper's), with the date, the
# machine and the commands, for docs/benchmarks.md's "The paper's tables, reproduced".
# A benchmark: it prints figures, it asserts nothing. Run from the top folder
# after `make build`:   sh tests/bench/paper_tables.sh [OUT_DIR]
set -e
out=${1:-out/paper_tables}
mkdir -p "$out"
echo "date: $(date -u '+%Y-%m-%d %H:%M UTC')"
echo "machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//'), $(nproc) cores"
echo "commit: $(git rev-parse --short HEAD 2>/dev/null || echo unknown)"
for run in "atom 32 cost" "atom 32 paper" "dino 4 cost" "dino 4 paper"; do
    set -- $run
    command="build/hexant render examples/$1.pov examples/$1.ini --spp $2 --split $3 --compare -o $out/$1-$3/frame_####.png --stats-json $out/$1-$3.json"
    echo
    echo "\$ $command"
    $command
done
