"""mdr.fit_map on a stack of arrays writes and returns what `mdr fit CASE --map FILE` does for an instrument map: the
rows of map.csv from the same C++ row builder (fitcase::map_rows), map.json from the same writer; and what mdr writes
as JSON from Python goes through the one writer (io::to_json)."""

from __future__ import annotations

import csv
import io
import json
import math
import os
import subprocess
import sys

import numpy as np
import pytest

import mdr
from conftest import REPO_ROOT

MAP = REPO_ROOT / "examples" / "data" / "vendor" / "fmt-jpk-fd_map-data-reference-points.jpk-force-map"
#: The case of the command line's map (one [[fit.data]] table: the map's) and of the stack's (the same, without it).
CASE_TOML = """
[material]
model = "elastic"
G = 1000.0

[indenter]
shape = "sphere"
R = 5.0e-6

[fit]
free = ["material.G"]

[[fit.data]]
file = "map.jpk-force-map"
segments = ["extend"]
"""
CASE = {"material": {"model": "elastic", "G": 1000.0}, "indenter": {"shape": "sphere", "R": 5.0e-6},
        "fit": {"free": ["material.G"]}}


@pytest.fixture(scope="module")
def command_line_map(mdr_binary, tmp_path_factory):
    """The result directory of `mdr fit case.toml --map MAP`."""
    directory = tmp_path_factory.mktemp("cli")
    (directory / "case.toml").write_text(CASE_TOML)
    subprocess.run([mdr_binary, "fit", "case.toml", "--map", MAP, "--out", "out"], cwd=directory, check=True,
                   capture_output=True, timeout=300)
    return directory / "out"


def hertz_stack(moduli: np.ndarray, radius: float = 5.0e-6):
    """Force curves F = (16/3) G sqrt(R) d^(3/2) (Hertz, docs/theory.md eq. 31 with E* = 4 G for nu = 1/2) of a
    grid of shear moduli `moduli`, contact at d = 0 after an approach, with their common time and depth."""
    t = np.linspace(0.0, 1.0, 61)
    d = 3.0e-7 * t - 1.0e-7
    return 16.0 / 3.0 * moduli[..., None] * math.sqrt(radius) * np.maximum(d, 0.0) ** 1.5, t, d


def test_a_stacks_map_has_the_columns_of_the_command_lines_map_csv(command_line_map):
    with open(command_line_map / "map.csv", newline="") as handle:
        columns = next(csv.reader(handle))
    moduli = np.array([[1.0e3, 2.0e3], [3.0e3, 4.0e3]])
    forces, t, d = hertz_stack(moduli)
    fits = mdr.fit_map(CASE, forces, time=t, depth=d, jobs=1)
    assert list(fits.values) == columns
    np.testing.assert_allclose(fits.values["material.G"], moduli, rtol=1e-3)
    np.testing.assert_array_equal(fits.values["column"], [[0, 1], [0, 1]])
    np.testing.assert_array_equal(fits.values["row"], [[0, 0], [1, 1]])
    np.testing.assert_array_equal(fits.values["index"], [[0, 1], [2, 3]])
    assert fits.values["failure"].tolist() == [["", ""], ["", ""]]
    assert fits.units["material.G"] == "Pa" and fits.units["contact_height"] == "m"


def test_a_stacks_map_json_has_the_layout_of_the_command_lines(command_line_map, tmp_path):
    cli = json.loads((command_line_map / "map.json").read_text())
    forces, t, d = hertz_stack(np.array([[1.0e3, 2.0e3, 3.0e3]]))
    forces[0, 2, 10] = np.nan  # a failed pixel
    fits = mdr.fit_map(CASE, forces, time=t, depth=d, jobs=1, out=tmp_path / "py", figures=False)
    stack = json.loads((tmp_path / "py" / "map.json").read_text())
    assert list(stack) == list(cli)
    assert {key: type(value) for key, value in stack.items()} == {key: type(value) for key, value in cli.items()}
    assert stack["column_units"] == cli["column_units"]  # the same case: the same columns in the same units
    assert (stack["columns"], stack["rows"], stack["pixels"], stack["failed"]) == (3, 1, 3, 1)
    assert stack == fits.summary()
    # The codes of the pixels stay status.npy; the fit's own status, flags and failure (text) are texts.csv.
    np.testing.assert_array_equal(np.load(tmp_path / "py" / "status.npy"), fits.status)
    with open(tmp_path / "py" / "texts.csv", newline="") as handle:
        texts = list(csv.DictReader(handle))
    assert [row["status"] for row in texts] == ["converged", "converged", ""] and list(texts[0]) == \
        ["row", "col", "status", "flags", "failure"]


def test_the_sweep_helper_writes_json_the_command_line_parses(monkeypatch, capsys):
    """A row whose summary holds a number that is not finite is written as null (io::to_json), not as NaN, which
    is no JSON and which the command line's parser (nlohmann::json) refuses."""
    from mdr import _sweep_rows

    _sweep_rows._emit({"first": 0, "rows": [({"max_force": math.nan, "steps": 3}, None)]})
    line = capsys.readouterr().out
    assert line.count("\n") == 1
    assert json.loads(line, parse_constant=lambda name: pytest.fail(f"{name} is no JSON")) == \
        {"first": 0, "rows": [[{"max_force": None, "steps": 3}, None]]}


def test_the_sweep_helper_writes_an_error_naming_an_undecodable_file(capsys):
    """An error naming a file whose name is not UTF-8 (Python holds its bytes as lone surrogates, os.fsdecode) is
    still one line of JSON, the bytes shown as Python's backslashreplace shows them; before, io::to_json's caster
    raised RuntimeError ('Unable to cast Python instance') and the helper wrote no line."""
    from mdr import _sweep_rows

    message = "--scheduler: OSError: cannot read " + os.fsdecode(b"/data/caf\xe9.toml")
    _sweep_rows._emit({"error": message})
    line = capsys.readouterr().out
    assert line.count("\n") == 1
    assert json.loads(line) == {"error": message.encode("utf-8", "backslashreplace").decode("utf-8")}
    assert json.loads(line)["error"].endswith("/data/caf\\udce9.toml")


def test_json_from_python_refuses_an_int_that_is_no_count_by_name():
    """mdr's documents hold an int as a count (std::size_t): a negative or too large int is a TypeError that says
    so; before, pybind11's RuntimeError 'Unable to cast Python instance to C++ type' named neither."""
    for number in (-1, 2**64):
        with pytest.raises(TypeError, match=rf"holds an int as a count .*, not {number}$"):
            mdr._mdr._to_json({"steps": number}, -1)
    assert mdr._mdr._to_json({"steps": 2**64 - 1}, -1) == '{"steps":18446744073709551615}'


@pytest.mark.parametrize("name", ["../outside", "sub/dir", "..", "", "status"])
def test_write_files_refuses_a_value_name_that_is_no_plain_file_name_and_writes_nothing(tmp_path, name):
    """CurveMap.write_files names NAME.npy by each value: a name with a path in it wrote outside the directory (or
    into a folder not there), and a number named "status" was overwritten by the codes' status.npy (a text value of
    that name goes to texts.csv); now refused naming the value, before any file is written."""
    from mdr.curve_maps import OK, CurveMap
    out = tmp_path / "out"
    out.mkdir()
    curve_map = CurveMap(values={"G": np.ones((1, 1)), name: np.zeros((1, 1))}, status=np.full((1, 1), OK),
                         reasons=np.full((1, 1), "", dtype=object))
    with pytest.raises(ValueError, match=r"^values\[.*must be a plain file name"):
        curve_map.write_files(str(out), figures=False)
    assert sorted(os.listdir(tmp_path)) == ["out"] and os.listdir(out) == []
