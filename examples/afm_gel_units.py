"""Eq. (15), (16), (21) for a sphere at constant speed d = v t on a standard solid, in the case's units (um-nN-s):
F(t) = 8 sqrt(R) v^(3/2) int_0^t G(t - s) sqrt(s) ds, G(t) = G_inf + G1 exp(-t/tau1)."""
import math
import sys

import numpy as np

import mdr
import mdr.maps
import mdr.plot

case = mdr.maps.read_case(sys.argv[1])
result = mdr.run(sys.argv[1])
m, R = case["material"], case["indenter"]["R"]
v = case["load"]["history"][-1][1] / case["load"]["history"][-1][0]
t = result.history["t"]
# int_0^t exp(-(t - s)/tau1) sqrt(s) ds with s = u^2 (a smooth integrand), by 60-point Gauss-Legendre.
nodes, weights = np.polynomial.legendre.leggauss(60)
u = 0.5 * np.sqrt(t)[:, None] * (nodes + 1.0)
branch = 0.5 * np.sqrt(t) * np.sum(weights * np.exp(-(t[:, None] - u**2) / m["tau1"]) * 2.0 * u**2, axis=1)
exact = 8.0 * math.sqrt(R) * v**1.5 * (m["G_inf"] * 2.0 / 3.0 * t**1.5 + m["G1"] * branch)
axes = mdr.plot.force_time(result.history, units=result.summary)
axes.plot(t[::100], exact[::100], "k.", label="eq. (15), (16), (21)")
axes.set_title("AFM probe into a gel (um-nN-s): MDR (line), closed form (dots)", pad=24)
print(result.description)
print(f"largest difference / peak force: {np.max(np.abs(result.history['F'] - exact)) / exact[-1]:.1e}")
print(mdr.plot.save(axes, sys.argv[2]))
