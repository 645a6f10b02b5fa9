"""Eq. (12) summed over the contact: k(omega) = 8 a0 G(omega) for a small harmonic depth on a pre-indented sphere;
and the bias of that small-amplitude formula as the amplitude grows to the pre-indentation (contact lost)."""
import copy
import math
import sys

import matplotlib.pyplot as plt
import numpy as np

import mdr
import mdr.maps
import mdr.plot

case = mdr.maps.read_case(sys.argv[1])
m = case["material"]
tau = m["tau1"]
R, d0 = case["indenter"]["R"], case["load"]["history"][-1][1]
a0 = math.sqrt(R * d0)
start = case["load"]["harmonic"]["start"]


def modulus(omega_tau):
    """G(omega) of the standard solid: G_inf + G1 i omega tau / (1 + i omega tau)."""
    return m["G_inf"] + m["G1"] * 1j * omega_tau / (1 + 1j * omega_tau)


def measured(omega_tau, amplitude):
    """k' + i k'' and the contact-loss fraction of the last cycle, 25 tau after the harmonic starts."""
    run = copy.deepcopy(case)
    frequency = omega_tau / (2 * math.pi * tau)
    end = start + max(2, math.ceil(25 * tau * frequency)) / frequency
    run["load"]["history"][-1][0] = end
    run["load"]["harmonic"] = {"amplitude": amplitude, "frequency": frequency, "start": start, "end": end}
    summary = mdr.run(run).summary
    return complex(summary["storage_stiffness"], summary["loss_stiffness"]), summary["contact_loss_fraction"]


omega_taus = np.logspace(-2, 2, 9)
spectrum = np.array([measured(w, 1e-3 * d0)[0] for w in omega_taus])
closed = 8 * a0 * np.array([modulus(w) for w in omega_taus])

ratios = [1e-3, 1e-2, 0.03, 0.1, 0.3, 1.0]
bias_at = [0.1, 1.0, 10.0]
print("| amplitude / d0 | " + " | ".join(f"k' at ωτ = {w:g} | k'' at ωτ = {w:g}" for w in bias_at) + " | contact lost |")
print("|---" * (2 * len(bias_at) + 2) + "|")
bias = {w: [] for w in bias_at}
for ratio in ratios:
    cells, lost = [], 0.0
    for w in bias_at:
        k, loss = measured(w, ratio * d0)
        exact = 8 * a0 * modulus(w)
        bias[w].append((k.real / exact.real - 1, k.imag / exact.imag - 1))
        cells += [f"{bias[w][-1][0]:+.1e}", f"{bias[w][-1][1]:+.1e}"]
        lost = max(lost, loss)
    print(f"| {ratio:g} | " + " | ".join(cells) + f" | {lost:.0%} |")

figure, (left, right) = plt.subplots(1, 2, figsize=(11, 4.5))
left.loglog(omega_taus, spectrum.real, "o", label="MDR k'")
left.loglog(omega_taus, spectrum.imag, "s", label="MDR k''")
fine = np.logspace(-2, 2, 200)
exact_fine = 8 * a0 * np.array([modulus(w) for w in fine])
left.loglog(fine, exact_fine.real, "k-", lw=0.8, label="8 a0 G'(ω)")
left.loglog(fine, exact_fine.imag, "k--", lw=0.8, label="8 a0 G''(ω)")
left.set(xlabel="ω τ1", ylabel="contact stiffness [N/m]", title="Dynamic stiffness, amplitude d0/1000")
left.legend()
for w in bias_at:
    right.loglog(ratios, [abs(b[0]) for b in bias[w]], "o-", label=f"k', ωτ = {w:g}")
    right.loglog(ratios, [abs(b[1]) for b in bias[w]], "s--", label=f"k'', ωτ = {w:g}")
right.set(xlabel="amplitude / d0", ylabel="|relative bias of 8 a0 G(ω)|", title="Bias of the linear formula")
right.legend(fontsize=8)
print(f"largest difference of k from 8 a0 G(omega) at amplitude d0/1000, relative: "
      f"{np.max(np.abs(spectrum - closed) / np.abs(closed)):.1e}")
print(mdr.plot.save(left, sys.argv[2]))
