"""The bad-input contract for `[tangential]` (docs: case-format.md; issue 4, "Bad input"), in the style of
test_bad_input.py: exit status 2, one stderr line naming the key, the value and the rule, no result directory.
Plus the good path: the tangential columns and summary keys."""

from __future__ import annotations

import csv
import json

import pytest

from test_bad_input import assert_bad_input, case_text

LOAD = '[load]\ncontrol = "displacement"\nhistory = [[0.0, 0.0], [0.5, 1.0e-4], [1.0, 1.0e-4]]\n'
HARMONIC = '[tangential]\nfriction = 0.3\namplitude = 1e-6\nfrequency = 10.0\nstart = 0.5\nend = 1.0\n'


def tangential_case(tangential: str, load: str = LOAD) -> str:
    return case_text(load=load, extra=tangential)


BAD_CASES = [
    ("negative-friction", tangential_case(HARMONIC.replace("friction = 0.3", "friction = -0.1")),
     ["tangential.friction", "-0.1", ">= 0"]),
    ("nan-friction", tangential_case(HARMONIC.replace("friction = 0.3", "friction = nan")),
     ["tangential.friction", "nan"]),
    ("infinite-friction", tangential_case(HARMONIC.replace("friction = 0.3", "friction = inf")),
     ["tangential.friction", "inf"]),
    ("zero-frequency", tangential_case(HARMONIC.replace("frequency = 10.0", "frequency = 0.0")),
     ["tangential.frequency", "= 0", "> 0"]),
    ("negative-frequency", tangential_case(HARMONIC.replace("frequency = 10.0", "frequency = -5.0")),
     ["tangential.frequency", "-5", "> 0"]),
    ("end-before-start", tangential_case(HARMONIC.replace("end = 1.0", "end = 0.2")),
     ["tangential.end", "0.2", "after tangential.start"]),
    ("unknown-control", tangential_case(HARMONIC + 'control = "velocity"\n'),
     ["tangential.control", '"velocity"', "unknown control"]),
    ("history-and-harmonic", tangential_case(HARMONIC + "history = [[0.0, 0.0], [1.0, 1e-6]]\n"),
     ["tangential", "either history or amplitude"]),
    ("history-jump", tangential_case('[tangential]\nfriction = 0.3\nhistory = [[0.5, 0.0], [0.5, 1e-6]]\n'),
     ["tangential.history", "no jumps"]),
    ("impact", case_text(load='[load]\ncontrol = "impact"\nvelocity = 0.1\n',
                         indenter='[indenter]\nshape = "sphere"\nR = 0.01\nmass = 0.01\n', extra=HARMONIC),
     ["tangential", "impact"]),
    # The tangential displacement moves before the normal contact is made.
    ("no-normal-contact", tangential_case(
        '[tangential]\nfriction = 0.3\nhistory = [[0.0, 0.0], [0.5, 1e-6]]\n',
        load='[load]\ncontrol = "displacement"\nhistory = [[0.0, 0.0], [0.5, 0.0], [1.0, 1.0e-4]]\n'),
     ["tangential", "no normal contact"]),
]


@pytest.mark.parametrize("text,fragments", [(c[1], c[2]) for c in BAD_CASES], ids=[c[0] for c in BAD_CASES])
def test_bad_tangential_input(run_case, text, fragments):
    assert_bad_input(run_case(text), *fragments)


def test_harmonic_outputs(run_case):
    result = run_case(tangential_case(HARMONIC + '\n[output]\nsnapshots = [0.75]\n'))
    assert result.returncode == 0, result.stderr
    with open(result.out / "history.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    assert list(rows[0].keys()) == ["t", "d", "F", "a", "u", "Fx", "c"]
    summary = json.loads((result.out / "summary.json").read_text())
    for key in ("max_tangential_force", "min_stick_radius", "dissipated_energy_per_cycle"):
        assert key in summary and summary[key] > 0.0, key
    with open(result.out / "profiles.csv", newline="") as f:
        assert next(csv.reader(f)) == ["t", "r", "p", "w", "tau"]


def test_gross_sliding_is_reported(run_case):
    result = run_case(tangential_case('[tangential]\nfriction = 0.3\ncontrol = "force"\n'
                                      'history = [[0.5, 0.0], [1.0, 10.0]]\n'))
    assert result.returncode == 0, result.stderr
    summary = json.loads((result.out / "summary.json").read_text())
    assert summary["gross_sliding"] is True
    assert 0.5 < summary["sliding_from"] <= 1.0


@pytest.mark.parametrize("material", [
    '[material]\nmodel = "standard"\nG_inf = 1.0e6\nG1 = 2.0e6\ntau1 = 0.1\nK = 3.0e6\n',
    '[material]\nmodel = "standard"\nG_inf = 1.0e6\nG1 = 2.0e6\ntau1 = 0.1\n',
], ids=["compressible", "two-bodies"])
def test_approximate_tangential_cases_run_with_one_warning(run_case, material):
    indenter = '[indenter]\nshape = "sphere"\nR = 0.01\n'
    if "K =" not in material:
        indenter += '[indenter.material]\nmodel = "elastic"\nG = 5.0e6\n'
    result = run_case(case_text(material=material, indenter=indenter, load=LOAD, extra=HARMONIC))
    assert result.returncode == 0, result.stderr
    lines = result.stderr_lines
    assert len(lines) == 1 and lines[0].startswith("mdr: warning:") and "approximation" in lines[0], lines
    summary = json.loads((result.out / "summary.json").read_text())
    assert summary["tangential_approximation"] is True


def test_exact_tangential_case_has_no_warning(run_case):
    result = run_case(tangential_case(HARMONIC))
    assert result.returncode == 0, result.stderr
    assert "warning" not in result.stderr
    assert json.loads((result.out / "summary.json").read_text())["tangential_approximation"] is False
