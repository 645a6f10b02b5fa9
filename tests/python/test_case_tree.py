"""A case given as dicts or objects goes to the core as a tree, never as TOML text (issue 27, item 3): no TOML
writer is called, the numbers arrive as they were, and messages name the same keys as for a case file."""

from __future__ import annotations

import pytest

import mdr

CASE_TEXT = """title = "tree"
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
[numerics]
elements = 40
time_step = 0.01
"""
CASE_DICT = {
    "title": "tree",
    "material": {"model": "standard", "G_inf": 1.0e6, "G1": 2.0e6, "tau1": 0.1},
    "indenter": {"shape": "sphere", "R": 0.01},
    "load": {"control": "displacement", "history": [[0.0, 0.0], [0.5, 1.0e-4], [1.0, 0.0]]},
    "numerics": {"elements": 40, "time_step": 0.01},
}


@pytest.fixture
def no_toml_writer(monkeypatch):
    """tomli-w, the TOML writer the package used for dict cases until issue 27, refuses to write: a case given as
    dicts that still went through text cannot run."""
    tomli_w = pytest.importorskip("tomli_w")

    def refuse(*args, **kwargs):
        raise AssertionError("a case given as dicts was written as TOML text")

    monkeypatch.setattr(tomli_w, "dumps", refuse)
    monkeypatch.setattr(tomli_w, "dump", refuse)


def test_dicts_and_objects_run_without_any_toml_writer(no_toml_writer, tmp_path):
    path = tmp_path / "case.toml"
    path.write_text(CASE_TEXT, encoding="utf-8")
    from_file = mdr.run(path)
    from_dict = mdr.run(CASE_DICT)
    from_objects = mdr.run(material=mdr.Material.standard(G_inf=1.0e6, G1=2.0e6, tau1=0.1),
                           indenter=mdr.Indenter.sphere(R=0.01), load=CASE_DICT["load"],
                           numerics=CASE_DICT["numerics"], title="tree")
    # The same case read from the file: the same forces, bit for bit (the Prony series of the standard solid has
    # the same single term).
    assert list(from_dict.history["F"]) == list(from_file.history["F"])
    assert list(from_objects.history["F"]) == list(from_file.history["F"])
    assert mdr.check(CASE_DICT) == mdr.check(path)
    table = mdr.sweep(CASE_DICT, {"material.tau1": [0.05, 0.1]}, jobs=1)
    assert table["max_force"][1] == from_file.summary["max_force"]


def test_an_integer_beyond_64_bits_names_its_key():
    """TOML text cannot carry 2**70 as an integer: the writer's text failed to parse at a line and column; the tree
    names the key."""
    case = dict(CASE_DICT, numerics={"elements": 2**70, "time_step": 0.01})
    with pytest.raises(ValueError, match=r"^numerics\.elements = 1180591620717411303424: must fit in 64 bits"):
        mdr.check(case)


def test_a_non_finite_sweep_value_names_its_key():
    with pytest.raises(ValueError, match=r"^vary\['material\.tau1'\] = nan: must be finite numbers"):
        mdr.sweep(CASE_DICT, {"material.tau1": [0.1, float("nan")]}, jobs=1)


def test_sweep_values_arrive_as_the_floats_given():
    """A value whose shortest decimal text differs from what a 15-digit printing gives: the sweep's point is the
    float itself."""
    value = 0.1 + 0.2  # 0.30000000000000004
    table = mdr.sweep(CASE_DICT, {"material.tau1": [value]}, jobs=1)
    assert table["material.tau1"][0] == value
    assert table["max_force"][0] == mdr.run(dict(CASE_DICT, material=dict(CASE_DICT["material"],
                                                                         tau1=value))).summary["max_force"]


def test_unsupported_values_are_type_errors_naming_the_key():
    with pytest.raises(TypeError, match=r"material\.G_inf: unsupported value of type object"):
        mdr.check(dict(CASE_DICT, material=dict(CASE_DICT["material"], G_inf=object())))
