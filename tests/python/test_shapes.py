"""The registries of indenter shapes and controls from Python (issue 9): mdr.Indenter's factories come from the
shape table, messages name its keys; and mdr.sweep takes the case's tables as keywords, as mdr.run does."""

import math
import pickle

import numpy as np
import pytest

import mdr

# A value for every required key of each shape (the cone by its slope).
EXAMPLES = {"sphere": {"R": 0.01}, "cone": {"slope_deg": 20.0}, "flat": {"a": 1e-3}, "power": {"c": 3.0, "n": 1.5},
            "profile": {"r": [0.0, 1e-3, 2e-3], "f": [0.0, 1e-5, 4e-5]}}


def test_every_registered_shape_is_a_documented_factory():
    shapes = mdr._mdr._shapes()
    assert [shape["name"] for shape in shapes] == list(EXAMPLES)
    for shape in shapes:
        factory = getattr(mdr.Indenter, shape["name"])
        assert shape["documentation"] in factory.__doc__, shape["name"]
        for parameter in shape["parameters"]:
            assert f"\n{parameter['key']} : " in factory.__doc__, (shape["name"], parameter["key"])
        assert shape["name"] in mdr.Indenter.__doc__


@pytest.mark.parametrize("name", list(EXAMPLES))
def test_a_factory_builds_its_table_again_and_pickles(name):
    indenter = getattr(mdr.Indenter, name)(**EXAMPLES[name])
    table = indenter.table
    assert table["shape"] == name
    again = getattr(mdr.Indenter, name)(**{key: value for key, value in table.items() if key != "shape"})
    assert again.table == table
    copy = pickle.loads(pickle.dumps(indenter))
    assert copy.table == table and repr(copy) == repr(indenter)
    x = np.linspace(0.0, 1.5e-3, 7)
    np.testing.assert_array_equal(copy.equivalent(x), indenter.equivalent(x))


def test_positional_arguments_follow_the_row_and_an_alternative_is_a_keyword():
    assert mdr.Indenter.power(3.0, 1.5).table == {"shape": "power", "c": 3.0, "n": 1.5}
    assert mdr.Indenter.profile([0.0, 1.0], [0.0, 1.0], "linear").table["interpolation"] == "linear"
    assert mdr.Indenter.profile([0.0, 1.0], [0.0, 1.0]).table["interpolation"] == "monotone_cubic"
    # half_angle_deg stands for slope_deg = 90 - half_angle_deg: keyword only.
    with pytest.raises(TypeError, match=r"^cone\(\) takes at most 1 positional arguments, 2 given"):
        mdr.Indenter.cone(20.0, 70.0)
    assert mdr.Indenter.cone(None, half_angle_deg=60.0).table == {"shape": "cone", "slope_deg": 30.0}


def test_bad_arguments_name_the_registry_keys():
    with pytest.raises(TypeError, match=r"^power\(\) got an unexpected keyword argument 'm'; valid: c, n$"):
        mdr.Indenter.power(c=1.0, m=2.0)
    with pytest.raises(TypeError, match=r"^power\(\) missing required argument 'n' \(arguments: c, n\)$"):
        mdr.Indenter.power(c=1.0)
    with pytest.raises(TypeError, match=r"^sphere\(\) got multiple values for argument 'R'$"):
        mdr.Indenter.sphere(0.01, R=0.02)
    with pytest.raises(TypeError, match=r"^r = 'abc': must be a sequence of numbers$"):
        mdr.Indenter.profile(r="abc", f=[0.0, 1.0])
    with pytest.raises(mdr.InvalidInput, match=r"^R = -1: must be > 0$"):
        mdr.Indenter.sphere(R=-1.0)
    with pytest.raises(mdr.InvalidInput, match=r"^interpolation = \"spline\": must be monotone_cubic or linear$"):
        mdr.Indenter.profile([0.0, 1.0], [0.0, 1.0], "spline")


LOAD = {"control": "displacement", "history": [[0.0, 0.0], [1.0, 1e-4]]}
MATERIAL = {"model": "elastic", "G": 1e6}


def test_case_messages_list_the_shapes_keys_and_the_controls():
    names = ", ".join(shape["name"] for shape in mdr._mdr._shapes())
    with pytest.raises(mdr.InvalidInput, match=rf"^indenter.shape = \"ball\": unknown shape; one of {names}$"):
        mdr.check(material=MATERIAL, indenter={"shape": "ball"}, load=LOAD)
    # No key is close: the valid ones are listed, the shape's own from its row.
    with pytest.raises(mdr.InvalidInput, match=r"unknown key; valid keys: shape, mass, moment_of_inertia, "
                                               r"material, r, f, interpolation$"):
        mdr.check(material=MATERIAL, indenter={"shape": "profile", "r": [0.0, 1.0], "f": [0.0, 1.0], "xyz": 1},
                  load=LOAD)
    controls = ", ".join(control["name"] for control in mdr._mdr._controls())
    with pytest.raises(mdr.InvalidInput, match=rf"^load.control = \"position\": unknown control; one of {controls}$"):
        mdr.check(material=MATERIAL, indenter={"shape": "sphere", "R": 0.01}, load={**LOAD, "control": "position"})
    for control in mdr._mdr._controls():
        assert control["documentation"] and control["keys"], control["name"]


# ---------------------------------------------------------------------------------------------------------------
# mdr.sweep with the tables as keywords


def test_sweep_takes_the_tables_as_keywords_and_runs_the_same_points():
    vary = {"load.history[1][1]": [0.5e-4, 1e-4, 2e-4]}
    indenter = mdr.Indenter.sphere(R=0.01)
    by_keywords = mdr.sweep(material=mdr.Material.elastic(G=1e6), indenter=indenter, load=LOAD, vary=vary, jobs=2)
    by_dict = mdr.sweep({"material": MATERIAL, "indenter": indenter.table, "load": LOAD}, vary, jobs=2)
    assert list(by_keywords) == list(by_dict)
    for column in set(by_dict) - {"wall_seconds"}:
        np.testing.assert_array_equal(by_keywords[column], by_dict[column], err_msg=column)
    # Hertz (eq. 35 with a^2 = R d, eq. 31): F = 16 G sqrt(R) d^(3/2) / 3; the defaults are accurate to 1e-3.
    depth = np.asarray(vary["load.history[1][1]"])
    hertz = 16.0 * 1e6 * math.sqrt(0.01) * depth ** 1.5 / 3.0
    np.testing.assert_array_equal(by_keywords["load.history[1][1]"], depth)
    np.testing.assert_allclose(by_keywords["max_force"], hertz, rtol=1e-3)
    assert list(by_keywords["error"]) == ["", "", ""]


def test_sweep_takes_a_case_one_way_only():
    with pytest.raises(TypeError, match="not both"):
        mdr.sweep("examples/default.toml", {"material.G_inf": [1e6]}, load=LOAD)
    with pytest.raises(TypeError, match=r"^case: give a case file, a dict, or material="):
        mdr.sweep(vary={"material.G": [1e6]})
    with pytest.raises(TypeError, match=r"^vary: expected a non-empty dict"):
        mdr.sweep(material=MATERIAL, indenter={"shape": "sphere", "R": 0.01}, load=LOAD)
    with pytest.raises(mdr.InvalidInput, match=r"^--vary = load.history\[5\]\[1\]: no such numeric key"):
        mdr.sweep(material=MATERIAL, indenter={"shape": "sphere", "R": 0.01}, load=LOAD,
                  vary={"load.history[5][1]": [1e-4]})
