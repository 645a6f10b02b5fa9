"""Oblique impact with spin (issue 13): the bad-input contract in the style of test_bad_input.py (exit status 2, one
stderr line naming the key, the value and the rule, no result directory), the history columns and summary keys,
and `mdr sweep` over the incidence angle and speed."""

from __future__ import annotations

import csv
import json
import math

import pytest

from test_bad_input import assert_bad_input, case_text

SPHERE = '[indenter]\nshape = "sphere"\nR = 0.01\nmass = 0.01\n'
IMPACT = '[load]\ncontrol = "impact"\nvelocity = 0.1\ntangential_velocity = 0.1\n'
FRICTION = '[tangential]\nfriction = 0.3\n'
NUMERICS = '[numerics]\nelements = 200\n'


def oblique_case(indenter=SPHERE, load=IMPACT, tangential=FRICTION, material=None, numerics=NUMERICS) -> str:
    sections = dict(indenter=indenter, load=load, numerics=numerics, extra=tangential)
    if material is not None:
        sections["material"] = material
    return case_text(**sections)


BAD_CASES = [
    ("negative-friction", oblique_case(tangential="[tangential]\nfriction = -0.2\n"),
     ["tangential.friction", "-0.2", ">= 0"]),
    ("missing-friction", oblique_case(tangential=""), ["tangential.friction", "(missing)", "oblique impact"]),
    ("friction-table-without-friction", oblique_case(tangential="[tangential]\n"),
     ["tangential.friction", "(missing)"]),
    ("zero-moment-of-inertia", oblique_case(indenter=SPHERE + "moment_of_inertia = 0.0\n"),
     ["indenter.moment_of_inertia", "0", "> 0"]),
    ("negative-moment-of-inertia", oblique_case(indenter=SPHERE + "moment_of_inertia = -1e-7\n"),
     ["indenter.moment_of_inertia", "-1e-07", "> 0"]),
    ("angle-90", oblique_case(load=IMPACT.replace("tangential_velocity = 0.1", "incidence_deg = 90.0")),
     ["load.incidence_deg", "90", "[0, 90)"]),
    ("angle-negative", oblique_case(load=IMPACT.replace("tangential_velocity = 0.1", "incidence_deg = -5.0")),
     ["load.incidence_deg", "-5", "[0, 90)"]),
    ("angle-and-velocity", oblique_case(load=IMPACT + "incidence_deg = 30.0\n"),
     ["load.incidence_deg", "30", "either"]),
    ("compressible", oblique_case(material='[material]\nmodel = "elastic"\nG = 1.0e6\nK = 3.0e6\n'),
     ["load.tangential_velocity", "0.1", "incompressible"]),
    ("two-bodies", oblique_case(indenter=SPHERE + '[indenter.material]\nmodel = "elastic"\nG = 1.0e9\n'),
     ["load.tangential_velocity", "0.1", "incompressible"]),
    ("cone", oblique_case(indenter='[indenter]\nshape = "cone"\nslope_deg = 10.0\nmass = 0.01\n'),
     ["indenter.shape", "cone", "sphere"]),
    ("tangential-velocity-without-impact",
     case_text(load='[load]\ncontrol = "displacement"\nhistory = [[0.0, 0.0], [1.0, 1e-4]]\n'
                    'tangential_velocity = 0.1\n', extra=FRICTION),
     ["load.tangential_velocity", "impact"]),
    ("history-with-impact", oblique_case(tangential=FRICTION + "history = [[0.0, 0.0], [1.0, 1e-6]]\n"),
     ["tangential.history", "not for an impact"]),
    ("nan-spin", oblique_case(load=IMPACT + "spin = nan\n"), ["load.spin", "nan"]),
]


@pytest.mark.parametrize("text,fragments", [c[1:] for c in BAD_CASES], ids=[c[0] for c in BAD_CASES])
def test_bad_oblique_input(run_case, text, fragments):
    assert_bad_input(run_case(text), *fragments)


@pytest.mark.parametrize("case_id", ["negative-friction", "compressible", "angle-90"])
def test_check_refuses_the_same_way(run_case, case_id):
    text, fragments = next(c[1:] for c in BAD_CASES if c[0] == case_id)
    assert_bad_input(run_case(text, command="check"), *fragments)


def test_columns_and_summary(run_case):
    result = run_case(oblique_case(load=IMPACT + "spin = 5.0\n"))
    assert result.returncode == 0, result.stderr
    with open(result.out / "history.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    assert list(rows[0]) == ["t", "d", "F", "a", "v", "u", "Fx", "c", "v_t", "omega"]
    assert float(rows[0]["v_t"]) == 0.1 and float(rows[0]["omega"]) == 5.0
    summary = json.loads((result.out / "summary.json").read_text())
    for key in ("restitution", "contact_time", "tangential_restitution", "rebound_tangential_velocity",
                "rebound_spin", "rebound_angle_deg", "impulse_ratio", "dissipated_energy_material",
                "dissipated_energy_friction", "max_tangential_force"):
        assert math.isfinite(summary[key]), key
    assert summary["slid_throughout"] in (True, False)
    # The friction force never exceeds mu times the normal force, so neither does the impulse.
    assert 0.0 < summary["impulse_ratio"] <= 0.3 * (1.0 + 1e-12)
    # The last row is the rebound.
    assert float(rows[-1]["v_t"]) == pytest.approx(summary["rebound_tangential_velocity"], rel=1e-12)
    assert float(rows[-1]["omega"]) == pytest.approx(summary["rebound_spin"], rel=1e-12)


def test_sweep_over_angle_and_speed(run_mdr, workdir):
    case = workdir / "case.toml"
    case.write_text(oblique_case(load='[load]\ncontrol = "impact"\nvelocity = 0.1\nincidence_deg = 10.0\n'),
                    encoding="utf-8")
    result = run_mdr("sweep", case, "--vary", "load.velocity=0.05,0.1", "--vary", "load.incidence_deg=0:80:5",
                     "--out", workdir / "out", "--jobs", "2")
    assert result.returncode == 0, result.stderr
    with open(workdir / "out" / "sweep.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    assert len(rows) == 10 and all(r["error"] == "" for r in rows)
    ratios = [float(r["impulse_ratio"]) for r in rows[:5]]
    # Head-on: no tangential impulse; steeper incidence: more, up to mu when the contact slides throughout.
    assert ratios[0] == 0.0
    assert ratios[0] < ratios[1] < ratios[2] < ratios[3] and ratios[3] == pytest.approx(ratios[4], rel=1e-9)
    assert ratios[-1] == pytest.approx(0.3, rel=1e-9)
