#!/usr/bin/env bash
# Runs the commands of a documentation page, so that a page of commands stays true: every fenced
# block marked ```sh, in order, as one bash script (set -euo pipefail) in an empty folder, with
# the texsplat command of a build first on PATH. Blocks marked otherwise (```console for the
# build itself, ``` for file contents) are shown, not run.
#
# Usage: scripts/run-doc-commands.sh PAGE.md TEXSPLAT_DIR [KEEP_DIR]
#   TEXSPLAT_DIR  the folder holding the built `texsplat` (build/release/apps)
#   KEEP_DIR      run there and keep what the commands made (default: a temporary folder,
#                 removed afterwards), e.g. to refresh a page's pictures
set -euo pipefail
page=$(realpath "$1")
texsplat_dir=$(realpath "$2")
[ -x "$texsplat_dir/texsplat" ] || { echo "run-doc-commands: no texsplat in $texsplat_dir" >&2; exit 2; }
if [ $# -ge 3 ]; then
    work=$(realpath -m "$3")
    mkdir -p "$work"
else
    work=$(mktemp -d)
    trap 'rm -rf "$work"' EXIT
fi
script="$work/doc-commands.sh"
{
    echo "set -euo pipefail"
    awk '/^```sh$/ { inside = 1; blocks++; printf "echo \"--- block %d\"\n", blocks; next }
         /^```/    { inside = 0; next }
         inside    { print }' "$page"
} > "$script"
blocks=$(grep -c '^```sh$' "$page" || true)
[ "$blocks" -gt 0 ] || { echo "run-doc-commands: $page has no sh blocks" >&2; exit 2; }
# Debian's python3 first (numpy, pyopenvdb come from its packages), then the build's texsplat.
(cd "$work" && PATH="$texsplat_dir:/usr/bin:$PATH" bash "$script")
echo "run-doc-commands: $(basename "$page"): $blocks blocks ran"
