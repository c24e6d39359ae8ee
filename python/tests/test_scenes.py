"""Scenes from Python: read, edit by DEF name, arrays in place of files, written back, animated,
and rendered to the command line's bits."""

import subprocess

import numpy as np
import pytest

import texsplat
from conftest import REPOSITORY, blob

SCENE = """#Inventor V2.1 ascii
Separator {
    DEF Data VolumeData { source BLOB resolution 24 24 24 }
    DEF TF TransferFunction { preset MAGMA opacities [ 0, 3 ] }
    TextureSplat { }
}
"""

ANIMATED = """#Inventor V2.1 ascii
Separator {
    DEF Data VolumeData { source TORNADO resolution 16 16 16 time = ElapsedTime { speed 4 } . timeOut }
    TransferFunction { preset VIRIDIS }
    TextureSplat { }
}
"""


def test_nodes_are_found_by_name_and_their_fields_are_python_values():
    scene = texsplat.parse_scene(SCENE)
    transfer = scene["TF"]
    assert transfer.type_name == "TransferFunction" and transfer.name == "TF"
    assert transfer.preset == "MAGMA"
    assert transfer.opacities == [0.0, 3.0]
    assert scene["Data"].resolution == (24.0, 24.0, 24.0)
    transfer.opacities = [0, 1, 5]
    transfer.opacityValues = np.linspace(0, 1, 3)
    transfer.range = (0.1, 0.9)
    assert transfer.opacities == [0.0, 1.0, 5.0] and transfer.range == pytest.approx((0.1, 0.9))
    assert "opacities" in transfer.fields and transfer.fields["range"] == "SFVec2f"
    assert "opacity" in transfer.field_description("opacities").lower()
    assert "opacities" in dir(transfer)
    assert len(scene.root.children) == 3


def test_bad_field_values_raise_with_the_readers_messages():
    scene = texsplat.parse_scene(SCENE)
    transfer = scene["TF"]
    with pytest.raises(ValueError, match=r"unknown value 'PURPLE' for SFEnum "
                                         r"TransferFunction\(TF\).preset \(expected one of GRAY"):
        transfer.preset = "PURPLE"
    with pytest.raises(TypeError, match=r"TransferFunction\(TF\).range: expected 2 numbers"):
        transfer.range = (1, 2, 3)
    with pytest.raises(TypeError, match="expected a number"):
        transfer.opacities = ["a"]
    with pytest.raises(AttributeError, match=r"TransferFunction\(TF\) has no field 'opacity'"):
        transfer.opacity = 1
    with pytest.raises(KeyError, match="no node named 'Missing'"):
        scene["Missing"]
    with pytest.raises(ValueError, match="unknown node type 'Teapot'"):
        texsplat.Node("Teapot")


def test_a_scene_is_read_from_a_path_or_from_its_text(tmp_path):
    path = tmp_path / "scene.iv"
    path.write_text(SCENE)
    from_path = texsplat.read_scene(path)
    assert from_path.name == str(path)
    assert texsplat.read_scene(SCENE)["TF"].preset == "MAGMA"
    assert texsplat.parse_scene(SCENE, "mine.iv").name == "mine.iv"
    from_path.write(tmp_path / "copy.iv")
    assert texsplat.read_scene(str(tmp_path / "copy.iv"))["TF"].opacities == [0.0, 3.0]


def test_scene_file_errors_name_file_line_and_column(tmp_path):
    broken = tmp_path / "broken.iv"
    broken.write_text("#Inventor V2.1 ascii\nSeparator {\n  TransferFunction { preset 3 }\n}\n")
    with pytest.raises(ValueError, match=r"broken.iv:3:"):
        texsplat.read_scene(str(broken))
    with pytest.raises(OSError, match="missing.iv"):
        texsplat.read_scene(str(tmp_path / "missing.iv"))


def test_an_array_replaces_a_file_and_the_scene_writes_back(tmp_path):
    scene = texsplat.parse_scene(SCENE)
    scene["Data"].set_array(blob(20), spacing=(1, 1, 2))
    scene["TF"].preset = "VIRIDIS"
    image = np.asarray(scene.render(size=(48, 48)))
    assert image[..., :3].max() > 0
    path = tmp_path / "edited.iv"
    scene.write(str(path))
    text = path.read_text()
    assert "preset VIRIDIS" in text and "source MEMORY" in text
    again = texsplat.read_scene(str(path))
    assert again["TF"].preset == "VIRIDIS"
    with pytest.raises(TypeError, match="is not a VolumeData"):
        scene["TF"].set_array(blob(4))


def test_a_scene_renders_to_the_command_lines_bits(tmp_path, cli):
    path = tmp_path / "scene.iv"
    path.write_text(SCENE)
    subprocess.run([cli, "render", str(path), "-o", str(tmp_path / "cli.exr"), "--size",
                    "80x60", "--backend", "cpu"], check=True)
    image = texsplat.read_scene(str(path)).render(size=(80, 60), backend="cpu")
    assert np.array_equal(np.asarray(image), np.asarray(texsplat.read_image(str(tmp_path / "cli.exr"))))
    subprocess.run([cli, "render", str(path), "-o", str(tmp_path / "cli.png"), "--size",
                    "200x150", "--colorbar"], check=True)
    texsplat.read_scene(str(path)).render(size=(200, 150)).save(str(tmp_path / "py.png"),
                                                                 colorbar=True)
    assert (tmp_path / "py.png").read_bytes() == (tmp_path / "cli.png").read_bytes()


def test_an_example_scene_renders_to_the_command_lines_bits(tmp_path, cli):
    scene = REPOSITORY / "examples" / "marschner-lobb.iv"
    subprocess.run([cli, "render", str(scene), "-o", str(tmp_path / "cli.exr"), "--size",
                    "64x64"], check=True)
    image = texsplat.read_scene(str(scene)).render(size=(64, 64))
    assert np.array_equal(np.asarray(image), np.asarray(texsplat.read_image(str(tmp_path / "cli.exr"))))


def test_render_at_a_time_shows_the_engines_at_that_time(tmp_path, cli):
    path = tmp_path / "animated.iv"
    path.write_text(ANIMATED)
    subprocess.run([cli, "render", str(path), "-o", str(tmp_path / "frame%d.exr"), "--size",
                    "48x48", "--frames", "3", "--fps", "2", "--backend", "cpu"], check=True)
    scene = texsplat.read_scene(str(path))
    later = np.asarray(scene.render(size=(48, 48), backend="cpu", time=1.0))
    assert scene.time == 1.0
    first = np.asarray(scene.render(size=(48, 48), backend="cpu", time=0.0))
    assert not np.array_equal(first, later)
    for frame, time in ((0, 0.0), (2, 1.0), (1, 0.5)):
        expected = np.asarray(texsplat.read_image(str(tmp_path / f"frame{frame}.exr")))
        assert np.array_equal(np.asarray(scene.render(size=(48, 48), backend="cpu", time=time)),
                              expected), f"frame {frame}"
    with pytest.raises(ValueError, match="time: expected a finite number of seconds >= 0"):
        scene.render(time=-1)
