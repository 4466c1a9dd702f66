#!/bin/sh
# The scale benchmark (issue 14): examples/swarm.pov, N spheres on tilted
# orbits, rendered at N = 10^3, 10^4, 10^5 over 16 and 64 frames (160 by 120,
# 4 samples per pixel), in spacetime mode (lazy build, and eager) and frames
# mode, one process each so that each peak memory is its own. Prints one row
# per run: build and render time, cells built and in a full build, object
# references, node and sweep memory, the process's resident memory at start
# and at its peak (getrusage), and rays per second.
#
#   sh tests/bench/scale.sh                     # everything (the 10^5 runs take minutes)
#   SCALE_N="1000 10000" SCALE_FRAMES=16 sh tests/bench/scale.sh
#   SCALE_RUNS="spacetime/lazy frames/lazy" ...  # only these mode/build pairs
#
# Times are wall-clock on whatever machine runs it: quote them with the
# date, machine and commit printed at the top, never as limits.
set -eu
cd "$(dirname "$0")/../.."
hexant=${HEXANT:-build/hexant}
sizes=${SCALE_N:-"1000 10000 100000"}
frame_counts=${SCALE_FRAMES:-"16 64"}
spp=${SCALE_SPP:-4}
runs=${SCALE_RUNS:-"spacetime/lazy spacetime/eager frames/lazy"}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

echo "date: $(date -u +%Y-%m-%dT%H:%MZ)"
echo "machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(nproc) cores"
echo "commit: $(git rev-parse --short HEAD 2>/dev/null || echo unknown)"
echo "scene: examples/swarm.pov examples/swarm.ini, 160x120, $spp spp"
echo

# field NAME FILE: one number from hexant's --stats-json (one mode per file).
field() {
    sed -n "s/.*\"$1\": \([^,}]*\).*/\1/p" "$2" | head -n 1
}

printf '%7s %6s %-16s %9s %9s %9s %9s %10s %8s %8s %8s %8s %8s\n' \
    N frames mode build_s render_s cells full_cells obj_refs nodes_MB sweep_MB start_MB peak_MB Mrays/s
for frames in $frame_counts; do
    for n in $sizes; do
        for run in $runs; do
            set -- $(echo "$run" | tr / ' ')
            json="$out/$1-$2-$n-$frames.json"
            "$hexant" render examples/swarm.pov examples/swarm.ini --declare "N=$n" \
                --frame-count "$frames" --spp "$spp" --mode "$1" --build "$2" --stats-full \
                -o "$out/frame_####.png" --stats-json "$json" > /dev/null
            printf '%7s %6s %-16s %9.3f %9.3f %9s %9s %10s %8.1f %8.1f %8.1f %8.1f %8.2f\n' \
                "$n" "$frames" "$1/$2" \
                "$(field 'build time (s)' "$json")" "$(field 'render time (s)' "$json")" \
                "$(field 'hierarchy cells' "$json")" "$(field 'cells of a full build' "$json")" \
                "$(field 'object references' "$json")" "$(field 'node memory (MB)' "$json")" \
                "$(field 'sweep memory (MB)' "$json")" "$(field 'memory at start (MB)' "$json")" \
                "$(field 'peak memory (MB)' "$json")" "$(field 'rays per second (M)' "$json")"
        done
    done
done
