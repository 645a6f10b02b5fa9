"""Declared unit systems (`units`, docs/case-format.md): nothing is converted, so a case written in another
consistent system must give its SI twin's results in that system's units, and every printed unit name must be the
declared system's. The twins are converted here, key by key, with the factors of each system's base units."""

from __future__ import annotations

import copy
import subprocess

import numpy as np
import pytest

import mdr

# (length, force, time) of each system in SI; pressure = force / length^2, mass = force time^2 / length.
SYSTEMS = {"mm-N-s": (1e-3, 1.0, 1.0), "um-nN-s": (1e-6, 1e-9, 1.0), "nm-nN-s": (1e-9, 1e-9, 1.0)}
NAMES = {"SI": ("m", "N", "Pa", "kg"), "mm-N-s": ("mm", "N", "MPa", "t"), "um-nN-s": ("µm", "nN", "kPa", "g"),
         "nm-nN-s": ("nm", "nN", "GPa", "kg")}


def scales(system: str) -> dict[str, float]:
    """SI value / value in `system`, per dimension."""
    length, force, time = SYSTEMS[system]
    return {"length": length, "force": force, "time": time, "pressure": force / length**2,
            "mass": force * time**2 / length, "velocity": length / time, "viscosity": force * time / length**2,
            "energy": force * length, "one": 1.0}


# The SI twins (AFM-sized: a 5 um probe and punch on kPa gels; an impact; fretting), with each value's dimension.
CASES = {
    "displacement": ({
        "material": {"model": "prony", "G_inf": 2.0e3, "terms": [[3.0e3, 0.05], [1.0e3, 1.0]]},
        "indenter": {"shape": "sphere", "R": 5.0e-6},
        "load": {"control": "displacement", "history": [[0.0, 0.0], [0.5, 1.0e-6], [1.0, 0.0]]},
        "output": {"snapshots": [0.25, 0.5]},
    }, {"material.G_inf": "pressure", "material.terms": ("pressure", "time"), "indenter.R": "length",
        "load.history": ("time", "length"), "output.snapshots": "time"}),
    # A flat punch: under force control with a dashpot, a curved indenter's first steps land on the jump of the
    # discrete force where an element enters contact, and which side the root takes there depends on round-off
    # (seen: one row of a Kelvin-Voigt cone 1e-4 of the peak force apart from its twin).
    "force-hold": ({
        "material": {"model": "kelvin_voigt", "G": 1.0e3, "eta": 50.0, "K": 2.0e4},
        "indenter": {"shape": "flat", "a": 5.0e-6},
        "load": {"control": "force", "history": [[0.0, 0.0], [0.2, 1.0e-9], [2.0, 1.0e-9], [2.5, 0.0]]},
    }, {"material.G": "pressure", "material.eta": "viscosity", "material.K": "pressure",
        "indenter.a": "length", "load.history": ("time", "force")}),
    "impact": ({
        "material": {"model": "standard", "G_inf": 1.0e6, "G1": 3.0e6, "tau1": 1.0e-4},
        "indenter": {"shape": "sphere", "R": 0.01, "mass": 3.27e-2},
        "load": {"control": "impact", "velocity": 0.1},
    }, {"material.G_inf": "pressure", "material.G1": "pressure", "material.tau1": "time", "indenter.R": "length",
        "indenter.mass": "mass", "load.velocity": "velocity"}),
    "fretting": ({
        "material": {"model": "standard", "G_inf": 1.0e6, "G1": 2.0e6, "tau1": 0.05},
        "indenter": {"shape": "sphere", "R": 0.01},
        "load": {"control": "displacement", "history": [[0.0, 0.0], [0.2, 1.0e-4], [1.0, 1.0e-4]]},
        "tangential": {"friction": 0.3, "control": "displacement", "amplitude": 1.0e-6, "frequency": 5.0,
                       "start": 0.3, "end": 1.0},
        "output": {"snapshots": [0.9]},
    }, {"material.G_inf": "pressure", "material.G1": "pressure", "material.tau1": "time", "indenter.R": "length",
        "load.history": ("time", "length"), "tangential.friction": "one", "tangential.amplitude": "length",
        "tangential.frequency": "one", "tangential.start": "time", "tangential.end": "time",
        "output.snapshots": "time"}),
}
HISTORY = {"t": "time", "d": "length", "F": "force", "a": "length", "v": "velocity", "u": "length", "Fx": "force",
           "c": "length"}
PROFILES = {"t": "time", "r": "length", "p": "pressure", "w": "length", "tau": "pressure"}
SUMMARY = {"max_force": "force", "max_depth": "length", "max_radius": "length", "final_force": "force",
           "final_depth": "length", "time_step": "time", "half_width": "length", "restitution": "one",
           "contact_time": "time", "rebound_velocity": "velocity", "dissipated_energy": "energy",
           "max_tangential_force": "force", "min_stick_radius": "length", "dissipated_energy_per_cycle": "energy",
           "steps": "one", "elements": "one"}


def in_system(case: dict, dimensions: dict, system: str) -> dict:
    """The case with every value divided by its unit's SI size, and `units = system`."""
    scale = scales(system)
    twin = copy.deepcopy(case)
    twin["units"] = system
    for key, dimension in dimensions.items():
        table, name = key.split(".")
        value = twin[table][name]
        if isinstance(dimension, tuple):
            twin[table][name] = [[x / scale[d] for x, d in zip(row, dimension)] for row in value]
        elif isinstance(value, list):
            twin[table][name] = [x / scale[dimension] for x in value]
        else:
            twin[table][name] = value / scale[dimension]
    return twin


def assert_twins(si: mdr.Result, twin: mdr.Result, system: str, tolerance: float, name: str) -> None:
    scale = scales(system)
    assert si.summary["units"] == "SI" and twin.summary["units"] == system
    assert set(twin.history) == set(si.history) and set(twin.profiles) == set(si.profiles)
    for column, dimension in HISTORY.items():
        if column in si.history and si.history[column].size:
            np.testing.assert_allclose(twin.history[column] * scale[dimension], si.history[column], rtol=0,
                                       atol=tolerance * np.abs(si.history[column]).max(), err_msg=f"{name}: {column}")
    for column, dimension in PROFILES.items():
        if column in si.profiles and si.profiles[column].size:
            np.testing.assert_allclose(twin.profiles[column] * scale[dimension], si.profiles[column], rtol=0,
                                       atol=tolerance * np.abs(si.profiles[column]).max(), err_msg=f"{name}: {column}")
    for key, dimension in SUMMARY.items():
        if key in si.summary:
            expected = pytest.approx(si.summary[key], rel=tolerance, abs=1e-300)
            assert twin.summary[key] * scale[dimension] == expected, key


@pytest.mark.parametrize("system", sorted(SYSTEMS))
@pytest.mark.parametrize("name", sorted(CASES))
def test_the_solver_has_no_absolute_scale(name, system):
    """With the same numerics (steps, elements, half-width in the twin's units; a coarse foundation, which does not
    matter here), a twin is its SI run to round-off: the solver has no constant with a unit."""
    case, dimensions = CASES[name]
    resolved = mdr.run(case).summary
    case = dict(case, numerics={"elements": 300, "time_step": resolved["time_step"],
                                "half_width": resolved["half_width"]})
    twin = in_system(case, dict(dimensions, **{"numerics.time_step": "time", "numerics.half_width": "length"}),
                     system)
    assert_twins(mdr.run(case), mdr.run(twin), system, 1e-9, name)


@pytest.mark.parametrize("system", sorted(SYSTEMS))
@pytest.mark.parametrize("name", sorted(CASES))
def test_a_case_in_any_declared_system_is_its_si_twin(name, system):
    """With the default numerics too, to their accuracy (1e-3; the summary): the estimates that size them (the
    elastic impact, the elastic radius under force control) bisect from a start of 1 in the case's units, so the
    time step and the half-width differ in the fifth digit from system to system."""
    case, dimensions = CASES[name]
    si = mdr.run(case)
    twin = mdr.run(in_system(case, dimensions, system))
    assert twin.summary["units"] == system
    scale = scales(system)
    for key, dimension in SUMMARY.items():
        if key in si.summary and key not in ("steps", "time_step", "half_width"):
            assert twin.summary[key] * scale[dimension] == pytest.approx(si.summary[key], rel=1e-3, abs=1e-300), key


def test_printed_names_are_the_declared_systems():
    case, dimensions = CASES["impact"]
    for system in ("SI", *SYSTEMS):
        twin = case if system == "SI" else in_system(case, dimensions, system)
        length, force, pressure, mass = NAMES[system]
        description = mdr.check(twin)
        assert f"G(0+) = " in description and f" {pressure}, G(inf)" in description, description
        assert f" {mass} at v0 = " in description and f" {length}/s" in description, description
        assert description.endswith("" if system == "SI" else f" [units {system}]"), description
        names = mdr._mdr._unit_system(system)
        assert (names["length"], names["force"], names["pressure"], names["mass"]) == (length, force, pressure, mass)
        assert names["velocity"] == f"{length}/s" and names["compliance"] == f"1/{pressure}"


def test_figures_name_the_declared_units():
    case, dimensions = CASES["displacement"]
    result = mdr.run(in_system(case, dimensions, "um-nN-s"))
    axes = mdr.plot.force_depth(result.history, units=result.summary)
    assert (axes.get_xlabel(), axes.get_ylabel()) == ("depth d [µm]", "normal force F [nN]")
    axes = mdr.plot.pressure_profiles(result.profiles, units="um-nN-s")
    assert axes.get_ylabel() == "pressure p [kPa]"
    assert mdr.plot.force_time(mdr.run(case).history).get_ylabel() == "normal force F [N]"
    import matplotlib.pyplot as plt

    plt.close("all")


def test_unknown_system_names_the_known_ones():
    case = dict(CASES["displacement"][0], units="nano")
    with pytest.raises(mdr.InvalidInput, match=r'^units = "nano": unknown unit system; one of SI, mm-N-s, '
                                               r'um-nN-s, nm-nN-s$'):
        mdr.check(case)


def test_the_command_line_reports_in_the_declared_units(mdr_binary, tmp_path):
    case, dimensions = CASES["impact"]
    import tomli_w

    path = tmp_path / "case.toml"
    path.write_text(tomli_w.dumps(in_system(case, dimensions, "mm-N-s")), encoding="utf-8")
    completed = subprocess.run([mdr_binary, "run", str(path), "--out", str(tmp_path / "out")], capture_output=True,
                               text=True, timeout=120)
    assert completed.returncode == 0, completed.stderr
    assert "max force" in completed.stdout and " N, max depth " in completed.stdout
    assert " mm, max contact radius " in completed.stdout and " mm/s\n" in completed.stdout
    assert "MPa" in completed.stdout and " t at v0 = " in completed.stdout


MODEL_CASE = """{units}
[material]
model = "kelvin_voigt"
G = {G}
eta = {eta}
[indenter]
shape = "cone"
slope_deg = 20.0
[load]
control = "displacement"
history = [[0.0, 0.0], [1.0, {depth}]]
"""


def test_check_prints_the_model_in_the_declared_units(mdr_binary, tmp_path):
    """`mdr check` names the model's keys in the case's units (kPa, kPa s in um-nN-s); SI as it always printed."""
    def check(text):
        path = tmp_path / "case.toml"
        path.write_text(text, encoding="utf-8")
        completed = subprocess.run([mdr_binary, "check", str(path)], capture_output=True, text=True, timeout=60)
        assert completed.returncode == 0, completed.stderr
        return completed.stdout

    cells = check(MODEL_CASE.format(units='units = "um-nN-s"', G=2.0, eta=0.5, depth=1.0))
    assert "kelvin_voigt (G = 2 kPa, eta = 0.5 kPa s) (G(0+) = inf kPa, G(inf) = 2 kPa, " in cells, cells
    assert " over t = 0 .. 1 s [units um-nN-s]" in cells, cells
    si = check(MODEL_CASE.format(units="", G=2.0e3, eta=500.0, depth=1.0e-6))
    assert si == ("ok: cone slope_deg = 20 (half_angle_deg = 70) on a viscoelastic half-space kelvin_voigt "
                  "(G = 2000 Pa, eta = 500 Pa s) (G(0+) = inf Pa, G(inf) = 2000 Pa, 0 branch(es)), displacement "
                  "control, 2 history points over t = 0 .. 1 s\n"), si


def write_flat_punch_curve(path, length, force):
    """A flat punch of radius 5 um pressed 1 um in 1 s into an elastic 2 kPa body: F = 8 G a d (Sneddon), the
    columns in data units of `length` and `force` [m, N]."""
    a, G = 5.0e-6, 2.0e3
    t = np.linspace(0.0, 1.0, 101)
    d = 1.0e-6 * t
    rows = ["t,d,F"] + [f"{ti!r},{di / length!r},{8.0 * G * a * di / force!r}" for ti, di in zip(t, d)]
    path.write_text("\n".join(rows) + "\n", encoding="utf-8")


def fit_flat_punch(tmp_path, units, G, a, data_file, data_units):
    import tomli_w

    case = {"material": {"model": "elastic", "G": G}, "indenter": {"shape": "flat", "a": a},
            "fit": {"free": ["material.G"], "contact_point": "fixed", "baseline": "fixed", "elements": 200,
                    "data": [{"file": data_file, "time": "t", "depth": "d", "force": "F", "units": data_units}]}}
    if units != "SI":
        case["units"] = units
    path = tmp_path / f"fit_{units}.toml"
    path.write_text(tomli_w.dumps(case), encoding="utf-8")
    return mdr.fit(str(path))


def test_fit_data_are_converted_to_the_declared_system(tmp_path):
    """The audit's flat punch: data in um and nN fitted in an um-nN-s case give G in kPa (not 1e-3 of it), the
    same as data in m and N there, and the SI twin's G in Pa / 1e3; fit.json and the fit figures name the units."""
    write_flat_punch_curve(tmp_path / "si.csv", 1.0, 1.0)
    write_flat_punch_curve(tmp_path / "cells.csv", 1.0e-6, 1.0e-9)
    si = fit_flat_punch(tmp_path, "SI", 5.0e2, 5.0e-6, "si.csv", {})
    cells = fit_flat_punch(tmp_path, "um-nN-s", 0.5, 5.0, "cells.csv", {"length": "um", "force": "nN"})
    named_si = fit_flat_punch(tmp_path, "um-nN-s", 0.5, 5.0, "si.csv", {"length": "m", "force": "N"})
    assert si.parameters["material.G"] == pytest.approx(2.0e3, rel=1e-3)  # the element model's discretisation
    for result in (cells, named_si):
        assert result.parameters["material.G"] * 1e3 == pytest.approx(si.parameters["material.G"], rel=1e-6)
        assert result.summary["units"] == "um-nN-s"
    assert si.summary["units"] == "SI"
    import matplotlib.pyplot as plt

    table = {"curve": np.array(["c"] * 3), "t": np.arange(3.0), "measured": np.ones(3), "model": np.ones(3),
             "residual": np.zeros(3)}
    axes = mdr.plot.fit_curves(table, units=cells.summary)
    assert axes.get_ylabel() == "force [nN] or depth [µm]"
    assert mdr.plot.fit_curves(table).get_ylabel() == "force [N] or depth [m]"
    drops = {"curve": np.array(["drops:restitution"] * 3 + ["drops:contact_time"] * 3),
             "t": np.tile([1.0, 2.0, 3.0], 2), "measured": np.full(6, 0.5), "model": np.full(6, 0.5)}
    bottom = mdr.plot.fit_rebounds(drops, units="nm-nN-s").figure.axes[1]
    assert (bottom.get_xlabel(), bottom.get_ylabel()) == ("approach speed v0 [nm/s]", "contact time T [ms]")
    plt.close("all")
