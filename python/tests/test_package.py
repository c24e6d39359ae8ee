"""The installed package: type stubs for editors, and what it exports."""

import pathlib

import texsplat


def test_type_stubs_are_installed():
    package = pathlib.Path(texsplat.__file__).parent
    stub = (package / "_texsplat.pyi").read_text()
    assert "class Node" in stub and "class Image" in stub and "def read_scene" in stub
    assert (package / "py.typed").exists()


def test_the_registry_lists_every_node_type():
    types = texsplat.node_types()
    for name in ("Separator", "VolumeData", "TransferFunction", "TextureSplat", "VectorSplat"):
        assert name in types
