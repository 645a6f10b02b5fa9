"""mdr.sweep of an mdr.ContactCase: each point built from the case's objects (io::CaseObjects), without text, with
the keys, rules and messages of the file sweep, and the parts no key names used as they are."""

from __future__ import annotations

import math

import numpy as np
import pytest

import mdr

STANDARD_CASE = """title = "standard"
[material]
model = "standard"
G_inf = 1.0e3
G1 = 2.0e3
tau1 = 0.1
[indenter]
shape = "sphere"
R = 1.0e-5
[load]
control = "displacement"
history = [[0.0, 0.0], [0.5, 1.0e-6], [1.0, 1.0e-6]]
[output]
snapshots = [0.5]
[numerics]
elements = 300
time_step = 0.01
"""

POWER_LAW_CASE = """[material]
model = "power_law"
G0 = 1.0e3
beta = 0.2
[indenter]
shape = "cone"
slope_deg = 20.0
[load]
control = "force"
history = [[0.0, 0.0], [0.2, 1.0e-7], [1.0, 1.0e-7]]
[numerics]
elements = 300
"""

RAMP_AND_HOLD = [(0.0, 0.0), (0.5, 1e-6), (1.0, 1e-6)]


def case_file(tmp_path, text):
    path = tmp_path / "case.toml"
    path.write_text(text)
    return path


def assert_same_tables(a, b):
    assert list(a) == list(b)
    for column in a:
        if column == "wall_seconds":
            continue
        if column == "error":
            assert list(a[column]) == list(b[column])
        else:
            np.testing.assert_array_equal(a[column], b[column], err_msg=column)


@pytest.mark.parametrize("text, vary", [
    (STANDARD_CASE, {"material.G1": [2e3, -1.0, 4e3], "indenter.R": [1e-5, 2e-5],
                     "load.history[1][1]": [1e-6, 2e-6]}),
    (STANDARD_CASE, {"load.history[1][0]": [0.4, 0.6, 1.5], "output.snapshots[0]": [0.3],
                     "numerics.time_step": [0.01, 0.02]}),
    (POWER_LAW_CASE, {"material.beta": [0.2, 0.35], "indenter.slope_deg": [20.0, 30.0],
                      "load.history[1][1]": [1e-7, 3e-7]}),
    (STANDARD_CASE, {"numerics.elements": [300, 600, 2.5]}),
])
def test_the_objects_give_the_file_sweeps_rows_bit_for_bit(tmp_path, text, vary):
    """The same case as a file and as the objects read from it (mdr.ContactCase.from_file): identical tables, the
    failed points' messages (G1 < 0; a history point after the next) included."""
    path = case_file(tmp_path, text)
    from_file = mdr.sweep(path, vary, jobs=2)
    from_objects = mdr.sweep(mdr.ContactCase.from_file(path), vary, jobs=2)
    assert_same_tables(from_file, from_objects)
    expected_errors = {"material.G1": "material.G1 = -1: must be > 0",
                       "load.history[1][0]": "load.history[2].t = 1: times must not go backwards (previous point is "
                                             "at t = 1.5)",
                       "numerics.elements": "numerics.elements = 2.5: must be an integer >= 1"}
    assert set(from_file["error"]) - {""} == {expected_errors[key] for key in vary if key in expected_errors}


def test_a_file_sweep_sets_a_count_as_an_integer(tmp_path):
    """`numerics.elements` (written as an integer) takes whole values: each row runs with them (it was refused at
    every point as `numerics.elements = 300: must be an integer >= 1`, the value set as a float)."""
    table = mdr.sweep(case_file(tmp_path, STANDARD_CASE), {"numerics.elements": [300, 600]}, jobs=1)
    assert list(table["error"]) == ["", ""]
    assert list(table["elements"]) == [300, 600]


def test_a_converted_material_keeps_its_certificate_when_another_key_varies():
    """The power law converted by its factory over (1e-5, 100) s with tolerance 1e-3: every point runs on that series
    with that certificate (material_error of the material given); the same material in a dict is converted again
    over the case's window, with another certificate."""
    cell = mdr.Material.power_law(G0=1e3, beta=0.2, window=(1e-5, 100.0), tolerance=1e-3)
    case = mdr.ContactCase(material=cell, indenter=mdr.Indenter.sphere(R=1e-5), control=mdr.DisplacementControl(),
                           history=RAMP_AND_HOLD, numerics=mdr.Numerics(elements=300))
    assert case.material_window == (1e-5, 100.0)
    vary = {"load.history[1][1]": [1e-6, 2e-6], "indenter.R": [1e-5, 3e-5]}
    table = mdr.sweep(case, vary, jobs=1)
    assert list(table["error"]) == [""] * 4
    assert list(table["material_error"]) == [cell.material_error] * 4
    converted_again = mdr.sweep(material=cell, indenter=mdr.Indenter.sphere(R=1e-5),
                                load={"control": "displacement", "history": RAMP_AND_HOLD},
                                numerics={"elements": 300}, vary=vary, jobs=1)
    assert converted_again["material_error"][0] != cell.material_error
    # Hertz on the same series: F ~ sqrt(R) d^(3/2) at each time, so the peak force scales exactly so.
    force = table["max_force"].reshape(2, 2)
    assert force[0, 1] / force[0, 0] == pytest.approx(math.sqrt(3.0), rel=1e-12)
    assert force[1, 0] / force[0, 0] == pytest.approx(2.0 ** 1.5, rel=1e-12)


def test_a_varied_converted_material_is_converted_again_over_its_own_window():
    """material.beta at its own value: the definition converted again over the certificate's window with its
    tolerance, the same series as the material given, so the run of the case itself."""
    cell = mdr.Material.power_law(G0=1e3, beta=0.2, window=(1e-5, 100.0), tolerance=1e-3)
    case = mdr.ContactCase(material=cell, indenter=mdr.Indenter.sphere(R=1e-5), control=mdr.DisplacementControl(),
                           history=RAMP_AND_HOLD, numerics=mdr.Numerics(elements=300))
    table = mdr.sweep(case, {"material.beta": [0.2, 0.3]}, jobs=1)
    assert table["max_force"][0] == mdr.run(case).summary["max_force"]
    assert table["material_error"][0] == cell.material_error
    assert table["max_force"][1] != table["max_force"][0]


def test_a_plain_material_is_varied_by_the_keys_of_its_prony_table():
    """An mdr.Material that is its own series has the keys of the table it stands for in a dict (G_inf, terms)."""
    material = mdr.Material.prony(G_inf=1e3, terms=[(2e3, 0.1)])
    case = mdr.ContactCase(material=material, indenter=mdr.Indenter.sphere(R=1e-5), control=mdr.DisplacementControl(),
                           history=RAMP_AND_HOLD, numerics=mdr.Numerics(elements=300))
    vary = {"material.G_inf": [1e3, 2e3], "material.terms[0][1]": [0.1, 0.2]}
    as_dict = mdr.sweep(material=material, indenter=mdr.Indenter.sphere(R=1e-5),
                        load={"control": "displacement", "history": RAMP_AND_HOLD}, numerics={"elements": 300},
                        vary=vary, jobs=1)
    assert_same_tables(as_dict, mdr.sweep(case, vary, jobs=1))


@pytest.mark.parametrize("key", ["material.nope", "material.tau9", "indenter.material.G", "load.history[3][1]",
                                 "load.history[0][2]", "layer.thickness", "load.harmonic.frequency", "title"])
def test_a_key_the_case_lacks_is_refused_as_by_the_file_sweep(tmp_path, key):
    path = case_file(tmp_path, STANDARD_CASE)
    with pytest.raises(mdr.InvalidInput) as from_file:
        mdr.sweep(path, {key: [1.0]}, jobs=1)
    with pytest.raises(mdr.InvalidInput) as from_objects:
        mdr.sweep(mdr.ContactCase.from_file(path), {key: [1.0]}, jobs=1)
    assert str(from_file.value).startswith(f"--vary = {key}: no such numeric key in the case file")
    assert str(from_objects.value).startswith(f"--vary = {key}: no such numeric key among those a case of objects")


def test_an_end_given_equal_to_the_default_stays_given(tmp_path):
    """`load.end = 1` equal to the history's last time: the file sweep stops there when the last point moves later,
    and so do the objects (the case records that its end was given, ContactCase::end_given; before, the objects took
    it for the default and ran to the new last time); `load.end` is then a key of both. Without `load.end` both run
    to the history's new end."""
    given = case_file(tmp_path, STANDARD_CASE.replace("[output]", "end = 1.0\n[output]"))
    vary = {"load.history[2][0]": [1.0, 2.0]}
    from_file = mdr.sweep(given, vary, jobs=1)
    assert from_file["steps"][1] == pytest.approx(from_file["steps"][0], rel=0.2)  # both stop at 1 s
    assert_same_tables(from_file, mdr.sweep(mdr.ContactCase.from_file(given), vary, jobs=1))
    assert_same_tables(mdr.sweep(given, {"load.end": [0.8, 1.0]}, jobs=1),
                       mdr.sweep(mdr.ContactCase.from_file(given), {"load.end": [0.8, 1.0]}, jobs=1))
    as_objects = mdr.ContactCase(material=mdr.Material.elastic(G=1e3), indenter=mdr.Indenter.sphere(R=1e-5),
                                 control=mdr.DisplacementControl(), history=RAMP_AND_HOLD, end=1.0,
                                 numerics=mdr.Numerics(elements=300, time_step=0.01))
    steps = mdr.sweep(as_objects, vary, jobs=1)["steps"]
    assert steps[1] == pytest.approx(steps[0], rel=0.2)
    default = case_file(tmp_path, STANDARD_CASE)
    from_file = mdr.sweep(default, vary, jobs=1)
    assert from_file["steps"][1] > 1.5 * from_file["steps"][0]  # the second runs to 2 s
    assert_same_tables(from_file, mdr.sweep(mdr.ContactCase.from_file(default), vary, jobs=1))


def test_an_oblique_impacts_friction_is_its_controls():
    """An oblique impact's friction (`tangential.friction` in a file) is its control's (ImpactControl.oblique), which
    the object sweep sets by the key its part declares (before, it was refused)."""
    case = mdr.ContactCase(material=mdr.Material.elastic(G=1e6), indenter=mdr.Indenter.sphere(R=1e-3),
                           control=mdr.ImpactControl(mass=1e-3, velocity=0.1,
                                                     oblique=mdr.ObliqueImpact(friction=0.3, spin=2.0)),
                           numerics=mdr.Numerics(elements=100))
    table = mdr.sweep(case, {"tangential.friction": [0.3, 0.0]}, jobs=1)
    assert list(table["error"]) == ["", ""]
    assert table["max_force"][0] == mdr.run(case).summary["max_force"]


def test_a_count_takes_integers_only():
    case = mdr.ContactCase(material=mdr.Material.elastic(G=1e3), indenter=mdr.Indenter.sphere(R=1e-5),
                           control=mdr.DisplacementControl(), history=RAMP_AND_HOLD,
                           numerics=mdr.Numerics(elements=300))
    table = mdr.sweep(case, {"numerics.elements": [300, 600, 2.5]}, jobs=1)
    assert list(table["elements"][:2]) == [300, 600]
    assert list(table["error"]) == ["", "", "numerics.elements = 2.5: must be an integer >= 1"]
