# Sourced by the scripts that make the docs' pictures:
#   source "$root/scripts/texsplat-executable.sh"
#   texsplat=$(texsplat_executable "${1:-}")
# texsplat_executable ARG prints the texsplat executable that ARG names (the executable, or a build
# dir holding apps/texsplat; empty: the checkout's build/release), or says it is missing and fails.
texsplat_executable() {
    local root texsplat
    root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
    texsplat=${1:-$root/build/release}
    [ -d "$texsplat" ] && texsplat="$texsplat/apps/texsplat"
    if [ ! -x "$texsplat" ] || [ ! -f "$texsplat" ]; then
        echo "$0: missing $texsplat: build it first or name the executable" >&2
        return 1
    fi
    echo "$texsplat"
}
