"""Issue 24: the figures of a fit say what a user quotes. A force-indentation figure with the contact point
marked, residual axes with their unit, Young's E beside G; `python3 -m mdr plot` draws a candidates directory
and an `--each` directory (one result folder per model or file)."""

from __future__ import annotations

import json
import pathlib
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import mdr  # noqa: E402

# A Hertz curve (G = 0.2 kPa, R = 5 um, E* = 4G: incompressible) in um-nN-s, contact at depth 1 um of the data,
# baseline 0.5 nN: independent of mdr's solver (closed form).
G, R, CONTACT, BASELINE = 0.2, 5.0, 1.0, 0.5


def hertz_curves(fitted="force"):
    t = np.linspace(0.0, 1.0, 101)
    depth = 4.0 * t                                   # data depth, um
    indentation = depth - CONTACT
    force = BASELINE + 16.0 / 3.0 * G * np.sqrt(R) * np.maximum(indentation, 0.0) ** 1.5
    if fitted == "force":
        curves = {"curve": np.array(["cell"] * t.size), "t": t, "measured": force, "model": force,
                  "residual": 0.0 * t, "drive": indentation}
    else:
        curves = {"curve": np.array(["cell"] * t.size), "t": t, "measured": depth, "model": depth,
                  "residual": 0.0 * t, "drive": force - BASELINE}
    summary = {"units": "um-nN-s", "parameters": {"material.G": G}, "young_moduli": {"material.G": 3.0 * G},
               "curves": [{"name": "cell", "kind": "curve", "fitted": fitted, "contact_point": CONTACT,
                           "baseline": BASELINE}]}
    return curves, summary


def contact_markers(axes):
    return [line for line in axes.get_lines() if line.get_marker() == "o"]


def test_force_indentation_marks_the_contact_point_in_the_case_units():
    for fitted in ("force", "depth"):
        curves, summary = hertz_curves(fitted)
        axes = mdr.plot.force_indentation(curves, summary)
        assert axes.get_xlabel() == "indentation d - contact point [µm]"
        assert axes.get_ylabel() == "force F [nN]"
        (marker,) = contact_markers(axes)
        assert marker.get_xdata()[0] == 0.0 and marker.get_ydata()[0] == BASELINE
        measured = axes.get_lines()[0]
        # The data's own contact: zero indentation where the Hertz force leaves the baseline.
        x, y = np.asarray(measured.get_xdata()), np.asarray(measured.get_ydata())
        assert np.allclose(y[x <= 0.0], BASELINE) and np.all(y[x > 0.0] > BASELINE)
        assert "E = 0.6" in axes.get_title() and "G = 0.2" in axes.get_title()
        plt.close("all")


def test_residuals_carry_the_unit_of_the_fitted_quantity():
    for fitted, unit in (("force", "[nN]"), ("depth", "[µm]")):
        curves, summary = hertz_curves(fitted)
        top = mdr.plot.fit_curves(curves, units=summary)
        bottom = top.figure.axes[1]
        assert bottom.get_ylabel().startswith("model - measured") and bottom.get_ylabel().endswith(unit)
        assert top.get_ylabel().endswith(unit)
        plt.close("all")
    # Without fit.json the quantity is unknown: both units are named, never none.
    curves, _ = hertz_curves()
    bottom = mdr.plot.fit_curves(curves).figure.axes[1]
    assert "force [N]" in bottom.get_ylabel() and "depth [m]" in bottom.get_ylabel()
    plt.close("all")


def test_a_curve_without_recorded_time_is_drawn_over_its_row_number():
    # curves.csv gives t = nan for a file that records no time (docs/case-format.md, "Instrument files").
    measured = np.array([0.0, 1.0, 4.0, 1.0])
    curves = {"curve": np.array(["a"] * 4), "t": np.full(4, np.nan), "measured": measured, "model": measured,
              "residual": np.zeros(4)}
    top = mdr.plot.fit_curves(curves)
    np.testing.assert_array_equal(top.lines[0].get_xdata(), [0.0, 1.0, 2.0, 3.0])
    assert "row number" in top.figure.axes[1].get_xlabel()
    plt.close(top.figure)


def test_the_material_figure_names_young_modulus():
    t = np.logspace(-2, 1, 20)
    functions = {"t": t, "G": 0.2 + 0 * t, "J": 5.0 + 0 * t}
    _, summary = hertz_curves()
    axes = mdr.plot.material_functions(functions, units=summary)
    assert "Young's E(t) = 3 G(t)" in axes.get_ylabel()   # E = 2 (1 + 0.5) G
    assert "Young" not in mdr.plot.material_functions(functions, units="um-nN-s").get_ylabel()
    plt.close("all")


CASE = """
units = "um-nN-s"
[material]
model = "elastic"
G = 0.1
[indenter]
shape = "sphere"
R = 5.0
[fit]
{fit}
[[fit.data]]
file = "{file}"
time = "t"
depth = "d"
force = "F"
"""


def write_hertz(path, contact):
    t = np.linspace(0.0, 1.0, 200)
    depth = 4.0 * t
    force = BASELINE + 16.0 / 3.0 * G * np.sqrt(R) * np.maximum(depth - contact, 0.0) ** 1.5
    force = force + np.random.default_rng(1).normal(0.0, 1e-3, t.size)
    path.write_text("t,d,F\n" + "".join(f"{a!r},{b!r},{c!r}\n" for a, b, c in zip(t, depth, force)))


def test_python_m_mdr_plot_draws_a_candidates_and_an_each_directory(mdr_binary, package_env, tmp_path):
    write_hertz(tmp_path / "a.csv", 1.0)
    write_hertz(tmp_path / "b.csv", 1.5)
    runs = {"candidates": ('candidates = ["elastic", "standard"]', []),
            "each": ('free = ["material.G"]', ["--each", "a.csv", "b.csv"])}
    for name, (fit, extra) in runs.items():
        (tmp_path / f"{name}.toml").write_text(CASE.format(fit=fit, file="a.csv"))
        completed = subprocess.run([mdr_binary, "fit", f"{name}.toml", "--out", name, *extra], cwd=tmp_path,
                                   capture_output=True, text=True, timeout=300)
        assert completed.returncode == 0, completed.stderr
        command = [sys.executable, "-m", "mdr", "plot", str(tmp_path / name)]
        completed = subprocess.run(command, capture_output=True, text=True, env=package_env, timeout=120)
        assert completed.returncode == 0, completed.stderr
        folders = ["elastic", "standard"] if name == "candidates" else ["a", "b"]
        for folder in folders:
            for figure in ("fit_curves", "force_indentation", "material"):
                assert (tmp_path / name / folder / f"{figure}.png").is_file(), (folder, figure)
        listed = (tmp_path / name / ".mdr-result").read_text().splitlines()
        assert f"{folders[0]}/force_indentation.png" in listed
        # Drawn again: the figures are mdr's now, replaced; and mdr may still replace the directory.
        assert subprocess.run(command, capture_output=True, text=True, env=package_env, timeout=120).returncode == 0
        completed = subprocess.run([mdr_binary, "fit", f"{name}.toml", "--out", name, *extra], cwd=tmp_path,
                                   capture_output=True, text=True, timeout=300)
        assert completed.returncode == 0, completed.stderr
    summary = json.loads((tmp_path / "each" / "b" / "fit.json").read_text())
    assert abs(summary["curves"][0]["contact_point"] - 1.5) < 0.05


def test_a_long_approach_leaves_the_contact_region_at_full_width():
    """A record whose approach is 10x longer than its indentation: the axis shows half the indentation's depth of
    the approach, not the whole approach (the contact region is no sliver)."""
    curves, summary = hertz_curves()
    curves = dict(curves, drive=np.concatenate([np.linspace(-30.0, -1.0, 50), curves["drive"][-51:]]))
    axes = mdr.plot.force_indentation(curves, summary)
    left, right = axes.get_xlim()
    assert left == -1.5 and right >= 3.0   # deepest 3 um
    plt.close("all")
