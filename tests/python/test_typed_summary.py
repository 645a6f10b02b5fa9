"""The summary reaches Python as typed values built in C++ (mdr/io/summary.hpp), with no JSON text in between: for
cases that give every kind of summary value (numbers, counts, flags, texts, lists), mdr.run's summary equals
json.load of the command line's summary.json key for key, in the same order and with the same Python types; it
pickles, and a sweep's columns are those summaries' numbers."""

from __future__ import annotations

import json
import math
import pickle
import subprocess

import pytest

import mdr
from conftest import REPO_ROOT

# A power law (a certified Prony series: material_error, material_window and material_frequencies, lists) under a
# harmonic depth (the harmonic keys).
POWER_LAW_HARMONIC = """title = "power law under a harmonic depth"
[material]
model = "power_law"
G0 = 1.0e6
beta = 0.2
[indenter]
shape = "sphere"
R = 0.01
[load]
control = "displacement"
history = [[0.0, 0.0], [0.01, 1.0e-4], [0.2, 1.0e-4]]
harmonic = { amplitude = 1.0e-7, frequency = 50.0, start = 0.01, end = 0.2 }
[numerics]
elements = 100
"""

CASES = {
    "oblique impact (flags, the oblique outcome)": REPO_ROOT / "examples" / "oblique_restitution.toml",
    "fretting (tangential outcome, gross_sliding)": REPO_ROOT / "examples" / "fretting_stick_radius.toml",
    "Shore A (readings)": REPO_ROOT / "examples" / "shore_a_filled_rubber.toml",
    "default (force control, profiles)": REPO_ROOT / "examples" / "default.toml",
    "power law, harmonic (lists)": None,
}


@pytest.fixture(params=list(CASES), ids=list(CASES))
def case_path(request, tmp_path):
    path = CASES[request.param]
    if path is None:
        path = tmp_path / "case.toml"
        path.write_text(POWER_LAW_HARMONIC)
    return path


def command_line_summary(mdr_binary: str, case, out) -> dict:
    completed = subprocess.run([mdr_binary, "run", str(case), "--out", str(out)], capture_output=True, text=True,
                               timeout=120)
    assert completed.returncode == 0, completed.stderr
    return json.loads((out / "summary.json").read_text())


def test_the_summary_is_summary_json_key_for_key_with_its_types(mdr_binary, case_path, tmp_path):
    expected = command_line_summary(mdr_binary, case_path, tmp_path / "out")
    summary = mdr.run(str(case_path)).summary
    assert list(summary) == list(expected)  # the same keys in the same order
    for key, value in expected.items():
        assert type(summary[key]) is type(value), key
        if key != "wall_seconds":
            assert summary[key] == value, key


def test_every_kind_of_value_is_covered(mdr_binary, tmp_path):
    kinds = set()
    for name, path in CASES.items():
        if path is None:
            path = tmp_path / "case.toml"
            path.write_text(POWER_LAW_HARMONIC)
        kinds |= {type(value) for value in mdr.run(str(path)).summary.values()}
    assert kinds == {float, int, bool, str, list}


def test_the_result_pickles_with_its_summary(case_path):
    result = mdr.run(str(case_path))
    again = pickle.loads(pickle.dumps(result))
    assert again.summary == result.summary
    assert list(again.summary) == list(result.summary)


def test_a_sweep_has_the_numbers_of_the_runs_summaries():
    case = {"material": {"model": "standard", "G_inf": 1.0e6, "G1": 2.0e6, "tau1": 0.01},
            "indenter": {"shape": "sphere", "R": 0.01},
            "load": {"control": "displacement", "history": [[0.0, 0.0], [0.1, 1.0e-4]]},
            "numerics": {"elements": 50}}
    table = mdr.sweep(case, {"material.G1": [1.0e6, -1.0, 3.0e6]})
    for i, G1 in enumerate([1.0e6, -1.0, 3.0e6]):
        if G1 < 0:
            assert table["error"][i] != "" and math.isnan(table["max_force"][i])
            continue
        run = mdr.run(dict(case, material=dict(case["material"], G1=G1))).summary
        assert table["error"][i] == ""
        for key, value in run.items():
            if isinstance(value, (int, float)) and key != "wall_seconds":
                assert table[key][i] == value, key


def test_a_sweep_table_has_the_columns_of_sweep_csv(mdr_binary, tmp_path):
    """One rule for the columns (io::sweep_columns): mdr.sweep's table has sweep.csv's header, in its order. An
    oblique impact's summary has flags (slid_throughout), which are no column of sweep.csv; mdr.sweep had them."""
    case = REPO_ROOT / "examples" / "oblique_restitution.toml"
    vary = ["load.velocity=0.5,1.0"]
    completed = subprocess.run([mdr_binary, "sweep", str(case), "--vary", *vary, "--out", str(tmp_path / "out")],
                               capture_output=True, text=True, timeout=120)
    assert completed.returncode == 0, completed.stderr
    header = (tmp_path / "out" / "sweep.csv").read_text().splitlines()[0].split(",")
    table = mdr.sweep(str(case), {"load.velocity": [0.5, 1.0]}, jobs=1)
    assert "slid_throughout" in mdr.run(str(case)).summary
    assert list(table) == header
