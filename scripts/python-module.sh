#!/usr/bin/env bash
# Builds the Python module as a user does (`pip install .` into a venv made with Debian's python3
# and --system-site-packages, docs/python.md) and runs its pytest suite against the texsplat
# command of the same build.
#
# Usage: scripts/python-module.sh [CMAKE_BUILD_DIR]
# With a CMake build directory (CI passes build/ci), its libraries are installed into
# CMAKE_BUILD_DIR/prefix and the module binds them (TEXSPLAT_PREFIX), instead of compiling every
# library a second time, and its texsplat command is the one the tests compare with; the
# extension's own build stays in CMAKE_BUILD_DIR/python between runs. Without one, pip builds the
# libraries too (what `pip install .` alone does).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-}
venv=build/python-venv
rm -rf "$venv"
/usr/bin/python3 -m venv --system-site-packages "$venv"
options=()
if [[ -n "$build" ]]; then
    cmake --install "$build" --prefix "$build/prefix" > /dev/null
    options=(--config-settings="cmake.define.TEXSPLAT_PREFIX=$PWD/$build/prefix"
             --config-settings="build-dir=$build/python")
    export TEXSPLAT_CLI=$PWD/$build/apps/texsplat
fi
start=$(date +%s)
"$venv/bin/pip" install --quiet --disable-pip-version-check "${options[@]}" .
echo "pip install .: $(( $(date +%s) - start )) s"
# From outside the checkout, so that `import texsplat` finds the installed package.
cd python/tests
"../../$venv/bin/python" -m pytest -q -p no:cacheprovider .
