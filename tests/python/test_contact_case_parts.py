"""mdr.ContactCase reads back its parts as given (issue 27): every example and fuzz-corpus case read from its file
rebuilds through mdr.ContactCase(**its parts) to a case whose outputs are bit-identical to the file's, and the bodies
a case file can hold (a compressible half-space, two bodies) are keywords with the file's names."""

from __future__ import annotations

import math
import pathlib
import tomllib

import numpy as np
import pytest

import mdr

REPO = pathlib.Path(__file__).resolve().parents[2]
PART_NAMES = ("material", "bulk", "indenter", "indenter_material", "control", "history", "harmonic", "end", "snapshots",
              "numerics", "tangential", "layer", "title", "units")


def contact_cases():
    """The contact cases the byte-identity harness runs (tests/support/compare_outputs.py): examples and the fuzz
    corpus, without the fit cases."""
    paths = sorted(REPO.glob("examples/**/*.toml")) + sorted(REPO.glob("tests/fuzz/corpus/*.toml"))
    return [path.relative_to(REPO) for path in paths if "fit" not in tomllib.loads(path.read_text())]


def parts(case):
    return {name: getattr(case, name) for name in PART_NAMES}


def assert_same_outputs(expected, actual):
    assert expected.history.keys() == actual.history.keys()
    for column, values in expected.history.items():
        np.testing.assert_array_equal(actual.history[column], values, err_msg=column)
    assert expected.profiles.keys() == actual.profiles.keys()
    for column, values in expected.profiles.items():
        np.testing.assert_array_equal(actual.profiles[column], values, err_msg=column)
    summary = {key: value for key, value in expected.summary.items() if key != "wall_seconds"}
    assert {key: actual.summary[key] for key in summary} == summary


@pytest.mark.parametrize("path", contact_cases(), ids=str)
def test_a_case_file_round_trips_through_its_parts(path):
    try:
        from_file = mdr.ContactCase.from_file(str(REPO / path))
    except mdr.InvalidInput:
        pytest.skip("refused as bad input (a regression case of the fuzz corpus): no parts to read back")
    rebuilt = mdr.ContactCase(**parts(from_file))
    assert_same_outputs(mdr.run(str(REPO / path)), mdr.run(rebuilt))


def test_the_parts_an_impact_and_a_shore_test_bring_read_back_as_none():
    """assemble_case gives an impact the history (0, 0) and a Shore test its indenter, base history and end; they
    are the control's, not given, so they read back as None and the case rebuilds (it was refused before)."""
    material = mdr.Material.standard(G_inf=1e6, G1=1e6, tau1=2.0)
    impact = mdr.ContactCase(material=material, indenter=mdr.Indenter.sphere(R=0.01),
                             control=mdr.ImpactControl(mass=1e-3, velocity=0.1))
    assert impact.history is None and impact.end == math.inf
    shore = mdr.ContactCase(material=material, control=mdr.ShoreTest(scale="A", duration=3.0))
    assert shore.history is None and shore.indenter is None and shore.end is None
    for case in (impact, shore):
        assert_same_outputs(mdr.run(case), mdr.run(mdr.ContactCase(**parts(case))))


MAXWELL = dict(model="maxwell", G=2.0e6, tau=0.05)
SPHERE = dict(shape="sphere", R=0.01)
FORCE = dict(control="force", history=[[0.0, 0.0], [0.5, 0.1], [1.0, 0.1]])
TANGENTIAL = dict(friction=0.3, control="force", history=[[0.5, 0.0], [1.0, 0.02]])


def maxwell():
    return mdr.Material.maxwell(G=2.0e6, tau=0.05)


def objects(**bodies):
    return mdr.ContactCase(**bodies, indenter=mdr.Indenter.sphere(R=0.01), control=mdr.ForceControl(),
                           history=[(0.0, 0.0), (0.5, 0.1), (1.0, 0.1)],
                           tangential=mdr.Tangential(friction=0.3, control="force",
                                                     history=[(0.5, 0.0), (1.0, 0.02)]),
                           numerics=mdr.Numerics(elements=300))


def as_dict(material, indenter=SPHERE):
    return {"material": material, "indenter": indenter, "load": FORCE, "tangential": TANGENTIAL,
            "numerics": {"elements": 300}}


@pytest.mark.parametrize("bodies, tree", [
    (lambda: dict(material=maxwell(), K=1.0e8), as_dict(dict(MAXWELL, K=1.0e8))),
    (lambda: dict(material=maxwell(), bulk=mdr.Material.kelvin_voigt(G=5e7, eta=1e4)),
     as_dict(dict(MAXWELL, bulk=dict(model="kelvin_voigt", K=5e7, eta=1e4)))),
    (lambda: dict(material=maxwell(), indenter_material=mdr.Material.elastic(G=5e8)),
     as_dict(MAXWELL, dict(SPHERE, material=dict(model="elastic", G=5e8)))),
    (lambda: dict(material=maxwell(), K=1.0e8, indenter_material=mdr.Material.elastic(G=5e8)),
     as_dict(dict(MAXWELL, K=1.0e8), dict(SPHERE, material=dict(model="elastic", G=5e8)))),
])
def test_a_compressible_body_and_two_bodies_run_as_the_same_dict(bodies, tree):
    """The bodies of a case file as keywords: the same case as the dict (the file's reader), bit-identical, with the
    tangential result flagged as the approximation of section 7; read back, the parts rebuild it."""
    case = objects(**bodies())
    expected = mdr.run(tree)
    assert expected.summary["tangential_approximation"] is True
    assert_same_outputs(expected, mdr.run(case))
    assert_same_outputs(expected, mdr.run(mdr.ContactCase(**parts(case))))


def test_a_compressible_layer_runs_as_the_same_dict():
    """A layer takes a constant Poisson ratio (an elastic G with an elastic K: nu = (3K - 2G) / (6K + 2G) = 0.4)."""
    case = mdr.ContactCase(material=mdr.Material.elastic(G=1e6), K=7e6, indenter=mdr.Indenter.sphere(R=0.01),
                           control=mdr.DisplacementControl(), history=[(0.0, 0.0), (1.0, 5e-5)],
                           layer=mdr.Layer(thickness=1e-3))
    expected = mdr.run({"material": {"model": "elastic", "G": 1e6, "K": 7e6}, "indenter": SPHERE,
                        "load": {"control": "displacement", "history": [[0.0, 0.0], [1.0, 5e-5]]},
                        "layer": {"thickness": 1e-3, "interface": "bonded"}})
    assert_same_outputs(expected, mdr.run(case))
    assert case.bulk.G_inf == 7e6 and case.material.G_inf == 1e6 and case.indenter_material is None


@pytest.mark.parametrize("changes, error, message", [
    (dict(K=-1.0), mdr.InvalidInput, "^material.K = -1: must be > 0"),
    (dict(K=1e8, bulk=mdr.Material.elastic(G=1e8)), mdr.InvalidInput,
     r"^material.K = 100000000: give either K or \[material.bulk\], not both"),
    (dict(K=True), TypeError, "^material.K: expected a number, got bool"),
    (dict(bulk={"model": "elastic", "K": 1e8}), TypeError, "^material.bulk: expected an mdr.Material, got dict"),
    (dict(indenter_material=5e8), TypeError, "^indenter.material: expected an mdr.Material, got float"),
])
def test_bad_bodies_are_refused_by_the_case_files_rules(changes, error, message):
    with pytest.raises(error, match=message):
        objects(**dict(dict(material=maxwell()), **changes))


def test_the_case_files_message_for_two_bulk_parts_is_the_same():
    with pytest.raises(mdr.InvalidInput) as from_dict:
        mdr.check(as_dict(dict(MAXWELL, K=1e8, bulk=dict(model="elastic", K=1e8))))
    with pytest.raises(mdr.InvalidInput) as from_objects:
        objects(material=maxwell(), K=1e8, bulk=mdr.Material.elastic(G=1e8))
    assert str(from_objects.value) == str(from_dict.value)


def test_a_compressible_indenter_has_no_object_form_and_says_so():
    case = mdr.ContactCase.from_dict(as_dict(MAXWELL, dict(SPHERE, material=dict(model="elastic", G=5e8, K=1e9))))
    with pytest.raises(ValueError, match="^indenter.material: a compressible indenter"):
        case.indenter_material


CONVERTED_CASES = {
    "power law under force": """
[material]
model = "power_law"
G0 = 2e3
beta = 0.2
[indenter]
shape = "sphere"
R = 1e-5
[load]
control = "force"
history = [[0, 0], [1, 1e-8], [3, 1e-8]]
""",
    "fractional Maxwell with K, um-nN-s": """
units = "um-nN-s"
[material]
model = "fractional_maxwell"
G = 10.0
c = 2.0
alpha = 0.4
K = 50.0
tolerance = 1e-5
[indenter]
shape = "sphere"
R = 5.0
[load]
control = "displacement"
history = [[0, 0], [1, 0.5], [2, 0]]
""",
    "springpot on a power-law indenter": """
[material]
model = "springpot"
c = 1e3
alpha = 0.3
[indenter]
shape = "cone"
half_angle_deg = 70
[indenter.material]
model = "power_law"
G0 = 1e5
beta = 0.05
[load]
control = "displacement"
history = [[0, 0], [0.5, 1e-5]]
""",
}


@pytest.mark.parametrize("text", CONVERTED_CASES.values(), ids=CONVERTED_CASES.keys())
def test_a_converted_material_of_a_case_file_rebuilds_with_its_origin(tmp_path, text):
    """A model converted to a series over the case's window reads back as an mdr.ConvertedMaterial with the file's
    certificate and definition, so the rebuilt case has the file's origin: its default time step (a series of a
    continuous spectrum sets none; an elastic body, no time at all, neither), its summary's material_error and
    material_window and its description. Before, case.material was the bare series: 9878 steps for the file's 2322
    (power law), no certificate in summary.json; and an elastic K read back as a body with times."""
    path = tmp_path / "case.toml"
    path.write_text(text)
    from_file = mdr.ContactCase.from_file(str(path))
    assert isinstance(from_file.material, mdr.ConvertedMaterial)
    assert from_file.material.material_window == from_file.material_window
    expected = mdr.run(str(path))
    rebuilt = mdr.run(mdr.ContactCase(**parts(from_file)))
    assert_same_outputs(expected, rebuilt)
    assert rebuilt.description == expected.description
    assert rebuilt.summary["material_window"] == expected.summary["material_window"]


@pytest.mark.parametrize("text", CONVERTED_CASES.values(), ids=CONVERTED_CASES.keys())
def test_a_rebuilt_case_reads_back_its_converted_material_for_the_next_rebuild(tmp_path, text):
    """A case built from an mdr.ConvertedMaterial reads it back as one (its definition and certificate), so that a
    case rebuilt from a rebuilt case is still the file's case. Before, the object constructor dropped the definition:
    the second rebuild's material was the bare series (no certificate, the series' own time step)."""
    path = tmp_path / "case.toml"
    path.write_text(text)
    from_file = mdr.ContactCase.from_file(str(path))
    once = mdr.ContactCase(**parts(from_file))
    assert isinstance(once.material, mdr.ConvertedMaterial)
    assert once.material._definition == from_file.material._definition
    twice = mdr.ContactCase(**parts(once))
    assert_same_outputs(mdr.run(str(path)), mdr.run(twice))
