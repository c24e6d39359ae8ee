#!/usr/bin/env bash
# Runs every libFuzzer target of a fuzz build for a bounded time, starting from the seed corpus
# in tests/fuzz/corpus/<target>/. Usage: scripts/fuzz.sh <fuzz build dir> [seconds per target]
# On a finding it prints the sanitizer report and the input (base64) so that a CI log alone is
# enough to reproduce it: base64 -d > crash.iv, then <target> crash.iv.
set -euo pipefail
build=${1:?usage: scripts/fuzz.sh <fuzz build dir> [seconds per target]}
seconds=${2:-60}
root="$(cd "$(dirname "$0")/.." && pwd)"
found=0
failed=0
for target in "$build"/tests/fuzz/fuzz_*; do
    [ -x "$target" ] || continue
    found=1
    name=$(basename "$target")
    work=$(mktemp -d)
    mkdir "$work/corpus" "$work/findings"
    cp -r "$root/tests/fuzz/corpus/$name/." "$work/corpus/" 2>/dev/null || true
    echo "fuzzing $name for ${seconds}s (seeds: $(ls "$work/corpus" | wc -l))"
    if "$target" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
        -artifact_prefix="$work/findings/" "$work/corpus" >"$work/log" 2>&1; then
        tail -n 12 "$work/log"
    else
        failed=1
        echo "$name found a problem; its report:"
        grep -v -E '^#[0-9]+' "$work/log" | tail -n 120
        for finding in "$work/findings"/*; do
            [ -f "$finding" ] || continue
            echo "input $(basename "$finding") ($(stat -c %s "$finding") bytes, base64):"
            base64 "$finding"
        done
    fi
    rm -rf "$work"
done
[ "$found" = 1 ] || { echo "no fuzz targets in $build/tests/fuzz" >&2; exit 1; }
exit "$failed"
