#!/usr/bin/env bash
# Long fuzzing, outside CI: runs every libFuzzer target of a fuzz build for a given time each,
# with random seeds, from the committed seeds in tests/fuzz/corpus/<target>/ (the corpus grows in
# a scratch copy). A run that finds a problem is counted, its input and report kept under the
# findings folder, and the target goes on for the rest of its time. Prints a table of totals:
# seconds, executions and findings per target (docs/reliability.md quotes it).
# Usage: scripts/fuzz-long.sh <fuzz build dir> [seconds per target, default 3600] [findings dir]
# A finding reproduces with: <build>/tests/fuzz/<target> <findings dir>/<target>/crash-...
set -euo pipefail
build=${1:?usage: scripts/fuzz-long.sh <fuzz build dir> [seconds per target] [findings dir]}
seconds=${2:-3600}
findings=${3:-$build/fuzz-findings}
root="$(cd "$(dirname "$0")/.." && pwd)"
export LSAN_OPTIONS="suppressions=$root/tests/fuzz/lsan.supp:print_suppressions=0"
# Memory counts when it is used: a finding is a process above -rss_limit_mb, not one allocation
# that a normal build would get lazily (a third-party reader reserving what a damaged size says,
# then reading the few bytes there are). An allocation no machine can give fails with bad_alloc,
# as in a normal build, and must come out as an error naming the file.
export ASAN_OPTIONS="allocator_may_return_null=1${ASAN_OPTIONS:+:$ASAN_OPTIONS}"
table="$(printf '%-20s %8s %14s %10s %9s' target seconds executions execs/s findings)"
found=0
for target in "$build"/tests/fuzz/fuzz_*; do
    [ -x "$target" ] || continue
    found=1
    name=$(basename "$target")
    work=$(mktemp -d)
    mkdir -p "$work/corpus" "$findings/$name"
    cp -r "$root/tests/fuzz/corpus/$name/." "$work/corpus/" 2>/dev/null || true
    echo "fuzzing $name for ${seconds}s (seeds: $(ls "$work/corpus" | wc -l))"
    executions=0
    problems=0
    start=$SECONDS
    while [ $((SECONDS - start)) -lt "$seconds" ]; do
        log="$work/log"
        if ! "$target" -max_total_time=$((seconds - (SECONDS - start))) -timeout=10 \
            -rss_limit_mb=2048 -malloc_limit_mb=1048576 -print_final_stats=1 \
            -artifact_prefix="$findings/$name/" "$work/corpus" >"$log" 2>&1; then
            problems=$((problems + 1))
            cp "$log" "$findings/$name/report-$problems.txt"
            echo "  finding $problems: $(grep -m1 -E 'SUMMARY|ERROR: libFuzzer' "$log" || echo '?')"
        fi
        runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -n 1)
        executions=$((executions + ${runs:-0}))
    done
    elapsed=$((SECONDS - start))
    table+=$'\n'"$(printf '%-20s %8d %14d %10d %9d' "$name" "$elapsed" "$executions" \
        $((executions / (elapsed > 0 ? elapsed : 1))) "$problems")"
    rm -rf "$work"
done
[ "$found" = 1 ] || { echo "no fuzz targets in $build/tests/fuzz" >&2; exit 1; }
echo "$table"
echo "findings (inputs and reports): $findings"
