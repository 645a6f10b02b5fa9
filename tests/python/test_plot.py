"""The figures: a force-controlled hold is drawn as a hold, legends cover neither titles nor axis labels, and
sweep.png plots the column asked for (python -m mdr plot DIR --column NAME)."""

from __future__ import annotations

import pathlib
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

import mdr  # noqa: E402

MATERIAL = {"model": "standard", "G_inf": 1.0e6, "G1": 3.0e6, "tau1": 0.2}
INDENTER = {"shape": "sphere", "R": 0.01}
HOLD_FORCE = {"control": "force", "history": [[0.0, 0.0], [0.5, 1.0], [2.0, 1.0], [2.5, 0.0], [3.0, 0.0]]}
HOLD_DEPTH = {"control": "displacement", "history": [[0.0, 0.0], [0.5, 1e-4], [2.0, 1e-4], [2.5, 0.0]]}
NUMERICS = {"elements": 200, "time_step": 0.01}


@pytest.fixture(scope="module")
def force_hold():
    return mdr.run(material=MATERIAL, indenter=INDENTER, load=HOLD_FORCE, numerics=NUMERICS)


@pytest.fixture(scope="module")
def depth_hold():
    return mdr.run(material=MATERIAL, indenter=INDENTER, load=HOLD_DEPTH, numerics=NUMERICS,
                   output={"snapshots": [0.5, 2.0]})


@pytest.mark.parametrize("given", [True, False], ids=["control given", "control inferred"])
def test_a_force_controlled_hold_is_a_hold(force_hold, given):
    h = force_hold.history
    phases = mdr.plot.load_phases(h["d"], h["F"], force_hold.summary["control"] if given else None)
    t = h["t"]
    # The depth creeps during the hold (0.5 < t <= 2): held force, growing depth.
    assert np.all(np.diff(h["d"][(t > 0.5) & (t <= 2.0)]) > 0)
    assert set(phases[(t > 0.0) & (t <= 0.5)]) == {"loading"}
    assert set(phases[(t > 0.5) & (t <= 2.0)]) == {"hold"}
    assert set(phases[t > 2.0]) == {"unloading"}  # down the ramp, then the free recovery at F = 0


@pytest.mark.parametrize("given", [True, False], ids=["control given", "control inferred"])
def test_a_displacement_controlled_hold_is_a_hold(depth_hold, given):
    h = depth_hold.history
    phases = mdr.plot.load_phases(h["d"], h["F"], depth_hold.summary["control"] if given else None)
    t = h["t"]
    assert np.all(np.diff(h["F"][(t > 0.5) & (t <= 2.0)]) < 0)  # the force relaxes
    assert set(phases[(t > 0.0) & (t <= 0.5)]) == {"loading"}
    assert set(phases[(t > 0.5) & (t <= 2.0)]) == {"hold"}
    assert set(phases[t > 2.0]) == {"unloading"}


def test_force_depth_draws_the_hold_in_its_own_colour(force_hold):
    axes = mdr.plot.force_depth(force_hold.history, control="force")
    lines = {line.get_label(): line for line in axes.get_lines()}
    assert set(lines) == {"loading", "hold", "unloading"}
    hold = lines["hold"]
    x, y = np.asarray(hold.get_xdata(), float), np.asarray(hold.get_ydata(), float)
    drawn = np.isfinite(y)
    assert y[drawn] == pytest.approx(1.0, rel=1e-12)  # at the held force
    d, t = force_hold.history["d"], force_hold.history["t"]
    assert x[drawn].min() == pytest.approx(d[t <= 0.5].max()) and x[drawn].max() == pytest.approx(d.max())
    plt.close("all")


def overlaps(a, b) -> bool:
    return a.width > 0 and b.width > 0 and a.overlaps(b)


def figures(force_hold, depth_hold):
    material = mdr.Material.standard(G_inf=1e6, G1=3e6, tau1=0.1)
    t = np.logspace(-3, 1, 40)
    w = np.logspace(-2, 3, 40)
    modulus = material.complex_modulus(w)
    table = {"material.tau1": np.repeat([0.01, 0.1, 1.0], 2), "indenter.R": np.tile([0.005, 0.01], 3),
             "max_force": np.arange(6.0) + 1.0}
    return {
        "force_depth hold": lambda: mdr.plot.force_depth(force_hold.history),
        "force_depth": lambda: mdr.plot.force_depth(depth_hold.history),
        "force_time": lambda: mdr.plot.force_time(force_hold.history),
        "force_time depth": lambda: mdr.plot.force_time(depth_hold.history),
        "pressure": lambda: mdr.plot.pressure_profiles(depth_hold.profiles),
        "material": lambda: mdr.plot.material_functions({"t": t, "G": material.relaxation(t),
                                                         "J": material.creep(t), "J_shear": material.creep(t) / 2}),
        "dynamic": lambda: mdr.plot.dynamic_moduli({"omega": w, "storage": modulus.real, "loss": modulus.imag}),
        "sweep": lambda: mdr.plot.sweep_map(table, "max_force"),
    }


@pytest.mark.parametrize("name", ["force_depth hold", "force_depth", "force_time", "force_time depth", "pressure",
                                  "material", "dynamic", "sweep"])
def test_legends_cover_no_title_and_no_label(name, force_hold, depth_hold, tmp_path):
    axes = figures(force_hold, depth_hold)[name]()
    figure = axes.figure
    figure.tight_layout()
    figure.canvas.draw()
    renderer = figure.canvas.get_renderer()
    legends = [each.get_legend() for each in figure.axes if each.get_legend()] + list(figure.legends)
    assert legends, name
    texts = []
    for each in figure.axes:
        texts += [each.title, each.xaxis.label, each.yaxis.label, each.xaxis.get_offset_text(),
                  each.yaxis.get_offset_text()]
        texts += each.get_xticklabels() + each.get_yticklabels()
    for legend in legends:
        box = legend.get_window_extent(renderer)
        for text in texts:
            if text.get_visible() and text.get_text():
                assert not overlaps(box, text.get_window_extent(renderer)), f"{name}: legend over {text.get_text()!r}"
        assert figure.bbox.contains(box.x0, box.y0) and figure.bbox.contains(box.x1, box.y1), f"{name}: cut off"
    plt.close(figure)


def test_sweep_png_plots_the_chosen_column(mdr_binary, package_env, tmp_path):
    case = pathlib.Path(__file__).resolve().parents[2] / "examples" / "default.toml"
    out = tmp_path / "sweep"
    completed = subprocess.run([mdr_binary, "sweep", str(case), "--vary", "material.G_inf=2e5,5e5,1e6", "--out",
                                str(out)], capture_output=True, text=True, timeout=300)
    assert completed.returncode == 0, completed.stderr
    axes = mdr.plot.sweep_map(mdr.plot.read_csv(str(out / "sweep.csv")), "final_force")
    assert axes.get_ylabel() == "final_force"
    plt.close("all")
    command = [sys.executable, "-m", "mdr", "plot", str(out), "--column", "max_radius"]
    completed = subprocess.run(command, capture_output=True, text=True, env=package_env, timeout=120)
    assert completed.returncode == 0, completed.stderr
    assert completed.stdout.strip().endswith("sweep.png")
    completed = subprocess.run(command[:-1] + ["radius"], capture_output=True, text=True, env=package_env,
                               timeout=120)
    assert completed.returncode == 2
    assert completed.stderr.startswith("mdr plot: error: column = radius: not a numeric column of the sweep; one of "
                                       "max_force, max_depth, max_radius")
    with pytest.raises(ValueError, match="column = error"):
        mdr.plot.plot_directory(str(out), column="error")


def test_read_csv_takes_quoted_fields_and_refuses_ragged_rows(tmp_path):
    """RFC 4180 (issue 23): a quoted name with a comma, a doubled quote and a line break is one field; a row with
    more fields than the header (an unquoted comma) is an error naming the line, never shifted columns."""
    path = tmp_path / "curves.csv"
    path.write_text('curve,t\n"cell,1",0.5\n"say ""hi""\nthere",1.5\n', encoding="utf-8")
    table = mdr.plot.read_csv(str(path))
    assert table["curve"].tolist() == ["cell,1", 'say "hi"\nthere'] and table["t"].tolist() == [0.5, 1.5]
    path.write_text("curve,t\ncell,1,0.5\n", encoding="utf-8")
    with pytest.raises(ValueError, match="line 2: 3 fields; the header has 2"):
        mdr.plot.read_csv(str(path))
