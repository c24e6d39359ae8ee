#!/usr/bin/env bash
# Runs every libFuzzer target of a fuzz build for a bounded time, starting from the seed corpus
# in tests/fuzz/corpus/<target>/. Usage: scripts/fuzz.sh <fuzz build dir> [seconds per target]
set -euo pipefail
build=${1:?usage: scripts/fuzz.sh <fuzz build dir> [seconds per target]}
seconds=${2:-60}
root="$(cd "$(dirname "$0")/.." && pwd)"
found=0
for target in "$build"/tests/fuzz/fuzz_*; do
    [ -x "$target" ] || continue
    found=1
    name=$(basename "$target")
    work=$(mktemp -d)
    cp -r "$root/tests/fuzz/corpus/$name/." "$work/" 2>/dev/null || true
    echo "fuzzing $name for ${seconds}s (seeds: $(ls "$work" | wc -l))"
    "$target" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
        "$work" 2>&1 | tail -n 12
    rm -rf "$work"
done
[ "$found" = 1 ] || { echo "no fuzz targets in $build/tests/fuzz" >&2; exit 1; }
