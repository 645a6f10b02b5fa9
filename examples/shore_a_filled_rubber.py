"""The Shore A reading of a filled rubber (a Prony series) after 1, 3 and 15 s: mdr's readings against an
independent solution of eq. (34) with the durometer's spring, written here in the relaxation form
k (z - d(t)) = int_0^t G(t - s) dP(a(s)) (Lee-Radok: the contact only grows), P the unit-modulus force of the
truncated cone, on graded steps with P linear in time over each (exact exponential update of each branch)."""
import math
import sys

import matplotlib.pyplot as plt
import numpy as np

import mdr
import mdr.maps

case = mdr.maps.read_case(sys.argv[1])
m = case["material"]
G_inf, terms = m["G_inf"], m["terms"]

# ASTM D2240 / ISO 48-4, Type A: flat tip of 0.79 mm diameter, 35 deg frustum, rod of 1.25 mm; spring
# 0.55 + 0.075 H [N] with H = 100 - d / 0.025 mm, i.e. F = k (z - d), k = 3000 N/m, k z = 8.05 N.
point = 0.025e-3
b, rod, T = 0.395e-3, 0.625e-3, 1.0 / math.tan(math.radians(17.5))
k, kz = 0.075 / point, 8.05


def depth(a):
    """g(a) of the frustum (eq. 9): T a acos(b / a) beyond the flat tip."""
    return T * a * math.acos(b / a)


def unit_force(a):
    """8 int_0^a (g(a) - g(x)) dx = 4 T (a^2 acos(b/a) + b sqrt(a^2 - b^2)) (eq. 21 at G = 1)."""
    return 4 * T * (a * a * math.acos(b / a) + b * math.sqrt(a * a - b * b))


def balance(residual):
    """The contact radius in [b, rod] where the rising residual(a) (contact force minus spring force) is zero."""
    lo, hi = b, rod
    assert residual(hi) > 0, "the contact reaches the rod: not this reference's case"
    for _ in range(80):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if residual(mid) < 0 else (lo, mid)
    return 0.5 * (lo + hi)


def reading(d):
    return 100 - d / point


def reference(times):
    """Readings at `times` (ascending): the landing at t = 0 on G(0) = G_inf + sum G_i, then steps dt <= t / 100
    (at most 1 ms)."""
    G0 = G_inf + sum(G for G, _ in terms)
    a = balance(lambda a: G0 * unit_force(a) - (kz - k * depth(a)))
    P = unit_force(a)
    h = [P for _ in terms]
    t, out = 0.0, []
    for target in times:
        while t < target:
            dt = min(max(1e-6, t / 100), 1e-3, target - t)
            E = [math.exp(-dt / tau) for _, tau in terms]
            B = [-math.expm1(-dt / tau) * tau / dt for _, tau in terms]
            memory = sum(G * e * hi for (G, _), e, hi in zip(terms, E, h))
            gain = G_inf + sum(G * Bi for (G, _), Bi in zip(terms, B))
            offset = memory - sum(G * Bi for (G, _), Bi in zip(terms, B)) * P
            a = balance(lambda a: gain * unit_force(a) + offset - (kz - k * depth(a)))
            P_new = unit_force(a)
            h = [e * hi + Bi * (P_new - P) for e, hi, Bi in zip(E, h, B)]
            P, t = P_new, t + dt
        out.append(reading(depth(a)))
    return np.array(out)


result = mdr.run(case)
times = [1.0, 3.0, 15.0]
measured = np.array([result.summary[f"shore_{t:g}s"] for t in times])
expected = reference(times)
for t, got, want in zip(times, measured, expected):
    print(f"Shore A after {t:g} s: {got:.3f} (reference {want:.3f})")
print(f"largest difference from the reference in Shore points: {np.max(np.abs(measured - expected)):.3g}")

t, H = result.history["t"], result.history["shore"]
landed = slice(1, None)  # the first row is the state before the foot lands (reading 100)
fig, ax = plt.subplots(figsize=(6.4, 4.0))
ax.semilogx(t[landed][1:], H[landed][1:], label="mdr (control = \"shore\")")
ax.plot(times, expected, "o", mfc="none", label="reference, eq. (34) with the spring")
for time, value in zip(times, measured):
    ax.annotate(f"{value:.1f}", (time, value), textcoords="offset points", xytext=(-6, 6), ha="right")
ax.axhline(H[1], color="0.6", lw=0.8, ls="--")
ax.text(t[2], H[1] + 0.6, f"elastic response at the landing: {H[1]:.1f}", color="0.4")
ax.set_ylim(top=H[1] + 4)
ax.set_xlabel("time after the foot's landing [s]")
ax.set_ylabel("Shore A reading")
ax.set_title("Filled rubber (Prony series), Shore A durometer")
ax.legend(loc="lower left")
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=120)
