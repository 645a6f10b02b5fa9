"""mdr.fit_map(case, "map.jpk-force-map"): the same per-pixel outputs as `mdr fit CASE --map FILE`'s map.csv, with
the same columns (both run mdr/fit/map_fit.hpp); a failed pixel is a row with its reason."""

from __future__ import annotations

import csv
import math
import subprocess

import numpy as np
import pytest

import mdr
from conftest import REPO_ROOT

MAP = REPO_ROOT / "examples" / "data" / "vendor" / "fmt-jpk-fd_map-data-reference-points.jpk-force-map"
BROKEN = REPO_ROOT / "tests" / "data" / "instrument" / "missing-channel.jpk-force-map"
CASE = {
    "material": {"model": "elastic", "G": 1000.0},
    "indenter": {"shape": "sphere", "R": 5.0e-6},
    "fit": {"free": ["material.G"], "data": [{"file": "map.jpk-force-map", "segments": ["extend"]}]},
}


def test_the_columns_and_values_of_the_command_lines_map_csv(mdr_binary, tmp_path):
    (tmp_path / "case.toml").write_text(mdr._toml.to_toml(CASE))
    subprocess.run([mdr_binary, "fit", "case.toml", "--map", MAP, "--out", "out"], cwd=tmp_path, check=True,
                   capture_output=True, timeout=300)
    with open(tmp_path / "out" / "map.csv", newline="") as handle:
        rows = list(csv.DictReader(handle))
    table = mdr.fit_map(CASE, MAP, out=tmp_path / "py")
    assert list(table.columns) == list(rows[0].keys())
    assert table.grid == (25, 25) and table.size == (5e-4, 5e-4)  # grid.ilength, grid.ulength of the header
    for name, values in table.columns.items():
        for value, row in zip(values, rows):
            if isinstance(value, str):
                assert value == row[name]
            else:
                assert value == float(row[name]) or (math.isnan(value) and row[name] in ("", "nan")), name
    assert (tmp_path / "py" / "map.csv").read_text() == (tmp_path / "out" / "map.csv").read_text()


def test_a_failed_pixel_is_a_row_with_its_reason():
    table = mdr.fit_map(CASE, BROKEN)
    assert list(table.columns["status"][[0, 2]]) != ["failed", "failed"]
    assert table.columns["status"][1] == "failed"
    assert "vDeflection.dat" in table.columns["failure"][1]
    assert np.isnan(table.columns["material.G"][1])


def test_a_bad_case_is_refused_naming_the_key():
    case = dict(CASE, fit={"free": ["material.G"], "data": [{"file": "x.csv", "time": "t", "depth": "d",
                                                              "force": "f"}]})
    with pytest.raises(ValueError, match="--map"):
        mdr.fit_map(case, MAP)
