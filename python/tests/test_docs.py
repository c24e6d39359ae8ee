"""The notebook of docs/python.md: its Python cells run in order in one namespace, in an empty
folder, and each ```text block after a cell is what that cell prints."""

import contextlib
import io
import re

from conftest import REPOSITORY


def cells():
    text = (REPOSITORY / "docs" / "python.md").read_text()
    return re.findall(r"```(python|text)\n(.*?)```", text, re.S)


def test_the_guides_cells_run_and_print_what_it_shows(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    namespace = {}
    printed = ""
    ran = 0
    for kind, code in cells():
        if kind == "text":
            assert printed == code, f"cell {ran} printed\n{printed}\nbut the guide shows\n{code}"
            continue
        output = io.StringIO()
        with contextlib.redirect_stdout(output):
            exec(compile(code, f"docs/python.md cell {ran + 1}", "exec"), namespace)
        printed = output.getvalue()
        ran += 1
    assert ran >= 6
    assert (tmp_path / "torus.png").read_bytes().startswith(b"\x89PNG")
    assert (tmp_path / "edited.iv").read_text().count("source MEMORY") == 1
