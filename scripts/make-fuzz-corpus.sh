#!/usr/bin/env bash
# Writes the seed corpora of the fuzz targets of files and the command line into
# tests/fuzz/corpus/<target>/ (the results are committed; each corpus stays under 50 KB): the
# binary formats through make_fuzz_corpus of a fuzz build (OpenVDB, PNG, OpenEXR, .glb), NetCDF
# through NetCDF's ncgen, glTF text and command lines as text.
# Usage: scripts/make-fuzz-corpus.sh <fuzz build dir>
set -euo pipefail
build=${1:?usage: scripts/make-fuzz-corpus.sh <fuzz build dir>}
corpus="$(cd "$(dirname "$0")/.." && pwd)/tests/fuzz/corpus"
"$build/tests/fuzz/make_fuzz_corpus" "$corpus"

# NetCDF: a ramp with coordinate variables (classic), a time series with _FillValue, scale and
# offset (64-bit offset), and the same ramp as NetCDF-4 (HDF5).
netcdf="$corpus/fuzz_netcdf_reader"
mkdir -p "$netcdf"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cat >"$work/ramp.cdl" <<'CDL'
netcdf ramp {
dimensions:
    depth = 2 ; lat = 2 ; lon = 3 ;
variables:
    double depth(depth) ; float lat(lat) ; float lon(lon) ;
    float salinity(depth, lat, lon) ;
        salinity:units = "psu" ;
    float surface(lat, lon) ;
data:
    depth = 0, 10 ; lat = 40, 40.5 ; lon = -5, -4, -3 ;
    salinity = 35, 35.1, 35.2, 35.3, 35.4, 35.5, 36, 36.1, 36.2, 36.3, 36.4, 36.5 ;
    surface = 1, 2, 3, 4, 5, 6 ;
}
CDL
cat >"$work/series.cdl" <<'CDL'
netcdf series {
dimensions:
    time = UNLIMITED ; level = 2 ; lat = 2 ; lon = 3 ;
variables:
    short t(time, level, lat, lon) ;
        t:scale_factor = 0.5 ;
        t:add_offset = 10. ;
        t:_FillValue = -1s ;
        t:missing_value = -2s ;
    int lat(lat) ;
    char label(lon) ;
data:
    t = 0, 1, 2, 3, 4, -1, 6, 7, 8, 9, -2, 11,
        12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23 ;
    lat = 5, 10 ;
    label = "abc" ;
}
CDL
ncgen -k classic -o "$netcdf/ramp-classic.nc" "$work/ramp.cdl"
ncgen -k "64-bit offset" -o "$netcdf/series-64bit-offset.nc" "$work/series.cdl"
ncgen -k nc4 -o "$netcdf/ramp-netcdf4.nc" "$work/ramp.cdl"

# glTF text: a triangle with its buffer inline (a data URI), and an indexed quad with a material
# and a node transform.
gltf="$corpus/fuzz_gltf_reader"
cat >"$gltf/triangle.gltf" <<'GLTF'
{"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
 "nodes": [{"mesh": 0, "translation": [10, 0, 0], "scale": [2, 2, 2]}],
 "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "mode": 4}]}],
 "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                "min": [0, 0, 0], "max": [1, 1, 0]}],
 "bufferViews": [{"buffer": 0, "byteLength": 36}],
 "buffers": [{"byteLength": 36,
   "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}]}
GLTF
cat >"$gltf/quad-indexed.gltf" <<'GLTF'
{"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
 "nodes": [{"children": [1], "rotation": [0, 0, 0.7071068, 0.7071068]}, {"mesh": 0}],
 "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [1, 0.5, 0.25, 1]}}],
 "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "material": 0,
                             "extras": {"note": [1, {"nested": true}]}}]}],
 "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
                "min": [0, 0, 0], "max": [1, 1, 0]},
               {"bufferView": 1, "componentType": 5123, "count": 6, "type": "SCALAR"}],
 "bufferViews": [{"buffer": 0, "byteLength": 48},
                 {"buffer": 0, "byteOffset": 48, "byteLength": 12}],
 "buffers": [{"byteLength": 60,
   "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAACAPwAAgD8AAAAAAAAAAAAAgD8AAAAAAAABAAIAAAACAAMA"}]}
GLTF

# Command lines, one argument a line, as fuzz_command_line splits them.
cli="$corpus/fuzz_command_line"
mkdir -p "$cli"
printf '%s\n' render scene.iv -o 'out%04d.png' --size 320x200 --frames 3 --fps 12 \
    --backend cpu --threads 2 --background 0.1,0.2,0.3 --memory-limit 512M >"$cli/render-frames"
printf '%s\n' render -o out.exr --camera orthographic --direction 1,0,-0.5 --azimuth 30 \
    --elevation -10 --zoom 2 --max-splats 1000 --error-threshold 0.01 --colorbar \
    --colorbar-position top >"$cli/render-view"
printf '%s\n' render scene.iv -o ref.exr --raycast --raycast-step 0.5 --time-report \
    >"$cli/render-raycast"
printf '%s\n' bench --dataset tornado32 --method texture,gaussian --size 64x64,128x96 \
    --backend cpu --repeat 2 --warmup 1 --csv out.csv --plot out.svg >"$cli/bench-datasets"
printf '%s\n' bench scene.iv --budgets 0.5,1 --direction 0,1,0 >"$cli/bench-scene"
printf '%s\n' compare a.png b.exr --diff d.png --diff-scale 0.5 --region 1,2,30,40 --peak 2 \
    --json >"$cli/compare"
printf '%s\n' kernel --kernel optimized --support 1.6 --spacing 1,1,2 --json >"$cli/kernel"
printf '%s\n' info --reference >"$cli/info"
printf '%s\n' --version >"$cli/version"
du -sh "$corpus"/*
