#!/usr/bin/env bash
# Turns a scene's animation into an animated image for the docs: renders its frames with
# `texsplat render --frames` (a simulated clock: the same file on every run) into a temporary
# folder, then assembles them into an animated GIF (ImageMagick) or WebP (img2webp).
#
# Usage: scripts/animation.sh SCENE.iv OUT.gif|OUT.webp [frames, default 48] [fps, default 24]
#                             [size WxH, default 256x256]
# The texsplat executable: $TEXSPLAT, else build/release/apps/texsplat, else texsplat on PATH.
# The assembling tools are for the docs only, not dependencies of texsplat (scripts/install-deps.sh
# leaves them out): .gif needs ImageMagick's convert (apt-get install imagemagick), .webp needs
# img2webp (apt-get install webp).
set -euo pipefail
usage="usage: $0 SCENE.iv OUT.gif|OUT.webp [frames=48] [fps=24] [size=256x256]"
[ $# -ge 2 ] && [ $# -le 5 ] || { echo "$usage" >&2; exit 2; }
scene=$1
out=$2
frames=${3:-48}
fps=${4:-24}
size=${5:-256x256}
root="$(cd "$(dirname "$0")/.." && pwd)"

texsplat=${TEXSPLAT:-}
if [ -z "$texsplat" ]; then
    if [ -x "$root/build/release/apps/texsplat" ]; then
        texsplat="$root/build/release/apps/texsplat"
    else
        texsplat=$(command -v texsplat || true)
    fi
fi
[ -n "$texsplat" ] && [ -x "$texsplat" ] || {
    echo "$0: no texsplat executable: build it (cmake --preset release && cmake --build --preset" \
         "release) or set TEXSPLAT" >&2
    exit 1
}

# Check the tool before rendering, which may take a while.
case "${out,,}" in
*.gif)
    if command -v magick > /dev/null; then
        assemble=(magick)
    elif command -v convert > /dev/null; then
        assemble=(convert)
    else
        echo "$0: $out needs ImageMagick's convert: apt-get install imagemagick" >&2
        exit 1
    fi
    ;;
*.webp)
    command -v img2webp > /dev/null || {
        echo "$0: $out needs img2webp: apt-get install webp" >&2
        exit 1
    }
    ;;
*)
    echo "$0: $out: expected a .gif or .webp output" >&2
    exit 1
    ;;
esac

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# texsplat checks the scene, the frame count, the rate and the size, and says what is wrong.
"$texsplat" render "$scene" --frames "$frames" --fps "$fps" --size "$size" \
    -o "$work/frame%06d.png"
shopt -s nullglob
pngs=("$work"/frame*.png) # zero-padded: the glob's order is the frame order
[ ${#pngs[@]} -gt 0 ] || { echo "$0: texsplat wrote no frames" >&2; exit 1; }

# GIF delays are whole hundredths of a second, WebP durations whole milliseconds.
case "${out,,}" in
*.gif)
    delay=$(awk -v fps="$fps" 'BEGIN { d = int(100 / fps + 0.5); print (d < 2 ? 2 : d) }')
    "${assemble[@]}" -delay "$delay" -loop 0 "${pngs[@]}" -layers Optimize "$work/animation.gif"
    result="$work/animation.gif"
    ;;
*.webp)
    duration=$(awk -v fps="$fps" 'BEGIN { d = int(1000 / fps + 0.5); print (d < 1 ? 1 : d) }')
    img2webp -loop 0 -lossless -d "$duration" "${pngs[@]}" -o "$work/animation.webp" > /dev/null
    result="$work/animation.webp"
    ;;
esac
# The finished file replaces the old one in one step (a rename within its folder).
cp "$result" "$out.tmp.$$"
mv -f "$out.tmp.$$" "$out"
echo "wrote $out: ${#pngs[@]} frames at $fps fps, $size"
