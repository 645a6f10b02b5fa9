"""An mdr.ConvertedMaterial in a case stands for its model (issue 23, item 1): the case converts it again over its
own window and harmonic frequencies, so an object gives exactly the result of the same [material] table given as a
dict, certificate included (before, it went in as its bare Prony series: other forces, no material_error)."""

import pickle

import numpy as np
import pytest

import mdr

RAMP_AND_HOLD = {"control": "displacement", "history": [[0.0, 0.0], [1e-3, 1e-6], [10.0, 1e-6]]}


def assert_same_run(material_object, material_table, load=RAMP_AND_HOLD):
    indenter = mdr.Indenter.sphere(R=1e-5)
    as_object = mdr.run(material=material_object, indenter=indenter, load=load)
    as_dict = mdr.run(material=material_table, indenter=indenter, load=load)
    assert as_object.history["t"].shape == as_dict.history["t"].shape
    for column, values in as_dict.history.items():
        np.testing.assert_allclose(as_object.history[column], values, rtol=1e-12, atol=0.0, err_msg=column)
    for key in ("material_error", "material_window"):
        assert key in as_object.summary
        assert as_object.summary[key] == as_dict.summary[key]
    return as_object


def test_power_law_object_runs_as_its_dict_with_the_cases_window():
    # The object is certified from 1e-3 s only; the case's window starts at a fifth of the ramp's steps
    # (docs/case-format.md), far below: the case converts the model again over its own window.
    cell = mdr.Material.power_law(G0=1e3, beta=0.2, t0=1, window=(1e-3, 10))
    result = assert_same_run(cell, {"model": "power_law", "G0": 1e3, "beta": 0.2, "t0": 1})
    assert result.summary["material_window"][0] < cell.material_window[0]
    assert result.summary["material_error"] <= 1e-4


def test_tolerance_and_the_springpots_go_with_the_object():
    gel = mdr.Material.fractional_maxwell(G=1e4, c=2e3, alpha=0.4, window=(1e-3, 1e2), tolerance=1e-6)
    assert_same_run(gel, {"model": "fractional_maxwell", "G": 1e4, "c": 2e3, "alpha": 0.4, "tolerance": 1e-6})


def test_table_object_runs_as_its_dict():
    t = np.geomspace(1e-4, 1e2, 40)
    G = 1e3 + 2e3 * np.exp(-t / 0.05) + 1e3 * np.exp(-t / 2.0)
    assert_same_run(mdr.Material.from_table(t=t, G=G), {"model": "table", "t": t, "G": G})


def test_table_file_is_found_from_any_directory(tmp_path, monkeypatch):
    t = np.geomspace(1e-4, 1e2, 40)
    G = 1e3 + 2e3 * np.exp(-t / 0.05)
    (tmp_path / "relaxation.csv").write_text("t,G\n" + "".join(f"{a!r},{b!r}\n" for a, b in zip(t, G)))
    monkeypatch.chdir(tmp_path)
    table = mdr.Material.from_table(file="relaxation.csv")
    monkeypatch.chdir(tmp_path.parent)
    assert_same_run(table, {"model": "table", "t": t, "G": G})


def test_the_definition_survives_a_pickle():
    cell = mdr.Material.power_law(1e3, 0.2, window=(1e-3, 1.0), tolerance=1e-5)
    copy = pickle.loads(pickle.dumps(cell))
    assert copy._definition == cell._definition == {"model": "power_law", "G0": 1e3, "beta": 0.2, "tolerance": 1e-5}
    assert_same_run(copy, {"model": "power_law", "G0": 1e3, "beta": 0.2, "tolerance": 1e-5})


def test_a_plain_material_is_still_its_own_series():
    standard = mdr.Material.standard(G_inf=1e3, G1=2e3, tau1=0.1)
    assert standard._definition is None
    result = mdr.run(material=standard, indenter=mdr.Indenter.sphere(R=1e-5), load=RAMP_AND_HOLD)
    assert "material_error" not in result.summary


@pytest.mark.parametrize("key", ["material.G0", "material.beta"])
def test_a_sweep_varies_the_objects_parameters(key):
    cell = mdr.Material.power_law(G0=1e3, beta=0.2, window=(1e-3, 10))
    values = {"material.G0": [1e3, 2e3], "material.beta": [0.2, 0.3]}[key]
    table = mdr.sweep(material=cell, indenter=mdr.Indenter.sphere(R=1e-5), load=RAMP_AND_HOLD,
                      vary={key: values}, jobs=1)
    assert list(table["error"]) == ["", ""]
    if key == "material.G0":  # linear viscoelasticity: the force scales with the modulus
        assert table["max_force"][1] / table["max_force"][0] == pytest.approx(2.0, rel=1e-12)
