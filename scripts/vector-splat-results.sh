#!/usr/bin/env bash
# Regenerates the pictures and numbers of docs/results/vector-splats.md with texsplat's own
# commands: the paper's figures 5-8 rendered headless from examples/figure*.iv (timed with
# --time-report), figure 5 as texture splats for the cost of the vectors, the two mark types on a
# vortex and figure 6 at three mark densities (docs/vector-splats.md shows them), and animated
# GIFs of figures 5 and 6 (scripts/animation.sh). The numbers replace the page's GENERATED block;
# the prose around them is written by hand. First it renders every scene snippet of
# docs/vector-splats.md, so that a snippet that no longer works fails here.
#
# Usage: scripts/vector-splat-results.sh [texsplat executable, or a build dir holding
#                                         apps/texsplat; default build/release]
# The GIFs need ImageMagick (apt-get install imagemagick), which texsplat itself does not.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
argument=${1:-$root/build/release}
texsplat=$argument
[ -d "$texsplat" ] && texsplat="$texsplat/apps/texsplat"
[ -x "$texsplat" ] && [ -f "$texsplat" ] || {
    echo "$0: missing $texsplat: build it first (cmake --preset release && cmake --build" \
         "--preset release) or name the executable" >&2
    exit 1
}
texsplat="$(cd "$(dirname "$texsplat")" && pwd)/$(basename "$texsplat")" # animation.sh runs it too
results="$root/docs/results"
page="$results/vector-splats.md"
guide="$root/docs/vector-splats.md"
begin='<!-- BEGIN GENERATED (scripts/vector-splat-results.sh): do not edit by hand -->'
end='<!-- END GENERATED -->'
for marker in "$begin" "$end"; do
    grep -qxF "$marker" "$page" || { echo "$0: $page lacks the line '$marker'" >&2; exit 1; }
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# 1. The guide's scene snippets: each fenced block that starts with the Inventor header.
awk -v dir="$work" '
    /^```/ {
        if (inside) {
            inside = 0
            if (file != "") close(file)
            file = ""
        } else {
            inside = 1
            first = 1
        }
        next
    }
    inside && first {
        first = 0
        if ($0 ~ /^#Inventor V2\.1 ascii/) {
            file = sprintf("%s/snippet-%03d.iv", dir, NR)
        }
    }
    inside && file != "" { print > file }
' "$guide"
snippets=0
for snippet in "$work"/snippet-*.iv; do
    [ -e "$snippet" ] || break
    line=$(basename "$snippet" .iv)
    line=$((10#${line#snippet-})) # the line of its '#Inventor' header
    "$texsplat" render "$snippet" -o "$work/snippet.png" --size 64x64 > /dev/null || {
        echo "$0: docs/vector-splats.md:$line: this scene snippet does not render" >&2
        exit 1
    }
    snippets=$((snippets + 1))
done
[ "$snippets" -gt 0 ] || { echo "$0: no scene snippets found in $guide" >&2; exit 1; }
echo "rendered the $snippets scene snippets of docs/vector-splats.md"

# 2. The marks: scratches and particles on the vortex of `bench --legibility` at 10 pixels a
# voxel; figure 6's winds at three mark densities. Side by side on black (ImageMagick).
"$texsplat" bench --legibility --backend cpu --repeat 1 --images "$work/legibility" > /dev/null
convert \( "$work/legibility/vortex-scratches-cpu-10.png" -background black -flatten \) \
        \( "$work/legibility/vortex-particles-cpu-10.png" -background black -flatten \) \
        -bordercolor gray20 -border 2 +append "$results/vector-marks.png"
for density in 0.3 0.6 1.5; do
    sed "s/^        markLength 7.5$/        markLength 7.5\n        markDensity $density/" \
        "$root/examples/figure6-jet-stream.iv" > "$work/density-$density.iv"
    "$texsplat" render "$work/density-$density.iv" -o "$work/density-$density.png" --size 384x384 \
        > /dev/null
    # The jets' band of the picture, on black.
    convert "$work/density-$density.png" -background black -flatten -crop 384x192+0+96 +repage \
        "$work/density-$density-band.png"
done
convert "$work"/density-0.3-band.png "$work"/density-0.6-band.png "$work"/density-1.5-band.png \
        -bordercolor gray20 -border 2 +append "$results/vector-density.png"

# 3. Figures 5-8 at 512 x 512, one frame each (scene time 0), timed.
value() { echo "$1" | awk -v key="$2" '$1 == key { print $2 }'; }
counts() { echo "$1" | awk '$1 == "splats" { gsub(",", ""); print $2, $4 }'; }
kib() { echo $(( $(stat -c %s "$1") / 1024 )); }
rows=()
context=
for scene in figure5-tornado figure6-jet-stream figure7-aerogel figure8-clouds-winds; do
    image="vector-$scene.png"
    report=$("$texsplat" render "$root/examples/$scene.iv" -o "$results/$image" \
             --size 512x512 --time-report)
    [ -n "$context" ] || context=$(echo "$report" | sed -n 's/^ *backend *\(.*\)$/\1/p')
    read -r splats triangles <<< "$(counts "$report")"
    number=${scene#figure}
    rows+=("$(printf '| %s | `examples/%s.iv` | %s | %s | %s | %s | %s | [%s](%s) (%s KiB) |' \
        "${number%%-*}" "$scene" "$splats" "$triangles" "$(value "$report" classify)" \
        "$(value "$report" order)" "$(value "$report" draw)" \
        "$image" "$image" "$(kib "$results/$image")")")
done

# The same figure 5 frame with TextureSplat in place of VectorSplat: the same voxels (|v|
# through the same transfer function), drawn as the scalar kernel instead of marks.
sed '/^ *VectorSplat {/,/^ *}/c\    TextureSplat { }' "$root/examples/figure5-tornado.iv" \
    > "$work/figure5-texture.iv"
if ! grep -q TextureSplat "$work/figure5-texture.iv" ||
    grep -q VectorSplat "$work/figure5-texture.iv"; then
    echo "$0: could not turn figure 5's VectorSplat into a TextureSplat" >&2
    exit 1
fi
# One frame's time varies with the load of a shared machine: take the best of 3 runs of each,
# alternating, so that both see the same conditions. A frame's splatting is classify + order
# (the marks are drawn there) + draw.
splatting() {
    awk -v c="$(value "$1" classify)" -v o="$(value "$1" order)" -v d="$(value "$1" draw)" \
        'BEGIN { printf "%.4f", c + o + d }'
}
vector_draw=
texture_draw=
smaller() { awk -v a="$1" -v b="$2" 'BEGIN { if (a == "" || b + 0 < a + 0) print b; else print a }'; }
for _ in 1 2 3; do
    vector_report=$("$texsplat" render "$root/examples/figure5-tornado.iv" \
                    -o "$work/figure5-vector.png" --size 512x512 --time-report)
    texture_report=$("$texsplat" render "$work/figure5-texture.iv" -o "$work/figure5-texture.png" \
                     --size 512x512 --time-report)
    vector_draw=$(smaller "$vector_draw" "$(splatting "$vector_report")")
    texture_draw=$(smaller "$texture_draw" "$(splatting "$texture_report")")
done

# 4. Animations: frames covering one life cycle of the marks (fps / speed of the scene's
# ElapsedTime) loop seamlessly.
TEXSPLAT="$texsplat" "$root/scripts/animation.sh" "$root/examples/figure5-tornado.iv" \
    "$results/vector-figure5-tornado.gif" 16 8 256x256
TEXSPLAT="$texsplat" "$root/scripts/animation.sh" "$root/examples/figure6-jet-stream.iv" \
    "$results/vector-figure6-jet-stream.gif" 16 4 256x256

{
    echo "$begin"
    echo
    echo "Regenerated by \`scripts/vector-splat-results.sh $([ $# -gt 0 ] && echo "$1")\`" \
         "on $(date -u +%Y-%m-%d),"
    echo "on a machine with $(nproc) CPU cores; backend:"
    echo "$context."
    echo "Each scene is rendered once at 512 × 512 (scene time 0) with"
    echo "\`texsplat render examples/NAME.iv -o vector-NAME.png --size 512x512 --time-report\`;"
    echo "times are wall seconds of that one frame (\`draw\` includes placing the marks for the"
    echo "view)."
    echo
    echo "| figure | scene | splats (of a VectorSplat: its marks) | triangles | classify (s) | order (s) | draw (s) | image |"
    echo "|---|---|---|---|---|---|---|---|"
    printf '%s\n' "${rows[@]}"
    echo
    read -r vector_splats _ <<< "$(counts "$vector_report")"
    read -r texture_splats _ <<< "$(counts "$texture_report")"
    echo "Figure 5's frame drawn the two ways: the scene as it is, and with \`TextureSplat { }\` in"
    echo "place of its \`VectorSplat\` (the same voxels, drawn as the scalar kernel); the best time"
    echo "of classify + order + draw (the marks are drawn in order) of 3 runs each, alternating:"
    echo
    echo "| splats as | splats | classify + order + draw (s) |"
    echo "|---|---|---|"
    echo "| \`VectorSplat\` (marks) | $vector_splats | $vector_draw |"
    echo "| \`TextureSplat\` (the scalar kernel) | $texture_splats | $texture_draw |"
    echo
    echo "The vector splats' frame is $(awk -v v="$vector_draw" -v t="$texture_draw" \
        'BEGIN { printf "%.2f", v / t }') times the texture splats'."
    echo
    echo "Animations (\`scripts/animation.sh\`, 256 × 256):"
    echo
    echo "| animation | frames | fps | loop (s) | size |"
    echo "|---|---|---|---|---|"
    echo "| [vector-figure5-tornado.gif](vector-figure5-tornado.gif) | 16 | 8 | 2 | $(kib "$results/vector-figure5-tornado.gif") KiB |"
    echo "| [vector-figure6-jet-stream.gif](vector-figure6-jet-stream.gif) | 16 | 4 | 4 | $(kib "$results/vector-figure6-jet-stream.gif") KiB |"
    echo
    echo "Times are wall seconds on a shared machine: compare them only with numbers taken in the"
    echo "same run."
    echo
    echo "$end"
} > "$work/generated.md"
awk -v begin="$begin" -v end="$end" -v generated="$work/generated.md" '
    $0 == begin { while ((getline line < generated) > 0) print line; skip = 1; next }
    $0 == end { skip = 0; next }
    !skip { print }
' "$page" > "$page.tmp"
mv "$page.tmp" "$page"
echo "wrote $page"
