#!/usr/bin/python3
"""Measures renders split over processes (mpirun texsplat render, docs/distributed.md) and fits the
cost model of docs/results.md, section "Beyond one machine":

  1. dense volumes of 320^3 and 512^3 floats (every voxel drawn), one process and 1 to 4 ranks of
     one thread each: each step's slowest rank, the largest rank's peak memory, the picture's
     PSNR against the one-process one;
  2. compositing against image size (256^2 to 2048^2) on 2 and 4 ranks, radix-k and MPI_Reduce;
  3. the pictures of bricks that cut along the view, as a simulation's own blocks do (the
     in-situ example), against texsplat's split across the slicing axis;
  4. the model t = a * voxels / P (splatting) + c * pixels * log2(P) (compositing), its fit, and
     its predictions for a 4096^3 volume on 64 and 1024 ranks.
Ranks beyond the machine's free cores share them: the runs print the load average they met.

Usage: /usr/bin/python3 scripts/distributed-results.py BUILD_DIR [OUT_DIR]
       /usr/bin/python3 scripts/distributed-results.py --model
  BUILD_DIR  a build with MPI (apps/texsplat, examples/texsplat_example_in_situ)
  OUT_DIR    where the volumes and images go (default build/distributed-results; 1 GiB)
  --model    only the model's tables, from docs/results/distributed.csv
Writes docs/results/distributed.csv and prints the tables of docs/results.md. 5 to 15 minutes on
a 2-core machine with 24 GiB; it needs about 8 GiB free (the one-process 512^3 render).
"""
import csv
import math
import os
import re
import subprocess
import sys

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
STEPS = ["split", "load", "gather", "classify", "order", "draw", "composite", "finish"]
SPLATTING = ["classify", "order", "draw"]
DIRECTION = "-1,-0.7,-0.4"
SIZE = "512x512"


def mpirun(ranks):
    command = ["mpirun", "--oversubscribe", "-np", str(ranks)]
    if os.geteuid() == 0:
        command.insert(1, "--allow-run-as-root")
    return command


def run(command):
    result = subprocess.run(command, capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit("failed: " + " ".join(command) + "\n" + result.stderr)
    return result.stdout


def dense_volume(path, n):
    """A smooth field over n^3 voxels, every voxel drawn (float32 .npy), written in slices."""
    if os.path.exists(path):
        return
    axis = np.linspace(-1.0, 1.0, n, dtype=np.float32)
    y, x = np.meshgrid(axis, axis, indexing="ij")
    volume = np.lib.format.open_memmap(path, mode="w+", dtype=np.float32, shape=(n, n, n))
    for k, z in enumerate(axis):
        volume[k] = (np.exp(-3.0 * (x * x + y * y + z * z))
                     + 0.3 * np.sin(7.0 * x) * np.cos(5.0 * y) * np.sin(3.0 * z) + 0.35)
    volume.flush()


def scene(path, data, opacity_values="0, 1", opacities="1, 6"):
    """Writes texture splats of the VolumeData fields `data` through a HOT transfer function."""
    with open(path, "w") as out:
        out.write("#Inventor V2.1 ascii\nSeparator {\n"
                  f"    TransferFunction {{ preset HOT opacityValues [ {opacity_values} ] "
                  f"opacities [ {opacities} ] }}\n"
                  f"    VolumeData {{ {data} }}\n"
                  "    TextureSplat { }\n}\n")


def report(text):
    """Seconds per step (distributed report) or per phase (one process), and the peak MiB."""
    times = {}
    for name, seconds in re.findall(r"^  ([a-z ]+?) +([0-9.]+)(?:  |$)", text, re.M):
        times[name] = float(seconds)
    peak = float(re.search(r"memory: peak ([0-9.]+) MiB", text).group(1))
    return times, peak


def psnr(texsplat, reference, test):
    out = run([texsplat, "compare", reference, test])
    return float(re.search(r"^RGB\s+\S+\s+(\S+)", out, re.M).group(1))


def dense_runs(texsplat, out, rows):
    print("\n### Dense volumes: each step's slowest rank (s), one thread a rank, image " + SIZE)
    print("\n| volume | ranks | split | load | gather | classify | order | draw | composite | "
          "finish | peak MiB (largest rank) | of one process | PSNR dB |")
    print("|---|---|" + "---|" * 11)
    for n in (320, 512):
        volume = os.path.join(out, f"dense{n}.npy")
        dense_volume(volume, n)
        path = os.path.join(out, f"dense{n}.iv")
        scene(path, f"source FILE_NPY fileName \"{volume}\"")
        alone = os.path.join(out, f"dense{n}-alone.exr")
        times, alone_peak = report(run([texsplat, "render", path, "-o", alone, "--size", SIZE,
                                        "--direction", DIRECTION, "--threads", "1",
                                        "--time-report"]))
        splat = sum(times[phase] for phase in ("classify", "order", "draw", "read back"))
        print(f"| {n}³ | one process | | {times['load']:.2f} | | {times['classify']:.2f} | "
              f"{times['order']:.2f} | {times['draw'] + times['read back']:.2f} | | | "
              f"{alone_peak:.0f} | 1 | |")
        rows.append({"test": "dense", "volume": n, "ranks": 0, "splatting": splat,
                     "peak": alone_peak})
        for ranks in (1, 2, 3, 4):
            image = os.path.join(out, f"dense{n}-{ranks}.exr")
            times, peak = report(run(mpirun(ranks) + [texsplat, "render", path, "-o", image,
                                                      "--size", SIZE, "--direction", DIRECTION,
                                                      "--threads", "1", "--time-report"]))
            quality = psnr(texsplat, alone, image)
            cells = " | ".join(f"{times[step]:.2f}" for step in STEPS)
            print(f"| {n}³ | {ranks} | {cells} | {peak:.0f} | {peak / alone_peak:.2f} | "
                  f"{quality:.0f} |")
            rows.append({"test": "dense", "volume": n, "ranks": ranks,
                         "splatting": sum(times[step] for step in SPLATTING),
                         "composite": times["composite"], "peak": peak, "psnr": quality})


def compositing_runs(texsplat, out, rows):
    print("\n### Compositing against image size: the composite step's slowest rank (ms)")
    print("\n| image | ranks | radix-k | MPI_Reduce |")
    print("|---|---|---|---|")
    path = os.path.join(out, "blob.iv")
    scene(path, "source BLOB resolution 64 64 64", opacities="0, 6")
    for side in (256, 512, 1024, 2048):
        for ranks in (2, 4):
            seconds = {}
            for method in ("radix-k", "reduce"):
                best = math.inf
                for _ in range(3):
                    times, _ = report(run(mpirun(ranks) + [
                        texsplat, "render", path, "-o", os.path.join(out, "blob.png"), "--size",
                        f"{side}x{side}", "--direction", DIRECTION, "--threads", "1",
                        "--compositing", method, "--time-report"]))
                    best = min(best, times["composite"])
                seconds[method] = best
                rows.append({"test": "composite", "pixels": side * side, "ranks": ranks,
                             "method": method, "composite": best})
            print(f"| {side}² | {ranks} | {seconds['radix-k'] * 1e3:.1f} | "
                  f"{seconds['reduce'] * 1e3:.1f} |")


def split_runs(texsplat, example, out, rows):
    print("\n### Planes along the view: PSNR (dB) against one process, 4 ranks")
    print("\n| view | texsplat's split (across the slicing axis) | a simulation's 2 x 2 x 1 "
          "blocks (in situ) |")
    print("|---|---|---|")
    path = os.path.join(out, "ml.iv")
    scene(path, "source BLOB resolution 48 48 48", opacity_values="0, 0.35, 1",
          opacities="0, 0, 6")
    for name, direction in (("along z", "0,0,-1"), ("2.9° off z", "0.05,0,-1"),
                            ("oblique", "-1,-0.6,-0.45")):
        alone = os.path.join(out, "split-alone.exr")
        split = os.path.join(out, "split-4.exr")
        run([texsplat, "render", path, "-o", alone, "--size", "256x256", "--direction",
             direction])
        run(mpirun(4) + [texsplat, "render", path, "-o", split, "--size", "256x256",
                         "--direction", direction])
        ours = psnr(texsplat, alone, split)
        text = run(mpirun(4) + [example, os.path.join(out, "insitu"), "--resolution", "48",
                                "--steps", "1", "--size", "256", "--direction", direction,
                                "--reference"])
        blocks = float(re.search(r"PSNR ([0-9.]+|inf)", text).group(1))
        print(f"| {name} | {ours:.0f} | {blocks:.0f} |")
        rows.append({"test": "split", "view": name, "psnr": ours, "blocks": blocks})


def model(rows):
    """Fits splatting = a * voxels / P on the one-rank runs (the rank's time is its work) and
    compositing = c * pixels * log2(P), checks them on the rest, predicts."""
    dense = [r for r in rows if r["test"] == "dense" and r["ranks"] >= 1]
    single = [r for r in dense if r["ranks"] == 1]
    a = sum(r["splatting"] / r["volume"] ** 3 for r in single) / len(single)
    composite = [r for r in rows if r["test"] == "composite" and r["method"] == "radix-k"]
    c = sum(r["composite"] / (r["pixels"] * math.log2(r["ranks"])) for r in composite) / len(
        composite)
    print("\n### The model against the measurements")
    print(f"\nsplatting = {a * 1e9:.1f} ns x voxels / P (fitted on one rank); compositing = "
          f"{c * 1e9:.2f} ns x pixels x log2 P (radix-k, fitted on all sizes). Cores the ranks "
          f"got: the model's work over the slowest rank's time, a x voxels / measured (P when "
          f"each rank has a core of its own).")
    print("\n| volume | ranks | splatting measured (s) | model, a core a rank (s) | "
          "cores the ranks got |")
    print("|---|---|---|---|---|")
    for r in dense:
        predicted = a * r["volume"] ** 3 / r["ranks"]
        got = a * r["volume"] ** 3 / r["splatting"]
        print(f"| {r['volume']}³ | {r['ranks']} | {r['splatting']:.2f} | {predicted:.2f} | "
              f"{got:.2f} |")
    print("\n| image | ranks | compositing measured (ms) | model (ms) |")
    print("|---|---|---|---|")
    for r in composite:
        predicted = c * r["pixels"] * math.log2(r["ranks"])
        print(f"| {int(math.sqrt(r['pixels']))}² | {r['ranks']} | {r['composite'] * 1e3:.1f} | "
              f"{predicted * 1e3:.1f} |")
    per_voxel = max(r["peak"] for r in dense if r["volume"] == 512 and r["ranks"] == 1) / 512 ** 3
    print("\n| 4096³, 2048² image | splatting (s) | compositing (s) | frame (s) | memory a rank |")
    print("|---|---|---|---|---|")
    voxels = 4096 ** 3
    pixels = 2048 * 2048
    for ranks in (64, 1024):
        splat = a * voxels / ranks
        comp = c * pixels * math.log2(ranks)
        print(f"| {ranks} ranks | {splat:.1f} | {comp:.2f} | {splat + comp:.1f} | "
              f"{per_voxel * voxels / ranks / 1024:.1f} GiB |")


def read_rows(path):
    """The rows of a CSV this script wrote, numbers as numbers."""
    rows = []
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            for key in ("volume", "pixels", "ranks"):
                row[key] = int(row[key]) if row[key] else 0
            for key in ("splatting", "composite", "peak", "psnr", "blocks"):
                row[key] = float(row[key]) if row[key] else None
            rows.append(row)
    return rows


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    if sys.argv[1] == "--model":
        model(read_rows(os.path.join(ROOT, "docs", "results", "distributed.csv")))
        return
    build = sys.argv[1]
    out = sys.argv[2] if len(sys.argv) > 2 else os.path.join(ROOT, "build",
                                                             "distributed-results")
    os.makedirs(out, exist_ok=True)
    texsplat = os.path.join(build, "apps", "texsplat")
    example = os.path.join(build, "examples", "texsplat_example_in_situ")
    rows = []
    print(f"Load average when the runs began: {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores")
    dense_runs(texsplat, out, rows)
    compositing_runs(texsplat, out, rows)
    split_runs(texsplat, example, out, rows)
    model(rows)
    fields = ["test", "volume", "view", "pixels", "ranks", "method", "splatting", "composite",
              "peak", "psnr", "blocks"]
    with open(os.path.join(ROOT, "docs", "results", "distributed.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=fields)
        writer.writeheader()
        writer.writerows(rows)


if __name__ == "__main__":
    main()
