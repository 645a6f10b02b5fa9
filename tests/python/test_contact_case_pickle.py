"""An mdr.ContactCase pickles over its typed parts, without text (python/bindings/case_state.cpp): the case read back
runs the same rows bit for bit, keeps a converted material's series and certificate, and whether its end was given;
each part's class pickles too."""

from __future__ import annotations

import pickle

import mdr
import numpy as np
import pytest
from test_sweep_contact_case import STANDARD_CASE, assert_same_tables, case_file
from test_sweep_contact_case_keys import (BULK_MODULUS, BULK_TABLE, FRETTING, HARMONIC, OBLIQUE, POWER_LAW, SHORE,
                                          SPRING, TANGENTIAL_HISTORY)

LAYER = STANDARD_CASE + '[layer]\nthickness = 2.0e-6\ninterface = "bonded"\n'
TWO_BODIES = STANDARD_CASE.replace('[load]', '[indenter.material]\nmodel = "elastic"\nG = 5.0e3\n[load]')
UNITS = SPRING.replace("[numerics]", "end = 12.0\n[numerics]")  # given, equal to the default


def round_trip(value):
    return pickle.loads(pickle.dumps(value))


def same_summary(a: dict, b: dict) -> None:
    assert a.keys() == b.keys()
    for key in a:
        if key != "wall_seconds":
            assert a[key] == b[key] or (a[key] != a[key] and b[key] != b[key]), key


@pytest.mark.parametrize("text, vary", [
    (STANDARD_CASE, {"material.G1": [2e3, 4e3]}),
    (LAYER, {"layer.thickness": [2e-6, 4e-6]}),
    (TWO_BODIES, {"indenter.material.G": [5e3, 1e4]}),
    (SPRING, {"load.spring_constant": [100.0, 300.0]}),
    (UNITS, {"load.history[2][0]": [11.0, 11.5]}),
    (OBLIQUE, {"load.spin": [0.0, 5.0]}),
    (SHORE, {"load.duration": [3.0, 1.5]}),
    (HARMONIC, {"load.harmonic.frequency": [15.9, 40.0]}),
    (BULK_MODULUS, {"material.K": [3e6, 1e7]}),
    (BULK_TABLE, {"material.bulk.eta": [2e5, 4e5]}),
    (POWER_LAW, {"material.beta": [0.2, 0.3]}),
    (FRETTING, {"tangential.amplitude": [1.5e-5, 3e-5]}),
    (TANGENTIAL_HISTORY, {"tangential.history[2][1]": [1e-5, 2e-5]}),
], ids=["standard", "layer", "two_bodies", "spring", "units_end", "oblique", "shore", "harmonic", "bulk_modulus",
        "bulk_table", "power_law", "fretting", "tangential_history"])
def test_a_pickled_case_is_the_case(tmp_path, text, vary):
    """The case read back describes itself alike, runs the same summary and sweeps the same table, bit for bit."""
    case = mdr.ContactCase.from_file(case_file(tmp_path, text))
    again = round_trip(case)
    assert repr(again) == repr(case)
    assert (again.material_error, again.material_window) == (case.material_error, case.material_window)
    same_summary(mdr.run(case).summary, mdr.run(again).summary)
    assert_same_tables(mdr.sweep(case, vary, jobs=1), mdr.sweep(again, vary, jobs=1))


def test_a_pickled_converted_material_keeps_its_series_and_certificate():
    """The factory's power law (converted over (1e-5, 100) s with tolerance 1e-3): the case read back runs on that
    series with that certificate, not one converted again over the case's window."""
    cell = mdr.Material.power_law(G0=1e3, beta=0.2, window=(1e-5, 100.0), tolerance=1e-3)
    case = mdr.ContactCase(material=cell, indenter=mdr.Indenter.sphere(R=1e-5), control=mdr.DisplacementControl(),
                           history=[(0.0, 0.0), (0.5, 1e-6), (1.0, 1e-6)], numerics=mdr.Numerics(elements=300))
    again = round_trip(case)
    assert again.material_window == (1e-5, 100.0) and again.material_error == cell.material_error
    assert again.material.terms == cell.terms
    assert mdr.run(again).summary["max_force"] == mdr.run(case).summary["max_force"]


def test_a_pickled_case_keeps_whether_its_end_was_given(tmp_path):
    """An end given equal to the history's default stays given (the last point moved later, the run still stops
    there); an end not given follows the history."""
    given = mdr.ContactCase.from_file(case_file(tmp_path, STANDARD_CASE.replace("[output]", "end = 1.0\n[output]")))
    default = mdr.ContactCase.from_file(case_file(tmp_path, STANDARD_CASE))
    vary = {"load.history[2][0]": [1.0, 2.0]}
    steps = mdr.sweep(round_trip(given), vary, jobs=1)["steps"]
    assert steps[1] == pytest.approx(steps[0], rel=0.2)  # both stop at 1 s
    steps = mdr.sweep(round_trip(default), vary, jobs=1)["steps"]
    assert steps[1] > 1.5 * steps[0]


def test_every_part_pickles():
    parts = [mdr.DisplacementControl(), mdr.ForceControl(),
             mdr.SpringControl(spring_constant=2.0, force_pauses=[(1.0, 2.0)]),
             mdr.ImpactControl(mass=1e-3, velocity=0.1, oblique=mdr.ObliqueImpact(friction=0.3, spin=2.0,
                                                                                  moment_of_inertia=1e-8)),
             mdr.ShoreTest(scale="D", duration=3.0),
             mdr.Harmonic(amplitude=1e-7, frequency=5.0, start=0.1, end=1.0),
             mdr.Numerics(elements=300, time_step=1e-3, output_every=2, max_memory=1e9),
             mdr.Tangential(friction=0.2, control="force", history=[(0.0, 0.0), (1.0, 1e-3)]),
             mdr.Tangential(friction=0.2, harmonic=mdr.Harmonic(amplitude=1e-6, frequency=5.0, start=0.0, end=1.0)),
             mdr.Layer(thickness=1e-3, interface="sliding")]
    for part in parts:
        again = round_trip(part)
        assert type(again) is type(part) and repr(again) == repr(part)
    shore = round_trip(mdr.ShoreTest(scale="A", duration=2.0))
    assert (shore.scale, shore.duration) == ("A", 2.0)
    assert round_trip(mdr.SpringControl(spring_constant=2.0, force_pauses=[(1.0, 2.0)])).force_pauses == [(1.0, 2.0)]


def test_a_pickle_of_another_layout_is_refused():
    case = mdr.ContactCase(material=mdr.Material.elastic(G=1e6), indenter=mdr.Indenter.sphere(R=0.01),
                           control=mdr.DisplacementControl(), history=[(0.0, 0.0), (1.0, 1e-5)])
    state = case.__getstate__()
    copy = mdr.ContactCase.__new__(mdr.ContactCase)
    with pytest.raises(ValueError, match="mdr.ContactCase pickle: 12 fields"):
        copy.__setstate__(state[:-1])
    # A state of the right length with a field mdr never writes: a ValueError naming the pickle, not a crash (the
    # half-space's body was dereferenced unchecked) nor pybind11's bare "Unable to cast".
    with pytest.raises(ValueError, match="mdr.ContactCase pickle: field 12 .* is None"):
        mdr.ContactCase.__new__(mdr.ContactCase).__setstate__(state[:11] + (None,) + state[12:])
    with pytest.raises(ValueError, match="mdr.ContactCase pickle: .*not a pickle that mdr wrote"):
        mdr.ContactCase.__new__(mdr.ContactCase).__setstate__(state[:8] + ("many",) + state[9:])
    assert np.isfinite(mdr.run(round_trip(case)).summary["max_force"])
