"""mdr.sweep of an mdr.ContactCase over every numeric key of its case file: a control's own keys (by the fields its
type declares, drivers::ControlField::key), a compressible body's `K` and `bulk.*`, a converted model's `tolerance`,
a `[tangential]` load's history and harmonic. The same case as a file and as the objects read from it gives the same
table bit for bit, the failed points' messages included (before, each key here was refused on the objects)."""

from __future__ import annotations

import mdr
import pytest
from test_sweep_contact_case import assert_same_tables, case_file

SPRING = """units = "um-nN-s"
[material]
model = "standard"
G_inf = 0.3
G1 = 0.7
tau1 = 1.0
[indenter]
shape = "sphere"
R = 5.0
[load]
control = "spring"
spring_constant = 100.0
history = [[0.0, -0.3], [1.0, 0.25], [11.0, 0.25], [12.0, -0.75]]
force_pauses = [[1.0, 11.0]]
[numerics]
elements = 200
"""

OBLIQUE = """[material]
model = "standard"
G_inf = 1.0e6
G1 = 3.0e6
tau1 = 1.0e-3
[indenter]
shape = "sphere"
R = 0.01
mass = 3.27e-2
moment_of_inertia = 1.3e-6
[load]
control = "impact"
velocity = 0.1
tangential_velocity = 0.06
spin = 0.0
[tangential]
friction = 0.3
[numerics]
elements = 100
"""

SHORE = """[material]
model = "prony"
G_inf = 1.0e6
terms = [[1.2e6, 0.01], [0.6e6, 0.1]]
[load]
control = "shore"
scale = "A"
duration = 3.0
[numerics]
elements = 200
"""

HARMONIC = """[material]
model = "standard"
G_inf = 1.0e6
G1 = 2.0e6
tau1 = 0.01
[indenter]
shape = "sphere"
R = 0.01
[load]
control = "displacement"
history = [[0.0, 0.0], [0.01, 1.0e-4], [0.3, 1.0e-4]]
harmonic = { amplitude = 1.0e-7, frequency = 15.915494309189533, start = 0.01, end = 0.3 }
[numerics]
elements = 200
"""

BULK_MODULUS = """[material]
model = "kelvin_voigt"
G = 1.0e6
eta = 1.0e5
K = 3.0e6
[indenter]
shape = "flat"
a = 1.0e-3
[load]
control = "displacement"
history = [[0.0, 0.0], [2.0, 2.0e-4]]
[numerics]
elements = 200
"""

BULK_TABLE = BULK_MODULUS.replace("K = 3.0e6\n", '[material.bulk]\nmodel = "kelvin_voigt"\nK = 3.0e6\neta = 2.0e5\n')

POWER_LAW = """[material]
model = "power_law"
G0 = 1.0e3
beta = 0.2
tolerance = 1.0e-3
[indenter]
shape = "sphere"
R = 1.0e-5
[load]
control = "displacement"
history = [[0.0, 0.0], [0.5, 1.0e-6], [1.0, 1.0e-6]]
[numerics]
elements = 200
"""

FRETTING = """[material]
model = "standard"
G_inf = 1.0e6
G1 = 3.0e6
tau1 = 0.01
[indenter]
shape = "sphere"
R = 0.01
[load]
control = "displacement"
history = [[0.0, 0.0], [0.01, 1.0e-4], [0.2, 1.0e-4]]
[tangential]
friction = 0.3
amplitude = 1.5e-5
frequency = 10.0
start = 0.1
end = 0.2
[numerics]
elements = 200
"""

TANGENTIAL_HISTORY = FRETTING.replace("amplitude = 1.5e-5\nfrequency = 10.0\nstart = 0.1\nend = 0.2\n",
                                      "history = [[0.0, 0.0], [0.1, 0.0], [0.2, 1.0e-5]]\n")


@pytest.mark.parametrize("text, vary, errors", [
    (SPRING, {"load.spring_constant": [100.0, -1.0, 300.0], "load.force_pauses[0][1]": [11.0, 6.0]},
     {"load.spring_constant = -1: must be > 0"}),
    (SPRING, {"load.force_pauses[0][0]": [1.0, 12.5]}, None),
    (OBLIQUE, {"indenter.mass": [3.27e-2, -1.0], "load.velocity": [0.1, 0.2]}, None),
    (OBLIQUE, {"tangential.friction": [0.3, 0.1], "load.tangential_velocity": [0.06, 0.02],
               "load.spin": [0.0, 5.0], "indenter.moment_of_inertia": [1.3e-6, 2.6e-6]}, set()),
    (SHORE, {"load.duration": [3.0, 1.5, -1.0]}, None),
    (HARMONIC, {"load.harmonic.frequency": [15.9, 40.0], "load.harmonic.amplitude": [1e-7, 2e-7]}, set()),
    (BULK_MODULUS, {"material.K": [3e6, -1.0, 1e7]}, {"material.K = -1: must be > 0"}),
    (BULK_TABLE, {"material.bulk.K": [3e6, 1e7], "material.bulk.eta": [2e5, 0.0]}, None),
    (POWER_LAW, {"material.tolerance": [1e-3, 1e-2]}, set()),
    (FRETTING, {"tangential.amplitude": [1.5e-5, 3e-5], "tangential.friction": [0.3, -0.1]}, None),
    (TANGENTIAL_HISTORY, {"tangential.history[2][1]": [1e-5, 2e-5], "tangential.history[1][0]": [0.1, 0.3]}, None),
], ids=["spring", "pause_start", "impact", "oblique", "shore", "harmonic", "bulk_modulus", "bulk_table", "tolerance",
        "fretting", "tangential_history"])
def test_the_objects_sweep_every_key_of_the_file_bit_for_bit(tmp_path, text, vary, errors):
    """The case as a file and as its objects (mdr.ContactCase.from_file): identical tables, failed points included;
    `errors` (where given) the set of the failed points' messages."""
    path = case_file(tmp_path, text)
    from_file = mdr.sweep(path, vary, jobs=2)
    from_objects = mdr.sweep(mdr.ContactCase.from_file(path), vary, jobs=2)
    assert_same_tables(from_file, from_objects)
    if errors is not None:
        assert set(from_file["error"]) - {""} == errors
    assert any(message == "" for message in from_file["error"])


def test_the_control_keys_change_the_run():
    """A key of a control sets its number: the spring twice as stiff gives another force at the end of the hold, and
    a heavier ball a deeper impact (the table is not the case's own at every point)."""
    case = mdr.ContactCase(material=mdr.Material.elastic(G=1e6), indenter=mdr.Indenter.sphere(R=0.01),
                           control=mdr.ImpactControl(mass=1e-2, velocity=0.1), numerics=mdr.Numerics(elements=100))
    table = mdr.sweep(case, {"indenter.mass": [1e-2, 4e-2]}, jobs=1)
    # Hertz impact: the largest depth grows as m^(2/5) (energy balance m v^2 / 2 = 8/15 E* sqrt(R) d^(5/2)).
    assert table["max_depth"][1] / table["max_depth"][0] == pytest.approx(4.0 ** 0.4, rel=2e-3)


@pytest.mark.parametrize("text, key", [
    (SHORE, "load.spring_constant"),   # the durometer's spring is the standard's, not a number of the case
    (BULK_MODULUS, "material.bulk.K"),
    (BULK_TABLE, "material.K"),
    (HARMONIC, "load.velocity"),
    (SPRING, "load.force_pauses[1][0]"),
    (SPRING, "indenter.mass"),
    (FRETTING, "tangential.history[0][0]"),
    (TANGENTIAL_HISTORY, "tangential.amplitude"),
    (HARMONIC, "material.tolerance"),
], ids=["shore_spring", "bulk_table_of_K", "K_of_bulk_table", "velocity", "pause", "mass", "tangential_history",
        "tangential_harmonic", "tolerance"])
def test_a_key_the_case_lacks_is_refused_on_the_objects_as_on_the_file(tmp_path, text, key):
    path = case_file(tmp_path, text)
    with pytest.raises(mdr.InvalidInput) as from_file:
        mdr.sweep(path, {key: [1.0]}, jobs=1)
    with pytest.raises(mdr.InvalidInput) as from_objects:
        mdr.sweep(mdr.ContactCase.from_file(path), {key: [1.0]}, jobs=1)
    assert str(from_file.value).startswith(f"--vary = {key}: no such numeric key in the case file")
    assert str(from_objects.value).startswith(f"--vary = {key}: no such numeric key among those a case of objects")


def test_the_rule_names_the_controls_declared_keys():
    """The message of a key the objects lack lists the controls' keys from their declared fields."""
    case = mdr.ContactCase(material=mdr.Material.elastic(G=1e6), indenter=mdr.Indenter.sphere(R=0.01),
                           control=mdr.DisplacementControl(), history=[(0.0, 0.0), (1.0, 1e-5)])
    with pytest.raises(mdr.InvalidInput) as refused:
        mdr.sweep(case, {"load.nope": [1.0]}, jobs=1)
    for key in ("load.spring_constant", "load.force_pauses[i][j]", "indenter.mass", "load.velocity",
                "tangential.friction", "load.tangential_velocity", "load.spin", "indenter.moment_of_inertia",
                "load.duration"):
        assert key in str(refused.value)
