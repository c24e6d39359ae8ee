#!/usr/bin/env bash
# Builds and runs the whole test suite (the README's second command; CI runs it too).
# Stages: ci (optimized, -Werror, asserts on), python (the module built with pip in a venv, bound to
# the ci build's libraries, and its pytest suite), asan (ASan + UBSan over the same tests), fuzz
# (clang libFuzzer targets, a bounded run each; the build leaves GL out, so its command line is
# also the check that texsplat builds and renders without GL). Each stage prints its own timing.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc)
stage() { printf '\n=== %s (%s) ===\n' "$1" "$(date -u +%H:%M:%S)"; }

stage "build and test: ci preset"
cmake --preset ci
cmake --build --preset ci -j "$jobs"
ctest --preset ci -j "$jobs"

stage "python: pip install . in a venv (bound to the ci build's libraries), pytest"
bash scripts/python-module.sh build/ci

stage "build and test: asan preset (AddressSanitizer + UndefinedBehaviorSanitizer)"
cmake --preset asan
cmake --build --preset asan -j "$jobs"
ctest --preset asan -j "$jobs"

stage "fuzz build (clang, ASan + UBSan, without GL or MPI): render and bench without them"
# One build for both: a separate GL-less build of the library took a sixth of the CI's time.
cmake --preset fuzz
cmake --build --preset fuzz -j "$jobs"
LSAN_OPTIONS="suppressions=$PWD/tests/sanitizers/lsan.supp:print_suppressions=0" \
    bash scripts/check-without-gl.sh build/fuzz/apps/texsplat

stage "fuzz: bounded libFuzzer runs"
bash scripts/fuzz.sh build/fuzz --ci
stage "done"
