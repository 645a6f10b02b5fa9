"""Ting's solution for d = v t, then v (2 t_m - t): the contact radius is the loading radius at t1(t), where
int_{t1}^t G(t-s) d'(s) ds = 0, and F = (16 sqrt(R)/3) int_0^{t1} G(t-s) d/ds[d(s)^(3/2)] ds."""
import sys

import numpy as np

import mdr
import mdr.maps
import mdr.plot

case = mdr.maps.read_case(sys.argv[1])
result = mdr.run(sys.argv[1])
m, R = case["material"], case["indenter"]["R"]
t_m, d_m = case["load"]["history"][1]
v = d_m / t_m


def relaxation(x):
    return m["G_inf"] + m["G1"] * np.exp(-x / m["tau1"])


def integral(x):  # Phi(x) = int_0^x G
    return m["G_inf"] * x + m["G1"] * m["tau1"] * (1 - np.exp(-x / m["tau1"]))


def edge_time(t):
    if t <= t_m:
        return t
    def condition(t1):  # int_{t1}^t G(t - s) d'(s) ds / v, decreasing in t1
        return integral(t - t1) - 2 * integral(t - t_m)

    if condition(0.0) <= 0.0:
        return 0.0  # contact lost
    low, high = 0.0, t_m
    for _ in range(100):
        middle = 0.5 * (low + high)
        low, high = (middle, high) if condition(middle) > 0.0 else (low, middle)
    return 0.5 * (low + high)


def force(t):
    t1 = edge_time(t)
    u = np.linspace(0.0, np.sqrt(t1), 2001)  # s = u^2 removes the sqrt(s) of d(d^1.5)/ds
    integrand = relaxation(t - u**2) * 1.5 * v**1.5 * u * 2 * u
    return 16 * np.sqrt(R) / 3 * np.trapz(integrand, u)


t = result.history["t"]
exact = np.array([force(time) for time in t[::40]])
axes = mdr.plot.force_depth(result.history)
axes.plot(result.history["d"][::40], exact, "k.", label="Ting")
axes.legend()
axes.set_title("Sphere load-unload on a standard solid: MDR and Ting")
print(f"largest difference / peak force: {np.max(np.abs(result.history['F'][::40] - exact)) / exact.max():.1e}")
print(mdr.plot.save(axes, sys.argv[2]))
