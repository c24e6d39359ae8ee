# What scripts/fuzz.sh (CI) and scripts/fuzz-long.sh share, sourced by both: the sanitizer
# settings and libFuzzer limits of every run, and the targets of a fuzz build with their seeds.
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
export LSAN_OPTIONS="suppressions=$root/tests/fuzz/lsan.supp:print_suppressions=0"
# Memory counts when it is used: a finding is a process above -rss_limit_mb, not one allocation
# that a normal build would get lazily (a third-party reader reserving what a damaged size says,
# then reading the few bytes there are). A malloc no machine can give returns null as in a normal
# build (ASan still reports a throwing `new` of that size; docs/reliability.md, Fuzzing).
export ASAN_OPTIONS="allocator_may_return_null=1${ASAN_OPTIONS:+:$ASAN_OPTIONS}"
fuzz_limits=(-timeout=10 -rss_limit_mb=2048 -malloc_limit_mb=1048576 -print_final_stats=1)

# for_each_target <function> <fuzz build dir>: calls <function> <target> <name> <corpus> for each
# fuzz_* target of the build, <corpus> a scratch folder holding a copy of its committed seeds
# (tests/fuzz/corpus/<name>/), removed afterwards. Fails when the build has no target.
for_each_target() {
    local run=$1 build=$2 found=0 target name corpus
    for target in "$build"/tests/fuzz/fuzz_*; do
        [ -x "$target" ] || continue
        found=1
        name=$(basename "$target")
        corpus=$(mktemp -d)
        cp -r "$root/tests/fuzz/corpus/$name/." "$corpus/" 2>/dev/null || true
        "$run" "$target" "$name" "$corpus"
        rm -rf "$corpus"
    done
    [ "$found" = 1 ] || { echo "no fuzz targets in $build/tests/fuzz" >&2; exit 1; }
}
