#!/usr/bin/env bash
# Soak (issue 14): many frames in one process, its resident memory sampled, so that a leak or a
# cache that grows per frame shows as growth. A benchmark script, not a CI test (minutes).
#
# Two scenes, each rendered as one `texsplat render --frames N` process:
#   animated     the paper's figure 5 (vector splats whose phase follows the scene's clock);
#   tf-edits     texture splats whose transfer function is edited every frame (its emission and
#                (the clock): each frame classifies again) and
#                whose octree cut is refined progressively (the error threshold falls with time).
# The resident size (VmRSS) is sampled every 0.2 s. Growth is the last sample less the sample
# when a tenth of the frames were done (caches and allocator pools are warm by then); the
# script fails when growth exceeds the bound.
#
# Usage: scripts/soak.sh [frames=10000] [backend=cpu] [size=64x64] [bound-MiB=8]
# The texsplat executable: $TEXSPLAT, else build/ci/apps/texsplat, else build/release/apps/texsplat.
set -euo pipefail
frames=${1:-10000}
backend=${2:-cpu}
size=${3:-64x64}
bound_mib=${4:-8}
root="$(cd "$(dirname "$0")/.." && pwd)"
texsplat=${TEXSPLAT:-}
for candidate in "$root/build/ci/apps/texsplat" "$root/build/release/apps/texsplat"; do
    if [ -z "$texsplat" ] && [ -x "$candidate" ]; then
        texsplat=$candidate
    fi
done
[ -n "$texsplat" ] || { echo "$0: no texsplat executable: build it or set TEXSPLAT" >&2; exit 1; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cat > "$work/tf-edits.iv" <<'EOF'
#Inventor V2.1 ascii
Separator {
    TransferFunction {
        preset HOT
        range 0 1
        opacityValues [ 0, 0.2, 1 ]
        opacities [ 0, 0, 20 ]
        emission = ElapsedTime { speed 0.01 } . timeOut
    }
    VolumeData { source MARSCHNER_LOBB resolution 24 24 24 }
    TextureSplat { errorThreshold = ElapsedTime { speed 0.0001 } . timeOut }
}
EOF

# soak NAME SCENE: renders FRAMES frames of SCENE, samples its memory, prints one line.
failed=0
soak() {
    local name=$1 scene=$2
    mkdir -p "$work/$name"
    local samples="$work/$name.rss"
    local start=$SECONDS
    "$texsplat" render "$scene" --backend "$backend" --size "$size" --frames "$frames" \
        --fps 24 -o "$work/$name/f%05d.png" > /dev/null 2> "$work/$name.log" &
    local pid=$!
    : > "$samples"
    local written=0
    while kill -0 "$pid" 2> /dev/null; do
        local rss
        rss=$(awk '/^VmRSS/ { print $2 }' "/proc/$pid/status" 2> /dev/null || true)
        # Frames are counted and removed as they come (a write renames a hidden temporary file).
        written=$((written + $(find "$work/$name" -name 'f*.png' -print -delete | wc -l)))
        [ -n "$rss" ] && echo "$written $rss" >> "$samples"
        sleep 0.2
    done
    wait "$pid" || { cat "$work/$name.log" >&2; failed=1; return; }
    local seconds=$((SECONDS - start))
    awk -v name="$name" -v frames="$frames" -v seconds="$seconds" -v bound="$bound_mib" '
        { rss[NR] = $2; count[NR] = $1; if ($2 > peak) peak = $2 }
        END {
            warm = rss[1]
            for (i = 1; i <= NR; ++i) if (count[i] * 10 <= frames) warm = rss[i]
            last = rss[NR]
            growth = (last - warm) / 1024
            format = "%-9s %6d frames %5d s  rss after 10%%: %6.1f MiB  peak: %6.1f MiB  " \
                     "last: %6.1f MiB  growth: %+5.1f MiB (bound %d MiB)"
            print sprintf(format, name, frames, seconds, warm / 1024, peak / 1024, last / 1024,
                          growth, bound)
            exit growth > bound ? 1 : 0
        }' "$samples" || failed=1
}

echo "texsplat soak: $("$texsplat" --version | tr '\n' ' '); backend $backend, $size"
soak animated "$root/examples/figure5-tornado.iv"
soak tf-edits "$work/tf-edits.iv"
exit $failed
