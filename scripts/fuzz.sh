#!/usr/bin/env bash
# Runs every libFuzzer target of a fuzz build, starting from the seed corpus in
# tests/fuzz/corpus/<target>/. Usage: scripts/fuzz.sh <fuzz build dir> [--ci | seconds per target]
# --ci (what CI runs): deterministic, so that a change cannot fail CI on a finding it did not
#   cause: a fixed libFuzzer seed (-seed=1) and a fixed number of runs per target
#   (TEXSPLAT_FUZZ_RUNS, default 500000, about 10-40 s each here), from the committed seeds only.
# seconds (default 60): exploration: a random seed (libFuzzer logs it as "INFO: Seed: N"; rerun
#   with -seed=N to repeat) for that long per target. Run it long, outside CI.
# On a finding it prints the sanitizer report and the input (base64) so that a CI log alone is
# enough to reproduce it: base64 -d > crash.iv, then <target> crash.iv.
set -euo pipefail
build=${1:?usage: scripts/fuzz.sh <fuzz build dir> [--ci | seconds per target]}
mode=${2:-60}
if [ "$mode" = --ci ]; then
    # A cap on the time too, so that a slow machine still ends; the runs end first here.
    limits=(-seed=1 -runs="${TEXSPLAT_FUZZ_RUNS:-500000}" -max_total_time=600)
    what="${TEXSPLAT_FUZZ_RUNS:-500000} runs, seed 1"
else
    limits=(-max_total_time="$mode")
    what="${mode}s, random seed"
fi
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
    echo "fuzzing $name: $what (seeds: $(ls "$work/corpus" | wc -l))"
    if "$target" "${limits[@]}" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
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
