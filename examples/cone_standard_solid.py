"""Eq. (28): F(t) = (8 v0^2/(pi tan theta)) [G_inf t^2 + 2 G1 tau1 t - 2 G1 tau1^2 (1 - exp(-t/tau1))]."""
import math
import sys

import numpy as np

import mdr
import mdr.maps
import mdr.plot

case = mdr.maps.read_case(sys.argv[1])
result = mdr.run(sys.argv[1])
m, theta = case["material"], math.radians(case["indenter"]["slope_deg"])
v0 = case["load"]["history"][-1][1] / case["load"]["history"][-1][0]
t = result.history["t"]
exact = 8 * v0**2 / (math.pi * math.tan(theta)) * (
    m["G_inf"] * t**2 + 2 * m["G1"] * m["tau1"] * t - 2 * m["G1"] * m["tau1"] ** 2 * (1 - np.exp(-t / m["tau1"])))
axes = mdr.plot.force_time(result.history)
axes.plot(t[::100], exact[::100], "k.", label="eq. (28)")
axes.set_title("Cone into a standard solid, d = v0 t: MDR (line) and eq. (28) (dots)")
print(f"largest difference / peak force: {np.max(np.abs(result.history['F'] - exact)) / exact[-1]:.1e}")
print(mdr.plot.save(axes, sys.argv[2]))
