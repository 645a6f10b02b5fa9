"""`mdr fit` with `[[fit.data]] start = "preloaded"` (issue 24; docs/theory.md §4d): a record that starts at rest
under a relaxed preload, made here by an independent reference (the preloaded Lee-Radok integral by scipy
quadrature), gives back G_inf, G1, tau1 and the preload depth d_0 within their errors; the flag; bad input."""

from __future__ import annotations

import csv
import json
import math
import random

import pytest
from scipy import integrate

from test_bad_input import assert_bad_input

R = 5.0e-4                                     # m, sphere
G_INF, G1, TAU1 = 1.0e4, 2.0e4, 0.3            # Pa, Pa, s
CONTACT, PRELOAD, DEEPEST = 1.0e-6, 2.0e-6, 8.0e-6   # m: contact in the data's depth, d_0, deepest indentation
REST, RAMP, HOLD, STEP = 0.5, 1.0, 3.0, 0.01   # s
LEVEL, NOISE = 3.0e-5, 5.0e-8                  # N: the rest rows' force (baseline + preload force), force noise


def indentation(t):
    """d(t) below the contact: d_0 at rest until t = 0, a ramp to DEEPEST over RAMP, held after."""
    return PRELOAD + (DEEPEST - PRELOAD) * min(max(t, 0.0), RAMP) / RAMP


def preloaded_force_change(t):
    """F(t) - G_inf F_el(d_0) = int_0^t G(t - s) dF_el(d(s)) (every branch relaxed under d_0 at t = 0), with the
    Hertz force of an incompressible half-space per unit shear modulus F_el(d) = (16/3) sqrt(R) d^1.5, so
    dF_el = 8 sqrt(R d) d'(s) ds, and G(t) = G_inf + G1 exp(-t / tau1): by adaptive quadrature."""
    if t <= 0.0:
        return 0.0
    rate = (DEEPEST - PRELOAD) / RAMP

    def integrand(s):
        relaxation = G_INF + G1 * math.exp(-(t - s) / TAU1)
        return relaxation * 8.0 * math.sqrt(R * indentation(s)) * rate

    value, _ = integrate.quad(integrand, 0.0, min(t, RAMP), epsabs=0.0, epsrel=1e-11, limit=200)
    return value


def write_record(path, seed=5):
    generator = random.Random(seed)
    with open(path, "w", newline="", encoding="utf-8") as handle:
        writer = csv.writer(handle)
        writer.writerow(["t", "depth", "force"])
        rows = int(round((REST + RAMP + HOLD) / STEP)) + 1
        for i in range(rows):
            t = -REST + STEP * i
            force = LEVEL + preloaded_force_change(t) + generator.gauss(0.0, NOISE)
            writer.writerow([f"{t:.6f}", f"{CONTACT + indentation(t):.12e}", f"{force:.12e}"])


CASE = """
[material]
model = "standard"
G_inf = 5.0e3
G1 = 1.0e4
tau1 = 0.1
[indenter]
shape = "sphere"
R = 5.0e-4
[fit]
free = ["material.G_inf", "material.G1", "material.tau1"]
[[fit.data]]
file = "record.csv"
time = "t"
depth = "depth"
force = "force"
start = "{start}"
"""


def test_recovers_the_material_and_the_preload_depth(run_mdr, workdir):
    write_record(workdir / "record.csv")
    (workdir / "case.toml").write_text(CASE.format(start="preloaded"), encoding="utf-8")
    result = run_mdr("fit", workdir / "case.toml", "--out", workdir / "out", timeout=300)
    assert result.returncode == 0, result.stderr
    summary = json.loads((workdir / "out" / "fit.json").read_text())
    assert summary["status"].startswith("converged"), summary["status"]
    values, errors = summary["parameters"], summary["standard_errors"]
    for key, truth in (("material.G_inf", G_INF), ("material.G1", G1), ("material.tau1", TAU1)):
        assert abs(values[key] - truth) < 4.0 * errors[key], (key, values[key], errors[key])
        assert errors[key] < 0.02 * truth, (key, errors[key])
    curve = summary["curves"][0]
    assert curve["start"] == "preloaded"
    assert abs(curve["preload_depth"] - PRELOAD) < 4.0 * curve["preload_depth_error"], curve
    assert curve["preload_depth_error"] < 0.02 * PRELOAD
    assert abs(curve["contact_point"] + curve["preload_depth"] - (CONTACT + PRELOAD)) < 1e-12
    assert summary["rms_residual"] < 1.5 * NOISE
    assert any("modelled as a relaxed preload" in flag for flag in curve["flags"]), curve["flags"]


def test_the_at_rest_model_cannot_follow_a_preloaded_record(run_mdr, workdir):
    # The same record with the default start: the model starts unloaded, the residual is far above the noise.
    write_record(workdir / "record.csv")
    (workdir / "case.toml").write_text(CASE.format(start="at_rest"), encoding="utf-8")
    result = run_mdr("fit", workdir / "case.toml", "--out", workdir / "out", timeout=300)
    assert result.returncode == 0, result.stderr
    summary = json.loads((workdir / "out" / "fit.json").read_text())
    curve = summary["curves"][0]
    assert curve["start"] == "at_rest" and "preload_depth" not in curve
    assert summary["rms_residual"] > 5.0 * NOISE
    assert any("start = \"preloaded\" models one" in flag for flag in curve["flags"]), curve["flags"]


@pytest.mark.parametrize("start, extra, fragments", [
    ("loaded", "", ("fit.data[0].start = \"loaded\"", "one of at_rest, preloaded")),
    ("preloaded", "contact_point = \"estimate\"\n",
     ("start = \"preloaded\"", "needs fit.contact_point = \"fit\"")),
    ("preloaded", "fitted = \"depth\"\n", ("fit.data[0].start = \"preloaded\"", "needs a depth-driven curve")),
    ("preloaded", "bounds = { contact_point = [4.0e-6, 6.0e-6] }\n",
     ("fit.bounds.contact_point = 4e-06", "must be below the first depth 3e-06")),
])
def test_bad_preload_input_is_refused(run_mdr, workdir, start, extra, fragments):
    write_record(workdir / "record.csv")
    text = CASE.format(start=start).replace("[fit]\n", "[fit]\n" + extra)
    (workdir / "case.toml").write_text(text, encoding="utf-8")
    assert_bad_input(run_mdr("fit", workdir / "case.toml", "--out", workdir / "out"), *fragments)


def test_a_preload_on_a_thick_layer_is_the_half_space_preload(run_mdr, workdir):
    # A [layer] of 1 m under this 63 um contact: its kernel vanishes (docs/theory.md eq. L4), so the preloaded layer
    # model (eq. L21) fits the half-space reference back as the half-space model does.
    write_record(workdir / "record.csv")
    layer = '[layer]\nthickness = 1.0\ninterface = "bonded"\n\n'
    (workdir / "case.toml").write_text(CASE.format(start="preloaded").replace("[fit]\n", layer + "[fit]\n"),
                                       encoding="utf-8")
    result = run_mdr("fit", workdir / "case.toml", "--out", workdir / "out", timeout=300)
    assert result.returncode == 0, result.stderr
    summary = json.loads((workdir / "out" / "fit.json").read_text())
    assert summary["status"].startswith("converged"), summary["status"]
    values, errors = summary["parameters"], summary["standard_errors"]
    for key, truth in (("material.G_inf", G_INF), ("material.G1", G1), ("material.tau1", TAU1)):
        assert abs(values[key] - truth) < 4.0 * errors[key], (key, values[key], errors[key])
    curve = summary["curves"][0]
    assert curve["start"] == "preloaded"
    assert abs(curve["preload_depth"] - PRELOAD) < 4.0 * curve["preload_depth_error"], curve
    assert summary["rms_residual"] < 1.5 * NOISE


def test_a_preload_on_a_layer_whose_contact_grows_again_is_refused(run_mdr, workdir):
    # The depth falls by 10 % of its range in the hold and rises again: outside Ting's class, where the preloaded
    # layer model (eq. L21) holds; the path beyond it starts unloaded, so the preload is refused naming its key.
    write_record(workdir / "record.csv")
    lines = (workdir / "record.csv").read_text(encoding="utf-8").splitlines()
    for index in range(300, 320):
        row = lines[index].split(",")
        row[1] = repr(float(row[1]) - 0.1 * (DEEPEST - PRELOAD))
        lines[index] = ",".join(row)
    (workdir / "record.csv").write_text("\n".join(lines) + "\n", encoding="utf-8")
    layer = '[layer]\nthickness = 2.0e-5\ninterface = "bonded"\n\n'
    text = CASE.format(start="preloaded").replace("[fit]\n", layer + "[fit]\n")
    (workdir / "case.toml").write_text(text, encoding="utf-8")
    assert_bad_input(run_mdr("fit", workdir / "case.toml", "--out", workdir / "out"),
                     'fit.data.start = "preloaded"', "would grow again after it shrank")


def test_a_preload_the_band_model_cannot_run_is_refused(run_mdr, workdir):
    # A Maxwell material (G_inf = 0) and a depth that dips once (outside the continuum model): no state at rest under
    # a preload (the drivers' elements start unloaded), so the preloaded curve is refused naming the key and the rule.
    write_record(workdir / "record.csv")
    lines = (workdir / "record.csv").read_text(encoding="utf-8").splitlines()
    row = lines[300].split(",")
    row[1] = repr(float(row[1]) - 1e-8)
    lines[300] = ",".join(row)
    (workdir / "record.csv").write_text("\n".join(lines) + "\n", encoding="utf-8")
    text = (CASE.format(start="preloaded").replace('model = "standard"', 'model = "maxwell"')
            .replace("G_inf = 5.0e3\n", "").replace("G1 = 1.0e4", "G = 1.0e4").replace("tau1 = 0.1", "tau = 0.1")
            .replace('["material.G_inf", "material.G1", "material.tau1"]', '["material.G", "material.tau"]'))
    (workdir / "case.toml").write_text(text, encoding="utf-8")
    assert_bad_input(run_mdr("fit", workdir / "case.toml", "--out", workdir / "out"),
                     'fit.data[0].start = "preloaded"', "equilibrium modulus G_inf > 0",
                     "the material has equilibrium modulus 0")


STANDARD = "model = \"standard\"\nG_inf = 5.0e3\nG1 = 1.0e4\ntau1 = 0.1\n"
FREE = "free = [\"material.G_inf\", \"material.G1\", \"material.tau1\"]\n"


@pytest.mark.parametrize("command", ["check", "fit"])
def test_a_material_that_relaxes_to_zero_cannot_start_preloaded(run_mdr, workdir, command):
    # A power law relaxes to 0 (no equilibrium modulus): no state at rest under a preload. `mdr check` said "ok" and
    # `mdr fit` refused it only when its model first ran; both refuse it now, naming the key and the material's G_inf.
    write_record(workdir / "record.csv")
    text = CASE.format(start="preloaded").replace(STANDARD, "model = \"power_law\"\nG0 = 1.0e4\nbeta = 0.3\n")
    (workdir / "case.toml").write_text(text.replace(FREE, "free = [\"material.G0\", \"material.beta\"]\n"),
                                       encoding="utf-8")
    extra = ("--out", workdir / "out") if command == "fit" else ()
    assert_bad_input(run_mdr(command, workdir / "case.toml", *extra), "fit.data[0].start = \"preloaded\"",
                     "equilibrium modulus G_inf > 0", "the material has equilibrium modulus 0")


def test_a_candidate_that_cannot_start_preloaded_is_named(run_mdr, workdir):
    write_record(workdir / "record.csv")
    text = CASE.format(start="preloaded").replace(FREE, "candidates = [\"standard\", \"power_law\"]\n")
    (workdir / "case.toml").write_text(text, encoding="utf-8")
    assert_bad_input(run_mdr("fit", workdir / "case.toml", "--out", workdir / "out", timeout=300),
                     "fit.data[0].start = \"preloaded\"", "equilibrium modulus 0", "(candidate power_law)")
