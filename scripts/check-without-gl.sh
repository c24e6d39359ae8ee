#!/usr/bin/env bash
# Checks a texsplat built with -DTEXSPLAT_WITH_GL=OFF and -DTEXSPLAT_WITH_MPI=OFF (the `nogl`
# preset; CI checks the `fuzz` preset's, which leaves both out too): it links no GL, EGL,
# libepoxy or MPI, renders and benchmarks on the CPU backend, and refuses --backend gl with a
# message.
# Usage: scripts/check-without-gl.sh build/nogl/apps/texsplat
set -euo pipefail
texsplat=${1:?usage: $0 path/to/texsplat}
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
fail() { echo "check-without-gl: $*" >&2; exit 1; }

if ldd "$texsplat" | grep -Eq 'lib(EGL|GL|GLX|OpenGL|epoxy)\.so'; then
    ldd "$texsplat" >&2
    fail "$texsplat links a GL library"
fi
if ldd "$texsplat" | grep -Eq 'lib(mpi|open-pal|open-rte)\.so'; then
    ldd "$texsplat" >&2
    fail "$texsplat links MPI"
fi
report=$("$texsplat" render -o "$scratch/default.png" --size 64x48 --time-report)
grep -q 'backend    CPU (.*(auto: built without GL)' <<<"$report" || fail "render: $report"
[ -s "$scratch/default.png" ] || fail "render wrote no image"
"$texsplat" render examples/marschner-lobb.iv -o "$scratch/ml.png" --size 32x32 --backend cpu \
    --threads 2 >/dev/null
"$texsplat" bench --dataset ml8 --size 16x16 --repeat 1 --no-reference --backend cpu \
    --method texture,polygon --csv "$scratch/bench.csv" >/dev/null 2>&1
[ "$(wc -l <"$scratch/bench.csv")" -eq 3 ] || fail "bench: $(cat "$scratch/bench.csv")"
if message=$("$texsplat" render -o "$scratch/gl.png" --backend gl 2>&1); then
    fail "--backend gl succeeded without GL"
fi
expected='texsplat: error: --backend gl: this texsplat was built without GL (TEXSPLAT_WITH_GL=OFF); only --backend cpu draws'
[ "$message" = "$expected" ] || fail "--backend gl said: $message"
[ ! -e "$scratch/gl.png" ] || fail "--backend gl left an image"
echo "check-without-gl: $texsplat renders and benchmarks on the CPU without GL or MPI"
