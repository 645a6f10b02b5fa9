"""mdr.fit's documents cross from C++ as Python objects built directly (no JSON text in between): the summary of a
fit equals json.load of the fit.json that `mdr fit` writes for the same case, and a model choice's ranking equals
ranking.json, key for key, in order and by type (null as None), every value but the wall times equal."""

from __future__ import annotations

import json
import math
import pathlib
import random
import subprocess

import numpy as np
import pytest

import mdr

G_TRUE, R = 2.0e5, 5.0e-4  # Hertz data of a sphere on an incompressible half-space [Pa], [m]

CASE = """
[material]
{material}
[indenter]
shape = "sphere"
R = 5.0e-4
[fit]
{fit}
[[fit.data]]
file = "curve.csv"
time = "t"
depth = "depth_um"
force = "force_uN"
units = {{ length = "um", force = "uN" }}
"""

CASES = {
    # one parameter, determined
    "elastic": ('model = "elastic"\nG = 5.0e4', 'free = ["material.G"]'),
    # a standard solid on elastic data: G1 and tau1 undetermined, their errors null (None) (with the baseline
    # fitted; from the rows before contact, the default, tau1 lands where its error is finite, if huge)
    "undetermined": ('model = "standard"\nG_inf = 5.0e4\nG1 = 5.0e4\ntau1 = 0.1',
                     'free = ["material.G_inf", "material.G1", "material.tau1"]\nbaseline = "fit"'),
    # a model choice: ranking.json and a fit.json per candidate
    "candidates": ('model = "elastic"\nG = 5.0e4', 'candidates = ["standard", "elastic"]'),
}


def write_case(directory: pathlib.Path, name: str) -> pathlib.Path:
    generator = random.Random(3)
    rows = ["t,depth_um,force_uN"]
    for i in range(300):
        d = -2.0e-6 + 3.0e-8 * i
        force = 16.0 / 3.0 * G_TRUE * math.sqrt(R) * max(d, 0.0) ** 1.5 + 3.0e-5 + generator.gauss(0.0, 2.0e-6)
        rows.append(f"{0.01 * i},{(d + 1.0e-6) * 1e6},{force * 1e6}")
    (directory / "curve.csv").write_text("\n".join(rows) + "\n", encoding="utf-8")
    material, fit = CASES[name]
    path = directory / "case.toml"
    path.write_text(CASE.format(material=material, fit=fit), encoding="utf-8")
    return path


def assert_same_document(from_python, from_file, where="") -> None:
    """Equal key for key (in order), by type and by value; wall times by type only."""
    assert type(from_python) is type(from_file), f"{where}: {type(from_python)} != {type(from_file)}"
    if isinstance(from_file, dict):
        assert list(from_python) == list(from_file), where
        for key in from_file:
            assert_same_document(from_python[key], from_file[key], f"{where}.{key}")
    elif isinstance(from_file, list):
        assert len(from_python) == len(from_file), where
        for i, (a, b) in enumerate(zip(from_python, from_file)):
            assert_same_document(a, b, f"{where}[{i}]")
    elif not where.endswith("wall_seconds"):
        assert from_python == from_file, where


def command_line_fit(mdr_binary, case: pathlib.Path) -> pathlib.Path:
    out = case.parent / "out"
    result = subprocess.run([mdr_binary, "fit", str(case), "--out", str(out)], capture_output=True, text=True,
                            timeout=300)
    assert result.returncode == 0, result.stderr
    return out


def load(path: pathlib.Path):
    with open(path, encoding="utf-8") as handle:
        return json.load(handle)


@pytest.mark.parametrize("name", ["elastic", "undetermined"])
def test_the_summary_is_fit_json(mdr_binary, tmp_path, name):
    case = write_case(tmp_path, name)
    result = mdr.fit(case)
    from_file = load(command_line_fit(mdr_binary, case) / "fit.json")
    assert_same_document(result.summary, from_file)
    if name == "undetermined":
        assert result.summary["standard_errors"]["material.tau1"] is None
        assert result.standard_errors["material.tau1"] != result.standard_errors["material.tau1"]  # NaN
        assert list(result.summary["undetermined"]) == ["material.G1", "material.tau1"]


def test_the_ranking_and_every_candidate_are_their_files(mdr_binary, tmp_path):
    case = write_case(tmp_path, "candidates")
    result = mdr.fit(case)
    out = command_line_fit(mdr_binary, case)
    ranking = load(out / "ranking.json")
    assert_same_document(result.ranking, ranking["candidates"], "candidates")
    assert list(result.candidates) == [entry["name"] for entry in ranking["candidates"]] == ["elastic", "standard"]
    for name, candidate in result.candidates.items():
        assert_same_document(candidate.summary, load(out / name / "fit.json"), name)


@pytest.mark.parametrize("name", ["elastic", "candidates"])
def test_the_fitted_case_is_fitted_toml(mdr_binary, tmp_path, name):
    """FitResult.fitted_case is fitted.toml's text (docs/python.md), every candidate's too: a case without `[load]`
    gets the first curve's driving history, so that it runs the fitted curve (docs/case-format.md, fitted.toml)."""
    case = write_case(tmp_path, name)
    result = mdr.fit(case)
    out = command_line_fit(mdr_binary, case)
    if not result.candidates:
        assert result.fitted_case == (out / "fitted.toml").read_text(encoding="utf-8")
    for candidate, fitted in result.candidates.items():
        assert fitted.fitted_case == (out / candidate / "fitted.toml").read_text(encoding="utf-8"), candidate


def test_a_fitted_case_without_a_load_drives_the_first_curve():
    """The rule of fitted.toml (docs/case-format.md): without a `[load]`, the first curve's driving history, the
    contact point removed (here fixed at 0, so the depths as given), at the data's own rows."""
    t = [0.1 * i for i in range(11)]
    d = [1e-6 * i for i in range(11)]
    force = [16.0 / 3.0 * G_TRUE * math.sqrt(R) * depth**1.5 for depth in d]
    case = {"material": {"model": "elastic", "G": 5e4}, "indenter": {"shape": "sphere", "R": R},
            "fit": {"free": ["material.G"], "contact_point": "fixed", "baseline": "fixed"}}
    result = mdr.fit(case, data=[{"time": t, "depth": d, "force": force}])
    load = __import__("tomllib").loads(result.fitted_case)["load"]
    assert load["control"] == "displacement"
    assert [point[0] for point in load["history"]] == pytest.approx(t, rel=1e-15, abs=0.0)
    assert [point[1] for point in load["history"]] == pytest.approx(d, rel=1e-15, abs=0.0)


def read_columns(path: pathlib.Path) -> dict[str, list[str]]:
    """A CSV file's columns by header, as text."""
    import csv

    with open(path, newline="", encoding="utf-8") as handle:
        rows = list(csv.reader(handle))
    return {name: [row[c] for row in rows[1:]] for c, name in enumerate(rows[0])}


def test_the_curves_and_material_arrays_are_the_columns_of_curves_csv_functions_csv_and_dynamic_csv(mdr_binary,
                                                                                                    tmp_path):
    """mdr.fit's curves have exactly curves.csv's columns (`curve` being each entry's name; `residual` = model -
    measured included) and its material arrays exactly those of functions.csv and dynamic.csv, with their values:
    both are written from one declaration (mdr/fitcase/fit_columns.hpp)."""
    case = write_case(tmp_path, "elastic")
    result = mdr.fit(case)
    out = command_line_fit(mdr_binary, case)
    curves = read_columns(out / "curves.csv")
    (curve,) = result.curves
    assert [key for key in curve if key not in ("name", "kind", "fitted")] == list(curves)[1:]
    assert [curve["name"]] * len(curve["t"]) == curves["curve"]
    for key in list(curves)[1:]:
        np.testing.assert_array_equal(curve[key], [float(value) for value in curves[key]], err_msg=key)
    np.testing.assert_array_equal(curve["residual"], curve["model"] - curve["measured"])
    tables = {**read_columns(out / "functions.csv"), **read_columns(out / "dynamic.csv")}
    assert sorted(result.material) == sorted(tables)
    for key, values in tables.items():
        np.testing.assert_array_equal(result.material[key], [float(value) for value in values], err_msg=key)
