"""Tangential restitution of the contact point against the incidence parameter chi = v_c0 / (mu v0) for an elastic
and a viscoelastic sphere. Where the contact slides throughout, the impulse ratio is mu and e_t follows from the
normal restitution e in closed form: e_t = (7/2) (1 + e) / chi - 1 (solid sphere, 1/m_t = 7/(2m))."""
import sys

import matplotlib.pyplot as plt
import numpy as np

import mdr
import mdr.maps
import mdr.plot

case = mdr.maps.read_case(sys.argv[1])
mu, v0 = case["tangential"]["friction"], case["load"]["velocity"]
elastic = dict(case, material={"model": "elastic", "G": case["material"]["G_inf"]})
chis = np.geomspace(0.2, 12.0, 17)
axes = plt.figure(figsize=(6.5, 4.5)).add_subplot()
worst = 0.0
for label, base in (("elastic, G = G_inf", elastic), ("standard solid", case)):
    e_t, sliding = [], []
    for chi in chis:
        summary = mdr.run(dict(base, load=dict(base["load"], tangential_velocity=chi * mu * v0))).summary
        e_t.append(summary["tangential_restitution"])
        if summary["slid_throughout"]:
            closed = 3.5 * (1.0 + summary["restitution"]) / chi - 1.0
            worst = max(worst, abs(summary["tangential_restitution"] - closed))
            sliding.append((chi, closed))
    line, = axes.plot(chis, e_t, "o-", label=f"MDR, {label} (e = {summary['restitution']:.3f})")
    x = np.geomspace(3.5 * (1.0 + summary["restitution"]) / 2.0, chis[-1], 50)
    axes.plot(x, 3.5 * (1.0 + summary["restitution"]) / x - 1.0, "--", color=line.get_color(),
              label="sliding throughout, closed form")
axes.axhline(0.0, color="0.7", lw=0.8)
axes.set(xscale="log", xlabel=r"incidence parameter $\chi = v_{c0} / (\mu v_0)$",
         ylabel=r"tangential restitution $e_t = -v_c(T) / v_c(0)$", title="Oblique impact of a sphere")
axes.legend(fontsize=8)
print(f"largest difference from the sliding closed form: {worst:.1e}")
print(mdr.plot.save(axes, sys.argv[2]))
