#!/usr/bin/env bash
# Runs every libFuzzer target of a fuzz build briefly, as CI's fuzz stage does, starting from the
# seed corpus in tests/fuzz/corpus/<target>/. Usage: scripts/fuzz.sh <fuzz build dir> --ci
# Deterministic, so that a change cannot fail CI on a finding it did not cause: a fixed libFuzzer
# seed (-seed=1) and a fixed number of runs per target, from the committed seeds only. The runs
# are set per target below so that each takes under a minute here: the header parsers run 500000,
# the file readers (a temporary file per input, third-party decoders: 2 to 400 runs a second
# under ASan) and the command line (a CLI11 app built per run, about 130 a second) fewer.
# TEXSPLAT_FUZZ_RUNS, when set, is the runs of every target.
# Long exploration with random seeds, outside CI: scripts/fuzz-long.sh.
# On a finding it prints the sanitizer report and the input (base64) so that a CI log alone is
# enough to reproduce it: base64 -d > crash.iv, then <target> crash.iv.
set -euo pipefail
build=${1:?usage: scripts/fuzz.sh <fuzz build dir> --ci}
[ "${2:-}" = --ci ] || { echo "usage: scripts/fuzz.sh <fuzz build dir> --ci" >&2; exit 2; }
source "$(dirname "$0")/fuzz-targets.sh"
# Runs per target in CI; 500000 for any target not named.
declare -A ci_runs=(
    [fuzz_vdb_reader]=3000 [fuzz_netcdf_reader]=200 [fuzz_gltf_reader]=4000
    [fuzz_png_reader]=3000 [fuzz_exr_reader]=80 [fuzz_command_line]=1000
)
failed=0

run_ci() {
    local target=$1 name=$2 corpus=$3 findings log runs
    findings=$(mktemp -d)
    log="$findings/log"
    runs=${TEXSPLAT_FUZZ_RUNS:-${ci_runs[$name]:-500000}}
    echo "fuzzing $name: $runs runs, seed 1 (seeds: $(ls "$corpus" | wc -l))"
    # A cap on the time too, so that a slow machine still ends; the runs end first here.
    if "$target" -seed=1 -runs="$runs" -max_total_time=600 "${fuzz_limits[@]}" \
        -artifact_prefix="$findings/" "$corpus" >"$log" 2>&1; then
        tail -n 12 "$log"
    else
        failed=1
        echo "$name found a problem; its report:"
        grep -v -E '^#[0-9]+' "$log" | tail -n 120
        for finding in "$findings"/*; do
            [ -f "$finding" ] && [ "$finding" != "$log" ] || continue
            echo "input $(basename "$finding") ($(stat -c %s "$finding") bytes, base64):"
            base64 "$finding"
        done
    fi
    rm -rf "$findings"
}

for_each_target run_ci "$build"
exit "$failed"
