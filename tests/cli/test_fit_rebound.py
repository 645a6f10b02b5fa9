"""`mdr fit` with rebound data (`[[fit.data]] kind = "rebound"`): a standard solid recovered from e(v0) and T(v0)
made by the independent impact ODE, the result files' rebound rows, a fitted case that runs the first impact, and
bad rebound input refused with one line and nothing written."""

from __future__ import annotations

import csv
import json

import pytest

from test_bad_input import assert_bad_input
from test_fit import plotted_figures

G1_TRUE, TAU1_TRUE = 3.0e6, 1.0e-3   # Pa, s (G_inf = 1 MPa; sphere R = 10 mm, m = 10 g)
# v0 [m/s], e, T [ms]: tests/support/reference/impact_ode.hpp (sphere_impact_ting, 3D Lee-Radok loading and Ting
# unloading, e to ~1e-9) for that material and sphere, printed to 17 digits.
ORACLE = [
    (0.01, 0.46350225373785503, 4.2031936840719544),
    (0.025, 0.49280879724736437, 3.3525438785399593),
    (0.063, 0.52989496325044505, 2.7052631626027814),
    (0.16, 0.57156247077271038, 2.201352842638062),
    (0.4, 0.61411456549911214, 1.8101798037382471),
    (1.0, 0.65634187118429865, 1.4956086714586481),
]

CASE = """
[material]
model = "standard"
G_inf = 1.0e6
G1 = 1.0e6
tau1 = 3.0e-3
[indenter]
shape = "sphere"
R = 0.01
{mass}
[fit]
free = ["material.G1", "material.tau1"]
{extra}
[[fit.data]]
kind = "rebound"
file = "drops.csv"
velocity = "v0_m_s"
restitution = "e"
contact_time = "T_ms"
units = {{ time = "ms" }}
restitution_error = 1.0e-4
contact_time_error = 1.0e-4
{data}
"""


def write_drops(path, rows=ORACLE):
    with open(path, "w", newline="", encoding="utf-8") as handle:
        writer = csv.writer(handle)
        writer.writerow(["v0_m_s", "e", "T_ms"])
        writer.writerows(rows)


@pytest.fixture
def rebound_case(workdir):
    write_drops(workdir / "drops.csv")

    def make(mass="mass = 0.01", extra="", data=""):
        path = workdir / "case.toml"
        path.write_text(CASE.format(mass=mass, extra=extra, data=data), encoding="utf-8")
        return path

    return make


def test_recovers_a_standard_solid_from_rebounds(run_mdr, rebound_case, workdir):
    # The mass given with the data (and none in [indenter]): fitted.toml then carries it as indenter.mass.
    result = run_mdr("fit", rebound_case(mass="", data="mass = 0.01"), "--out", workdir / "out", timeout=300)
    assert result.returncode == 0, result.stderr
    out = workdir / "out"
    summary = json.loads((out / "fit.json").read_text())
    assert summary["status"] == "converged"
    # Noise-free data: limited by the impact model's accuracy at its fit resolution (e within ~4e-6).
    assert summary["parameters"]["material.G1"] == pytest.approx(G1_TRUE, rel=1e-3)
    assert summary["parameters"]["material.tau1"] == pytest.approx(TAU1_TRUE, rel=1e-3)
    assert summary["points"] == 12 and summary["undetermined"] == {}
    assert [(c["name"], c["kind"], c["fitted"], c["points"]) for c in summary["curves"]] == [
        ("drops", "rebound", "restitution", 6), ("drops", "rebound", "contact_time", 6)]
    assert summary["curves"][0]["mass"] == 0.01 and "contact_point" not in summary["curves"][0]
    with open(out / "curves.csv", newline="", encoding="utf-8") as handle:
        rows = list(csv.DictReader(handle))
    assert list(rows[0]) == ["curve", "t", "measured", "model", "residual", "drive"]
    assert [row["curve"] for row in rows] == ["drops:restitution"] * 6 + ["drops:contact_time"] * 6
    assert [float(row["t"]) for row in rows[:6]] == [v0 for v0, _, _ in ORACLE]  # t holds v0
    assert float(rows[6]["measured"]) == pytest.approx(ORACLE[0][2] * 1e-3, rel=1e-15)  # T in seconds
    # fitted.toml runs the first impact with the fitted material.
    again = run_mdr("run", out / "fitted.toml", "--out", workdir / "again")
    assert again.returncode == 0, again.stderr
    rerun = json.loads((workdir / "again" / "summary.json").read_text())
    assert rerun["restitution"] == pytest.approx(ORACLE[0][1], abs=1e-4)
    assert plotted_figures(out) in (None, ["dynamic.png", "fit_rebounds.png", "material.png"])


@pytest.mark.parametrize("edit, fragments", [
    (lambda rows: rows.__setitem__(2, (-0.025, *rows[2][1:])), ["fit.data[0].velocity = -0.025", "line 3", "> 0"]),
    (lambda rows: rows.__setitem__(3, (0.063, 1.2, 2.7)), ["fit.data[0].restitution = 1.2", "line 4", "[0, 1]"]),
    (lambda rows: rows.__setitem__(4, (0.16, -0.1, 2.2)), ["fit.data[0].restitution = -0.1", "[0, 1]"]),
    (lambda rows: rows.__setitem__(5, (0.4, "nan", 1.8)), ["fit.data[0].restitution", "finite"]),
    # Once "the model cannot be evaluated at the fitted values", exit 1 without a result (the fit fuzzer's find).
    (lambda rows: rows.__setitem__(3, (0.063, 0.53, 1e308)),
     ["fit.data[0].contact_time = 1e+305", "line 4", "from 1e-100 to 1e+100"]),
])
def test_bad_rebound_data(run_mdr, rebound_case, workdir, edit, fragments):
    path = rebound_case()
    rows = [("v0_m_s", "e", "T_ms"), *ORACLE]
    edit(rows)
    with open(workdir / "drops.csv", "w", newline="", encoding="utf-8") as handle:
        csv.writer(handle).writerows(rows)
    assert_bad_input(run_mdr("fit", path, "--out", workdir / "out"), *fragments)


@pytest.mark.parametrize("change, fragments", [
    (('restitution = "e"', 'restitution = "e_measured"'), ["fit.data[0].restitution", "no such column", "v0_m_s"]),
    (('velocity = "v0_m_s"\n', ""), ["fit.data[0].velocity", "(missing)"]),
    (("mass = 0.01\n", ""), ["fit.data[0].mass = (missing)", "indenter"]),
    # Once "bad optional access", exit 1 without a result (the fit fuzzer's find).
    (("mass = 0.01\n", "mass = 9223372036854775807\n"),
     ["indenter.mass = 9223372036854775807", "cannot hold exactly"]),
    (("restitution_error = 1.0e-4", "restitution_error = 0.0"), ["fit.data[0].restitution_error = 0", "> 0"]),
    (('contact_time = "T_ms"\n', ""), ["fit.data[0].contact_time_error", "only with contact_time"]),
    (('kind = "rebound"', 'kind = "bounce"'), ["fit.data[0].kind", "one of curve, rebound"]),
    (('velocity = "v0_m_s"', 'velocity = "v0_m_s"\ntime = "t"'), ["fit.data[0].time", "unknown key"]),
    (('free = ["material.G1", "material.tau1"]', 'candidates = ["standard"]'),
     ["fit.candidates", "not with rebound data"]),
])
def test_bad_rebound_tables(run_mdr, rebound_case, workdir, change, fragments):
    path = rebound_case()
    text = path.read_text()
    assert change[0] in text
    path.write_text(text.replace(change[0], change[1], 1))
    assert_bad_input(run_mdr("fit", path, "--out", workdir / "out"), *fragments)
