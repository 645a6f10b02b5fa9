"""The bad-input contract of the Shore durometer test (`[load] control = "shore"`, docs: case-format.md; issue 11),
in the style of test_bad_input.py: exit status 2, one stderr line naming the key, the value and the rule, no result
directory. Plus the good path: the summary keys and the history column."""

from __future__ import annotations

import csv
import json

import pytest

from test_bad_input import assert_bad_input

MATERIAL = '[material]\nmodel = "standard"\nG_inf = 1.0e6\nG1 = 1.0e6\ntau1 = 2.0\n'
SHORE = '[load]\ncontrol = "shore"\nscale = "A"\n'
NUMERICS = '[numerics]\nelements = 200\n'


def shore_case(load: str = SHORE, extra: str = "") -> str:
    return MATERIAL + load + NUMERICS + extra


BAD_CASES = [
    ("unknown-scale", shore_case(SHORE.replace('"A"', '"B"')), ["load.scale", '"B"', "one of A, D"]),
    ("lower-case-scale", shore_case(SHORE.replace('"A"', '"a"')), ["load.scale", '"a"', "one of A, D"]),
    ("missing-scale", shore_case('[load]\ncontrol = "shore"\n'), ["load.scale", "(missing)"]),
    ("zero-duration", shore_case(SHORE + "duration = 0.0\n"), ["load.duration", "= 0", "> 0"]),
    ("negative-duration", shore_case(SHORE + "duration = -15.0\n"), ["load.duration", "-15", "> 0"]),
    ("infinite-duration", shore_case(SHORE + "duration = inf\n"), ["load.duration", "inf"]),
    ("history-with-shore", shore_case(SHORE + "history = [[0.0, 0.0], [1.0, 1.0e-4]]\n"),
     ["load.history", 'only with control = "displacement", "force" or "spring", not "shore"']),
    ("spring-constant-with-shore", shore_case(SHORE + "spring_constant = 1.0e3\n"),
     ["load.spring_constant", 'only with control = "spring", not "shore"']),
    ("harmonic-with-shore", shore_case(SHORE + "harmonic = { amplitude = 1e-6, frequency = 1.0, start = 0.0, end = 1.0 }\n"),
     ["load.harmonic", 'only with control = "displacement", "force" or "spring", not "shore"']),
    ("indenter-with-shore", shore_case(extra='[indenter]\nshape = "sphere"\nR = 0.01\n'),
     ["indenter", "not with control = \"shore\"", "standard"]),
    ("tangential-with-shore", shore_case(extra="[tangential]\nfriction = 0.3\nhistory = [[0.0, 0.0], [1.0, 1e-6]]\n"),
     ["tangential", "not with control = \"shore\""]),
    ("scale-without-shore",
     MATERIAL + '[indenter]\nshape = "sphere"\nR = 0.01\n[load]\ncontrol = "displacement"\nscale = "A"\n'
     'history = [[0.0, 0.0], [1.0, 1.0e-4]]\n', ["load.scale", "only with control = \"shore\""]),
    ("duration-without-shore",
     MATERIAL + '[indenter]\nshape = "sphere"\nR = 0.01\n[load]\ncontrol = "force"\nduration = 15.0\n'
     'history = [[0.0, 0.0], [1.0, 1.0]]\n', ["load.duration", "only with control = \"shore\""]),
]


@pytest.mark.parametrize("text,fragments", [case[1:] for case in BAD_CASES], ids=[case[0] for case in BAD_CASES])
def test_run_refuses_bad_shore_case(run_case, text, fragments):
    assert_bad_input(run_case(text), *fragments)


@pytest.mark.parametrize("case_id", ["unknown-scale", "zero-duration", "indenter-with-shore"])
def test_check_refuses_the_same_way(run_case, case_id):
    text, fragments = next(case[1:] for case in BAD_CASES if case[0] == case_id)
    assert_bad_input(run_case(text, command="check"), *fragments)


def test_shore_run_writes_the_readings(run_case):
    result = run_case(shore_case())
    assert result.returncode == 0, result.stderr
    summary = json.loads((result.out / "summary.json").read_text())
    assert summary["control"] == "shore"
    assert summary["shore_1s"] > summary["shore_3s"] > summary["shore_15s"] > 0.0  # the reading drifts down
    with open(result.out / "history.csv", newline="") as file:
        rows = list(csv.DictReader(file))
    assert list(rows[0]) == ["t", "d", "F", "a", "shore"]
    last = rows[-1]
    assert float(last["t"]) == 15.0
    assert float(last["shore"]) == pytest.approx(100.0 - float(last["d"]) / 2.5e-5, abs=1e-9)
    assert float(last["shore"]) == pytest.approx(summary["shore_15s"], abs=1e-9)


def test_kelvin_voigt_readings_stay_on_the_scale(run_case):
    # A parallel dashpot holds the indenter at the surface at the landing: from then on every row keeps the Type A
    # spring's balance F = 8.05 N - 3000 N/m d (docs/case-format.md) and reads within 0..100 (the first step's depth
    # solve once flew off to d = -2.1 mm, F = 0: a reading of 185).
    result = run_case('[material]\nmodel = "kelvin_voigt"\nG = 1.0e6\neta = 1.0e6\n' + SHORE + NUMERICS)
    assert result.returncode == 0, result.stderr
    with open(result.out / "history.csv", newline="") as file:
        rows = list(csv.DictReader(file))
    for row in rows:
        assert 0.0 <= float(row["shore"]) <= 100.0, row
    for row in rows[1:]:  # after the landing
        assert float(row["F"]) == pytest.approx(8.05 - 3000.0 * float(row["d"]), rel=1e-9), row


def test_short_shore_test_reports_only_the_readings_it_reaches(run_case):
    result = run_case(shore_case(SHORE + "duration = 2.0\n"))
    assert result.returncode == 0, result.stderr
    summary = json.loads((result.out / "summary.json").read_text())
    assert "shore_1s" in summary and "shore_3s" not in summary and "shore_15s" not in summary


# A Shore test on a sheet ([layer], issue 28): the same columns and summary, the reading harder than the half-space's.
SHEET = '[layer]\nthickness = 2.0e-3\ninterface = "bonded"\n'
LAYER_BAD_CASES = [
    ("layer-contact-reaches-the-rod", '[material]\nmodel = "elastic"\nG = 1.0e4\n' + SHORE + SHEET,
     ["load.control", '"shore"', "the contact reaches the durometer's rod"]),
    ("layer-parallel-dashpot", '[material]\nmodel = "kelvin_voigt"\nG = 1.0e6\neta = 1.0e6\n' + SHORE + SHEET,
     ["material.eta", "parallel dashpot", "[layer]"]),
]


@pytest.mark.parametrize("text,fragments", [case[1:] for case in LAYER_BAD_CASES],
                         ids=[case[0] for case in LAYER_BAD_CASES])
def test_run_refuses_what_a_sheet_does_not_build(run_case, text, fragments):
    assert_bad_input(run_case(text), *fragments)


def test_check_refuses_a_durometer_on_a_sheet_against_a_dashpot(run_case):
    """A rule of the parts, not of the run's course (drivers::validate_layer): `mdr check` refuses it as `mdr run`
    does, so that no case passes check and then fails to run (check said ok before, issue 27's audit)."""
    text, fragments = next(case[1:] for case in LAYER_BAD_CASES if case[0] == "layer-parallel-dashpot")
    assert_bad_input(run_case(text, command="check"), *fragments)


def test_shore_on_a_sheet_writes_the_readings(run_case):
    half_space = run_case(MATERIAL + SHORE)
    assert half_space.returncode == 0, half_space.stderr
    thick = json.loads((half_space.out / "summary.json").read_text())
    sheet = run_case(MATERIAL + SHORE + SHEET)  # into the same result directory
    assert sheet.returncode == 0, sheet.stderr
    summary = json.loads((sheet.out / "summary.json").read_text())
    assert summary["control"] == "shore"
    for key in ("shore_1s", "shore_3s", "shore_15s"):
        assert summary[key] > thick[key] + 1.0  # the table carries part of the load (docs/case-format.md)
    with open(sheet.out / "history.csv", newline="") as file:
        rows = list(csv.DictReader(file))
    assert list(rows[0]) == ["t", "d", "F", "a", "shore"]
    assert float(rows[-1]["shore"]) == pytest.approx(summary["shore_15s"], abs=1e-9)


def test_a_layers_elements_beyond_the_cap_are_said(run_case):
    """`numerics.elements` above a layer's cap (twice the default rule, 96 Gauss nodes within 12 thicknesses) runs on
    the cap: stdout says so, naming the key, the value asked for and the count taken (review of session 18: only the
    count showed)."""
    asked = run_case(MATERIAL + SHORE + SHEET + "[numerics]\nelements = 200\n")
    assert asked.returncode == 0, asked.stderr
    assert "numerics.elements = 200 ran as 96 Gauss nodes" in asked.stdout
    within = run_case(MATERIAL + SHORE + SHEET + "[numerics]\nelements = 64\n")
    assert within.returncode == 0, within.stderr
    assert "numerics.elements" not in within.stdout
