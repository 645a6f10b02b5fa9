"""Eq. (55): the radius c of the permanent stick zone, 2 |G^(omega)| u0 = 3 mu G_inf [d0 - g(c)], g = x^2/R."""
import math
import sys

import matplotlib.pyplot as plt
import numpy as np

import mdr
import mdr.maps
import mdr.plot

case = mdr.maps.read_case(sys.argv[1])
result = mdr.run(sys.argv[1])
m, tangential = case["material"], case["tangential"]
material = mdr.Material.standard(G_inf=m["G_inf"], G1=m["G1"], tau1=m["tau1"])
modulus = abs(material.complex_modulus(2 * math.pi * tangential["frequency"]))
R, d0 = case["indenter"]["R"], case["load"]["history"][-1][1]
g_c = d0 - 2 * modulus * tangential["amplitude"] / (3 * tangential["friction"] * m["G_inf"])
c_55 = math.sqrt(R * g_c)
figure, (left, right) = plt.subplots(1, 2, figsize=(11, 4.5))
h = result.history
left.plot(h["t"], h["c"], label="MDR stick radius c(t)")
left.plot(h["t"], h["a"], color="0.6", label="contact radius a")
left.axhline(c_55, color="k", ls="--", label="eq. (55)")
left.set(xlabel="time t [s]", ylabel="radius [m]", xlim=(0.9, 2.0), title="Stick zone under fretting")
left.legend()
mdr.plot.tangential_loop(h, axes=right)
period = 1 / tangential["frequency"]
last = h["t"] >= tangential["end"] - period
print(f"last-cycle minimum stick radius vs eq. (55), relative to a: {abs(h['c'][last].min() - c_55) / h['a'][-1]:.1e}")
print(mdr.plot.save(left, sys.argv[2]))
