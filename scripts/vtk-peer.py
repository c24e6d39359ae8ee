#!/usr/bin/python3
"""texsplat beside VTK 9's CPU ray caster on the same scene: the same data, camera and transfer
function, rendered by texsplat (`texsplat render`) and by vtkFixedPointVolumeRayCastMapper, then
compared pixel by pixel.

The scene is the VTK peer's (reference/cpu-splat/ts_scene.py): the Marschner-Lobb test signal
(f_M = 6, alpha = 0.25) sampled on N^3 vertices over [-1, 1]^3, a grey ramp from the data's
smallest value (black) to its largest (white), opacity 0.05 s per voxel length (s = the value
normalized over the range, VTK's scalar opacity unit distance = the spacing; in texsplat the
extinction -ln(1 - 0.05 s) per spacing), seen along -z by an orthographic camera from 3 extents
away with a view 1.6 extents high, over black.

Prints the interior RMSE of the two images in steps of 255 (RGB pooled, over the pixels inside
the volume's projected square, less a margin of 5 % of its side on each side, where the two
renderers' edge treatments do not matter), the largest difference there, and the time of one
VTK render (median of --repeat, after a first render that builds VTK's tables) and of texsplat's
whole `render` command (median of --repeat), so that the speed comparison uses the same scene.

Usage: /usr/bin/python3 scripts/vtk-peer.py PATH/TO/texsplat [--size 128] [--image 512]
           [--backend cpu] [--repeat 3] [--sample-distance 0.5] [--out DIR]
Needs numpy and VTK's Python module (Debian: python3-numpy, python3-vtk9). VTK draws its image
through an X window: without a DISPLAY the script runs itself again under xvfb-run.
"""
import argparse
import math
import os
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np

ALPHA = 0.25
FREQUENCY = 6.0
RAMP_POINTS = 41


def marschner_lobb(n):
    """The test signal on n^3 vertices over [-1, 1]^3, indexed [z, y, x] (x fastest in memory)."""
    axis = np.linspace(-1.0, 1.0, n)
    z, y, x = np.meshgrid(axis, axis, axis, indexing="ij")
    radial = np.cos(2.0 * math.pi * FREQUENCY * np.cos(math.pi * np.sqrt(x * x + y * y) / 2.0))
    value = (1.0 - np.sin(math.pi * z / 2.0) + ALPHA * (1.0 + radial)) / (2.0 * (1.0 + ALPHA))
    return value.astype(np.float32)


def write_texsplat_scene(volume, spacing, out):
    """The raw volume and the scene file of ts_scene.py's scene; answers the scene's path."""
    n = volume.shape[0]
    lo, hi = float(volume.min()), float(volume.max())
    raw = os.path.join(out, "ml.raw")
    with open(raw, "wb") as f:
        f.write((f"texsplat-raw 1\ndims {n} {n} {n}\ntype float32\ncomponents 1\n"
                 f"spacing {spacing!r} {spacing!r} {spacing!r}\norigin -1 -1 -1\n"
                 "endian little\ndata\n").encode())
        f.write(volume.astype("<f4").tobytes())
    ramp = [i / (RAMP_POINTS - 1) for i in range(RAMP_POINTS)]
    extinctions = [-math.log(1.0 - 0.05 * s) / spacing for s in ramp]
    extent = 2.0
    scene = os.path.join(out, "ml.iv")
    with open(scene, "w") as f:
        f.write(f"""#Inventor V2.1 ascii
Separator {{
  OrthographicCamera {{ position 0 0 {3 * extent} nearDistance {2 * extent} farDistance {4 * extent}
                       focalDistance {3 * extent} height {1.6 * extent} }}
  TransferFunction {{
    colorValues [ 0, 1 ] colors [ 0 0 0, 1 1 1 ]
    opacityValues [ {", ".join(repr(s) for s in ramp)} ]
    opacities [ {", ".join(repr(t) for t in extinctions)} ]
    range {lo!r} {hi!r}
  }}
  VolumeData {{ source FILE_RAW fileName "{raw}" }}
  TextureSplat {{ }}
}}
""")
    return scene


def render_texsplat(texsplat, scene, size, backend, repeat, out):
    """texsplat's PNG as an array [row, column, rgb] (top row first) and its median wall time."""
    png = os.path.join(out, "texsplat.png")
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        subprocess.run([texsplat, "render", scene, "-o", png, "--size", f"{size}x{size}",
                        "--backend", backend], check=True)
        times.append(time.perf_counter() - start)
    return read_png(png), statistics.median(times)


def read_png(path):
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy

    reader = vtk.vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    data = reader.GetOutput()
    width, height, _ = data.GetDimensions()
    pixels = vtk_to_numpy(data.GetPointData().GetScalars())
    channels = pixels.shape[1] if pixels.ndim > 1 else 1
    # VTK's rows start at the bottom.
    return pixels.reshape(height, width, channels)[::-1, :, :3].astype(np.float64)


def render_vtk(volume, spacing, size, sample_distance, repeat):
    """VTK's image as an array [row, column, rgb] (top row first) and its median render time."""
    import vtk
    from vtk.util.numpy_support import numpy_to_vtk, vtk_to_numpy

    n = volume.shape[0]
    lo, hi = float(volume.min()), float(volume.max())
    image = vtk.vtkImageData()
    image.SetDimensions(n, n, n)
    image.SetSpacing(spacing, spacing, spacing)
    image.SetOrigin(-1.0, -1.0, -1.0)
    image.GetPointData().SetScalars(numpy_to_vtk(volume.ravel(), deep=True))

    color = vtk.vtkColorTransferFunction()
    color.AddRGBPoint(lo, 0.0, 0.0, 0.0)
    color.AddRGBPoint(hi, 1.0, 1.0, 1.0)
    opacity = vtk.vtkPiecewiseFunction()
    for i in range(RAMP_POINTS):
        s = i / (RAMP_POINTS - 1)
        opacity.AddPoint(lo + s * (hi - lo), 0.05 * s)
    prop = vtk.vtkVolumeProperty()
    prop.SetColor(color)
    prop.SetScalarOpacity(opacity)
    prop.SetScalarOpacityUnitDistance(spacing)
    prop.SetInterpolationTypeToLinear()
    prop.ShadeOff()

    mapper = vtk.vtkFixedPointVolumeRayCastMapper()
    mapper.SetInputData(image)
    mapper.AutoAdjustSampleDistancesOff()
    mapper.SetSampleDistance(sample_distance * spacing)
    mapper.SetImageSampleDistance(1.0)
    actor = vtk.vtkVolume()
    actor.SetMapper(mapper)
    actor.SetProperty(prop)

    renderer = vtk.vtkRenderer()
    renderer.SetBackground(0.0, 0.0, 0.0)
    renderer.AddVolume(actor)
    camera = renderer.GetActiveCamera()
    extent = 2.0
    camera.ParallelProjectionOn()
    camera.SetPosition(0.0, 0.0, 3.0 * extent)
    camera.SetFocalPoint(0.0, 0.0, 0.0)
    camera.SetViewUp(0.0, 1.0, 0.0)
    camera.SetParallelScale(0.8 * extent)
    camera.SetClippingRange(2.0 * extent, 4.0 * extent)
    window = vtk.vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(size, size)
    window.AddRenderer(renderer)
    window.Render()  # the first render builds the mapper's tables
    times = []
    for _ in range(repeat):
        mapper.Modified()
        start = time.perf_counter()
        window.Render()
        times.append(time.perf_counter() - start)
    grab = vtk.vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.SetInputBufferTypeToRGB()
    grab.ReadFrontBufferOff()
    grab.Update()
    pixels = vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars())
    return pixels.reshape(size, size, 3)[::-1].astype(np.float64), statistics.median(times)


def interior(size):
    """The rows and columns inside the volume's projected square less a 5 % margin."""
    extent = 2.0
    pixels_per_unit = size / (1.6 * extent)
    half = 0.5 * extent * pixels_per_unit
    margin = 0.05 * 2.0 * half
    first = int(math.ceil(size / 2.0 - half + margin))
    last = int(math.floor(size / 2.0 + half - margin))
    return slice(first, last), slice(first, last)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("texsplat")
    parser.add_argument("--size", type=int, default=128, help="grid vertices per axis")
    parser.add_argument("--image", type=int, default=512, help="image width and height")
    parser.add_argument("--backend", default="cpu", help="texsplat's --backend")
    parser.add_argument("--repeat", type=int, default=3, help="timed renders of each")
    parser.add_argument("--sample-distance", type=float, default=0.5,
                        help="VTK's ray sample distance in voxels")
    parser.add_argument("--out", help="keep the images and the scene in this folder")
    args = parser.parse_args()
    try:
        import vtk  # noqa: F401 (checked before anything is rendered)
    except ImportError:
        sys.exit("vtk-peer.py: VTK 9's Python module is not installed; as root: "
                 "bash scripts/install-deps.sh --peers (Debian's python3-vtk9)")
    if not os.environ.get("DISPLAY") and not os.environ.get("TEXSPLAT_UNDER_XVFB"):
        env = dict(os.environ, TEXSPLAT_UNDER_XVFB="1")
        sys.exit(subprocess.run(["xvfb-run", "-a", sys.executable] + sys.argv, env=env).returncode)

    out = args.out or tempfile.mkdtemp(prefix="texsplat-vtk-peer-")
    os.makedirs(out, exist_ok=True)
    volume = marschner_lobb(args.size)
    spacing = 2.0 / (args.size - 1)
    scene = write_texsplat_scene(volume, spacing, out)
    ours, our_time = render_texsplat(args.texsplat, scene, args.image, args.backend,
                                     args.repeat, out)
    theirs, vtk_time = render_vtk(volume, spacing, args.image, args.sample_distance, args.repeat)
    if args.out:
        np.save(os.path.join(out, "vtk.npy"), theirs.astype(np.uint8))
    rows, columns = interior(args.image)
    difference = ours[rows, columns] - theirs[rows, columns]
    rmse = float(np.sqrt(np.mean(difference ** 2)))
    print(f"scene            Marschner-Lobb {args.size}^3, {args.image}x{args.image}, "
          f"orthographic, grey ramp, opacity 0.05 s per voxel")
    print(f"interior         rows and columns {rows.start}..{rows.stop - 1} "
          f"({(rows.stop - rows.start) ** 2} pixels)")
    print(f"interior RMSE    {rmse:.2f} steps of 255 (RGB pooled)")
    print(f"largest diff     {float(np.abs(difference).max()):.0f} steps of 255")
    print(f"mean             texsplat {ours[rows, columns].mean():.2f}, "
          f"VTK {theirs[rows, columns].mean():.2f} (of 255)")
    print(f"VTK render       {1000 * vtk_time:.1f} ms (vtkFixedPointVolumeRayCastMapper, "
          f"sample distance {args.sample_distance} voxel, median of {args.repeat})")
    print(f"texsplat render  {1000 * our_time:.1f} ms (the whole `texsplat render` command, "
          f"--backend {args.backend}, median of {args.repeat})")
    print(f"images           {out}")


if __name__ == "__main__":
    main()
