"""A Prony series with a parallel dashpot, G(t) = G_inf + eta delta(t) + G1 exp(-t/tau1) (the `prony` model's
optional `eta`), in a case: as an mdr.Material, as a dict and as a TOML file, against Lee-Radok's closed forms for a
rigid sphere on an incompressible half-space (handbook eq. 6 and the Hertz relation F = (16/3) G sqrt(R) d^(3/2),
E* = 4G): a displacement ramp (relaxation) and a force ramp (creep), with the element convergence of the ramp."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.special import dawsn

import mdr

G_INF, ETA, G1, TAU = 1.0e6, 1.0e3, 1.0e6, 0.1  # [Pa], [Pa s], [Pa], [s]
R = 0.01                                         # sphere radius [m]
SPEED, T = 1.0e-4, 1.0                           # depth rate [m/s] and ramp duration [s]
F_MAX, T_RAMP = 0.5, 0.1                         # force ramp to F_MAX [N] over T_RAMP [s], then held to T
INDENTER = {"shape": "sphere", "R": R}
RAMP = {"control": "displacement", "history": [[0.0, 0.0], [T, SPEED * T]]}
CREEP = {"control": "force", "history": [[0.0, 0.0], [T_RAMP, F_MAX], [T, F_MAX]]}


def ramp_force(t):
    """F(t) = (16/3) sqrt(R) int_0^t G(t - s) d/ds[d(s)^(3/2)] ds for d = v s (Lee-Radok, eq. 6): with
    int_0^t exp(-(t - s)/tau) sqrt(s) ds = tau^(3/2) (x - D(x)), x = sqrt(t/tau), D Dawson's integral."""
    x = np.sqrt(t / TAU)
    return 16.0 / 3.0 * math.sqrt(R) * SPEED**1.5 * (
        G_INF * t**1.5 + 1.5 * ETA * np.sqrt(t) + 1.5 * G1 * TAU**1.5 * (x - dawsn(x)))


def creep_depth(t):
    """d(t)^(3/2) = 3/(16 sqrt(R)) int_0^t J(t - s) dF(s) (Lee-Radok: the contact grows under a rising or held
    force), with J(t) = 1/G_inf + B exp(-r1 t) + C exp(-r2 t) from the partial fractions of 1/(s^2 G^(s)),
    s G^(s) = G_inf + eta s + G1 s/(s + 1/tau)."""
    beta = 1.0 / TAU
    r1, r2 = np.roots([ETA, G_INF + ETA * beta + G1, G_INF * beta]) * -1.0
    amplitudes = [(beta - r) / (ETA * -r * (other - r)) for r, other in ((r1, r2), (r2, r1))]

    def creep_integral(u0, u1):  # int_u0^u1 J(u) du
        total = (u1 - u0) / G_INF
        for amplitude, r in zip(amplitudes, (r1, r2)):
            total += amplitude / r * (np.exp(-r * u0) - np.exp(-r * u1))
        return total

    loaded = np.minimum(t, T_RAMP)  # dF/ds = F_MAX/T_RAMP on [0, T_RAMP]
    integral = F_MAX / T_RAMP * creep_integral(t - loaded, t)
    return (3.0 / (16.0 * math.sqrt(R)) * integral) ** (2.0 / 3.0)


def relative_error(result, exact, column):
    t = result.history["t"]
    late = t >= 0.05 * T  # away from t = 0, where the dashpot's sqrt(t) dominates a force of almost nothing
    return float(np.max(np.abs(result.history[column][late] / exact(t[late]) - 1.0)))


def test_the_material_object_goes_into_a_case_as_a_prony_table():
    material = mdr.Material(G_INF, ETA, [(G1, TAU)])
    result = mdr.run({"material": material, "indenter": INDENTER, "load": RAMP})
    assert relative_error(result, ramp_force, "F") < 1e-4
    assert "prony (G_inf = 1000000 Pa, 1 terms, eta = 1000 Pa s)" in mdr.check(
        {"material": material, "indenter": INDENTER, "load": RAMP})


def test_dict_file_and_object_give_one_run(tmp_path):
    table = {"model": "prony", "G_inf": G_INF, "terms": [[G1, TAU]], "eta": ETA}
    by_object = mdr.run(material=mdr.Material(G_INF, ETA, [(G1, TAU)]), indenter=INDENTER, load=RAMP)
    by_dict = mdr.run({"material": table, "indenter": INDENTER, "load": RAMP})
    path = tmp_path / "dashpot.toml"
    path.write_text('[material]\nmodel = "prony"\nG_inf = 1.0e6\neta = 1.0e3\nterms = [[1.0e6, 0.1]]\n'
                    '[indenter]\nshape = "sphere"\nR = 0.01\n'
                    '[load]\ncontrol = "displacement"\nhistory = [[0.0, 0.0], [1.0, 1.0e-4]]\n', encoding="utf-8")
    by_file = mdr.run(path)
    for result in (by_dict, by_file):
        np.testing.assert_array_equal(result.history["F"], by_object.history["F"])
    assert relative_error(by_file, ramp_force, "F") < 1e-4


def test_without_eta_the_prony_model_is_unchanged():
    table = {"model": "prony", "G_inf": G_INF, "terms": [[G1, TAU]]}
    assert mdr.Material.prony(G_inf=G_INF, terms=[(G1, TAU)]).eta == 0.0
    assert mdr.Material.prony(G_INF, [(G1, TAU)], ETA).eta == ETA
    with_zero = mdr.run({"material": dict(table, eta=0.0), "indenter": INDENTER, "load": RAMP})
    without = mdr.run({"material": table, "indenter": INDENTER, "load": RAMP})
    np.testing.assert_array_equal(with_zero.history["F"], without.history["F"])


def test_creep_under_a_force_ramp_and_hold():
    result = mdr.run(material={"model": "prony", "G_inf": G_INF, "eta": ETA, "terms": [[G1, TAU]]},
                     indenter=INDENTER, load=CREEP)
    assert relative_error(result, creep_depth, "d") < 1e-3


def test_the_ramp_converges_with_the_elements():
    errors = [relative_error(mdr.run(material=mdr.Material(G_INF, ETA, [(G1, TAU)]), indenter=INDENTER, load=RAMP,
                                     numerics={"elements": n, "time_step": 0.01}), ramp_force, "F")
              for n in (50, 100, 200)]
    assert errors[0] > 1.8 * errors[1] > 1.8 * 1.8 * errors[2], errors


def test_a_negative_eta_is_refused():
    with pytest.raises(ValueError, match=r"^material\.eta = -1: "):
        mdr.check({"material": {"model": "prony", "G_inf": G_INF, "eta": -1.0, "terms": [[G1, TAU]]},
                   "indenter": INDENTER, "load": RAMP})
