#!/usr/bin/env bash
# Installs everything texsplat needs to build, test and run, from Debian 12's packages.
# Run as root on a fresh Debian 12 machine. Safe to run again.
#   bash scripts/install-deps.sh           everything: the build, the tests, the Python module,
#                                          fuzzing, the docs' commands
#   bash scripts/install-deps.sh --build   only what the texsplat command line needs (the README's
#                                          first command; the rest is for the test suite)
#   bash scripts/install-deps.sh --peers   the peers benchmarks measure texsplat against, beside
#                                          everything: VTK 9 (scripts/cpu-backend-targets.sh,
#                                          scripts/vtk-peer.py; not needed by CI)
set -euo pipefail
export DEBIAN_FRONTEND=noninteractive
build=(
    cmake ninja-build g++ pkg-config
    libglm-dev libhwy-dev libtbb-dev libepoxy-dev libegl-dev libgl-dev libgl1-mesa-dri libegl-mesa0
    libopenvdb-dev libboost-iostreams-dev libtinygltf-dev nlohmann-json3-dev libopenexr-dev
    libstb-dev fonts-dejavu-core
    libcli11-dev libglfw3-dev libimgui-dev
    libnetcdf-dev zlib1g-dev
)
tests=(
    libgtest-dev libbenchmark-dev libcoin-dev
    clang libclang-rt-14-dev xvfb xauth xdotool locales
    python3-numpy
    # The Python module (docs/python.md): a venv, the headers its extension compiles against,
    # pytest for its tests, xarray and tqdm that it works with.
    python3-venv python3-dev python3-pytest python3-xarray python3-tqdm
    # ncgen and unu write the NetCDF and NRRD files of the readers' tests; pyopenvdb and netCDF4
    # the .vdb and .nc of docs/getting-started.md, whose commands a test runs.
    netcdf-bin teem-apps python3-openvdb python3-netcdf4
    # Pillow grabs the viewer's window for the docs (scripts/viewer-screenshot.sh) and compresses
    # the docs' pictures again without changing a pixel.
    python3-pil
    # MPI for renders split over processes (TEXSPLAT_WITH_MPI, docs/distributed.md): Debian's
    # OpenMPI; the README's first command builds without it.
    libopenmpi-dev openmpi-bin
)
peers=(python3-vtk9)
case "${1:-}" in
    --build) packages=("${build[@]}") ;;
    "") packages=("${build[@]}" "${tests[@]}") ;;
    --peers) packages=("${build[@]}" "${tests[@]}" "${peers[@]}") ;;
    *) echo "usage: bash scripts/install-deps.sh [--build | --peers]" >&2; exit 2 ;;
esac
apt-get update
apt-get install -y --no-install-recommends "${packages[@]}"
if [ "${1:-}" != --build ]; then
    # A comma-decimal locale, so the reader's locale-independence test runs instead of skipping.
    localedef -i de_DE -f UTF-8 de_DE.UTF-8
fi
