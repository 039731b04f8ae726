#!/usr/bin/env bash
# Instructions boxlod::render executes per frame, one thread, for the
# rasterizer benchmark's scenes at 1920x1080 (callgrind; docs/performance.md).
# Unlike the clock of a shared machine, the count repeats exactly, so it
# separates a change of a few per cent. Frames are counted as render_tile
# calls / 510 (30 x 17 tiles of 64 pixels): Google Benchmark picks the number.
# A scene counted over one frame (the 1M-triangle frame) is counted over its
# first, which also clears the renderer's scratch vectors as they grow.
# Usage: instructions_per_frame.sh [BUILD]   (default build; needs valgrind)
set -euo pipefail
build=${1:-build}
benchmark=$build/experiments/rasterizer_benchmark
command -v valgrind >/dev/null || { echo "instructions_per_frame.sh: valgrind is not installed (apt-get install valgrind)" >&2; exit 2; }
[ -x "$benchmark" ] || { echo "instructions_per_frame.sh: $benchmark: not built (make bench builds it)" >&2; exit 2; }
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
printf '| scene | frames counted | instructions per frame |\n|---|---:|---:|\n'
for scene in "FZK-Haus:boxlod_model/0/1/" "manual:boxlod_model/1/1/" "1M-triangle frame:boxlod_frame/1/"; do
    name=${scene%%:*} filter=${scene#*:}
    out=$scratch/callgrind.out
    total=$(valgrind --tool=callgrind --callgrind-out-file="$out" --toggle-collect='boxlod::render(*' \
            "$benchmark" --benchmark_filter="$filter" --benchmark_min_time=0 2>&1 |
            awk '/Collected/ {if ($4 + 0 > v) v = $4 + 0} END {print v}')  # not the isolated reader's child: 0
    # callgrind names a function once, then refers to it by its number.
    # (Its lambdas, when not inlined, are named after it: left out.)
    id=$(grep '^c\?fn=([0-9]*) boxlod::(anonymous namespace)::render_tile(' "$out" | grep -v '::{lambda' | head -1 |
         grep -o '^c\?fn=([0-9]*)' | grep -o '([0-9]*)')
    tiles=$(grep -A1 "^cfn=$id" "$out" | awk -F'[= ]' '/^calls=/ {s += $2} END {print s}')
    frames=$((tiles / 510))
    awk -v name="$name" -v frames="$frames" -v total="$total" \
        'BEGIN {printf "| %s | %d | %.1f M |\n", name, frames, total / frames / 1e6}'
done
