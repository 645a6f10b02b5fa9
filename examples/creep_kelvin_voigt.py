"""Eq. (33): a(t)^3 = (3 F0 R / (16 G)) (1 - exp(-t/tau)), tau = eta/G, with a^2 = R d (eq. 31)."""
import sys

import matplotlib.pyplot as plt
import numpy as np

import mdr
import mdr.maps
import mdr.plot

case = mdr.maps.read_case(sys.argv[1])
result = mdr.run(sys.argv[1])
G, eta = case["material"]["G"], case["material"]["eta"]
R, F0 = case["indenter"]["R"], case["load"]["history"][0][1]
t = result.history["t"]
exact = np.cbrt(3 * F0 * R / (16 * G) * (1 - np.exp(-t * G / eta)))
axes = plt.figure(figsize=(6, 4.5)).add_subplot()
axes.plot(t, np.sqrt(R * result.history["d"]), label="MDR: sqrt(R d)")
axes.plot(t[::200], exact[::200], "k.", label="eq. (33)")
axes.set(xlabel="time t [s]", ylabel="contact radius a [m]", title="Creep of a sphere on a Kelvin-Voigt body")
axes.legend()
late = t > 0.05 * eta / G
print(f"largest difference / final radius (t > 0.05 tau): {np.max(np.abs(np.sqrt(R * result.history['d'][late]) - exact[late])) / exact[-1]:.1e}")
print(mdr.plot.save(axes, sys.argv[2]))
