#!/usr/bin/env bash
# How the CPU backend's frame time scales, measured with `texsplat bench --backend cpu` of the
# release build (build/release, the `release` preset of CMakePresets.json: RelWithDebInfo), on
# the paper's texture splats:
#   threads  1, 2 and all cores (--threads N)       on $BASE_DATASET at $BASE_SIZE
#   size     256², 512², 1024², 2048² (--size)      on $BASE_DATASET, all cores
#   splats   ml64, ml128, ml256 (--dataset) at full resolution and the octree cuts of a quarter
#            and a twentieth of the splats (--method texture@0.25, texture@0.05), $BASE_SIZE
# into docs/results/cpu-scaling-{threads,size,splats}.csv (bench's CSV columns, the thread sweep
# with `round,threads` in front), then prints a summary.
#
# The machine may be shared and noisy, so the summary gives ratios to a baseline measured close
# in time rather than absolute times alone: the thread counts run in $ROUNDS interleaved rounds
# and each is divided by the single thread of its own round (median over rounds); sizes are
# divided by $BASE_SIZE of the same run; octree cuts by the full-resolution texture splats of the
# same dataset and run (bench's full_frame_ratio). No ray-cast reference (--no-reference): it
# would cost more than the splats and the errors are not what this measures.
#
# Usage: scripts/cpu-backend-scaling.sh           (the full sweep: tens of minutes, all cores)
# Environment (defaults in brackets), e.g. to check the script in seconds:
#   DATASETS=ml16 BASE_DATASET=ml16 SIZES=32x32,64x64 BASE_SIZE=64x64 OUT_DIR=/tmp/scaling \
#   scripts/cpu-backend-scaling.sh
#   DATASETS      datasets of the splat sweep            [ml64,ml128,ml256]
#   CUTS          octree-cut methods of the splat sweep  [texture@0.25,texture@0.05]
#   SIZES         sizes of the size sweep                [256x256,512x512,1024x1024,2048x2048]
#   BASE_DATASET  dataset of the thread and size sweeps  [ml128]
#   BASE_SIZE     size of the thread and splat sweeps    [512x512]
#   ROUNDS        rounds of the thread sweep             [3]
#   REPEAT        timed frames per bench row (median)    [5]
#   OUT_DIR       where the CSVs go                      [docs/results]
#   TEXSPLAT      the executable                         [build/release/apps/texsplat]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
datasets=${DATASETS:-ml64,ml128,ml256}
cuts=${CUTS:-texture@0.25,texture@0.05}
sizes=${SIZES:-256x256,512x512,1024x1024,2048x2048}
base_dataset=${BASE_DATASET:-ml128}
base_size=${BASE_SIZE:-512x512}
rounds=${ROUNDS:-3}
repeat=${REPEAT:-5}
out_dir=${OUT_DIR:-$root/docs/results}
texsplat=${TEXSPLAT:-$root/build/release/apps/texsplat}

if [ ! -x "$texsplat" ]; then
    echo "$0: no $texsplat. This measures the release build; make it with" >&2
    echo "    cmake --preset release && cmake --build --preset release --target texsplat" >&2
    echo "(or set TEXSPLAT to another texsplat executable)." >&2
    exit 1
fi
mkdir -p "$out_dir"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cores=$(nproc)
thread_counts=$(printf '%s\n' 1 2 "$cores" | awk '!seen[$1]++' | tr '\n' ' ')
log="$work/bench.log"

# bench ARGS...: one `texsplat bench` of the CPU backend, its table to the log; stops the script
# with the log's tail when it fails.
bench() {
    if ! "$texsplat" bench --backend cpu --no-reference --repeat "$repeat" "$@" \
        >> "$log" 2>&1; then
        echo "$0: texsplat bench $* failed:" >&2
        tail -n 20 "$log" >&2
        exit 1
    fi
}

# column CSV NAME...: the named columns of a CSV with a header row, space-separated.
column() {
    local csv=$1
    shift
    awk -F, -v names="$*" 'NR == 1 {
            n = split(names, wanted, " ")
            for (i = 1; i <= NF; ++i) index_of[$i] = i
            for (j = 1; j <= n; ++j) if (!(wanted[j] in index_of)) {
                print "no column " wanted[j] > "/dev/stderr"; exit 1
            }
            next
        }
        { line = ""; for (j = 1; j <= n; ++j) line = line (j > 1 ? " " : "") $index_of[wanted[j]]
          print line }' "$csv"
}

echo "texsplat: $texsplat (source $(git -C "$root" describe --always --dirty 2>/dev/null || echo "?"))"
echo "machine: $cores cores, $(awk -F': ' '/model name/ { print $2; exit }' /proc/cpuinfo)"

# Threads: interleaved rounds, so that a load that comes and goes hits every thread count.
threads_csv="$out_dir/cpu-scaling-threads.csv"
for round in $(seq 1 "$rounds"); do
    for threads in $thread_counts; do
        echo "threads: round $round/$rounds, $threads thread(s)" >&2
        bench --dataset "$base_dataset" --size "$base_size" --method texture \
            --threads "$threads" --csv "$work/threads-$round-$threads.csv"
        if [ ! -e "$threads_csv.tmp" ]; then
            echo "round,threads,$(head -n 1 "$work/threads-$round-$threads.csv")" \
                > "$threads_csv.tmp"
        fi
        tail -n +2 "$work/threads-$round-$threads.csv" | sed "s/^/$round,$threads,/" \
            >> "$threads_csv.tmp"
    done
done
mv "$threads_csv.tmp" "$threads_csv"
echo "size sweep: $sizes" >&2
size_csv="$out_dir/cpu-scaling-size.csv"
bench --dataset "$base_dataset" --size "$sizes" --method texture --threads 0 --csv "$size_csv"
echo "splat sweep: $datasets, texture,$cuts" >&2
splats_csv="$out_dir/cpu-scaling-splats.csv"
bench --dataset "$datasets" --size "$base_size" --method "texture,$cuts" --threads 0 \
    --csv "$splats_csv"

echo
grep '^texsplat bench:' "$log" | tail -n 1
echo
echo "Threads ($base_dataset, $base_size, texture; median of $rounds rounds; speed-up: the 1-thread"
echo "frame over this one, in the same round)"
column "$threads_csv" round threads frame_ms | awk '
    { frame[$1, $2] = $3; if (!($2 in seen)) { seen[$2] = 1; order[++n] = $2 }
      rounds[$1] = 1 }
    function median(values, count,    i, j, t) {
        for (i = 2; i <= count; ++i) for (j = i; j > 1 && values[j - 1] > values[j]; --j) {
            t = values[j]; values[j] = values[j - 1]; values[j - 1] = t }
        return count % 2 ? values[(count + 1) / 2] : (values[count / 2] + values[count / 2 + 1]) / 2
    }
    END {
        printf "  %-8s %10s %9s %11s\n", "threads", "frame ms", "speed-up", "efficiency"
        for (k = 1; k <= n; ++k) {
            t = order[k]; m = 0; split("", times); split("", ratios)
            for (r in rounds) { m++; times[m] = frame[r, t]; ratios[m] = frame[r, 1] / frame[r, t] }
            s = median(ratios, m)
            printf "  %-8s %10.2f %9.2f %10.0f%%\n", t, median(times, m), s, 100 * s / t
        }
    }'
echo
echo "Image size ($base_dataset, texture, all cores; vs base: frame time over $base_size's)"
column "$size_csv" width height frame_ms draw_ms | awk -v base="$base_size" '
    { row[NR] = $0; if ($1 "x" $2 == base) base_ms = $3 }
    END {
        printf "  %-10s %10s %9s %9s %10s\n", "size", "frame ms", "draw ms", "vs base", "ns/pixel"
        for (i = 1; i <= NR; ++i) {
            split(row[i], f, " ")
            printf "  %-10s %10.2f %9.2f %9s %10.2f\n", f[1] "x" f[2], f[3], f[4],
                base_ms ? sprintf("%.3f", f[3] / base_ms) : "-", 1e6 * f[3] / (f[1] * f[2])
        }
    }'
echo
echo "Splat count ($base_size, all cores; frame/tex: frame time over the full-resolution texture"
echo "splats of the same dataset, bench's full_frame_ratio)"
column "$splats_csv" dataset method splats frame_ms full_frame_ratio | awk '
    BEGIN { printf "  %-8s %-14s %10s %10s %9s %10s\n", "dataset", "method", "splats", "frame ms",
                   "ns/splat", "frame/tex" }
    { printf "  %-8s %-14s %10d %10.2f %9.1f %10s\n", $1, $2, $3, $4,
             ($3 > 0 ? 1e6 * $4 / $3 : 0), ($5 == "" ? "-" : sprintf("%.3f", $5)) }'
echo
echo "wrote $threads_csv, $size_csv, $splats_csv"
