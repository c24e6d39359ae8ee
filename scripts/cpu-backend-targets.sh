#!/usr/bin/env bash
# The CPU backend against its targets (issue 32), measured in one run on this machine and
# written as a Markdown table to docs/results/cpu-targets.md (and stdout):
#   speed    the reference splatter (../shared/reference/cpu-splat/run.sh: Marschner-Lobb 128^3
#            at 512^2, orthographic, VTK's transfer function) and texsplat's `bench` frame of the
#            same scene, alternated, $ROUNDS rounds; VTK 9's fixed-point ray caster on the same
#            scene (scripts/vtk-peer.py) and texsplat's image against VTK's (interior RMSE)
#   images   texsplat's CPU image against its GL image of the same scene (OpenEXR, PSNR)
#   threads  bench frames on 1 and 2 threads, alternated, $ROUNDS rounds
#   one-shot the draw of one `texsplat render` against bench's warm frame
#   size     dense Marschner-Lobb 128^3 and 320^3 float volumes at 384^2, orthographic, oblique:
#            order + draw per splat and the peak resident memory, from `render --time-report`
#
# The machine may be shared: ratios come from measurements close in time (the same round), and
# the table says the load. Needs g++, numpy and python3-vtk9 (the reference and the VTK peer:
# `bash scripts/install-deps.sh --peers`),
# and texsplat built with GL for the GL image (without it that row is left out).
# Usage: scripts/cpu-backend-targets.sh [PATH/TO/texsplat or build dir] [ROUNDS]
#   OUT     where the table goes   [docs/results/cpu-targets.md]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
source "$root/scripts/texsplat-executable.sh"
texsplat=$(texsplat_executable "${1:-}")
rounds=${2:-3}
out=${OUT:-$root/docs/results/cpu-targets.md}
reference=${REFERENCE:-$root/../shared/reference/cpu-splat}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
load_before=$(cut -d' ' -f1 /proc/loadavg)

# median of the numbers on stdin; best: the smallest.
median() {
    sort -g | awk '{ v[NR] = $1 }
                   END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'
}
smallest() { sort -g | head -1; }

# The bench frame (ms) of a scene on the CPU backend: bench_frame SCENE [OPTIONS...]
bench_frame() {
    local scene=$1
    shift
    "$texsplat" bench "$scene" --budgets 1 --repeat 5 --no-reference --backend cpu "$@" 2>/dev/null |
        awk '$3 == "scene" { print $8 }'
}

# speed: the reference and texsplat alternated (run.sh), then VTK on the same scene.
"$reference/run.sh" "$texsplat" "$rounds" | tee "$work/run.log" >&2
ratios=$(sed -n 's/.*: \([0-9.]*\)x the reference/\1/p' "$work/run.log")
reference_ms=$(sed -n 's/.*reference \([0-9.]*\) ms,.*/\1/p' "$work/run.log" | median)
texsplat_ms=$(sed -n 's/.*texsplat \([0-9.]*\) ms:.*/\1/p' "$work/run.log" | median)
scene=${TMPDIR:-/tmp}/texsplat-reference/ml128_ortho.iv
/usr/bin/python3 "$root/scripts/vtk-peer.py" "$texsplat" --size 128 --image 512 --repeat 3 \
    --backend cpu > "$work/vtk.log"
vtk_ms=$(sed -n 's/^VTK render *\([0-9.]*\) ms.*/\1/p' "$work/vtk.log")
vtk_rmse=$(sed -n 's/^interior RMSE *\([0-9.]*\) steps.*/\1/p' "$work/vtk.log")

# images: CPU against GL, in float.
gl_psnr="-"
if "$texsplat" render "$scene" --backend gl -o "$work/gl.exr" 2>/dev/null; then
    "$texsplat" render "$scene" --backend cpu -o "$work/cpu.exr" 2>/dev/null
    gl_psnr=$("$texsplat" compare "$work/gl.exr" "$work/cpu.exr" | awk '$1 == "RGB" { print $3 }')
fi

# threads: 1 and 2, alternated.
for r in $(seq "$rounds"); do
    one=$(bench_frame "$scene" --threads 1)
    two=$(bench_frame "$scene" --threads 2)
    echo "threads round $r: 1 thread $one ms, 2 threads $two ms" >&2
    /usr/bin/python3 -c "print($one / $two)" >> "$work/scaling"
done
scaling=$(median < "$work/scaling")

# one-shot: a whole `render` (its draw) against bench's warm frame, alternated.
for r in $(seq "$rounds"); do
    warm=$(bench_frame "$scene")
    cold=$("$texsplat" render "$scene" --backend cpu -o "$work/once.png" --time-report 2>&1 |
           awk '$1 == "draw" { print 1000 * $2 }')
    echo "one-shot round $r: render's draw $cold ms, bench frame $warm ms" >&2
    /usr/bin/python3 -c "print($cold / $warm)" >> "$work/oneshot"
done
oneshot=$(median < "$work/oneshot")

# size: dense volumes, oblique, orthographic, 384^2.
size_row() {
    local n=$1
    cat > "$work/ml$n.iv" <<EOF
#Inventor V2.1 ascii
Separator {
  TransferFunction { colorValues [ 0, 1 ] colors [ 0 0 0, 1 1 1 ] opacityValues [ 0, 1 ] opacities [ 0, 0.05 ] }
  VolumeData { source MARSCHNER_LOBB resolution $n $n $n }
  TextureSplat { }
}
EOF
    "$texsplat" render "$work/ml$n.iv" --backend cpu --camera orthographic --direction -1,-0.7,-1.3 \
        --size 384x384 -o "$work/ml$n.png" --time-report 2>&1 |
        awk -v n="$n" '$1 == "order" { order = $2 } $1 == "draw" { draw = $2 }
             $1 == "splats" { splats = $2 } /memory: peak/ { peak = $3 }
             END { printf "| dense %d³ float (%.0f MiB), 384², oblique | %d | %.2f s | %.0f ns | %s MiB |\n",
                   n, n * n * n * 4 / 1048576, splats, order + draw, 1e9 * (order + draw) / splats, peak }'
}

{
    echo "Measured $(date -u +%Y-%m-%d) by \`scripts/cpu-backend-targets.sh\` ($rounds rounds;" \
         "load $load_before at the start, $(cut -d' ' -f1 /proc/loadavg) at the end; $(nproc) cores," \
         "$(awk -F': ' '/model name/ { print $2; exit }' /proc/cpuinfo))."
    echo
    echo "| Marschner–Lobb 128³ at 512², orthographic | frame | against the reference |"
    echo "|---|---|---|"
    echo "| reference splatter (2 threads, median) | $reference_ms ms | 1 |"
    echo "| texsplat \`bench --backend cpu\` (median) | $texsplat_ms ms |" \
         "$(echo "$ratios" | smallest)× best, $(echo "$ratios" | median)× median (target ≤ 1.2×) |"
    echo "| VTK 9 \`vtkFixedPointVolumeRayCastMapper\` | $vtk_ms ms |" \
         "$(/usr/bin/python3 -c "print(f'{$vtk_ms / $reference_ms:.1f}')")× |"
    echo
    echo "| check | measured | target |"
    echo "|---|---|---|"
    echo "| texsplat's image against VTK's (interior RMSE) | $vtk_rmse steps of 255 | ≤ 1.5 |"
    echo "| texsplat's CPU image against its GL image | $gl_psnr dB | ≥ 50 dB |"
    echo "| frame on 2 threads over 1 (median) | $(printf %.2f "$scaling")× | ≥ 1.85× |"
    echo "| one \`render\`'s draw over bench's warm frame (median) | $(printf %.2f "$oneshot")× | ≈ 1 |"
    echo
    echo "| volume (CPU backend) | splats | order + draw | per splat | peak resident |"
    echo "|---|---|---|---|---|"
    size_row 128
    size_row 320
} | tee "$out"
