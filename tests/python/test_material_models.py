"""The registry of material models from Python (issue 9) and the power-law material (issue 12)."""

import math
import os
import pathlib
import subprocess
import sys

import numpy as np
import pytest

import mdr

ROOT = pathlib.Path(__file__).resolve().parents[2]


def test_stubs_and_docs_follow_the_registry(package_env):
    completed = subprocess.run([sys.executable, str(ROOT / "scripts" / "material-reference"), "--check"],
                               capture_output=True, text=True, timeout=60, env=package_env)
    assert completed.returncode == 0, completed.stderr


def test_every_registered_model_is_a_factory():
    for model in mdr._mdr._material_models():
        assert callable(getattr(mdr.Material, model["name"])), model["name"]
        assert model["documentation"] in getattr(mdr.Material, model["name"]).__doc__


def test_factories_take_positional_and_keyword_arguments():
    a = mdr.Material.standard(1e6, 2e6, 0.1)
    b = mdr.Material.standard(G_inf=1e6, tau1=0.1, G1=2e6)
    assert a.terms == b.terms == [(2e6, 0.1)] and a.G_inf == b.G_inf == 1e6
    with pytest.raises(TypeError, match=r"^elastic\(\) got an unexpected keyword argument 'H'; valid: G$"):
        mdr.Material.elastic(H=3)
    with pytest.raises(TypeError, match=r"^standard\(\) missing required argument 'G1'"):
        mdr.Material.standard(G_inf=1.0, tau1=1.0)
    with pytest.raises(TypeError, match=r"^G_inf = 'a': must be a number$"):
        mdr.Material.standard("a", 1.0, 1.0)
    with pytest.raises(ValueError, match=r"^G1 = -1: must be > 0$"):
        mdr.Material.standard(1.0, -1.0, 1.0)


@pytest.mark.parametrize("model, arguments, key", [("elastic", {"G": True}, "G"),
                                                   ("prony", {"G_inf": 1e3, "terms": [(True, 1.0)]}, "terms")])
def test_factories_refuse_a_bool_as_a_case_file_does(model, arguments, key):
    """A bool is an int to Python and was taken as 1.0 (prony's terms [(True, 1.0)] a modulus of 1 Pa); a case file
    refuses it where it wants a number, and so do the controls' keywords."""
    with pytest.raises(TypeError, match=rf"^{key} = .*True.*: must be a "):
        getattr(mdr.Material, model)(**arguments)


@pytest.mark.parametrize("beta", [0.05, 0.3, 0.7])
def test_power_law_series_is_certified_over_its_window(beta):
    G0, t0 = 2e3, 0.5
    material = mdr.Material.power_law(G0, beta, t0, window=(1e-4, 1e2))
    t = np.geomspace(1e-4, 1e2, 777)
    np.testing.assert_allclose(material.relaxation(t), G0 * (t / t0) ** -beta, rtol=1e-4, atol=0)
    omega = 1 / t
    exact = G0 * math.gamma(1 - beta) * (1j * omega * t0) ** beta
    assert np.max(np.abs(material.complex_modulus(omega) - exact) / np.abs(exact)) < 1e-4
    with pytest.raises(ValueError, match=r"^window = \(missing\)"):
        mdr.Material.power_law(G0, beta)  # a value the model needs to be built, not an argument of Python's
    with pytest.raises(ValueError, match=r"^beta = 1: must be > 0 and < 1$"):
        mdr.Material.power_law(G0, 1.0, window=(1e-3, 1.0))


def test_power_law_case_reports_its_certificate():
    case = {
        "material": {"model": "power_law", "G0": 1e3, "beta": 0.2, "t0": 1.0},
        "indenter": {"shape": "sphere", "R": 1e-5},
        "load": {"control": "displacement", "history": [[0.0, 0.0], [1.0, 1e-6]]},
        "numerics": {"elements": 200},
    }
    result = mdr.run(case)
    assert 0 < result.summary["material_error"] <= 1e-4
    assert result.summary["material_window"] == [pytest.approx(1.0 / 2000 / 5), 1.0]
    assert "power_law (G0 = 1000 Pa, beta = 0.2, t0 = 1 s)" in result.description
    exact = 8 * math.sqrt(1e-5) * 1e3 * 1e-9 * math.gamma(1.5) * math.gamma(0.8) / math.gamma(2.3)
    assert result.summary["max_force"] == pytest.approx(exact, rel=1e-3)  # 200 elements: coarse


TRUTH = mdr.Material.prony(G_inf=1e5, terms=[(3e5, 2.3e-3), (1e6, 0.047), (4e5, 1.9)])


def test_table_from_arrays_recovers_a_prony_series():
    t = np.geomspace(1e-4, 1e2, 41)
    fitted = mdr.Material.from_table(t=t, G=TRUTH.relaxation(t))
    dense = np.geomspace(1e-4, 1e2, 1001)
    np.testing.assert_allclose(fitted.relaxation(dense), TRUTH.relaxation(dense), rtol=1e-6)
    w = np.geomspace(1e-2, 1e4, 41)
    modulus = TRUTH.complex_modulus(w)
    fitted = mdr.Material.table(omega=w, storage=modulus.real, loss=modulus.imag)
    np.testing.assert_allclose(fitted.relaxation(dense), TRUTH.relaxation(dense), rtol=1e-6)


def test_table_case_from_a_csv_next_to_the_case(tmp_path):
    t = np.geomspace(1e-3, 10.0, 31)
    rows = "\n".join(f"{x!r},{y!r}" for x, y in zip(t, TRUTH.creep(t)))
    (tmp_path / "creep.csv").write_text("t,J\n" + rows + "\n", encoding="utf-8")
    (tmp_path / "case.toml").write_text(
        '[material]\nmodel = "table"\nfile = "creep.csv"\n'
        '[indenter]\nshape = "sphere"\nR = 0.01\n'
        '[load]\ncontact = 1\n'.replace("contact = 1", 'control = "displacement"\nhistory = [[0.0, 0.0], [1.0, 1e-5]]')
        + '[numerics]\nelements = 100\n', encoding="utf-8")
    elsewhere = subprocess.run([os.environ.get("MDR_BINARY", "build/bin/mdr"), "check", str(tmp_path / "case.toml")],
                               capture_output=True, text=True, timeout=60, cwd="/")
    assert elsewhere.returncode == 0, elsewhere.stderr
    assert 'table (file = "creep.csv")' in elsewhere.stdout and "fit residual" in elsewhere.stdout
    result = mdr.run(str(tmp_path / "case.toml"))
    assert result.summary["material_error"] < 1e-6
    assert result.summary["material_window"] == [pytest.approx(1e-3), pytest.approx(10.0)]
    (tmp_path / "creep.csv").write_text("t,J\n1,2\n2,1\n", encoding="utf-8")
    refused = subprocess.run([os.environ.get("MDR_BINARY", "build/bin/mdr"), "check", str(tmp_path / "case.toml")],
                             capture_output=True, text=True, timeout=60)
    assert refused.returncode == 2
    assert refused.stderr.startswith("mdr: error: material.J[1] = 1: below the earlier 2: a creep compliance cannot")


def power_law_case(**material):
    return {
        "material": dict({"model": "power_law", "G0": 1e3, "beta": 0.2}, **material),
        "indenter": {"shape": "sphere", "R": 1e-5},
        "load": {"control": "displacement", "history": [[0.0, 0.0], [1.0, 1e-6]]},
    }


@pytest.mark.parametrize("material,message", [
    ({"beta": 1.5}, r"^material\.beta = 1\.5: must be > 0 and < 1$"),
    ({"G0": -1.0}, r"^material\.G0 = -1: must be > 0$"),
    ({"xyzzy": 1.0}, r"^material\.xyzzy = 1: unknown key; valid keys: model, G0, beta, t0, tolerance, K, bulk$"),
    ({"bet": 0.3}, r"^material\.bet = 0\.3: unknown key; did you mean 'beta'\?$"),
    ({"tolerance": 0.5}, r"^material\.tolerance = 0\.5: must be from 1e-10 to 0\.1$"),
    ({"bulk": {"model": "power_law", "G0": 1e3, "beta": 0.2}}, r"^material\.bulk\.G0 = 1000: unknown key"),
    ({"bulk": {"model": "power_law", "K0": -1e3, "beta": 0.2}}, r"^material\.bulk\.K0 = -1000: must be > 0$"),
])
def test_power_law_case_errors_name_the_key(material, message):
    with pytest.raises(ValueError, match=message):
        mdr.check(power_law_case(**material))


def test_power_law_bulk_and_impact_windows():
    assert "with bulk power_law (K0 = 3000 Pa" in mdr.check(
        power_law_case(bulk={"model": "power_law", "K0": 3e3, "beta": 0.1}))
    impact = dict(power_law_case(), load={"control": "impact", "velocity": 1e-3})
    impact["indenter"] = {"shape": "sphere", "R": 1e-5, "mass": 1e-9}
    with pytest.raises(ValueError, match=r"^load\.end = \(missing\): a material converted to a Prony series"):
        mdr.check(impact)
    impact["load"]["end"] = 1e-2
    impact["numerics"] = {"time_step": 1e-6}
    assert "relative error" in mdr.check(impact)


def test_material_command_shows_model_and_series_side_by_side(tmp_path, package_env):
    case = tmp_path / "case.toml"
    case.write_text('[material]\nmodel = "power_law"\nG0 = 1e3\nbeta = 0.3\n[indenter]\nshape = "sphere"\nR = 1e-5\n'
                    '[load]\ncontrol = "displacement"\nhistory = [[0.0, 0.0], [1.0, 1e-6]]\n', encoding="utf-8")
    binary = os.environ.get("MDR_BINARY", "build/bin/mdr")
    completed = subprocess.run([binary, "material", str(case), "--out", str(tmp_path / "m")], capture_output=True,
                               text=True, timeout=60)
    assert completed.returncode == 0, completed.stderr
    assert completed.stdout.startswith("power_law (G0 = 1000 Pa, beta = 0.3, t0 = 1 s) as ")
    data = np.genfromtxt(tmp_path / "m" / "functions.csv", delimiter=",", names=True)
    assert data["t"][0] == pytest.approx(1e-4) and data["t"][-1] == pytest.approx(1.0)  # the certified window
    np.testing.assert_allclose(data["G_model"], 1e3 * data["t"] ** -0.3, rtol=1e-14)
    np.testing.assert_allclose(data["G"], data["G_model"], rtol=1e-4)
    dynamic = np.genfromtxt(tmp_path / "m" / "dynamic.csv", delimiter=",", names=True)
    np.testing.assert_allclose(dynamic["storage"], dynamic["storage_model"], rtol=1e-4)
    np.testing.assert_allclose(dynamic["loss"], dynamic["loss_model"], rtol=1e-4)
    figures = subprocess.run([sys.executable, "-m", "mdr", "plot", str(tmp_path / "m")], capture_output=True,
                             text=True, timeout=120, env=package_env)
    assert figures.returncode == 0, figures.stderr
    assert (tmp_path / "m" / "material.png").stat().st_size > 1000
