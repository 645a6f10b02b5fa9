"""The bad-input contract for a harmonic normal load (`load.harmonic`) and `control = "spring"` (docs:
case-format.md; issue 11, "Speed and bad input"), in the style of test_bad_input.py: exit status 2, one stderr line
naming the key, the value and the rule, no result directory. Plus the good paths: the summary keys and the columns."""

from __future__ import annotations

import csv
import json

import pytest

from test_bad_input import assert_bad_input, case_text

HISTORY = "history = [[0.0, 0.0], [0.5, 1.0e-4], [1.0, 1.0e-4]]\n"
HARMONIC = "harmonic = { amplitude = 1.0e-6, frequency = 20.0, start = 0.5, end = 1.0 }\n"
DISPLACEMENT = '[load]\ncontrol = "displacement"\n' + HISTORY + HARMONIC
FORCE = '[load]\ncontrol = "force"\nhistory = [[0.0, 0.0], [0.5, 1.0], [1.0, 1.0]]\n' + \
    HARMONIC.replace("1.0e-6", "0.1")
SPRING = '[load]\ncontrol = "spring"\nspring_constant = 1.0e4\nhistory = [[0.0, -1.0e-6], [0.5, 2.0e-4], [1.0, 2.0e-4]]\n'


BAD_CASES = [
    ("zero-frequency", DISPLACEMENT.replace("frequency = 20.0", "frequency = 0.0"),
     ["load.harmonic.frequency", "= 0", "> 0"]),
    ("negative-frequency", DISPLACEMENT.replace("frequency = 20.0", "frequency = -1.0"),
     ["load.harmonic.frequency", "-1", "> 0"]),
    ("zero-amplitude", DISPLACEMENT.replace("amplitude = 1.0e-6", "amplitude = 0.0"),
     ["load.harmonic.amplitude", "= 0", "> 0"]),
    ("end-before-start", DISPLACEMENT.replace("end = 1.0 }", "end = 0.4 }"),
     ["load.harmonic.end", "0.4", "after load.harmonic.start"]),
    ("start-before-history", DISPLACEMENT.replace("start = 0.5", "start = -1.0"),
     ["load.harmonic.start", "-1", "first history time"]),
    ("unknown-harmonic-key", DISPLACEMENT.replace("end = 1.0 }", "end = 1.0, phase = 1.0 }"),
     ["load.harmonic.phase", "unknown"]),
    ("harmonic-not-a-table", '[load]\ncontrol = "displacement"\n' + HISTORY + "harmonic = 1.0\n",
     ["load.harmonic", "table"]),
    ("harmonic-without-history", '[load]\ncontrol = "displacement"\n' + HARMONIC,
     ["load.history", "(missing)", "base history"]),
    ("force-amplitude-pulls", FORCE.replace("amplitude = 0.1", "amplitude = 1.5"),
     ["load.harmonic.amplitude", "1.5", "smallest force", "cannot"]),
    ("impact-harmonic", '[load]\ncontrol = "impact"\nvelocity = 0.1\n' + HARMONIC,
     ["load.harmonic", "impact"]),
    ("zero-spring", SPRING.replace("spring_constant = 1.0e4", "spring_constant = 0.0"),
     ["load.spring_constant", "= 0", "> 0"]),
    ("negative-spring", SPRING.replace("spring_constant = 1.0e4", "spring_constant = -5.0"),
     ["load.spring_constant", "-5", "> 0"]),
    ("missing-spring", SPRING.replace("spring_constant = 1.0e4\n", ""),
     ["load.spring_constant", "(missing)", "spring"]),
    ("spring-without-spring-control", DISPLACEMENT + "spring_constant = 1.0e4\n",
     ["load.spring_constant", "only with control"]),
    ("spring-starts-pressed", SPRING.replace("[0.0, -1.0e-6]", "[0.0, 1.0e-6]"),
     ["load.history[0].z", "<= 0"]),
    ("spring-jump", SPRING.replace("[0.5, 2.0e-4], [1.0", "[0.5, 2.0e-4], [0.5, 1.0e-4], [1.0"),
     ["load.history[2].t", "must not jump"]),
]


def indenter_for(load: str) -> str:
    return '[indenter]\nshape = "sphere"\nR = 0.01\n' + ("mass = 0.01\n" if "impact" in load else "")


@pytest.mark.parametrize("load,fragments", [(c[1], c[2]) for c in BAD_CASES], ids=[c[0] for c in BAD_CASES])
def test_bad_normal_harmonic_input(run_case, load, fragments):
    assert_bad_input(run_case(case_text(load=load, indenter=indenter_for(load))), *fragments)


@pytest.mark.parametrize("load", [DISPLACEMENT, FORCE, SPRING + HARMONIC], ids=["displacement", "force", "spring"])
def test_harmonic_summary(run_case, load):
    result = run_case(case_text(load=load, numerics=""))
    assert result.returncode == 0, result.stderr
    summary = json.loads((result.out / "summary.json").read_text())
    for key in ("storage_stiffness", "loss_stiffness", "loss_tangent", "force_amplitude", "depth_amplitude",
                "normal_dissipated_energy_per_cycle"):
        assert summary[key] > 0.0, key
    assert summary["contact_loss_fraction"] == 0.0
    assert 0.0 < summary["phase_angle"] < 1.5708
    # The default step resolves the period: 200 steps per cycle.
    assert summary["time_step"] <= 1.0 / 20.0 / 200.0 * (1 + 1e-12)


def test_spring_columns(run_case):
    result = run_case(case_text(load=SPRING))
    assert result.returncode == 0, result.stderr
    with open(result.out / "history.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    assert list(rows[0].keys()) == ["t", "d", "F", "a", "z", "deflection"]
    assert float(rows[0]["z"]) == -1.0e-6 and float(rows[0]["d"]) == -1.0e-6
    k = 1.0e4
    for row in rows:
        assert float(row["F"]) == pytest.approx(k * float(row["deflection"]), rel=1e-9, abs=1e-12)
    summary = json.loads((result.out / "summary.json").read_text())
    assert summary["control"] == "spring"
