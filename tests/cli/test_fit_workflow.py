"""Issue 24, part C: units cannot slip (the spring constant's unit is stated wherever the case's force / length is
not N/m), `mdr check` validates fit cases, `mdr fit` reports progress, `mdr fit --each` fits one material per
file. Curves from closed forms (Hertz), never from mdr."""

from __future__ import annotations

import csv
import math
import random
import subprocess
import time

import pytest

from test_bad_input import assert_bad_input

# Hertz in um-nN-s: G in kPa, R and depths in um, forces in nN; F = (16/3) G sqrt(R) d^1.5 (E* = 4G, nu = 0.5).
G_TRUE, R, K_N_PER_M = 0.2, 5.0, 0.05   # kPa, um, N/m (= 50 nN/um)
K_CASE = K_N_PER_M * 1e3                # nN/um


def hertz(indentation):
    return 16.0 / 3.0 * G_TRUE * math.sqrt(R) * max(indentation, 0.0) ** 1.5


def write_afm_curve(path, contact=1.0, seed=5, rows=300):
    """Raw AFM columns in um: the tip height (piezo + deflection) falls by the indentation, the cantilever bends by
    F / k; contact `contact` um after the first row."""
    generator = random.Random(seed)
    with open(path, "w", newline="", encoding="utf-8") as handle:
        writer = csv.writer(handle)
        writer.writerow(["t", "piezo", "defl"])
        for i in range(rows):
            t = i / (rows - 1)
            depth = -contact + (contact + 3.0) * t
            deflection = (hertz(depth) + generator.gauss(0.0, 0.002)) / K_CASE
            writer.writerow([t, 10.0 - depth - deflection, deflection])


def write_hertz_curve(path, contact=1.0, seed=5, rows=300):
    """depth and force columns (um, nN), contact `contact` um after the first row."""
    generator = random.Random(seed)
    with open(path, "w", newline="", encoding="utf-8") as handle:
        writer = csv.writer(handle)
        writer.writerow(["t", "d", "F"])
        for i in range(rows):
            t = i / (rows - 1)
            depth = -contact + (contact + 3.0) * t
            writer.writerow([t, depth + contact, hertz(depth) + generator.gauss(0.0, 0.002)])


AFM_CASE = """
units = "um-nN-s"
[material]
model = "elastic"
G = 0.05
[indenter]
shape = "sphere"
R = 5.0
[fit]
free = ["material.G"]
{fit}
[[fit.data]]
file = "afm.csv"
time = "t"
piezo = "piezo"
deflection = "defl"
{data}
"""


def write_case(workdir, data, fit="", name="case.toml"):
    path = workdir / name
    path.write_text(AFM_CASE.format(data=data, fit=fit), encoding="utf-8")
    return path


def fitted_modulus(run_mdr, path, workdir):
    result = run_mdr("fit", path, "--out", workdir / "out", timeout=300)
    assert result.returncode == 0, result.stderr
    import json
    return json.loads((workdir / "out" / "fit.json").read_text())["parameters"]["material.G"]


@pytest.mark.parametrize("data", [
    f'spring_constant = {K_N_PER_M}\nunits = {{ spring_constant = "N/m" }}',
    f'spring_constant = {K_CASE}\nunits = {{ spring_constant = "nN/um" }}',
    f'spring_constant = {K_CASE * 1e3}\nunits = {{ spring_constant = "pN/um" }}',
])
def test_a_stated_spring_constant_unit_gives_the_true_modulus(run_mdr, workdir, data):
    write_afm_curve(workdir / "afm.csv")
    G = fitted_modulus(run_mdr, write_case(workdir, data), workdir)
    assert G == pytest.approx(G_TRUE, rel=0.02)


def test_a_bare_spring_constant_in_a_non_si_case_is_refused(run_mdr, workdir):
    """0.05 reads as N/m to an AFM user and as nN/um to a um-nN-s case (1000x apart): the unit must be stated."""
    write_afm_curve(workdir / "afm.csv")
    path = write_case(workdir, f"spring_constant = {K_N_PER_M}")
    assert_bad_input(run_mdr("fit", path, "--out", workdir / "out"), "fit.data[0].spring_constant = 0.05",
                     "um-nN-s", 'fit.data[0].units.spring_constant = "N/m"', '"nN/um"')
    path = write_case(workdir, f'spring_constant = {K_N_PER_M}\nunits = {{ spring_constant = "N/cm2" }}')
    assert_bad_input(run_mdr("fit", path, "--out", workdir / "out"), 'fit.data[0].units.spring_constant = "N/cm2"',
                     "force / length")
    path = write_case(workdir, f"spring_constant = {K_N_PER_M}\nunits = {{ spring_constant = 1.0 }}")
    assert_bad_input(run_mdr("fit", path, "--out", workdir / "out"), "fit.data[0].units.spring_constant = 1",
                     "string")


def test_an_si_case_keeps_its_spring_constant_in_n_per_m(run_mdr, workdir):
    """SI cases are unchanged: N/m is the case's force / length, no unit needed (the same curve in m and N)."""
    write_afm_curve(workdir / "afm.csv")
    with open(workdir / "afm.csv", newline="", encoding="utf-8") as handle:
        header, *rows = list(csv.reader(handle))
    with open(workdir / "afm.csv", "w", newline="", encoding="utf-8") as handle:
        csv.writer(handle).writerows([header, *[[t, float(p) * 1e-6, float(d) * 1e-6] for t, p, d in rows]])
    text = AFM_CASE.format(data=f"spring_constant = {K_N_PER_M}", fit="").replace('units = "um-nN-s"', "")
    (workdir / "case.toml").write_text(text.replace("G = 0.05", "G = 50.0").replace("R = 5.0", "R = 5e-6"))
    assert fitted_modulus(run_mdr, workdir / "case.toml", workdir) == pytest.approx(G_TRUE * 1e3, rel=0.02)


def test_check_validates_a_fit_case_with_its_curves(run_mdr, workdir):
    write_afm_curve(workdir / "afm.csv")
    path = write_case(workdir, f'spring_constant = {K_CASE}\nunits = {{ spring_constant = "nN/um" }}')
    result = run_mdr("check", path)
    assert result.returncode == 0, result.stderr
    assert result.stdout.strip() == ("ok: fit case: 1 free parameter(s) (material.G), 1 curve(s) of 300 points, "
                                     "0 rebound data set(s)")
    # Its bad input is refused as mdr fit refuses it: a column the file lacks, the spring constant's unit.
    assert_bad_input(run_mdr("check", write_case(workdir, f"spring_constant = {K_CASE}")),
                     "fit.data[0].spring_constant")
    bad = write_case(workdir, f'spring_constant = {K_CASE}\nunits = {{ spring_constant = "nN/um" }}')
    bad.write_text(bad.read_text().replace('deflection = "defl"', 'deflection = "deflection"'))
    assert_bad_input(run_mdr("check", bad), "deflection", "defl")
    candidates = write_case(workdir, f'spring_constant = {K_CASE}\nunits = {{ spring_constant = "nN/um" }}')
    text = candidates.read_text().replace('free = ["material.G"]', 'candidates = ["elastic", "standard"]')
    candidates.write_text(text)
    result = run_mdr("check", candidates)
    assert result.returncode == 0, result.stderr
    assert result.stdout.strip().endswith("; candidates elastic, standard")


def test_check_of_a_fractional_model_at_its_default_bounds_takes_seconds(run_mdr, workdir):
    """`mdr check` builds the model at every bound of fit.free; a fractional model's default alpha bounds (start/1e4
    and 1 - 3e-5) made its Mittag-Leffler certificate take minutes (the quadrature's spacing shrank with the strip
    of analyticity). Now well within run_mdr's 60 s (observed 0.3 s), and the bounds are still checked: one that the
    model refuses is named."""
    write_afm_curve(workdir / "afm.csv")
    path = write_case(workdir, f'spring_constant = {K_CASE}\nunits = {{ spring_constant = "nN/um" }}')
    text = path.read_text().replace('model = "elastic"\nG = 0.05',
                                    'model = "fractional_standard"\nG_inf = 0.05\nG1 = 0.1\nc = 0.02\nalpha = 0.7')
    path.write_text(text.replace('free = ["material.G"]',
                                 'free = ["material.G_inf", "material.G1", "material.c", "material.alpha"]'))
    started = time.monotonic()
    result = run_mdr("check", path)
    assert result.returncode == 0, result.stderr
    assert result.stdout.startswith("ok: fit case: 4 free parameter(s)")
    assert time.monotonic() - started < 30.0
    path.write_text(path.read_text().replace('[fit]\n', '[fit]\nbounds = { "material.alpha" = [0.1, 1.2] }\n'))
    assert_bad_input(run_mdr("check", path), "fit.bounds.material.alpha", "1.2")


def test_fit_reports_its_iterations_on_stderr(mdr_binary, workdir):
    """A slow fit (a force-driven curve of a material with a dashpot on many elements: no band model, every run on
    the elements) prints "mdr: fit iteration N, chi^2 = X, T s so far" every 5 s when stderr is a pipe, like mdr
    run's progress."""
    import signal
    write_hertz_curve(workdir / "hertz.csv")
    case = AFM_CASE.format(data="", fit='fitted = "depth"\nelements = 100000')
    case = case.replace('piezo = "piezo"\ndeflection = "defl"', 'depth = "d"\nforce = "F"')
    case = case.replace('model = "elastic"\nG = 0.05', 'model = "kelvin_voigt"\nG = 0.05\neta = 1e-4')
    (workdir / "case.toml").write_text(case.replace("afm.csv", "hertz.csv"))
    process = subprocess.Popen([mdr_binary, "fit", "case.toml", "--out", "out"], cwd=workdir,
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    start = time.monotonic()
    line = process.stderr.readline()
    elapsed = time.monotonic() - start
    process.send_signal(signal.SIGINT)
    process.communicate(timeout=60)
    assert line.startswith("mdr: fit iteration "), line
    fields = line.split()
    assert fields[4] == "chi^2" and float(fields[6].rstrip(",")) > 0.0 and line.rstrip().endswith("s so far")
    assert 4.5 < elapsed < 30.0


def test_each_labels_its_progress_lines_with_the_file(mdr_binary, workdir):
    """`mdr fit --each`: the progress lines say which file they belong to, "mdr: [1/2 cell-a.csv] fit iteration N,
    ..." (they did not: a batch's lines were those of one fit). The slow fit of
    test_fit_reports_its_iterations_on_stderr, its first line (the second file's would need the first fit's end,
    about a minute here: fit_each.cpp labels each file alike)."""
    import signal
    write_hertz_curve(workdir / "cell-a.csv")
    write_hertz_curve(workdir / "cell-b.csv", seed=6)
    case = AFM_CASE.format(data="", fit='fitted = "depth"\nelements = 100000')
    case = case.replace('piezo = "piezo"\ndeflection = "defl"', 'depth = "d"\nforce = "F"')
    case = case.replace('model = "elastic"\nG = 0.05', 'model = "kelvin_voigt"\nG = 0.05\neta = 1e-4')
    (workdir / "case.toml").write_text(case.replace("afm.csv", "cell-a.csv"))
    process = subprocess.Popen([mdr_binary, "fit", "case.toml", "--each", "cell-a.csv", "cell-b.csv", "--out", "out"],
                               cwd=workdir, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    line = process.stderr.readline()
    process.send_signal(signal.SIGINT)
    process.communicate(timeout=60)
    assert line.startswith("mdr: [1/2 cell-a.csv] fit iteration "), line
    assert line.rstrip().endswith("s so far")


def test_candidates_label_their_progress_lines_with_the_model(mdr_binary, workdir):
    """`fit.candidates`: the progress lines say which candidate's fit they belong to, "mdr: [kelvin_voigt] fit
    iteration N, ..." (they did not: the lines of the elastic reference and of every candidate read alike). The slow
    fit of test_fit_reports_its_iterations_on_stderr as a choice between the elastic model and Kelvin-Voigt: the
    first line, 5 s in, belongs to one of the two."""
    import signal
    write_hertz_curve(workdir / "hertz.csv")
    case = AFM_CASE.format(data="", fit='fitted = "depth"\nelements = 100000\ncandidates = ["elastic", "kelvin_voigt"]')
    case = case.replace('piezo = "piezo"\ndeflection = "defl"', 'depth = "d"\nforce = "F"')
    case = case.replace('model = "elastic"\nG = 0.05', 'model = "kelvin_voigt"\nG = 0.05\neta = 1e-4')
    case = case.replace('free = ["material.G"]\n', "")  # the candidates free the material's keys
    (workdir / "case.toml").write_text(case.replace("afm.csv", "hertz.csv"))
    process = subprocess.Popen([mdr_binary, "fit", "case.toml", "--out", "out"], cwd=workdir,
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    line = process.stderr.readline()
    process.send_signal(signal.SIGINT)
    process.communicate(timeout=60)
    assert line.startswith(("mdr: [elastic] fit iteration ", "mdr: [kelvin_voigt] fit iteration ")), line
    assert line.rstrip().endswith("s so far")


def test_each_fits_one_material_per_file(run_mdr, workdir):
    for name, contact, seed in (("cell-a", 1.0, 1), ("cell-b", 1.5, 2)):
        write_afm_curve(workdir / f"{name}.csv", contact=contact, seed=seed)
    write_afm_curve(workdir / "afm.csv")
    path = write_case(workdir, f'spring_constant = {K_CASE}\nunits = {{ spring_constant = "nN/um" }}')
    result = run_mdr("fit", path, "--each", "cell-a.csv", "cell-b.csv", "--out", workdir / "out", timeout=300)
    assert result.returncode == 0, result.stderr
    with open(workdir / "out" / "each.csv", newline="", encoding="utf-8") as handle:
        rows = list(csv.DictReader(handle))
    assert list(rows[0]) == ["file", "material.G", "material.G_stderr", "E_material.G", "E_material.G_stderr",
                             "status", "residual_to_noise"]
    assert [row["file"] for row in rows] == ["cell-a", "cell-b"]
    import json
    for row, contact in zip(rows, (1.0, 1.5)):
        assert float(row["material.G"]) == pytest.approx(G_TRUE, rel=0.02)
        # Young's modulus beside G, as fit.json and map.csv have it: E = 2 (1 + nu) G, nu = 0.5 (incompressible).
        assert float(row["E_material.G"]) == pytest.approx(3.0 * float(row["material.G"]), rel=1e-12)
        assert float(row["E_material.G_stderr"]) == pytest.approx(3.0 * float(row["material.G_stderr"]), rel=1e-12)
        assert f"{row['file']}:  material.G = " in result.stdout and "(E = " in result.stdout
        assert row["status"] == "converged" and 0.7 < float(row["residual_to_noise"]) < 1.3
        summary = json.loads((workdir / "out" / row["file"] / "fit.json").read_text())
        assert summary["parameters"]["material.G"] == float(row["material.G"])
        assert summary["curves"][0]["name"] == row["file"]
        # Tip height at the first row is 10 um; contact `contact` um below it: the data's depth of contact.
        assert summary["curves"][0]["contact_point"] == pytest.approx(contact, abs=0.05)
    # Bad input in any file: refused before the first fit, nothing written.
    (workdir / "bad.csv").write_text("t,piezo\n0,1\n")
    assert_bad_input(run_mdr("fit", path, "--each", "cell-a.csv", "bad.csv", "--out", workdir / "new",
                             out=workdir / "new"),
                     "bad.csv", "defl")
    assert_bad_input(run_mdr("fit", path, "--each", "cell-a.csv", "sub/cell-a.csv", "--out", workdir / "new",
                             out=workdir / "new"),
                     "--each = sub/cell-a.csv", "cell-a")
    two = path.read_text() + '\n[[fit.data]]\nfile = "afm.csv"\ntime = "t"\npiezo = "piezo"\ndeflection = "defl"\n'
    (workdir / "two.toml").write_text(two + f'spring_constant = {K_CASE}\nunits = {{ spring_constant = "nN/um" }}\n')
    assert_bad_input(run_mdr("fit", workdir / "two.toml", "--each", "cell-a.csv", "--out", workdir / "new",
                             out=workdir / "new"),
                     "--each", "exactly one [[fit.data]]")


def fit_flags(run_mdr, workdir, case_text):
    import json
    (workdir / "case.toml").write_text(case_text)
    result = run_mdr("fit", workdir / "case.toml", "--out", workdir / "out", timeout=300)
    assert result.returncode in (0, 1), result.stderr
    summary = json.loads((workdir / "out" / "fit.json").read_text())
    return summary["flags"], summary["curves"][0]["flags"], result.stdout


DEPTH_CASE = AFM_CASE.replace('piezo = "piezo"\ndeflection = "defl"', 'depth = "d"\nforce = "F"').replace(
    "afm.csv", "hertz.csv")


def test_lengths_in_another_unit_than_the_case_are_flagged(run_mdr, workdir):
    """The issue's trap: a um-nN-s case whose file holds metres and leaves out units.length reads 4e-6 m as 4e-6 um,
    1e-6 of the tip's radius: flagged on the curve, naming the key to set."""
    write_hertz_curve(workdir / "hertz.csv")
    with open(workdir / "hertz.csv", newline="", encoding="utf-8") as handle:
        header, *rows = list(csv.reader(handle))
    with open(workdir / "hertz.csv", "w", newline="", encoding="utf-8") as handle:
        csv.writer(handle).writerows([header, *[[t, float(d) * 1e-6, f] for t, d, f in rows]])
    _, curve_flags, stdout = fit_flags(run_mdr, workdir, DEPTH_CASE.format(data="", fit=""))
    # Among the curve's flags (the misfit and contact flags of such a fit come too): the unit's, naming the key.
    unit_flags = [flag for flag in curve_flags if "below 0.0001 of the sphere's R = 5 µm" in flag]
    assert len(unit_flags) == 1 and "units.length" in unit_flags[0] and "flag (hertz)" in stdout
    # The same file with its unit stated: no flag, the true modulus.
    _, curve_flags, _ = fit_flags(run_mdr, workdir, DEPTH_CASE.format(data='units = { length = "m" }', fit=""))
    assert curve_flags == []


def test_a_curve_name_with_control_characters_is_shown_escaped_in_the_flag_lines(run_mdr, workdir):
    """A curve's name is the user's text: a TOML escape puts an ANSI colour sequence (ESC) or a NUL in it. The flag
    lines on stdout show it as a message shows a text from the input (include/mdr/error.hpp, message_text: `\\x1b`);
    fit.json keeps it exactly. Found by the fit fuzzer (tests/fuzz/findings/control_byte_in_curve_name_stdout)."""
    write_hertz_curve(workdir / "hertz.csv")
    with open(workdir / "hertz.csv", newline="", encoding="utf-8") as handle:
        header, *rows = list(csv.reader(handle))
    with open(workdir / "hertz.csv", "w", newline="", encoding="utf-8") as handle:   # metres: the unit flag
        csv.writer(handle).writerows([header, *[[t, float(d) * 1e-6, f] for t, d, f in rows]])
    import json
    (workdir / "case.toml").write_text(DEPTH_CASE.format(data='name = "\\u001b[31mred\\u0000"', fit=""))
    result = run_mdr("fit", workdir / "case.toml", "--out", workdir / "out", timeout=300)
    assert result.returncode in (0, 1), result.stderr
    assert "\x1b" not in result.stdout and "\x00" not in result.stdout
    assert "flag (\\x1b[31mred\\x00): " in result.stdout
    assert json.loads((workdir / "out" / "fit.json").read_text())["curves"][0]["name"] == "\x1b[31mred\x00"


def test_an_indentation_beyond_the_sphere_radius_is_flagged(run_mdr, workdir):
    write_hertz_curve(workdir / "hertz.csv")   # 3 um deep on R = 5 um: plausible
    _, curve_flags, _ = fit_flags(run_mdr, workdir, DEPTH_CASE.format(data="", fit=""))
    assert curve_flags == []
    case = DEPTH_CASE.format(data="", fit="").replace("R = 5.0", "R = 2.0").replace("G = 0.05", "G = 0.1")
    _, curve_flags, _ = fit_flags(run_mdr, workdir, case)
    assert len(curve_flags) == 1 and "exceeds the sphere's R = 2 µm" in curve_flags[0]


def test_a_modulus_outside_the_moduli_of_materials_is_flagged(run_mdr, workdir):
    """0.2 kPa read in an SI case is 0.2 Pa: below the softest gels (1 Pa)."""
    write_hertz_curve(workdir / "hertz.csv")
    case = DEPTH_CASE.format(data="", fit="").replace('units = "um-nN-s"', "")
    flags, _, _ = fit_flags(run_mdr, workdir, case)
    assert len(flags) == 3 and "(0.2 to 0.2 Pa)" in flags[0] and "1 Pa to 1e+12 Pa" in flags[0]
    # The key, at its start value (0.05 Pa) and at its fitted value (0.2 Pa), each a flag naming it.
    assert flags[1].startswith("material.G: the start value 0.05 Pa (0.05 Pa) is outside") and "1 Pa to 1e+12" in flags[1]
    assert flags[2].startswith("material.G: the fitted value 0.2") and "(0.2 Pa)" in flags[2]
    flags, _, _ = fit_flags(run_mdr, workdir, DEPTH_CASE.format(data="", fit=""))
    assert flags == []


def test_each_candidates_modulus_is_checked(run_mdr, workdir):
    """Every candidate's result gets the plausibility flags (before: only a single fit's): kPa data in an SI case."""
    import json
    write_hertz_curve(workdir / "hertz.csv")
    case = DEPTH_CASE.format(data="", fit='candidates = ["elastic", "standard"]').replace('units = "um-nN-s"', "")
    case = case.replace('free = ["material.G"]\n', "")
    (workdir / "case.toml").write_text(case)
    result = run_mdr("fit", workdir / "case.toml", "--out", workdir / "out", timeout=300)
    assert result.returncode in (0, 1), result.stderr
    for model in ("elastic", "standard"):
        flags = json.loads((workdir / "out" / model / "fit.json").read_text())["flags"]
        assert any(flag.startswith("the fitted G(t) spans 0.2 to 0.2 Pa") for flag in flags), flags
    # The elastic G is determined: its key is named (the standard solid's G1 and tau1 are undetermined on Hertz data,
    # and an undetermined value is reported as such, not as a unit error).
    flags = json.loads((workdir / "out" / "elastic" / "fit.json").read_text())["flags"]
    assert any(flag.startswith("material.G: the fitted value 0.2") for flag in flags), flags


def test_several_curve_tables_share_one_material(run_mdr, workdir):
    """Two [[fit.data]] tables (two cells of the same material, contacts 1 and 1.5 um into their records): one G,
    each curve its own contact point."""
    import json
    write_afm_curve(workdir / "afm.csv", contact=1.0, seed=3)
    write_afm_curve(workdir / "second.csv", contact=1.5, seed=4)
    data = f'spring_constant = {K_CASE}\nunits = {{ spring_constant = "nN/um" }}'
    text = AFM_CASE.format(data=data, fit="")
    text += ('\n[[fit.data]]\nfile = "second.csv"\ntime = "t"\npiezo = "piezo"\ndeflection = "defl"\n' + data + "\n")
    (workdir / "case.toml").write_text(text)
    result = run_mdr("fit", workdir / "case.toml", "--out", workdir / "out", timeout=300)
    assert result.returncode == 0, result.stderr
    summary = json.loads((workdir / "out" / "fit.json").read_text())
    assert summary["parameters"]["material.G"] == pytest.approx(G_TRUE, rel=0.02)
    contacts = [curve["contact_point"] for curve in summary["curves"]]
    assert contacts == [pytest.approx(1.0, abs=0.05), pytest.approx(1.5, abs=0.05)]
