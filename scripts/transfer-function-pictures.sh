#!/usr/bin/env bash
# Regenerates the pictures of docs/transfer-functions.md with texsplat's own renderer: every
# fenced scene of the page that starts with the Inventor header and has a line
# "# picture: NAME.png [render options]" is rendered to docs/transfer-functions/NAME.png, and two
# variants that the page describes in words: distance-clamped.png (distance-auto's scene with
# `range 0 1` written) and rings-wide.png (rings' scene with a peak two voxels wide). The data
# the scenes read, sphere-distance.npy (a sphere's signed distance in voxel units of a 64^3
# grid over [-1, 1]^3, clamped to -0.15..0.15), is written with numpy (python3-numpy; set
# PYTHON to a python3 that has it if the first on PATH has not).
#
# colorbar-matplotlib.png puts texsplat's colour bar of MAGMA under matplotlib's own (matplotlib
# and Pillow: python3-matplotlib, python3-pil).
#
# Usage: scripts/transfer-function-pictures.sh [texsplat executable, or a build dir holding
#                                               apps/texsplat; default build/release]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
source "$root/scripts/texsplat-executable.sh"
texsplat=$(texsplat_executable "${1:-}")
page="$root/docs/transfer-functions.md"
pictures="$root/docs/transfer-functions"
mkdir -p "$pictures"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

"${PYTHON:-python3}" - "$work/sphere-distance.npy" <<'PYTHON'
import sys
import numpy as np
n = 64
axis = (np.arange(n) + 0.5) / n * 2.0 - 1.0
z, y, x = np.meshgrid(axis, axis, axis, indexing="ij")  # C order: x varies fastest
distance = np.sqrt(x**2 + (1.2 * y)**2 + z**2) - 0.6
np.save(sys.argv[1], np.clip(distance, -0.15, 0.15).astype(np.float32))
PYTHON

# Each picture scene of the page into $work/NAME.iv, and its render options into $work/NAME.args.
awk -v dir="$work" '
    /^```/ {
        if (inside) { inside = 0; if (file != "") close(file); file = ""; next }
        inside = 1; first = 1; text = ""; next
    }
    inside && first { first = 0; if ($0 != "#Inventor V2.1 ascii") { inside = 0; next } }
    inside {
        text = text $0 "\n"
        if ($2 == "picture:") {
            name = $3; sub(/\.png$/, "", name); file = dir "/" name ".iv"
            options = ""; for (i = 4; i <= NF; ++i) options = options " " $i
            print options > (dir "/" name ".args"); close(dir "/" name ".args")
            printf "%s", text > file
        } else if (file != "") {
            print > file
        }
    }
' "$page"

sed 's/^    TransferFunction {$/    TransferFunction {\n        range 0 1/' "$work/distance-auto.iv" \
    > "$work/distance-clamped.iv"
cp "$work/distance-auto.args" "$work/distance-clamped.args"
sed 's/opacityValues \[ 0.47, 0.5, 0.53 \]/opacityValues [ 0.3, 0.5, 0.7 ]/' "$work/rings.iv" \
    > "$work/rings-wide.iv"
cp "$work/rings.args" "$work/rings-wide.args"

for scene in "$work"/*.iv; do
    name=$(basename "$scene" .iv)
    # shellcheck disable=SC2046 # the options are words
    "$texsplat" render "$scene" -o "$pictures/$name.png" --size 240x240 --backend cpu \
        --direction 1,-0.7,-1.4 $(cat "$work/$name.args")
    echo "wrote docs/transfer-functions/$name.png"
done

# texsplat's colour bar beside matplotlib's, of the same map over the same range: the bar's
# strip cut from a render with --colorbar at the bottom, under matplotlib's own colorbar.
cat > "$work/bar.iv" <<'SCENE'
#Inventor V2.1 ascii
Separator {
    TransferFunction { preset MAGMA range 0 1.2 title "magma" units "texsplat" }
    VolumeData { source MARSCHNER_LOBB resolution 8 8 8 }
    TextureSplat { }
}
SCENE
"$texsplat" render "$work/bar.iv" -o "$work/bar.png" --size 480x480 --backend cpu \
    --colorbar --colorbar-position bottom --colorbar-ticks 7 --background white
"${PYTHON:-python3}" - "$work/bar.png" "$pictures/colorbar-matplotlib.png" <<'PYTHON'
import sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from PIL import Image

texsplat = np.asarray(Image.open(sys.argv[1]).convert("RGB"))[480:]  # the strip under the picture
height = texsplat.shape[0] / 100.0
figure = plt.figure(figsize=(4.8, 0.9 + height), dpi=100)
bar = figure.add_axes([0.1, 1.0 - 0.25 / (0.9 + height), 0.8, 0.2 / (0.9 + height)])
figure.colorbar(matplotlib.cm.ScalarMappable(matplotlib.colors.Normalize(0.0, 1.2), "magma"),
                cax=bar, orientation="horizontal", label="magma (matplotlib)")
figure.figimage(texsplat, xo=0, yo=0)
figure.savefig(sys.argv[2], dpi=100)
PYTHON
echo "wrote docs/transfer-functions/colorbar-matplotlib.png"
