"""Eq. (58)-(61): the element is a Kelvin-Voigt unit (G, eta) in series with one (K + G/3, xi + eta/3); with u the
first unit's displacement, (eta + eta2) u' + (G + G2) u = G2 v0 t + eta2 v0, F = 8 a (G u + eta u')."""
import sys

import numpy as np

import mdr
import mdr.maps
import mdr.plot

case = mdr.maps.read_case(sys.argv[1])
result = mdr.run(sys.argv[1])
G, eta = case["material"]["G"], case["material"]["eta"]
K, xi = case["material"]["bulk"]["K"], case["material"]["bulk"]["eta"]
a = case["indenter"]["a"]
t_end, d_end = case["load"]["history"][-1]
v0 = d_end / t_end
G2, eta2 = K + G / 3, xi + eta / 3
tau = (eta + eta2) / (G + G2)
A = G2 * v0 / (G + G2)
B = (eta2 * v0 - (eta + eta2) * A) / (G + G2)
t = result.history["t"]
u = A * t + B * (1 - np.exp(-t / tau))
exact = 8 * a * (G * u + eta * (A + B / tau * np.exp(-t / tau)))
exact[0] = 0.0  # the dashpots' force appears at t = 0+
axes = mdr.plot.force_time(result.history)
axes.plot(t[::100], exact[::100], "k.", label="eq. (59)-(60)")
axes.set_title("Flat punch into a compressible Kelvin-Voigt body")
print(f"largest difference / final force (t > 0): {np.max(np.abs(result.history['F'][1:] - exact[1:])) / exact[-1]:.1e}")
print(mdr.plot.save(axes, sys.argv[2]))
