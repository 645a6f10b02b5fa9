"""`numerics.layer_cells` (the cells of a layer's coupled time-stepping) in Python: mdr.Numerics, its pickle, and the
sweeps of a file and of its objects, which vary it as any count (docs/python.md, docs/case-format.md "Layers")."""

from __future__ import annotations

import math
import pickle

import mdr
import pytest
from test_sweep_contact_case import assert_same_tables, case_file

# A harmonic on a thick layer: it runs on the cells from the start, `elements` in summary.json their number.
LAYER_HARMONIC = """[material]
model = "standard"
G_inf = 1.0e3
G1 = 3.0e3
tau1 = 0.2
[indenter]
shape = "sphere"
R = 1.0e-5
[load]
control = "displacement"
history = [[0.0, 0.0], [0.5, 1.0e-6], [1.5, 1.0e-6]]
harmonic = { amplitude = 0.3e-6, frequency = 2.0, start = 0.5, end = 1.5 }
[layer]
thickness = 2.0e-5
interface = "bonded"
[numerics]
time_step = 5.0e-3
elements = 30
layer_cells = 60
"""


def test_the_numerics_object_holds_the_cells_and_pickles_them():
    numerics = mdr.Numerics(elements=30, layer_cells=1600)
    assert numerics.layer_cells == 1600 and numerics.elements == 30
    assert mdr.Numerics().layer_cells is None
    assert "layer_cells=1600" in repr(numerics)
    assert pickle.loads(pickle.dumps(numerics)).layer_cells == 1600
    with pytest.raises(TypeError):
        mdr.Numerics(layer_cells=True)  # a bool is not a count


def test_a_case_of_objects_runs_its_cells_and_its_pickle_keeps_them(tmp_path):
    case = mdr.ContactCase.from_file(case_file(tmp_path, LAYER_HARMONIC))
    assert case.numerics.layer_cells == 60 and case.numerics.elements == 30
    assert pickle.loads(pickle.dumps(case)).numerics.layer_cells == 60
    # The file's keys as objects: the cells are the run's elements (the nodes stay 30).
    table = mdr.sweep(case, {"numerics.layer_cells": [60, 80]}, jobs=1)
    assert list(table["elements"]) == [60, 80]


def test_the_sweeps_vary_the_cells_as_a_count_and_refuse_a_bad_one(tmp_path):
    path = case_file(tmp_path, LAYER_HARMONIC)
    vary = {"numerics.layer_cells": [60, 1, 120]}
    from_file = mdr.sweep(path, vary, jobs=2)
    from_objects = mdr.sweep(mdr.ContactCase.from_file(path), vary, jobs=2)
    assert_same_tables(from_file, from_objects)
    assert list(from_file["error"]) == ["", "numerics.layer_cells = 1: must be an integer from 2 to 4096 (the cells "
                                        "of the [layer]'s coupled time-stepping)", ""]
    assert from_file["elements"][0] == 60 and from_file["elements"][2] == 120 and math.isnan(from_file["elements"][1])
    # More cells move the force (second order in the cell): the key reaches the run.
    assert from_file["max_force"][0] != from_file["max_force"][2]


def test_a_case_of_objects_on_the_half_space_refuses_the_cells():
    with pytest.raises(mdr.InvalidInput, match=r"numerics.layer_cells = 100: only with a \[layer\]"):
        mdr.ContactCase(material=mdr.Material.elastic(G=1e3), indenter=mdr.Indenter.sphere(R=1e-5),
                        control=mdr.DisplacementControl(), history=[(0.0, 0.0), (1.0, 1e-6)],
                        numerics=mdr.Numerics(layer_cells=100))
