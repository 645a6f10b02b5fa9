"""The Python bindings: mdr.run / mdr.check against the command line, errors, Material factories against the
closed forms of Table 1, and the plots (headless)."""

from __future__ import annotations

import ast
import csv
import inspect
import json
import math
import pathlib
import re
import subprocess
import sys

import numpy as np
import pytest

import mdr
import mdr.plot

REPO_ROOT = pathlib.Path(__file__).resolve().parents[2]

CASE_DICT = {
    "title": "bindings test",
    "material": {"model": "standard", "G_inf": 1.0e6, "G1": 2.0e6, "tau1": 0.1},
    "indenter": {"shape": "sphere", "R": 0.01},
    "load": {"control": "displacement", "history": [[0.0, 0.0], [0.5, 1.0e-4], [1.0, 0.0]]},
    "output": {"snapshots": [0.25, 0.5]},
    "numerics": {"elements": 60, "time_step": 0.01},
}

CASE_TEXT = """title = "bindings test"

[material]
model = "standard"
G_inf = 1.0e6
G1 = 2.0e6
tau1 = 0.1

[indenter]
shape = "sphere"
R = 0.01

[load]
control = "displacement"
history = [[0.0, 0.0], [0.5, 1.0e-4], [1.0, 0.0]]

[output]
snapshots = [0.25, 0.5]

[numerics]
elements = 60
time_step = 0.01
"""

SUMMARY_KEYS = ("case", "max_force", "max_depth", "max_radius", "steps", "elements", "wall_seconds")


@pytest.fixture
def case_file(tmp_path) -> pathlib.Path:
    path = tmp_path / "case.toml"
    path.write_text(CASE_TEXT, encoding="utf-8")
    return path


@pytest.fixture(scope="module")
def file_result(tmp_path_factory):
    path = tmp_path_factory.mktemp("case") / "case.toml"
    path.write_text(CASE_TEXT, encoding="utf-8")
    return mdr.run(str(path))


def read_csv(path: pathlib.Path) -> dict[str, list[float]]:
    with open(path, newline="", encoding="utf-8") as handle:
        rows = list(csv.reader(handle))
    return {name: [float(row[i]) for row in rows[1:]] for i, name in enumerate(rows[0])}


# ---------------------------------------------------------------------------------------------------------------
# mdr.run and mdr.check


def test_result_arrays_are_1d_float64_of_equal_length(file_result):
    assert set(file_result.history) >= {"t", "d", "F", "a"}
    lengths = set()
    for name, array in file_result.history.items():
        assert isinstance(array, np.ndarray), name
        assert array.dtype == np.float64 and array.ndim == 1, name
        lengths.add(array.size)
    assert len(lengths) == 1 and lengths.pop() > 2
    assert set(file_result.profiles) >= {"t", "r", "p"}
    profile_lengths = {array.size for array in file_result.profiles.values()}
    assert len(profile_lengths) == 1 and profile_lengths.pop() > 0
    for array in file_result.profiles.values():
        assert array.dtype == np.float64 and array.ndim == 1
    assert sorted(set(file_result.profiles["t"].tolist())) == pytest.approx([0.25, 0.5])
    for key in SUMMARY_KEYS:
        assert key in file_result.summary, key
    assert file_result.summary["case"] == "bindings test"


def test_run_accepts_a_path_object(case_file, file_result):
    result = mdr.run(case_file)
    np.testing.assert_array_equal(result.history["F"], file_result.history["F"])


def test_file_and_dict_give_identical_arrays(file_result):
    from_dict = mdr.run(CASE_DICT)
    for name in ("t", "d", "F", "a"):
        np.testing.assert_array_equal(from_dict.history[name], file_result.history[name], err_msg=name)
    for name in file_result.profiles:
        np.testing.assert_array_equal(from_dict.profiles[name], file_result.profiles[name], err_msg=name)
    for key, value in file_result.summary.items():
        if key != "wall_seconds":
            assert from_dict.summary[key] == value, key


def test_dict_with_numpy_values_matches(file_result):
    case = json.loads(json.dumps(CASE_DICT))
    case["load"]["history"] = np.array(case["load"]["history"])
    case["material"]["G_inf"] = np.float64(1.0e6)
    case["numerics"]["elements"] = np.int64(60)
    np.testing.assert_array_equal(mdr.run(case).history["F"], file_result.history["F"])


def test_bindings_agree_with_the_command_line_to_the_last_digit(mdr_binary, case_file, tmp_path):
    out = tmp_path / "out"
    completed = subprocess.run([mdr_binary, "run", str(case_file), "--out", str(out)], capture_output=True,
                               text=True, timeout=60)
    assert completed.returncode == 0, completed.stderr
    result = mdr.run(str(case_file))
    history = read_csv(out / "history.csv")
    assert list(history) == ["t", "d", "F", "a"]
    for name, column in history.items():
        np.testing.assert_array_equal(np.array(column), result.history[name], err_msg=name)
    profiles = read_csv(out / "profiles.csv")
    assert set(profiles) == set(result.profiles)
    for name, column in profiles.items():
        np.testing.assert_array_equal(np.array(column), result.profiles[name], err_msg=name)
    summary = json.loads((out / "summary.json").read_text())
    assert set(summary) == set(result.summary)
    for key, value in summary.items():
        if key != "wall_seconds":
            assert result.summary[key] == value, key


def test_default_example_agrees_with_the_command_line(mdr_binary, tmp_path):
    case = REPO_ROOT / "examples" / "default.toml"
    out = tmp_path / "out"
    completed = subprocess.run([mdr_binary, "run", str(case), "--out", str(out)], capture_output=True, text=True,
                               timeout=120)
    assert completed.returncode == 0, completed.stderr
    result = mdr.run(str(case))
    for name, column in read_csv(out / "history.csv").items():
        np.testing.assert_array_equal(np.array(column), result.history[name], err_msg=name)
    summary = json.loads((out / "summary.json").read_text())
    for key, value in summary.items():
        if key != "wall_seconds":
            assert result.summary[key] == value, key


def test_check_returns_the_description(case_file, mdr_binary):
    description = mdr.check(str(case_file))
    assert isinstance(description, str) and description
    completed = subprocess.run([mdr_binary, "check", str(case_file)], capture_output=True, text=True, timeout=60)
    assert completed.stdout == f"ok: {description}\n"
    assert mdr.check(CASE_DICT) == description


# ---------------------------------------------------------------------------------------------------------------
# errors: ValueError with the command line's message; wrong types: TypeError or ValueError, never a crash

BAD_TEXTS = {
    "unknown-key": CASE_TEXT.replace("G_inf", "Ginf"),
    "negative-modulus": CASE_TEXT.replace("G1 = 2.0e6", "G1 = -2.0e6"),
    "nan-time": CASE_TEXT.replace("tau1 = 0.1", "tau1 = nan"),
    "malformed": CASE_TEXT.replace("R = 0.01", "R = = 0.01"),
    "backwards": CASE_TEXT.replace("[1.0, 0.0]]", "[0.2, 0.0]]"),
    "snapshot-outside": CASE_TEXT.replace("[0.25, 0.5]", "[0.25, 5.0]"),
    "elements-zero": CASE_TEXT.replace("elements = 60", "elements = 0"),
    "tangential": CASE_TEXT + '\n[tangential]\nfriction = -0.3\ncontrol = "displacement"\n'
                              'history = [[0.0, 0.0], [1.0, 1e-6]]\n',
    "impact": CASE_TEXT.replace('control = "displacement"', 'control = "impact"'),
}


@pytest.mark.parametrize("name", sorted(BAD_TEXTS))
def test_errors_carry_the_command_line_message(name, tmp_path, mdr_binary):
    path = tmp_path / "bad.toml"
    path.write_text(BAD_TEXTS[name], encoding="utf-8")
    completed = subprocess.run([mdr_binary, "check", str(path)], capture_output=True, text=True, timeout=60)
    assert completed.returncode == 2
    line = completed.stderr.splitlines()
    assert len(line) == 1 and line[0].startswith("mdr: error: ")
    expected = line[0][len("mdr: error: "):]
    for call in (mdr.run, mdr.check):
        with pytest.raises(ValueError) as caught:
            call(str(path))
        assert str(caught.value) == expected, call.__name__
        assert isinstance(caught.value, mdr.InvalidInput)


def test_missing_file_message_matches_the_command_line(tmp_path, mdr_binary):
    path = str(tmp_path / "no-such-case.toml")
    completed = subprocess.run([mdr_binary, "check", path], capture_output=True, text=True, timeout=60)
    assert completed.returncode == 2
    expected = completed.stderr.splitlines()[0][len("mdr: error: "):]
    with pytest.raises(ValueError) as caught:
        mdr.run(path)
    assert str(caught.value) == expected


def test_dict_errors_name_the_key():
    case = json.loads(json.dumps(CASE_DICT))
    case["material"]["tau1"] = -1.0
    with pytest.raises(ValueError, match=r"^material\.tau1 = -1: must be > 0$"):
        mdr.run(case)
    case = json.loads(json.dumps(CASE_DICT))
    del case["indenter"]
    with pytest.raises(ValueError, match=r"^indenter = \(missing\): is required$"):
        mdr.run(case)


def test_run_of_a_number_is_a_type_error():
    with pytest.raises(TypeError, match="case"):
        mdr.run(42)
    with pytest.raises(TypeError, match="case"):
        mdr.check(None)


def test_history_of_strings_names_the_key():
    case = json.loads(json.dumps(CASE_DICT))
    case["load"]["history"] = ["0, 0", "1, 1e-4"]
    with pytest.raises((TypeError, ValueError), match=r"load\.history"):
        mdr.run(case)


@pytest.mark.parametrize("value", [object(), {1, 2}, None])
def test_unsupported_dict_value_names_the_key(value):
    case = json.loads(json.dumps(CASE_DICT))
    case["indenter"]["R"] = value
    with pytest.raises((TypeError, ValueError), match=r"indenter\.R"):
        mdr.run(case)


def test_string_for_number_in_a_dict():
    case = json.loads(json.dumps(CASE_DICT))
    case["indenter"]["R"] = "0.01"
    with pytest.raises(ValueError, match=r"^indenter\.R = ['\"]0\.01['\"]: must be a number$"):
        mdr.run(case)


def test_non_string_key_is_a_type_error():
    case = json.loads(json.dumps(CASE_DICT))
    case["material"][3] = 1.0
    with pytest.raises((TypeError, ValueError), match="3"):
        mdr.run(case)


def test_low_level_entry_points_reject_wrong_types():
    with pytest.raises(TypeError):
        mdr._mdr._run_case(42)
    with pytest.raises(TypeError):
        mdr.Material.standard("a", 1.0, 1.0)
    with pytest.raises(TypeError):
        mdr.Material.standard(1.0, 1.0)


# ---------------------------------------------------------------------------------------------------------------
# Material: factories, shapes, the closed forms of Table 1

TIMES = np.array([0.0, 1e-4, 1e-3, 0.01, 0.05, 0.1, 0.3, 1.0, 3.0, 10.0])
OMEGAS = np.array([1e-3, 0.1, 1.0, 7.0, 10.0, 100.0, 1e4])
G, ETA, TAU, G_INF, G1, TAU1 = 2.0e6, 3.0e4, 0.02, 1.0e6, 3.0e6, 0.1


def closed_forms():
    """(name, material, G(t), J(t), G^(omega)) per model of Table 1; G(t) without the dashpot's delta."""
    t, w = TIMES, OMEGAS
    iw = 1j * w
    retardation = (G_INF + G1) * TAU1 / G_INF
    return [
        ("elastic", mdr.Material.elastic(G=G), np.full_like(t, G), np.full_like(t, 1 / G), G + 0j * w),
        ("viscous", mdr.Material.viscous(eta=ETA), np.zeros_like(t), t / ETA, iw * ETA),
        ("kelvin_voigt", mdr.Material.kelvin_voigt(G=G, eta=ETA), np.full_like(t, G),
         (1 - np.exp(-G * t / ETA)) / G, G + iw * ETA),
        ("maxwell", mdr.Material.maxwell(G=G, tau=TAU), G * np.exp(-t / TAU), 1 / G + t / (G * TAU),
         G * iw * TAU / (1 + iw * TAU)),
        ("standard", mdr.Material.standard(G_inf=G_INF, G1=G1, tau1=TAU1), G_INF + G1 * np.exp(-t / TAU1),
         (1 - G1 / (G_INF + G1) * np.exp(-t / retardation)) / G_INF, G_INF + G1 * iw * TAU1 / (1 + iw * TAU1)),
        ("prony-one-term", mdr.Material.prony(G_inf=G_INF, terms=[(G1, TAU1)]), G_INF + G1 * np.exp(-t / TAU1),
         (1 - G1 / (G_INF + G1) * np.exp(-t / retardation)) / G_INF, G_INF + G1 * iw * TAU1 / (1 + iw * TAU1)),
    ]


@pytest.mark.parametrize("case", closed_forms(), ids=lambda case: case[0] if isinstance(case, tuple) else "")
def test_material_matches_table_1(case):
    name, material, relaxation, creep, modulus = case
    np.testing.assert_allclose(material.relaxation(TIMES), relaxation, rtol=1e-12, atol=0, err_msg=name)
    np.testing.assert_allclose(material.creep(TIMES), creep, rtol=1e-12, atol=1e-30, err_msg=name)
    computed = material.complex_modulus(OMEGAS)
    assert computed.dtype == np.complex128
    np.testing.assert_allclose(computed.real, modulus.real, rtol=1e-12, atol=1e-12 * np.abs(modulus).max())
    np.testing.assert_allclose(computed.imag, modulus.imag, rtol=1e-12, atol=1e-12 * np.abs(modulus).max())


def test_prony_creep_satisfies_the_convolution_identity():
    # s^2 G*(s) J*(s) = 1 (eq. 6)  <=>  int_0^t G(t - s) J(s) ds = t for the regular G of a solid.
    material = mdr.Material.prony(G_inf=0.5e6, terms=[(1.0e6, 1e-3), (0.8e6, 1e-2), (0.6e6, 1e-1)])
    for t in (2e-3, 0.05, 0.4):
        # Gauss-Legendre on panels that resolve the shortest time scale
        nodes, weights = np.polynomial.legendre.leggauss(20)
        edges = np.concatenate([[0.0], np.geomspace(1e-6, t, 60)])
        total = 0.0
        for lower, upper in zip(edges[:-1], edges[1:]):
            s = 0.5 * (upper - lower) * nodes + 0.5 * (upper + lower)
            total += 0.5 * (upper - lower) * np.sum(weights * material.relaxation(t - s) * material.creep(s))
        assert total == pytest.approx(t, rel=1e-9), t
    assert material.creep(0.0) == pytest.approx(1 / (0.5e6 + 1.0e6 + 0.8e6 + 0.6e6), rel=1e-12)
    assert material.creep(1e3) == pytest.approx(1 / 0.5e6, rel=1e-12)


def test_series_adds_creep_functions():
    a = mdr.Material.standard(G_inf=G_INF, G1=G1, tau1=TAU1)
    b = mdr.Material.maxwell(G=G, tau=TAU)
    np.testing.assert_allclose(a.series(b).creep(TIMES), a.creep(TIMES) + b.creep(TIMES), rtol=1e-12)
    c = mdr.Material.elastic(G=G)
    np.testing.assert_allclose(a.series(c).creep(TIMES), a.creep(TIMES) + 1 / G, rtol=1e-12)


@pytest.mark.parametrize("method", ["relaxation", "creep", "complex_modulus"])
@pytest.mark.parametrize("value", [0.5, 2, [0.1, 1.0], np.array([[0.1, 0.2, 0.3], [1.0, 2.0, 3.0]]),
                                   np.array([], dtype=float), np.arange(4, dtype=np.float32)])
def test_material_functions_keep_the_input_shape(method, value):
    material = mdr.Material.standard(G_inf=G_INF, G1=G1, tau1=TAU1)
    result = getattr(material, method)(value)
    if np.ndim(value) == 0:  # scalar in, scalar out
        assert type(result) is (complex if method == "complex_modulus" else float)
    else:
        assert isinstance(result, np.ndarray)
        assert result.shape == np.shape(value)
        assert result.dtype == (np.complex128 if method == "complex_modulus" else np.float64)
    flat = np.asarray(value, dtype=float).ravel()
    for x, y in zip(flat, np.asarray(result).ravel()):
        assert y == getattr(material, method)(np.array([x]))[0]


@pytest.mark.parametrize("factory,arguments,key", [
    ("elastic", {"G": -1.0}, "G"), ("viscous", {"eta": 0.0}, "eta"), ("maxwell", {"G": 1.0, "tau": math.nan}, "tau"),
    ("standard", {"G_inf": 1.0, "G1": 1.0, "tau1": -1.0}, "tau1"),
    ("kelvin_voigt", {"G": math.inf, "eta": 1.0}, "G"), ("prony", {"G_inf": 1.0, "terms": [(1.0, 0.0)]}, "terms[0].tau"),
])
def test_material_factories_refuse_bad_parameters(factory, arguments, key):
    with pytest.raises(ValueError, match=r"^" + key.replace("[", r"\[").replace("]", r"\]") + " = "):
        getattr(mdr.Material, factory)(**arguments)


# ---------------------------------------------------------------------------------------------------------------
# plots, headless


@pytest.fixture(scope="module")
def result_directory(tmp_path_factory, mdr_binary):
    directory = tmp_path_factory.mktemp("plot") / "result"
    case = directory.parent / "case.toml"
    case.write_text(CASE_TEXT, encoding="utf-8")
    completed = subprocess.run([mdr_binary, "run", str(case), "--out", str(directory)], capture_output=True,
                               text=True, timeout=60)
    assert completed.returncode == 0, completed.stderr
    return directory


def is_png(path: pathlib.Path) -> bool:
    return path.stat().st_size > 1000 and path.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_plot_command_writes_pngs(result_directory, package_env):
    env = dict(package_env)
    env.pop("DISPLAY", None)
    completed = subprocess.run([sys.executable, "-m", "mdr", "plot", str(result_directory)], capture_output=True,
                               text=True, env=env, timeout=120)
    assert completed.returncode == 0, completed.stderr
    expected = {"force_depth.png", "force_time.png", "contact_radius.png", "pressure.png"}
    written = {pathlib.Path(line).name for line in completed.stdout.splitlines()}
    assert written == expected
    for name in expected:
        assert is_png(result_directory / name), name


def test_plot_command_on_a_non_result_directory(tmp_path, package_env):
    completed = subprocess.run([sys.executable, "-m", "mdr", "plot", str(tmp_path)], capture_output=True, text=True,
                               env=package_env, timeout=120)
    assert completed.returncode == 2
    assert len(completed.stderr.splitlines()) == 1 and "history.csv" in completed.stderr
    assert list(tmp_path.iterdir()) == []


def test_plot_module_defaults_to_agg_without_a_display(package_env):
    env = dict(package_env)
    env.pop("DISPLAY", None)
    env.pop("MPLBACKEND", None)
    code = "import mdr.plot, matplotlib; print(matplotlib.get_backend())"
    completed = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env, timeout=120)
    assert completed.returncode == 0, completed.stderr
    assert completed.stdout.strip().lower() == "agg"


def test_every_plot_function_runs_headless(result_directory, file_result, tmp_path):
    import matplotlib.pyplot as plt

    history = mdr.plot.read_csv(str(result_directory / "history.csv"))
    profiles = mdr.plot.read_csv(str(result_directory / "profiles.csv"))
    material = mdr.Material.standard(G_inf=1e6, G1=3e6, tau1=0.1)
    times = np.logspace(-3, 1, 20)
    for name in ("t", "d", "F", "a"):
        np.testing.assert_array_equal(history[name], file_result.history[name])
    calls = {
        "read_csv": lambda: mdr.plot.read_csv(str(result_directory / "history.csv")),
        "force_depth": lambda: mdr.plot.force_depth(file_result.history),
        "force_time": lambda: mdr.plot.force_time(history),
        "contact_radius": lambda: mdr.plot.contact_radius(file_result.history),
        "pressure_profiles": lambda: mdr.plot.pressure_profiles(profiles),
        "plot_directory": lambda: mdr.plot.plot_directory(str(result_directory)),
        "save": lambda: mdr.plot.save(mdr.plot.force_depth(history), str(tmp_path / "saved.png")),
        "material_functions": lambda: mdr.plot.material_functions(
            {"t": times, "G": material.relaxation(times), "J": material.creep(times)}),
        "dynamic_moduli": lambda: mdr.plot.dynamic_moduli(
            {"omega": times, "storage": material.complex_modulus(times).real,
             "loss": material.complex_modulus(times).imag}),
        "shear_stress_profiles": lambda: mdr.plot.shear_stress_profiles(
            {"t": np.zeros(3), "r": np.array([0.0, 1e-4, 2e-4]), "tau": np.array([1.0, 2.0, 0.0])}),
        "tangential_loop": lambda: mdr.plot.tangential_loop(
            {"u": np.array([0.0, 1e-6, 0.0]), "Fx": np.array([0.0, 0.1, 0.05])}),
        "load_phases": lambda: mdr.plot.load_phases(history["d"], history["F"]),
        "fit_curves": lambda: mdr.plot.fit_curves(
            {"curve": np.array(["a", "a", "b"]), "t": np.array([0.0, 1.0, 0.0]), "measured": np.array([0.0, 1.0, 2.0]),
             "model": np.array([0.0, 1.1, 2.0]), "residual": np.array([0.0, 0.1, 0.0])}),
        "force_indentation": lambda: mdr.plot.force_indentation(
            {"curve": np.array(["a", "a", "a"]), "t": np.array([0.0, 1.0, 2.0]),
             "measured": np.array([0.0, 1.0, 2.0]), "model": np.array([0.0, 1.1, 2.0]),
             "residual": np.array([0.0, 0.1, 0.0]), "drive": np.array([0.0, 1e-6, 2e-6])},
            {"units": "SI", "curves": [{"name": "a", "kind": "curve", "fitted": "force", "contact_point": 0.0,
                                        "baseline": 0.0}]}),
        "fit_rebounds": lambda: mdr.plot.fit_rebounds(
            {"curve": np.array(["a", "d:restitution", "d:restitution", "d:contact_time"]),
             "t": np.array([0.0, 0.1, 1.0, 0.1]), "measured": np.array([1.0, 0.5, 0.6, 2e-3]),
             "model": np.array([1.0, 0.51, 0.6, 2e-3]), "residual": np.array([0.0, 0.01, 0.0, 0.0])}),
        "sweep_map": lambda: mdr.plot.sweep_map(
            {"material.tau1": np.array([0.1, 1.0, 0.1, 1.0]), "material.G1": np.array([1.0, 1.0, 2.0, 2.0]),
             "max_force": np.array([1.0, 2.0, 3.0, 4.0])}, "max_force"),
    }
    public = {name for name, member in inspect.getmembers(mdr.plot, inspect.isfunction)
              if member.__module__ == "mdr.plot" and not name.startswith("_")}
    assert public <= set(calls), f"untested plot functions: {sorted(public - set(calls))}"
    for name, call in calls.items():
        call()
    for draw in (mdr.plot.force_depth, mdr.plot.force_time, mdr.plot.contact_radius):
        figure, axes = plt.subplots()
        assert draw(file_result.history, axes=axes) is axes
        figure.savefig(tmp_path / f"{draw.__name__}.png")
        plt.close(figure)
        assert is_png(tmp_path / f"{draw.__name__}.png")
    figure, axes = plt.subplots()
    assert mdr.plot.pressure_profiles(file_result.profiles, axes=axes) is axes
    plt.close("all")


def test_restitution_map_from_a_sweep_table(tmp_path):
    """mdr.maps: p1 of eq. (40) and the Fig. 3 plot from a sweep table built here."""
    import mdr.maps

    case = {"material": {"G_inf": 1e6}, "indenter": {"R": 0.01, "mass": 3.27e-2}, "load": {"velocity": 0.1}}
    rho = 3 * 3.27e-2 / (4 * np.pi * 0.01**3)
    assert mdr.maps.p1_scale(case) == pytest.approx(0.1**0.2 * (1e6 / rho) ** 0.4 / 0.01, rel=1e-14)
    tau = np.array([1e-4, 1e-3, 1e-2, 1e-4, 1e-3, 1e-2])
    sweep = {"material.tau1": tau, "material.G1": np.repeat([1e6, 3e6], 3),
             "restitution": np.array([0.9, 0.7, 0.95, 0.8, 0.5, 0.9])}
    axes = mdr.maps.restitution_map(sweep, case)
    assert len(axes.lines) == 2 and axes.get_xscale() == "log"
    path = mdr.plot.save(axes, str(tmp_path / "map.png"))
    assert (tmp_path / "map.png").stat().st_size > 0 and path.endswith("map.png")


def test_stubs_list_every_public_binding():
    """python/mdr/_mdr.pyi stays in step with the compiled module."""

    stub = (pathlib.Path(mdr.__file__).parent / "_mdr.pyi").read_text()
    names = {name for name in dir(mdr._mdr) if not name.startswith("__")}
    for name in names:
        assert re.search(rf"\b(def|class) {name}\b|^{name}:", stub, re.M), f"{name} missing from _mdr.pyi"
    for name in (n for n in dir(mdr.Material) if not n.startswith("_")):
        assert re.search(rf"def {name}\b", stub), f"Material.{name} missing from _mdr.pyi"


def test_the_package_exports_every_public_class_of_the_core_as_the_stub_lists_them():
    """mdr exports _mdr.__all__ (every public name of the module, python/bindings/public_names.cpp) with no list of
    its own, and the stub's __all__ is the module's: a class bound in C++ is exported, and one missing from the stub
    fails here."""
    stub = (pathlib.Path(mdr.__file__).parent / "_mdr.pyi").read_text()
    listed = ast.literal_eval(re.search(r"^__all__ = (\[.*?\])", stub, re.M | re.S).group(1))
    public = [name for name in vars(mdr._mdr) if not name.startswith("_")]
    assert mdr._mdr.__all__ == public and sorted(listed) == sorted(public)
    for name in public:
        assert name in mdr.__all__ and getattr(mdr, name) is getattr(mdr._mdr, name)


def test_the_stubs_load_controls_are_the_variants_alternatives():
    """case.control gives one class per alternative of drivers::LoadControl (_mdr._load_controls, folded over the
    variant: importing _mdr fails while one is not bound); the stub's _LoadControl names the same classes, and the
    constructor's _Control adds the Shore test."""
    stub = (pathlib.Path(mdr.__file__).parent / "_mdr.pyi").read_text()
    union = re.search(r"^_LoadControl = (.*)$", stub, re.M).group(1)
    assert [name.strip() for name in union.split("|")] == [cls.__name__ for cls in mdr._mdr._load_controls]
    assert re.search(r"^_Control = _LoadControl \| ShoreTest$", stub, re.M)
    assert re.search(r"def control\(self\) -> _LoadControl:", stub)


def test_sweep_from_python(tmp_path):
    table = mdr.sweep(CASE_DICT_FOR_SWEEP, {"material.tau1": "0.05:0.5:3:log", "material.G1": [1e6, 2e6]}, jobs=2)
    assert table["material.tau1"].shape == (6,) and table["material.G1"].tolist() == [1e6, 2e6] * 3
    assert table["max_force"].dtype == np.float64 and np.all(table["max_force"] > 0)
    assert list(table["error"]) == [""] * 6
    failed = mdr.sweep(CASE_DICT_FOR_SWEEP, {"material.tau1": [-1.0, 0.1]})
    assert failed["error"][0] == "material.tau1 = -1: must be > 0" and np.isnan(failed["max_force"][0])
    with pytest.raises(ValueError, match="no such numeric key"):
        mdr.sweep(CASE_DICT_FOR_SWEEP, {"material.tau": [1.0]})
    with pytest.raises(TypeError):
        mdr.sweep(CASE_DICT_FOR_SWEEP, {})


CASE_DICT_FOR_SWEEP = {
    "material": {"model": "standard", "G_inf": 1.0e6, "G1": 3.0e6, "tau1": 0.2},
    "indenter": {"shape": "sphere", "R": 0.01},
    "load": {"control": "displacement", "history": [[0.0, 0.0], [1.0, 1.0e-4], [2.0, 0.0]]},
    "numerics": {"elements": 100, "time_step": 0.02},
}


def test_indenters_and_their_equivalent_profiles():
    """mdr.Indenter: g(x) of eq. (9) in closed form for the analytic shapes; a table reproduces the sphere."""
    x = np.linspace(0.0, 1e-3, 11)
    sphere = mdr.Indenter.sphere(R=0.01)
    np.testing.assert_allclose(sphere.equivalent(x), x**2 / 0.01, rtol=1e-14, atol=0)
    np.testing.assert_allclose(sphere.gap(x), x**2 / 0.02, rtol=1e-14, atol=0)
    cone = mdr.Indenter.cone(slope_deg=10.0)
    np.testing.assert_allclose(cone.equivalent(x), np.pi / 2 * np.tan(np.radians(10.0)) * x, rtol=1e-14)
    assert sphere.contact_radius(1e-4) == pytest.approx(1e-3, rel=1e-14)
    assert np.isinf(mdr.Indenter.flat(a=1e-3).equivalent(2e-3))
    r = np.linspace(0.0, 2e-3, 41)
    table = mdr.Indenter.profile(r=r, f=r**2 / 0.02)
    np.testing.assert_allclose(table.equivalent(x), x**2 / 0.01, rtol=1e-10, atol=1e-18)
    assert sphere.equivalent(np.ones((2, 3))).shape == (2, 3)
    with pytest.raises(ValueError, match="R = -1"):
        mdr.Indenter.sphere(R=-1.0)


def test_dict_cases_take_any_title_and_material_objects():
    """Dicts go to the reader through a real TOML writer (tomli-w): a title with an emoji or quotes is kept as
    written, and an mdr.Material stands for its [material] table (here the standard solid as a Prony series)."""
    case = dict(CASE_DICT, title='Gummi 🎉 "A", 50 °C')
    case["material"] = mdr.Material.standard(G_inf=1.0e6, G1=2.0e6, tau1=0.1)
    result = mdr.run(case)
    assert result.summary["case"] == 'Gummi 🎉 "A", 50 °C'
    assert result.summary["max_force"] == pytest.approx(mdr.run(CASE_DICT).summary["max_force"], rel=1e-12)
    for material in (mdr.Material.elastic(G=1e6), mdr.Material.kelvin_voigt(G=1e6, eta=1e3),
                     mdr.Material.viscous(eta=1e3)):
        assert mdr.check(dict(CASE_DICT, material=material))


def test_a_key_with_a_space_is_an_unknown_key_not_a_toml_error():
    case = dict(CASE_DICT, material=dict(CASE_DICT["material"], **{"tau 1": 0.1}))
    with pytest.raises(ValueError, match=r"^material\.tau 1 = 0\.1: unknown key"):
        mdr.check(case)


def test_materials_pickle_and_compressible_materials_follow_eq_56():
    import pickle

    material = mdr.Material.prony(G_inf=1e6, terms=[(2e6, 0.01), (1e6, 1.0)])
    copy = pickle.loads(pickle.dumps(material))
    t = np.array([0.0, 0.1, 10.0])
    assert np.array_equal(copy.relaxation(t), material.relaxation(t))
    assert copy.terms == material.terms
    # Elastic G and K: J_eff = 1/G + 1/(K + G/3) = 2 (1 - nu) / G (the plane-strain modulus E* = 4 G_eff).
    G, K = 1.0e6, 5.0e6
    nu = (3 * K - 2 * G) / (2 * (3 * K + G))
    effective = mdr.Material.elastic(G=G).with_bulk(mdr.Material.elastic(G=K))
    assert effective.creep([1.0])[0] == pytest.approx(2 * (1 - nu) / G, rel=1e-12)


@pytest.mark.parametrize("indenter", [mdr.Indenter.sphere(R=0.01), mdr.Indenter.cone(slope_deg=20.0),
                                      mdr.Indenter.flat(a=1e-3), mdr.Indenter.power(c=2e3, n=2.5),
                                      mdr.Indenter.profile(r=[0.0, 1e-3, 2e-3], f=[0.0, 1e-5, 5e-5],
                                                           interpolation="linear")])
def test_indenters_pickle_and_stand_for_their_table_in_a_case(indenter):
    import pickle

    copy = pickle.loads(pickle.dumps(indenter))
    x = np.linspace(0.0, 0.9e-3, 7)
    assert np.array_equal(copy.equivalent(x), indenter.equivalent(x))
    assert copy.table == indenter.table
    assert repr(copy) == repr(indenter)
    # In a case, the object is its [indenter] table: the same run as with the table written out.
    case = dict(CASE_DICT, load={"control": "force", "history": [[0.0, 0.0], [0.5, 1e-3], [1.0, 1e-3]]},
                output={})
    by_object = mdr.run(dict(case, indenter=indenter)).summary["max_depth"]
    by_table = mdr.run(dict(case, indenter=dict(indenter.table))).summary["max_depth"]
    assert by_object == by_table and by_object > 0.0


def test_a_linear_profile_of_a_cone_is_the_cone():
    """Eq. 9 is exact per linear segment: a two-point linear table of a cone has the cone's g(x) = (pi/2) tan x."""
    slope = math.tan(math.radians(20.0))
    table = mdr.Indenter.profile(r=[0.0, 1e-2], f=[0.0, 1e-2 * slope], interpolation="linear")
    x = np.linspace(0.0, 5e-3, 11)
    assert table.equivalent(x) == pytest.approx(0.5 * math.pi * slope * x, rel=1e-12, abs=1e-18)
    with pytest.raises(ValueError, match="must be monotone_cubic or linear"):
        mdr.Indenter.profile(r=[0.0, 1e-2], f=[0.0, 1e-3], interpolation="spline")


def test_a_result_pickles():
    import pickle

    result = mdr.run(CASE_DICT)
    copy = pickle.loads(pickle.dumps(result))
    assert copy.summary == result.summary and np.array_equal(copy.history["F"], result.history["F"])
