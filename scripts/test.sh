#!/usr/bin/env bash
# Builds and runs the whole test suite (the README's second command; CI runs it too).
# Stages: ci (optimized, -Werror, asserts on), python (the module built with pip in a venv, bound to
# the ci build's libraries, and its pytest suite), asan (ASan + UBSan over the same tests), nogl
# (the command line built without GL, checked on the CPU backend), fuzz (clang libFuzzer
# targets, a bounded run each). Each stage prints its own timing.
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

stage "build without GL (TEXSPLAT_WITH_GL=OFF): render and bench on the CPU backend"
cmake --preset nogl
cmake --build --preset nogl -j "$jobs"
bash scripts/check-without-gl.sh build/nogl/apps/texsplat

stage "fuzz: bounded libFuzzer runs"
cmake --preset fuzz
cmake --build --preset fuzz -j "$jobs"
bash scripts/fuzz.sh build/fuzz --ci
stage "done"
