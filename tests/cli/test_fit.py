"""`mdr fit`: a material recovered from a curve made by a closed form (Hertz), the result directory of the spec,
a fitted case that runs, and bad fit input refused with one line and nothing written."""

from __future__ import annotations

import csv
import json
import math
import os
import pathlib
import random
import subprocess
import sys

import pytest

from test_bad_input import assert_bad_input

G_TRUE, R = 2.0e5, 5.0e-4         # Pa, m
CONTACT, BASELINE, NOISE = 1.0e-6, 3.0e-5, 2.0e-6   # m, N, N


def hertz_force(depth):
    """Hertz for an incompressible half-space: F = (16/3) G sqrt(R) d^1.5 (E* = 4G)."""
    return 16.0 / 3.0 * G_TRUE * math.sqrt(R) * max(depth, 0.0) ** 1.5


def write_curve(path, rows=300, noise=NOISE, seed=3):
    generator = random.Random(seed)
    with open(path, "w", newline="", encoding="utf-8") as handle:
        writer = csv.writer(handle)
        writer.writerow(["t", "depth_um", "force_uN"])
        for i in range(rows):
            t = 0.01 * i
            d = -2.0e-6 + 3.0e-8 * i  # from 2 um above the surface to 7 um into it
            writer.writerow([t, (d + CONTACT) * 1e6, (BASELINE + hertz_force(d) + generator.gauss(0.0, noise)) * 1e6])


CASE = """
[material]
model = "elastic"
G = 5.0e4
[indenter]
shape = "sphere"
R = 5.0e-4
[fit]
free = ["material.G"]
{extra}
[[fit.data]]
file = "curve.csv"
time = "t"
depth = "depth_um"
force = "force_uN"
units = {{ length = "um", force = "uN" }}
"""


@pytest.fixture
def fit_case(workdir):
    write_curve(workdir / "curve.csv")

    def make(extra=""):
        path = workdir / "case.toml"
        path.write_text(CASE.format(extra=extra), encoding="utf-8")
        return path

    return make


def test_recovers_the_modulus_and_writes_the_result_directory(run_mdr, fit_case, workdir):
    result = run_mdr("fit", fit_case(), "--out", workdir / "out", timeout=300)
    assert result.returncode == 0, result.stderr
    out = workdir / "out"
    summary = json.loads((out / "fit.json").read_text())
    for key in ("status", "parameters", "standard_errors", "correlation", "rms_residual", "noise", "aic", "bic",
                "evaluations", "wall_seconds"):
        assert key in summary, key
    assert summary["status"] == "converged"
    G, error = summary["parameters"]["material.G"], summary["standard_errors"]["material.G"]
    assert abs(G - G_TRUE) < 4.0 * error and error < 0.02 * G_TRUE
    # Young's modulus of the incompressible body, E = 2 (1 + 0.5) G, beside G (fit.json and the console).
    assert summary["young_moduli"] == {"material.G": pytest.approx(3.0 * G, rel=1e-15)}
    assert summary["young_moduli_errors"] == {"material.G": pytest.approx(3.0 * error, rel=1e-15)}
    assert "(E = " in result.stdout and "standard errors: " in result.stdout
    assert summary["misfit"] is False and summary["error_kind"] == "white noise (chi-square)"
    # A modulus, domain (0, inf): its interval on the log scale, G exp(-/+ t error / G), t ~ 1.97 for 300 rows.
    assert summary["interval_scales"] == {"material.G": "log"}
    lower, upper = summary["intervals_95"]["material.G"]
    assert math.sqrt(lower * upper) == pytest.approx(G, rel=1e-12)
    assert math.log(upper / G) == pytest.approx(1.97 * error / G, rel=0.01)
    curve = summary["curves"][0]
    assert abs(curve["contact_point"] - CONTACT) < 4.0 * curve["contact_point_error"] + 2e-8
    # The baseline is the mean of the rows before contact (the default "constant"; 66 rows before the contact, at
    # least 50 of them before the estimate's), not fitted: within 4 NOISE / sqrt(50) of the truth, with the error of
    # a mean of 50 to 66 rows (within the noise estimate's 20 %).
    assert abs(curve["baseline"] - BASELINE) < 4.0 * NOISE / math.sqrt(50)
    assert 0.8 * NOISE / math.sqrt(66) < curve["baseline_error"] < 1.2 * NOISE / math.sqrt(50)
    assert 0.8 < summary["rms_residual"] / NOISE < 1.2
    with open(out / "curves.csv", newline="", encoding="utf-8") as handle:
        rows = list(csv.DictReader(handle))
    assert list(rows[0]) == ["curve", "t", "measured", "model", "residual", "drive"]
    assert len(rows) == 300
    # fitted.toml runs as a case of its own: the first curve's history with the fitted modulus.
    again = run_mdr("run", out / "fitted.toml", "--out", workdir / "again")
    assert again.returncode == 0, again.stderr
    rerun = json.loads((workdir / "again" / "summary.json").read_text())
    assert rerun["max_force"] == pytest.approx(hertz_force(rerun["max_depth"]) * G / G_TRUE, rel=1e-3)
    # The identified material with its band (G +- 1.96 standard errors for an elastic body), and its figures.
    with open(out / "functions.csv", newline="", encoding="utf-8") as handle:
        functions = list(csv.DictReader(handle))
    assert list(functions[0]) == ["t", "G", "G_lower", "G_upper", "J", "J_lower", "J_upper"]
    assert float(functions[0]["G_upper"]) - float(functions[0]["G"]) == pytest.approx(1.96 * error, rel=1e-4)
    assert (out / "dynamic.csv").exists()
    assert plotted_figures(out) in (None, ["dynamic.png", "fit_curves.png", "force_indentation.png", "material.png"])


def plotted_figures(out):
    """The figures `python3 -m mdr plot OUT` writes, sorted; None in a build without the Python package (the
    sanitizer build)."""
    package = pathlib.Path(os.environ.get("MDR_PYTHONPATH", "/nonexistent"))
    if not (package / "mdr").is_dir():
        return None
    environment = dict(os.environ, PYTHONPATH=str(package), MPLBACKEND="Agg")
    plotted = subprocess.run([sys.executable, "-m", "mdr", "plot", str(out)], capture_output=True, text=True,
                             env=environment)
    assert plotted.returncode == 0, plotted.stderr
    return sorted(pathlib.Path(p).name for p in plotted.stdout.split())


def test_a_compressible_body_against_a_deformable_indenter_reports_no_young_modulus_and_says_why(run_mdr, fit_case,
                                                                                               workdir):
    # K = 2 G (nu = 0.2857, constant in time) against an elastic indenter: the contact's material is the pair's, so
    # E = 2 (1 + nu) G is not reported, and the flag names the deformable indenter, not a Poisson ratio that changes
    # with time (which this body's does not).
    path = fit_case()
    text = path.read_text(encoding="utf-8").replace("G = 5.0e4\n", "G = 5.0e4\nK = 1.0e5\n", 1)
    path.write_text(text.replace("R = 5.0e-4\n", "R = 5.0e-4\n[indenter.material]\nmodel = \"elastic\"\nG = 1.0e12\n"),
                    encoding="utf-8")
    result = run_mdr("fit", path, "--out", workdir / "out", timeout=300)
    assert result.returncode == 0, result.stderr
    summary = json.loads((workdir / "out" / "fit.json").read_text())
    assert summary["young_moduli"] == {}
    flags = [flag for flag in summary["flags"] if flag.startswith("young_moduli: not reported")]
    assert len(flags) == 1 and "deformable" in flags[0] and "changes with time" not in flags[0], summary["flags"]


@pytest.mark.parametrize("name", ['cell,1', 'a "quoted" name', "two\nlines", "plain"])
def test_curve_names_read_back_as_one_field(run_mdr, fit_case, workdir, name):
    """curves.csv is RFC 4180 CSV whatever the curve's name (issue 23): read with the csv module (and with
    mdr.plot.read_csv where the package is built), every row has the header's 5 fields and the name as given. A
    plain name is written as it is."""
    case = fit_case().read_text(encoding="utf-8").replace('file = "curve.csv"',
                                                          f'file = "curve.csv"\nname = {json.dumps(name)}')
    (workdir / "case.toml").write_text(case, encoding="utf-8")
    result = run_mdr("fit", workdir / "case.toml", "--out", workdir / "out", timeout=300)
    assert result.returncode == 0, result.stderr
    with open(workdir / "out" / "curves.csv", newline="", encoding="utf-8") as handle:
        rows = list(csv.reader(handle))
    assert rows[0] == ["curve", "t", "measured", "model", "residual", "drive"]
    assert len(rows) == 301 and all(len(row) == 6 and row[0] == name for row in rows[1:])
    if name == "plain":
        assert (workdir / "out" / "curves.csv").read_text(encoding="utf-8").splitlines()[1].startswith("plain,")
    package = pathlib.Path(os.environ.get("MDR_PYTHONPATH", "/nonexistent"))
    if (package / "mdr").is_dir():
        script = ("import sys, mdr.plot; c = mdr.plot.read_csv(sys.argv[1]); "
                  "print(len(c['curve']), set(c['curve'].tolist()) == {sys.argv[2]}, c['residual'].dtype.kind)")
        read = subprocess.run([sys.executable, "-c", script, str(workdir / "out" / "curves.csv"), name],
                              capture_output=True, text=True, timeout=120,
                              env=dict(os.environ, PYTHONPATH=str(package), MPLBACKEND="Agg"))
        assert read.stdout.split() == ["300", "True", "f"], read.stderr


@pytest.mark.parametrize("extra, fragments", [
    ('bounds = { "material.G" = [1.0e6, 1.0e3] }', ["fit.bounds.material.G", "lower bound"]),
    ('bounds = { "material.G" = [1.0e6, 1.0e7] }', ["material.G = 50000", "within its bounds"]),
    ('fitted = "stiffness"', ["fit.fitted", "one of force, depth"]),
    ("colour = 1", ["fit.colour", "unknown key"]),
    ('bounds = { contact_point = [1.0, 0.0] }', ["fit.bounds.contact_point = [1, 0]", "lower bound"]),
    ('contact_point = "estimate"\nbounds = { contact_point = [0.0, 1.0] }',
     ["fit.bounds.contact_point = [0, 1]", "a fitted contact point only"]),
    ('baseline = "tilted"', ["fit.baseline", "constant, line"]),
])
def test_bad_fit_settings(run_mdr, fit_case, workdir, extra, fragments):
    assert_bad_input(run_mdr("fit", fit_case(extra), "--out", workdir / "out"), *fragments)


def test_a_free_key_the_model_does_not_have(run_mdr, fit_case, workdir):
    path = fit_case()
    path.write_text(path.read_text().replace('free = ["material.G"]', 'free = ["material.tau1"]'))
    assert_bad_input(run_mdr("fit", path, "--out", workdir / "out"), "fit.free = material.tau1", "no number")


@pytest.mark.parametrize("edit, fragments", [
    (lambda rows: rows[5].__setitem__(2, "nan"), ["force", "finite"]),
    (lambda rows: rows[7].__setitem__(0, "0.01"), ["time", "increase strictly"]),
])
def test_bad_data(run_mdr, fit_case, workdir, edit, fragments):
    path = fit_case()
    with open(workdir / "curve.csv", newline="", encoding="utf-8") as handle:
        rows = list(csv.reader(handle))
    edit(rows)
    with open(workdir / "curve.csv", "w", newline="", encoding="utf-8") as handle:
        csv.writer(handle).writerows(rows)
    assert_bad_input(run_mdr("fit", path, "--out", workdir / "out"), "fit.data[0].", *fragments)


def message_of_data(run_mdr, fit_case, workdir, data: bytes, file="curve.csv"):
    """The one error line of a fit whose curve file holds `data` (the case names `file`)."""
    path = fit_case()
    path.write_text(path.read_text().replace('file = "curve.csv"', f"file = {json.dumps(file)}"))
    (workdir / "curve.csv").write_bytes(data)
    result = run_mdr("fit", path, "--out", workdir / "out")
    assert len(result.stderr_lines) == 1 and result.returncode == 2, result.stderr
    assert result.stdout == "" and not (workdir / "out").exists()
    return result.stderr_lines[0]


def test_values_from_a_curve_file_are_echoed_escaped_and_short(run_mdr, fit_case, workdir):
    """Issue 23: a cell with a terminal escape is shown escaped; a file with CR line ends (one line to the reader) or
    with a long first line is never echoed whole: at most 6 escaped names of at most 60 characters, then the count;
    a file that is not the expected CSV (a system file, say) shows no more than its first 60 characters."""
    cell = message_of_data(run_mdr, fit_case, workdir, b"t,depth_um,force_uN\n0,1,2\n0.1,2,\x1b[2J3\n")
    assert "\x1b" not in cell and '.force = \\x1b[2J3: in curve.csv, line 3, column "force_uN"' in cell
    rows = "".join(f"{i},{i},{i}\r" for i in range(300))  # one line of 301 * 2 commas: 603 fields
    cr = message_of_data(run_mdr, fit_case, workdir, ("t,depth_um,force_uN\r" + rows).encode())
    assert "its columns: t, depth_um, force_uN\\r0, 0, 0\\r1, 1, ... (603 in all)" in cr and len(cr) < 300
    secret = "root:x:0:0:root:/root:/bin/bash" * 10
    system = message_of_data(run_mdr, fit_case, workdir, (secret + "\nsecond line\n").encode())
    assert secret not in system and "second line" not in system and "(310 bytes)" in system and len(system) < 200


def test_a_symbolic_link_loop_is_told_as_such(run_mdr, fit_case, workdir):
    """Issue 23: the system's reason, not "no such file"."""
    (workdir / "loop.csv").symlink_to("loop.csv")
    line = message_of_data(run_mdr, fit_case, workdir, b"t\n", file="loop.csv")
    assert "loop.csv" in line and "too many levels of symbolic links" in line


def test_a_curve_that_never_makes_contact(run_mdr, fit_case, workdir):
    path = fit_case('fitted = "depth"\ncontact_point = "fixed"\nbaseline = "fixed"')
    with open(workdir / "curve.csv", "w", newline="", encoding="utf-8") as handle:
        writer = csv.writer(handle)
        writer.writerow(["t", "depth_um", "force_uN"])
        for i in range(50):
            writer.writerow([0.01 * i, -1.0, 0.0])
    assert_bad_input(run_mdr("fit", path, "--out", workdir / "out"), "never makes contact")


def test_ctrl_c_stops_a_fit_and_leaves_nothing(mdr_binary, fit_case, workdir):
    import signal
    import subprocess
    import time

    # Long model runs (the element model of a force-driven fit): the fit is stopped at the next one.
    path = fit_case('fitted = "depth"\nelements = 200000')
    process = subprocess.Popen([mdr_binary, "fit", str(path), "--out", str(workdir / "out")], cwd=workdir,
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    time.sleep(1.5)
    assert process.poll() is None, "the fit ended before it could be interrupted"
    interrupted_at = time.monotonic()
    process.send_signal(signal.SIGINT)
    stdout, stderr = process.communicate(timeout=60)
    assert time.monotonic() - interrupted_at < 10.0
    assert process.returncode == 128 + signal.SIGINT
    assert stderr.splitlines()[-1] == "mdr: interrupted; no result was written"
    assert stdout == ""
    assert sorted(p.name for p in workdir.iterdir()) == ["case.toml", "curve.csv"]


def rewrite_curve(workdir, edit):
    """Applies `edit` to the rows (lists of floats) of curve.csv, header kept."""
    with open(workdir / "curve.csv", newline="", encoding="utf-8") as handle:
        header, *rows = list(csv.reader(handle))
    numbers = [[float(value) for value in row] for row in rows]
    rows = edit(numbers) or numbers
    with open(workdir / "curve.csv", "w", newline="", encoding="utf-8") as handle:
        csv.writer(handle).writerows([header, *rows])


def set_value(row, column, value):
    def edit(rows):
        rows[row][column] = value
    return edit


# Data whose values the fit cannot weigh (once "converged" with an infinite residual and nulls in fit.json, or exit 1
# with glog's lines on stderr): refused naming the column and the line, nothing written.
@pytest.mark.parametrize("edit, fragments", [
    (set_value(150, 2, 1e308), ["fit.data[0].force", "line 152", "magnitude from 1e-100 to 1e+100"]),
    (lambda rows: [[t, d, f * 1e200] for t, d, f in rows], ["fit.data[0].force", "line 2", "magnitude"]),
    (lambda rows: [[t, d, 0.0] for t, d, _ in rows[:-1]] + [[rows[-1][0], rows[-1][1], 1.7976931348623157e308]],
     ["fit.data[0].force", "line 301", "magnitude"]),
    (set_value(150, 1, 1e308), ["fit.data[0].depth", "line 152", "magnitude"]),
    (lambda rows: [[t, d, 0.0] for t, d, _ in rows], ["fit.data[0].force = 0 in every row", "noise"]),
])
def test_data_the_fit_cannot_weigh(run_mdr, fit_case, workdir, edit, fragments):
    # A fitted baseline: the default ("constant") would refuse the force that is 0 in every row first, for having no
    # rows before contact (test_zero_force_has_no_rows_before_contact).
    path = fit_case('baseline = "fit"')
    rewrite_curve(workdir, edit)
    assert_bad_input(run_mdr("fit", path, "--out", workdir / "out"), *fragments)


def test_zero_force_has_no_rows_before_contact(run_mdr, fit_case, workdir):
    path = fit_case()
    rewrite_curve(workdir, lambda rows: [[t, d, 0.0] for t, d, _ in rows])
    assert_bad_input(run_mdr("fit", path, "--out", workdir / "out"), 'fit.baseline = "constant"',
                     "has no rows before contact", 'baseline = "fit"')


# Settings and values the fit cannot run with (once exit 0 or 1 with a wrong status, a raw glog line, "bad optional
# access" or "(missing)"): refused with the key and its rule, one stderr line, nothing written.
@pytest.mark.parametrize("edit, fragments", [
    (('[fit]', '[fit]\nmax_iterations = 2147483648'), ["fit.max_iterations = 2147483648", "from 1 to 1000000"]),
    (('[fit]', '[fit]\nelements = 1000000000\nfitted = "depth"'), ["fit.elements = 1000000000", "from 1 to"]),
    (('[fit]', '[fit]\nstart = { "material.G" = 0.0 }\nbounds = { "material.G" = [0.0, 1.0e6] }'),
     ["material.G = 0", "must be > 0", "start values"]),
    (('[fit]', '[fit]\nstart = { "material.G" = 9007199254740993 }'),
     ["fit.start.material.G = 9007199254740993", "cannot hold exactly"]),
    (('free = ["material.G"]', 'free = "material.G"'), ["fit.free", "must be an array of dotted keys"]),
    (('units = {', 'segment_column = "t"\nsegments = []\nunits = {'),
     ["fit.data[0].segments = []", "at least one segment"]),
    (('length = "um"', 'length = 1e308'), ["fit.data[0].units.length = 1e+308", "line 2", "magnitude"]),
    (('units = {', 'until = "never"\nunits = {'), ["fit.data[0].until = \"never\"", "one of pull_off, end"]),
    (('units = {', 'window = { time = [2.0, 1.0] }\nunits = {'),
     ["fit.data[0].window.time = [2, 1]", "lower end must be below"]),
    (('units = {', 'window = { speed = [0.0, 1.0] }\nunits = {'), ["fit.data[0].window.speed", "unknown key"]),
    (('units = {', 'window = { time = [0.0, 1.0e-9] }\nunits = {'),
     ["fit.data[0].window = 1 rows kept", "at least 10 rows"]),
    (('model = "elastic"\nG = 5.0e4', 'model = "kelvin_voigt"\nG = 5.0e4\neta = 5e-320'),
     ["material.eta = 5e-320", "subnormal"]),
    (('model = "elastic"\nG = 5.0e4', 'model = "standard"\nG_inf = 5.0e4\nG1 = 5e-324\ntau1 = 0.5'),
     ["material.G1 = 5e-324", "subnormal"]),
    # A bound where the material cannot be built (once met mid-solve: "the model cannot be evaluated", exit 1).
    (('[fit]', '[fit]\nbounds = { "material.G" = [-1.0e308, 1.0e6] }'),
     ["fit.bounds.material.G = [-1e+308, 1000000]", "cannot be built at the bound -1e+308", "must be > 0"]),
])
def test_fit_input_refused_with_its_key(run_mdr, fit_case, workdir, edit, fragments):
    path = fit_case()
    text = path.read_text()
    assert edit[0] in text
    text = text.replace(edit[0], edit[1], 1)
    path.write_text(text.replace('"material.G"]', '"material.G_inf"]') if "G_inf" in text else text)
    assert_bad_input(run_mdr("fit", path, "--out", workdir / "out"), *fragments)


@pytest.mark.parametrize("spring_constant, fragments", [
    ("1e308", ["fit.data[0].spring_constant = 1e+308", "line 2", "magnitude"]),
    ("1e-308", ["fit.data[0].spring_constant = 1e-308", "subnormal"]),
])
def test_a_spring_constant_the_fit_cannot_weigh(run_mdr, fit_case, workdir, spring_constant, fragments):
    path = fit_case()
    rewrite_curve(workdir, lambda rows: [[t, -d, f * 1e-3] for t, d, f in rows])  # piezo, deflection in um
    text = path.read_text().replace('depth = "depth_um"\nforce = "force_uN"',
                                    f'piezo = "depth_um"\ndeflection = "force_uN"\nspring_constant = {spring_constant}')
    path.write_text(text.replace(', force = "uN"', ""))
    assert_bad_input(run_mdr("fit", path, "--out", workdir / "out"), *fragments)


def test_a_depth_driven_curve_that_never_makes_contact(run_mdr, fit_case, workdir):
    """All depths negative with the contact point fixed at the data's zero: the docs promise a refusal. (A fitted
    baseline: the default "constant" would refuse the curve first, for having no contact estimate.)"""
    path = fit_case('contact_point = "fixed"\nbaseline = "fit"')
    rewrite_curve(workdir, lambda rows: [[t, -1.0 - 1e-3 * i, f] for i, (t, _, f) in enumerate(rows)])
    assert_bad_input(run_mdr("fit", path, "--out", workdir / "out"), "fit.data[0]", "never makes contact")
