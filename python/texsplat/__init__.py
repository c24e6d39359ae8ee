"""texsplat from Python: render a NumPy array or an Inventor scene with texture splats.

    import numpy as np, texsplat
    image = texsplat.render(np.random.rand(64, 64, 64).astype(np.float32), colormap="viridis")
    image.save("volume.png", colorbar=True)

docs/python.md is the guide. The work runs in texsplat's C++ libraries without the GIL; errors
raise ValueError, TypeError, OSError or MemoryError subclasses with the command line's messages.
"""

from __future__ import annotations

import math
from typing import Any, Callable, Optional, Sequence, Union

import numpy as np

from ._texsplat import (
    Cancelled,
    DataError,
    Error,
    GlError,
    Image,
    IoError,
    Node,
    ParseError,
    ResourceError,
    Scene,
    node_types,
    parse_scene,
    read_image,
    read_scene,
)

__all__ = [
    "Cancelled", "DataError", "Error", "GlError", "Image", "IoError", "Node", "ParseError",
    "ResourceError", "Scene", "node_types", "parse_scene", "read_image", "read_scene", "render",
    "TqdmProgress",
]

#: What ``progress`` may be: a callable ``(step, fraction)`` (returning False cancels), True
#: (progress bars with tqdm), or None.
Progress = Union[None, bool, Callable[[str, float], Optional[bool]]]


class TqdmProgress:
    """A progress callback that shows each long step (reading, classifying, building the octree)
    as a tqdm progress bar; ``render(..., progress=True)`` uses it."""

    def __init__(self, **tqdm_options: Any) -> None:
        from tqdm.auto import tqdm

        self._tqdm = tqdm
        self._options = tqdm_options
        self._bar = None
        self._step = None

    def __call__(self, step: str, fraction: float) -> None:
        if step != self._step:
            self.close()
            self._step = step
            if fraction < 1.0:
                self._bar = self._tqdm(total=100, desc=step, unit="%", leave=False,
                                       **self._options)
        if self._bar is not None:
            self._bar.update(int(fraction * 100) - self._bar.n)
            if fraction >= 1.0:
                self.close()

    def close(self) -> None:
        """Closes the bar shown, if any (a step reported done again shows no new one)."""
        if self._bar is not None:
            self._bar.close()
            self._bar = None


def _coordinate_axis(coordinate, name: str):
    """Spacing and origin of one dimension from its coordinate values, and whether the axis runs
    backwards (decreasing values: the array is read reversed along it)."""
    values = np.asarray(coordinate, dtype=np.float64)
    if values.size < 2:
        return 1.0, float(values[0]) if values.size == 1 else 0.0, False
    steps = np.diff(values)
    step = float(steps.mean())
    if step == 0.0 or not np.allclose(steps, step, rtol=1e-4, atol=0.0):
        raise ValueError(f"volume: coordinate '{name}' is not evenly spaced (steps from "
                         f"{steps.min():g} to {steps.max():g}); texsplat draws regular grids")
    if step < 0.0:
        return -step, float(values[-1]), True
    return step, float(values[0]), False


def _from_xarray(volume):
    """The values, spacing and origin (x, y, z) of an xarray.DataArray of dims (z, y, x) or
    (z, y, x, component); another shape passes on, for the array's own message."""
    if volume.ndim not in (3, 4):
        return volume.values, None, None
    spatial = volume.dims[:3]
    spacing, origin, reverse = [], [], []
    for name in spatial:
        if name in volume.coords:
            step, start, backwards = _coordinate_axis(volume.coords[name].values, name)
        else:
            step, start, backwards = 1.0, 0.0, False
        spacing.append(step)
        origin.append(start)
        reverse.append(backwards)
    values = volume.values
    values = values[tuple(slice(None, None, -1) if backwards else slice(None)
                          for backwards in reverse)]
    return values, spacing[::-1], origin[::-1]


def _array(volume):
    """NumPy values (converted once to float32 for types the C++ side does not read)."""
    values = np.asarray(volume)
    if values.dtype.kind in "biuf" and values.dtype.str not in (
            "<f4", ">f4", "<f8", ">f8", "|u1", "|i1", "<u2", ">u2", "<i2", ">i2", "<u4", ">u4",
            "<i4", ">i4"):
        values = values.astype(np.float32)
    return values


def render(volume, size=(512, 512), colormap: str = "viridis", opacity=None,
           value_range: Optional[Sequence[float]] = None, azimuth: float = 0.0,
           elevation: float = 0.0, zoom: float = 1.0, background=None, backend: str = "auto",
           max_splats: Optional[int] = None, *, spacing: Optional[Sequence[float]] = None,
           origin: Optional[Sequence[float]] = None, threads: int = 0,
           memory_limit: Union[None, int, str] = None, progress: Progress = None,
           title: Optional[str] = None, units: Optional[str] = None) -> Image:
    """A NumPy array rendered with texture splats, in one call.

    ``volume``: a 3-D array of a real dtype indexed (z, y, x), as NumPy holds a volume; a
    (z, y, x, 3) array of vectors (drawn with vector splats); or an ``xarray.DataArray`` whose
    coordinates give the spacing and origin. A C-contiguous float32 array is drawn without a
    copy, anything else is converted once. NaN and infinite values are empty voxels.
    ``spacing`` and ``origin`` (x, y, z) place the voxels (an xarray's coordinates do it).

    ``colormap``: viridis, magma, inferno, plasma, cividis, turbo, cool_warm, gray, hot, browns.
    ``opacity``: extinction per voxel length over the value range: a number (constant), or
    numbers at evenly spaced points from the range's low to its high end; None: 0 rising to 1.
    ``value_range``: (low, high) mapped onto the colour map; None: the data's range.
    ``max_splats``: the octree's splat budget (coarser splats where it must).
    ``title`` and ``units``: what the values are, for the colour bar ("Temperature", "K" gives
    "Temperature (K)"); an xarray's ``long_name`` (or name) and ``units`` attributes by default,
    as xarray's own plots label theirs. The other
    arguments are Scene.render()'s. Returns a texsplat.Image: ``numpy.asarray(image)``, or
    ``image.save("figure.png", colorbar=True)``.
    """
    scene = Scene(_array_scene(volume, colormap, opacity, value_range, max_splats, spacing,
                               origin, title, units), "volume")
    return scene.render(size, backend=backend, background=background, azimuth=azimuth,
                        elevation=elevation, zoom=zoom, threads=threads,
                        memory_limit=memory_limit, progress=progress)


def _array_scene(volume, colormap, opacity, value_range, max_splats, spacing, origin, title,
                 units) -> Node:
    if type(volume).__module__.startswith("xarray"):
        values, coordinate_spacing, coordinate_origin = _from_xarray(volume)
        spacing = coordinate_spacing if spacing is None else spacing
        origin = coordinate_origin if origin is None else origin
        label = volume.attrs.get("long_name", volume.name)
        if title is None and label is not None:
            title = str(label)
        if units is None and "units" in volume.attrs:
            units = str(volume.attrs["units"])
    else:
        values = volume
    values = _array(values)
    data = Node("VolumeData")
    data.set_array(values, spacing=None if spacing is None else [float(s) for s in spacing],
                   origin=None if origin is None else [float(o) for o in origin], name="volume")
    transfer = Node("TransferFunction", unitDistance=0.0)
    if not isinstance(colormap, str):
        raise TypeError(f"colormap: expected the name of a colour map, got {colormap!r}")
    transfer.preset = {"coolwarm": "COOL_WARM", "greys": "GRAY", "grey": "GRAY"}.get(
        colormap.lower(), colormap.upper().replace("-", "_"))
    if opacity is not None:
        opacities = [float(opacity)] * 2 if np.isscalar(opacity) else [float(o) for o in opacity]
        if len(opacities) == 1:
            opacities *= 2
        transfer.opacityValues = [i / (len(opacities) - 1) for i in range(len(opacities))]
        transfer.opacities = opacities
    if value_range is not None:
        low, high = (float(v) for v in value_range)
        if not (math.isfinite(low) and math.isfinite(high) and low < high):
            raise ValueError(f"value_range: expected finite (low, high) with low < high, got "
                             f"{tuple(value_range)!r}")
        transfer.range = (low, high)
    for field, text in (("title", title), ("units", units)):
        if text is not None:
            if not isinstance(text, str):
                raise TypeError(f"{field}: expected a string, got {text!r}")
            setattr(transfer, field, text)
    splat = Node("VectorSplat" if np.ndim(values) == 4 else "TextureSplat")
    if max_splats is not None:
        splat.maxSplats = int(max_splats)
    root = Node("Separator")
    for child in (data, transfer, splat):
        root.add_child(child)
    return root
