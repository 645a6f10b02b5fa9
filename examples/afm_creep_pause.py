"""The AFM creep segment: a spring approach, a 10 s pause at constant force (`force_pauses`) and a retract from the
base the pause reached. Reference, independent of mdr: eq. (34) in its creep form for a sphere,
P(d(t)) = int_0^t J(t - s) dF(s), P(d) = (16/3) sqrt(R) d^(3/2) the unit-modulus Hertz force and
J(t) = J_inf - dJ exp(-t / tau_c) the standard solid's creep function (Table 1). The approach has F = k (z - d),
solved step by step with F linear in time over each step; in the pause F is held, so the depth follows in closed
form. (The retract is left out: the contact recedes there, where eq. (34) no longer holds.)"""
import math
import sys

import numpy as np

import mdr
import mdr.maps
import mdr.plot

case = mdr.maps.read_case(sys.argv[1])
m, R, load = case["material"], case["indenter"]["R"], case["load"]
k = load["spring_constant"]
(t_start, t_end), = load["force_pauses"]
(t0, z0), (t1, z1) = load["history"][:2]
assert t1 == t_start, "the approach is the history's first segment"
J_inf, J_0 = 1 / m["G_inf"], 1 / (m["G_inf"] + m["G1"])
dJ, tau_c = J_inf - J_0, m["tau1"] * (m["G_inf"] + m["G1"]) / m["G_inf"]


def unit_force(d):
    return 16 / 3 * math.sqrt(R) * max(d, 0.0) ** 1.5


def reference_pause(steps=20000):
    """F held and q(t_start) of q(t) = int_0^t exp(-(t - s)/tau_c) dF(s): the approach from the first contact (z = 0)
    to t_start on uniform steps, each depth by Newton on P(d) - (J_inf - dJ beta) k (z - d) + dJ (e q - beta F)."""
    contact = t0 + (0 - z0) / (z1 - z0) * (t1 - t0)
    dt = (t_start - contact) / steps
    e, beta = math.exp(-dt / tau_c), -math.expm1(-dt / tau_c) * tau_c / dt
    F = q = d = 0.0
    for n in range(1, steps + 1):
        z = z1 * n / steps  # z rises linearly from 0 at the contact to z1
        gain, offset = (J_inf - dJ * beta) * k, dJ * (e * q - beta * F)
        for _ in range(50):
            step = (unit_force(d) - gain * (z - d) + offset) / (8 * math.sqrt(R * max(d, 0.0)) + gain)
            d -= step
            if abs(step) < 1e-15 * z1:
                break
        F_new = k * (z - d)
        q, F = e * q + beta * (F_new - F), F_new
    return F, q


def depth_in_pause(t, F, q):
    return (3 * (J_inf * F - dJ * q * np.exp(-(t - t_start) / tau_c)) / (16 * math.sqrt(R))) ** (2 / 3)


result = mdr.run(case)
history = result.history
t, d, z = history["t"], history["d"], history["z"]
held, q = reference_pause()
pause = (t >= t_start) & (t <= t_end)
expected = depth_in_pause(t[pause], held, q)
print(result.description)
print(f"force held: {history['F'][pause][0]:.6f} nN (reference {held:.6f} nN); creep from {d[pause][0]:.4f} to "
      f"{d[pause][-1]:.4f} µm; the base ends the pause at z = {z[pause][-1]:.4f} µm and the retract ends at "
      f"{z[-1]:.4f} µm; {result.summary['steps']} steps in {result.summary['wall_seconds'] * 1e3:.0f} ms")
print(f"largest difference of the depth in the pause / its final depth: "
      f"{np.max(np.abs(d[pause] - expected)) / expected[-1]:.1e}")

axes = mdr.plot.force_time(history, units=result.summary)
right = axes.figure.axes[1]
right.plot(t, z, color="C2", ls=":", label="base z")
right.plot(t[pause][::100], expected[::100], "k.", label="eq. (34), creep at constant force")
right.set_ylabel(f"depth d, base z [{right.get_ylabel().split('[')[1]}")
right.legend(loc="lower center")
axes.axvspan(t_start, t_end, color="0.92", zorder=0)
axes.set_title("AFM creep: approach, 10 s at constant force, retract", pad=24)
print(mdr.plot.save(axes, sys.argv[2]))
