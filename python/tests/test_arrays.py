"""texsplat.render() of NumPy arrays and xarray DataArrays, and the errors of bad arrays."""

import sys

import numpy as np
import pytest

import texsplat
from conftest import blob


def test_a_volume_renders_to_an_image_of_the_size_asked(volume):
    image = texsplat.render(volume, size=(96, 64))
    pixels = np.asarray(image)
    assert (image.width, image.height) == (96, 64)
    assert pixels.shape == (64, 96, 4) and pixels.dtype == np.float32
    # Opaque black background, the blob drawn in the middle, nothing at the corners.
    assert pixels[..., 3].min() == pytest.approx(1.0)
    assert pixels[32, 48, :3].sum() > 0.05
    assert np.all(pixels[0, 0, :3] == 0)


def test_a_float32_c_array_is_read_where_it_lies_and_others_are_converted(volume):
    node = texsplat.Node("VolumeData")
    references = sys.getrefcount(volume)
    node.set_array(volume)
    assert sys.getrefcount(volume) == references + 1  # the grid holds the array: no copy
    converted = volume.astype(np.float64)
    converted_references = sys.getrefcount(converted)
    node.set_array(converted)
    assert sys.getrefcount(converted) == converted_references  # converted into a grid of its own
    assert sys.getrefcount(volume) == references  # the first grid, and its reference, are gone
    assert node.source == "MEMORY"


def test_every_real_dtype_and_layout_gives_the_same_image(volume):
    reference = np.asarray(texsplat.render(volume, size=(48, 48)))
    scaled = np.round(volume * 1000).astype(np.float32)
    expected = np.asarray(texsplat.render(scaled, size=(48, 48)))
    for variant in (scaled.astype(np.float64), scaled.astype(np.int32), scaled.astype(np.int64),
                    np.asfortranarray(scaled), scaled.astype(">f4"),
                    np.ascontiguousarray(scaled[::-1])[::-1]):
        assert np.array_equal(np.asarray(texsplat.render(variant, size=(48, 48))), expected)
    assert not np.array_equal(reference, np.zeros_like(reference))


def test_bad_arrays_raise_with_the_messages_of_the_npy_reader():
    with pytest.raises(ValueError, match=r"^volume: array of shape \(4, 5\) is not supported; "
                                         r"expected \(z, y, x\) or \(z, y, x, 3\)$"):
        texsplat.render(np.zeros((4, 5), np.float32))
    with pytest.raises(TypeError, match=r"^volume: data type '<c8' is not supported; expected "
                                        r"<f4, <f8"):
        texsplat.render(np.zeros((4, 4, 4), np.complex64))
    with pytest.raises(ValueError, match=r"^volume: array of shape \(0, 4, 4\): "):
        texsplat.render(np.zeros((0, 4, 4), np.float32))
    with pytest.raises(ValueError, match=r"^volume: all 64 voxels are NaN or infinite"):
        texsplat.render(np.full((4, 4, 4), np.nan, np.float32))


def test_nan_voxels_are_empty(volume):
    holes = volume.copy()
    holes[:, :, : volume.shape[2] // 2] = np.nan
    image = np.asarray(texsplat.render(holes, size=(64, 64)))
    assert np.all(np.isfinite(image))
    assert image[..., :3].sum() < np.asarray(texsplat.render(volume, size=(64, 64)))[..., :3].sum()


def test_vectors_are_drawn_with_vector_splats():
    n = 16
    vectors = np.zeros((n, n, n, 3), np.float32)
    vectors[..., 0] = 1.0
    image = np.asarray(texsplat.render(vectors, size=(64, 64)))
    assert image[..., :3].max() > 0.0


def test_arguments_are_checked(volume):
    with pytest.raises(ValueError, match="size: expected"):
        texsplat.render(volume, size=(0, 10))
    with pytest.raises(ValueError, match="unknown value 'NOPE' for SFEnum TransferFunction.preset"):
        texsplat.render(volume, colormap="nope")
    with pytest.raises(ValueError, match="zoom: expected a magnification > 0"):
        texsplat.render(volume, zoom=0)
    with pytest.raises(ValueError, match="--backend: expected cpu, gl or auto, got 'vulkan'"):
        texsplat.render(volume, backend="vulkan")
    with pytest.raises(ValueError, match="background: expected"):
        texsplat.render(volume, background="pink")


def test_the_memory_limit_refuses_work_before_it_allocates(volume):
    with pytest.raises(MemoryError, match="rendering a 512x512 image would need .* more than "
                                          "the memory limit of"):
        texsplat.render(volume, memory_limit="1K")
    with pytest.raises(ValueError, match="memory_limit: expected a byte count"):
        texsplat.render(volume, memory_limit="lots")


def test_view_options_change_the_picture(volume):
    front = np.asarray(texsplat.render(volume, size=(64, 64)))
    turned = np.asarray(texsplat.render(volume, size=(64, 64), azimuth=90))
    closer = np.asarray(texsplat.render(volume, size=(64, 64), zoom=2))
    assert not np.array_equal(front, turned) and not np.array_equal(front, closer)


def test_a_splat_budget_draws_fewer_coarser_splats():
    volume = blob(48)
    full = np.asarray(texsplat.render(volume, size=(64, 64)))
    budget = np.asarray(texsplat.render(volume, size=(64, 64), max_splats=200))
    assert not np.array_equal(full, budget)


def test_xarray_coordinates_give_spacing_and_origin(volume):
    xarray = pytest.importorskip("xarray")
    n = volume.shape[0]
    data = xarray.DataArray(volume, dims=("z", "y", "x"),
                            coords={"z": np.arange(n) * 2.0 + 5, "y": np.arange(n) * 2.0,
                                    "x": np.arange(n) * 2.0})
    from_xarray = np.asarray(texsplat.render(data, size=(48, 48)))
    placed = np.asarray(texsplat.render(volume, size=(48, 48), spacing=(2, 2, 2),
                                        origin=(0, 0, 5)))
    assert np.array_equal(from_xarray, placed)
    # Decreasing coordinates (latitude from north to south) read the axis backwards.
    flipped = data.isel(y=slice(None, None, -1))
    assert np.array_equal(np.asarray(texsplat.render(flipped, size=(48, 48))), from_xarray)
    with pytest.raises(ValueError, match=r"^volume: array of shape \(4, 5\) is not supported"):
        texsplat.render(xarray.DataArray(np.zeros((4, 5), np.float32), dims=("y", "x")))
    uneven = data.assign_coords(x=np.arange(n) ** 2.0)
    with pytest.raises(ValueError, match="coordinate 'x' is not evenly spaced"):
        texsplat.render(uneven)
