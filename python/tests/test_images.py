"""texsplat.Image: the pixels as an array, files as the command line writes them, notebooks."""

import numpy as np
import pytest

import texsplat


def test_the_array_is_the_premultiplied_rgba_an_exr_holds(tmp_path, volume):
    image = texsplat.render(volume, size=(40, 30), background="transparent")
    pixels = np.asarray(image)
    assert pixels.shape == (30, 40, 4) and pixels.dtype == np.float32
    assert np.all(pixels[..., :3] <= pixels[..., 3:] + 1e-6)  # premultiplied: colour <= alpha
    image.save(str(tmp_path / "image.exr"))
    assert np.array_equal(np.asarray(texsplat.read_image(str(tmp_path / "image.exr"))), pixels)
    assert np.asarray(image, dtype=np.float64).dtype == np.float64


def test_png_files_and_notebooks(tmp_path, volume):
    image = texsplat.render(volume, size=(40, 30))
    image.save(str(tmp_path / "image.png"))
    png = (tmp_path / "image.png").read_bytes()
    assert png.startswith(b"\x89PNG") and image._repr_png_() == png
    image.save(str(tmp_path / "legend.png"), colorbar=True, colorbar_position="bottom")
    assert (tmp_path / "legend.png").read_bytes() != png
    with pytest.raises(OSError, match=r"image.tif: unknown image extension '.tif'"):
        image.save(str(tmp_path / "image.tif"))
    with pytest.raises(ValueError, match="colorbar_position: "):
        image.save(str(tmp_path / "x.png"), colorbar=True, colorbar_position="middle")
    assert repr(image) == "<texsplat.Image 40x30>"


def test_the_colour_bar_says_what_the_values_are(tmp_path, volume):
    def bar(name, data=volume, **labels):
        texsplat.render(data, size=(40, 30), **labels).save(str(tmp_path / name), colorbar=True)
        return (tmp_path / name).read_bytes()

    untitled = bar("untitled.png")
    titled = bar("titled.png", title="Density", units="g/cm³")
    assert titled != untitled and bar("again.png", title="Density", units="g/cm³") == titled
    with pytest.raises(TypeError, match="^title: expected a string, got 3"):
        texsplat.render(volume, title=3)
    # An xarray's long_name and units label its bar, as xarray's own plots do.
    xarray = pytest.importorskip("xarray")
    data = xarray.DataArray(volume, dims=("z", "y", "x"), name="rho",
                            attrs={"long_name": "Density", "units": "g/cm³"})
    assert bar("xarray.png", data) == titled
    named = xarray.DataArray(volume, dims=("z", "y", "x"), name="Density")
    assert bar("named.png", named) == bar("density.png", title="Density")
