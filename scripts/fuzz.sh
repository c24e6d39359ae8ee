#!/usr/bin/env bash
# Runs every libFuzzer target of a fuzz build briefly, as CI's fuzz stage does, starting from the
# seed corpus in tests/fuzz/corpus/<target>/. Usage: scripts/fuzz.sh <fuzz build dir> --ci
# Deterministic, so that a change cannot fail CI on a finding it did not cause: a fixed libFuzzer
# seed (-seed=1) and a fixed number of runs per target, from the committed seeds only. The runs
# are set per target below so that each takes about 5-20 s here: the header parsers run 500000,
# the file readers (a temporary file per input, third-party decoders) and the command line
# fewer. TEXSPLAT_FUZZ_RUNS, when set, is the runs of every target.
# Long exploration with random seeds, outside CI: scripts/fuzz-long.sh.
# On a finding it prints the sanitizer report and the input (base64) so that a CI log alone is
# enough to reproduce it: base64 -d > crash.iv, then <target> crash.iv.
set -euo pipefail
build=${1:?usage: scripts/fuzz.sh <fuzz build dir> --ci}
[ "${2:-}" = --ci ] || { echo "usage: scripts/fuzz.sh <fuzz build dir> --ci" >&2; exit 2; }
# Runs per target in CI; 500000 for any target not named.
declare -A ci_runs=(
    [fuzz_vdb_reader]=4000 [fuzz_netcdf_reader]=4000 [fuzz_gltf_reader]=20000
    [fuzz_png_reader]=20000 [fuzz_exr_reader]=10000 [fuzz_command_line]=20000
)
root="$(cd "$(dirname "$0")/.." && pwd)"
export LSAN_OPTIONS="suppressions=$root/tests/fuzz/lsan.supp:print_suppressions=0"
# Memory counts when it is used: a finding is a process above -rss_limit_mb, not one allocation
# that a normal build would get lazily (a third-party reader reserving what a damaged size says,
# then reading the few bytes there are). An allocation no machine can give fails with bad_alloc,
# as in a normal build, and must come out as an error naming the file.
export ASAN_OPTIONS="allocator_may_return_null=1${ASAN_OPTIONS:+:$ASAN_OPTIONS}"
found=0
failed=0
for target in "$build"/tests/fuzz/fuzz_*; do
    [ -x "$target" ] || continue
    found=1
    name=$(basename "$target")
    work=$(mktemp -d)
    mkdir "$work/corpus" "$work/findings"
    cp -r "$root/tests/fuzz/corpus/$name/." "$work/corpus/" 2>/dev/null || true
    runs=${TEXSPLAT_FUZZ_RUNS:-${ci_runs[$name]:-500000}}
    echo "fuzzing $name: $runs runs, seed 1 (seeds: $(ls "$work/corpus" | wc -l))"
    # A cap on the time too, so that a slow machine still ends; the runs end first here.
    if "$target" -seed=1 -runs="$runs" -max_total_time=600 -timeout=10 -rss_limit_mb=2048 \
        -malloc_limit_mb=1048576 -print_final_stats=1 -artifact_prefix="$work/findings/" \
        "$work/corpus" >"$work/log" 2>&1; then
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
