"""mdr.ConvertedMaterial (issue 12): the factories of converted models keep the error, window and frequencies of
the conversion; the complex modulus at frequencies far outside the window against the closed forms."""

import math
import pickle
import subprocess

import numpy as np
import pytest

import mdr


def power_law_modulus(G0, beta, t0, omega):
    return G0 * math.gamma(1 - beta) * (1j * omega * t0) ** beta


@pytest.mark.parametrize("beta", [0.1, 0.5, 0.9])
def test_power_law_keeps_its_certificate_and_matches_far_frequencies(beta):
    G0, t0 = 2e3, 0.5
    frequencies = [1e7, 1e-4]  # four decades beyond each end of the window (1e-3, 1)
    material = mdr.Material.power_law(G0, beta, t0, window=(1e-3, 1.0), frequencies=frequencies)
    assert isinstance(material, mdr.ConvertedMaterial) and isinstance(material, mdr.Material)
    assert 0 < material.material_error <= 1e-4
    assert material.material_window == (1e-3, 1.0)
    assert material.material_frequencies == [1e-4, 1e7]  # ascending
    for omega in frequencies:
        exact = power_law_modulus(G0, beta, t0, omega)
        assert abs(material.complex_modulus(omega) - exact) / abs(exact) <= material.material_error


def test_springpot_family_keeps_its_certificate():
    gel = mdr.Material.fractional_maxwell(G=1e4, c=2e3, alpha=0.4, window=(1e-3, 1e2), frequencies=[1e5],
                                          tolerance=1e-5)
    assert 0 < gel.material_error <= 1e-5 and gel.material_window == (1e-3, 1e2)
    springpot = 2e3 * (1j * 1e5) ** 0.4
    exact = 1 / (1 / 1e4 + 1 / springpot)
    assert abs(gel.complex_modulus(1e5) - exact) / abs(exact) <= gel.material_error
    plain = mdr.Material.springpot(c=1e3, alpha=0.5, window=(1e-2, 1.0))
    assert plain.material_frequencies == []


def test_table_reports_its_fit_residual_over_the_data():
    t = np.geomspace(1e-3, 1e2, 30)
    table = mdr.Material.from_table(t=t, G=1e6 + 2e6 * np.exp(-t / 0.1))
    assert isinstance(table, mdr.ConvertedMaterial)
    assert table.material_error < 1e-6
    assert table.material_window == (pytest.approx(1e-3), pytest.approx(1e2))
    assert table.material_frequencies == []


def test_exact_models_and_derived_materials_have_none():
    standard = mdr.Material.standard(1e6, 2e6, 0.1)
    assert type(standard) is mdr.Material
    assert standard.material_error is None and standard.material_window is None
    assert standard.material_frequencies is None
    cell = mdr.Material.power_law(1e3, 0.2, window=(1e-3, 1.0))
    derived = cell.series(standard)  # the error of a combination is the case's (summary.json), not the Material's
    assert type(derived) is mdr.Material and derived.material_error is None


def test_converted_material_pickles_with_its_certificate():
    cell = mdr.Material.power_law(1e3, 0.2, window=(1e-3, 1.0), frequencies=[50.0])
    copy = pickle.loads(pickle.dumps(cell))
    assert type(copy) is mdr.ConvertedMaterial
    assert copy.terms == cell.terms and copy.G_inf == cell.G_inf
    assert (copy.material_error, copy.material_window, copy.material_frequencies) == \
        (cell.material_error, cell.material_window, cell.material_frequencies)
    assert repr(copy).startswith("ConvertedMaterial(G_inf=0, eta=0, branches=")


def test_frequencies_are_checked():
    with pytest.raises(ValueError, match=r"^frequencies\[0\] = -1: must be > 0$"):
        mdr.Material.power_law(1e3, 0.2, window=(1e-3, 1.0), frequencies=[-1.0])
    with pytest.raises(ValueError, match=r"^window = \(missing\)"):
        mdr.Material.power_law(1e3, 0.2, frequencies=[1.0])
    with pytest.raises(TypeError, match=r"unexpected keyword argument 'frequencies'"):
        mdr.Material.standard(1.0, 1.0, 1.0, frequencies=[1.0])


def test_harmonic_case_reports_its_frequencies():
    case = {
        "material": {"model": "fractional_kelvin_voigt", "G": 1e5, "c": 1e3, "alpha": 0.5},
        "indenter": {"shape": "flat", "a": 1e-3},
        "load": {"control": "displacement", "history": [[0.0, 0.0], [0.01, 1e-5], [0.05, 1e-5]],
                 "harmonic": {"amplitude": 2e-6, "frequency": 200.0, "start": 0.01, "end": 0.05}},
        "numerics": {"elements": 1},
    }
    result = mdr.run(case)
    omega = 2 * math.pi * 200.0
    assert result.summary["material_frequencies"] == [pytest.approx(omega)]
    assert 0 < result.summary["material_error"] <= 1e-4
    assert "and at omega = 1257 rad/s" in result.description


def test_material_command_tabulates_the_harmonic_frequency(tmp_path, mdr_binary):
    case = tmp_path / "case.toml"
    case.write_text('[material]\nmodel = "springpot"\nc = 1e3\nalpha = 0.5\n[indenter]\nshape = "flat"\na = 1e-3\n'
                    '[load]\ncontrol = "displacement"\nhistory = [[0.0, 0.0], [0.01, 1e-5], [0.05, 1e-5]]\n'
                    'harmonic = { amplitude = 1e-7, frequency = 100.0, start = 0.01, end = 0.05 }\n', encoding="utf-8")
    completed = subprocess.run([mdr_binary, "material", str(case), "--out", str(tmp_path / "m")], capture_output=True,
                               text=True, timeout=60)
    assert completed.returncode == 0, completed.stderr
    assert "and at omega = 628.3 rad/s" in completed.stdout
    dynamic = np.genfromtxt(tmp_path / "m" / "dynamic.csv", delimiter=",", names=True)
    row = np.flatnonzero(np.isclose(dynamic["omega"], 2 * math.pi * 100.0, rtol=1e-12))
    assert row.size == 1
    np.testing.assert_allclose(dynamic["storage"][row], dynamic["storage_model"][row], rtol=1e-4)
    np.testing.assert_allclose(dynamic["loss"][row], dynamic["loss_model"][row], rtol=1e-4)
