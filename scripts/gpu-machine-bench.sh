#!/bin/bash
# texsplat on the lent GPU machine: GL on a real GPU against the CPU backend, and the CPU
# backend's thread scaling on 16 cores, in one short run (the machine's time is counted).
# What it needs beside the repository, made here first (both ignored by git):
#   .devrun/texsplat   cmake -S . -B build/device -G Ninja -DCMAKE_BUILD_TYPE=Release
#                      -DTEXSPLAT_WITH_{OPENVDB,NETCDF,GLTF,EXR,VIEWER}=OFF
#                      -DTEXSPLAT_BUILD_{TESTS,EXAMPLES}=OFF && ninja -C build/device apps/texsplat,
#                      copied and stripped; .devrun/lib: the libraries `ldd` names beside libc
#                      and libstdc++ (libepoxy, libz, libhwy, libtbb)
#   .gl/*.deb          libegl1 libglvnd0 libopengl0 libgl1 libglx0 libgles2 (apt-get download)
# The files it writes to $OUT are the CSVs under docs/results/*-h100.csv.
cd "$(dirname "$0")/.."
for f in .gl/*.deb; do dpkg -x $f /; done; ldconfig
export LD_LIBRARY_PATH=$PWD/.devrun/lib
T=.devrun/texsplat
echo "== machine"; nvidia-smi -L; nproc; grep -m1 "model name" /proc/cpuinfo; date -u
ldd $T | grep "not found"
echo "== GL context"
if ! $T render --backend gl -o $OUT/default-gl.png --time-report 2>&1; then
    export __EGL_VENDOR_LIBRARY_FILENAMES=/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json
    echo "retry with $__EGL_VENDOR_LIBRARY_FILENAMES"
    $T render --backend gl -o $OUT/default-gl.png --time-report 2>&1
fi
$T render --backend auto -o $OUT/default-auto.png --time-report 2>&1 | grep -E "backend|draw"
echo "== backends side by side, 512^2 (with the ray-cast reference)"
$T bench --dataset ml128,tornado128 --size 512x512 --backend cpu,gl --method texture,texture@0.25,texture@0.05 --repeat 5 --csv $OUT/h100-backends.csv 2>&1 | grep -vE ": (load|texture|polygon)"
echo "== CPU threads, ML 128^3 at 512^2"
for t in 1 2 4 8 16; do
    $T bench --dataset ml128 --method texture,texture@0.25 --backend cpu --threads $t --no-reference --repeat 5 --csv $OUT/h100-threads-$t.csv 2>&1 | grep -E "^ml128 .*cpu"
done
echo "== sizes and ML 256^3, both backends, 16 threads"
$T bench --dataset ml256 --size 512x512,2048x2048 --method texture,texture@0.25 --backend cpu,gl --no-reference --repeat 3 --csv $OUT/h100-ml256.csv 2>&1 | grep -E "^ml256"
date -u
