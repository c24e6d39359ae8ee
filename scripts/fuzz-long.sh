#!/usr/bin/env bash
# Long fuzzing, outside CI (CI runs scripts/fuzz.sh: seed 1, fixed runs): runs every libFuzzer
# target of a fuzz build for a given time each, from a stated seed, from the committed seeds in tests/fuzz/corpus/<target>/ (the corpus grows in
# a scratch copy). A run that finds a problem is counted, its input and report kept under the
# findings folder, and the target goes on for the rest of its time. Prints a table of totals:
# seconds, executions and findings per target (docs/reliability.md quotes it).
# Usage: scripts/fuzz-long.sh <fuzz build dir> [seconds per target, default 3600] [findings dir]
#        [seed, default the current time]
# Every libFuzzer run gets an explicit -seed= (the seed, plus one per restart after a finding),
# printed with the run, so that a run is repeatable; give another seed to explore elsewhere.
# A finding reproduces with: <build>/tests/fuzz/<target> <findings dir>/<target>/crash-...
set -euo pipefail
build=${1:?usage: scripts/fuzz-long.sh <fuzz build dir> [seconds per target] [findings dir]}
seconds=${2:-3600}
findings=${3:-$build/fuzz-findings}
seed=${4:-$(date +%s)}
[[ "$seed" =~ ^[0-9]+$ ]] || { echo "fuzz-long: the seed must be a whole number, got '$seed'" >&2; exit 2; }
source "$(dirname "$0")/fuzz-targets.sh"
table="$(printf '%-20s %8s %14s %10s %9s' target seconds executions execs/s findings)"

run_long() {
    local target=$1 name=$2 corpus=$3 executions=0 problems=0 start=$SECONDS runs
    local log="$findings/$name/last.log"
    mkdir -p "$findings/$name"
    echo "fuzzing $name for ${seconds}s from seed $seed (seeds: $(ls "$corpus" | wc -l))"
    while [ $((SECONDS - start)) -lt "$seconds" ]; do
        if ! "$target" -seed=$((seed + problems)) \
            -max_total_time=$((seconds - (SECONDS - start))) "${fuzz_limits[@]}" \
            -artifact_prefix="$findings/$name/" "$corpus" >"$log" 2>&1; then
            problems=$((problems + 1))
            cp "$log" "$findings/$name/report-$problems.txt"
            echo "  finding $problems:" \
                "$(grep -a -m1 -E 'SUMMARY|ERROR: libFuzzer' "$log" || echo '?')"
        fi
        runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -n 1)
        executions=$((executions + ${runs:-0}))
    done
    local elapsed=$((SECONDS - start))
    table+=$'\n'"$(printf '%-20s %8d %14d %10d %9d' "$name" "$elapsed" "$executions" \
        $((executions / (elapsed > 0 ? elapsed : 1))) "$problems")"
}

for_each_target run_long "$build"
echo "seed $seed (scripts/fuzz-long.sh $build $seconds $findings $seed repeats this run)"
echo "$table"
echo "findings (inputs and reports): $findings"
