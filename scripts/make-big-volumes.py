#!/usr/bin/python3
"""Makes the two big test volumes of docs/results/big-volumes.md, reproducibly (fixed seeds, no
downloads), with the scenes that render them:

  cloud.vdb      a sparse OpenVDB cloud: a 1024^3 bounding box, about 2 % of it active
                 (puffs of smooth density along a wandering path; inactive voxels are empty)
  cloud.iv       that cloud as texture splats
  dense512.raw   a dense 512^3 float32 volume (headerless raw, little endian, 512 MiB):
                 a smooth turbulent field, non-empty everywhere
  dense512.iv    that volume as texture splats, through a transfer function that hides most of it

Usage: /usr/bin/python3 scripts/make-big-volumes.py [OUT_DIR]   (default build/big-volumes)
Needs numpy and OpenVDB's Python module (Debian: python3-numpy, python3-openvdb; both are in
scripts/install-deps.sh). Takes about a minute and about 3 GiB of memory.
"""
import math
import os
import sys

import numpy as np

CLOUD_BOX = 1024
CLOUD_PUFFS = 330
DENSE_SIZE = 512
CHUNK = 128


def puffs(rng):
    """Centres, radii and densities of the cloud's puffs: a random walk across the box."""
    centres, radii, weights = [], [], []
    position = np.array([150.0, 500.0, 512.0])
    step = np.array([1.0, 0.0, 0.0])
    for _ in range(CLOUD_PUFFS):
        step = step + rng.normal(0.0, 0.35, 3)
        step /= np.linalg.norm(step)
        position = np.clip(position + step * rng.uniform(6.0, 14.0), 80.0, CLOUD_BOX - 80.0)
        centres.append(position + rng.normal(0.0, 18.0, 3))
        radii.append(rng.uniform(14.0, 34.0))
        weights.append(rng.uniform(0.6, 1.0))
    return np.array(centres), np.array(radii), np.array(weights)


def write_cloud(out_dir):
    import pyopenvdb as vdb

    rng = np.random.default_rng(20261126)
    centres, radii, weights = puffs(rng)
    grid = vdb.FloatGrid()
    grid.name = "density"
    axis = np.arange(CHUNK, dtype=np.float32)
    active = 0
    for z0 in range(0, CLOUD_BOX, CHUNK):
        for y0 in range(0, CLOUD_BOX, CHUNK):
            for x0 in range(0, CLOUD_BOX, CHUNK):
                low = np.array([x0, y0, z0], dtype=float)
                near = np.all((centres + 2 * radii[:, None] > low) &
                              (centres - 2 * radii[:, None] < low + CHUNK), axis=1)
                if not near.any():
                    continue
                # numpy arrays are [x][y][z] for copyFromArray: index (i, j, k) is voxel x, y, z.
                density = np.zeros((CHUNK, CHUNK, CHUNK), dtype=np.float32)
                x = (axis + x0)[:, None, None]
                y = (axis + y0)[None, :, None]
                z = (axis + z0)[None, None, :]
                for c, r, w in zip(centres[near], radii[near], weights[near]):
                    d2 = (x - c[0]) ** 2 + (y - c[1]) ** 2 + (z - c[2]) ** 2
                    density += w * np.exp(-d2 / (0.5 * r * r))
                # Wisps: a fixed ripple carves the puffs' edges.
                ripple = 0.5 + 0.5 * np.sin(0.11 * x + 0.07 * y) * np.cos(0.09 * z - 0.05 * x)
                density *= 0.75 + 0.5 * ripple
                density[density < 0.08] = 0.0
                active += int(np.count_nonzero(density))
                grid.copyFromArray(density, ijk=(x0, y0, z0), tolerance=0.0)
        print(f"cloud: slab z={z0} done, {active} active voxels so far", flush=True)
    # The bounding box of the active voxels decides the grid's box; pin it to 1024^3 with two
    # faint corner voxels, so that the box is what the issue asks for.
    accessor = grid.getAccessor()
    accessor.setValueOn((0, 0, 0), 0.08)
    accessor.setValueOn((CLOUD_BOX - 1,) * 3, 0.08)
    path = os.path.join(out_dir, "cloud.vdb")
    vdb.write(path + ".part", grids=[grid])
    os.replace(path + ".part", path)
    total = CLOUD_BOX ** 3
    print(f"cloud: wrote {path}: {grid.activeVoxelCount()} active voxels of {total} "
          f"({100.0 * grid.activeVoxelCount() / total:.2f} %)")


def write_dense(out_dir):
    path = os.path.join(out_dir, "dense512.raw")
    n = DENSE_SIZE
    axis = np.linspace(0.0, 1.0, n, dtype=np.float32)
    x = axis[None, None, :]
    y = axis[None, :, None]
    with open(path + ".part", "wb") as file:
        for z0 in range(0, n, 32):
            z = axis[z0:z0 + 32, None, None]
            # Slices of 32 z planes, x fastest in the file.
            value = (np.sin(9.0 * x + 3.0 * np.sin(7.0 * z)) * np.cos(11.0 * y - 2.0 * x)
                     + 0.5 * np.sin(23.0 * z + 13.0 * x * y)) * 0.25 + 0.5
            value.astype("<f4").tofile(file)
    os.replace(path + ".part", path)
    print(f"dense: wrote {path}: {n}^3 float32 values")


CLOUD_SCENE = """#Inventor V2.1 ascii
# A sparse 1024^3 OpenVDB cloud (scripts/make-big-volumes.py), as texture splats.
VolumeData { source FILE_VDB fileName "cloud.vdb" }
TransferFunction {
    rangeMode FIXED
    range 0.08 1.6
    preset GRAY
    opacityValues [ 0, 0.3, 1 ]
    opacities [ 0, 0.004, 0.03 ]
    emission 0.02
}
TextureSplat { }
"""

DENSE_SCENE = """#Inventor V2.1 ascii
# A dense 512^3 float volume (scripts/make-big-volumes.py), as texture splats; the transfer
# function shows the values above 0.72.
VolumeData {
    source FILE_RAW_HEADERLESS
    fileName "dense512.raw"
    dimensions 512 512 512
    dataType FLOAT32
}
TransferFunction {
    rangeMode FIXED
    range 0.72 1.0
    preset VIRIDIS
    opacityValues [ 0, 0.3, 1 ]
    opacities [ 0, 0.15, 0.6 ]
}
TextureSplat { }
"""


def main():
    out_dir = sys.argv[1] if len(sys.argv) > 1 else os.path.join("build", "big-volumes")
    os.makedirs(out_dir, exist_ok=True)
    write_cloud(out_dir)
    write_dense(out_dir)
    for name, text in (("cloud.iv", CLOUD_SCENE), ("dense512.iv", DENSE_SCENE)):
        with open(os.path.join(out_dir, name), "w") as file:
            file.write(text)
    print(f"scenes: {out_dir}/cloud.iv, {out_dir}/dense512.iv")


if __name__ == "__main__":
    main()
