"""bench/lammps_pair_cost.py --slide: the forces it reads from LAMMPS's pressure tensor (a contact's F_N and
|F_t| / (mu F_N) at the last step) against closed forms for `granular hertz/material` + `tangential mindlin`:
Hertz's normal force, its tangential spring (Mindlin's initial stiffness) in stick and Coulomb's limit in gross slip;
and mdr/visco in gross slip at Coulomb's limit too. The lattice is the bench's at 3^3 spheres (81 contacts).

The environment (tests/lammps/CMakeLists.txt): LMP, MDR_LAMMPS_PLUGIN."""

import math
import os
import subprocess
import sys
from pathlib import Path

BENCH = Path(__file__).resolve().parents[2] / "bench" / "lammps_pair_cost.py"
# the bench's hertz/material: E, Poisson's ratio; its spheres' radius, the lattice spacing, mu, the time step
YOUNG, POISSON, RADIUS, SPACING, FRICTION, TIME_STEP = 3e6, 0.49, 0.005, 0.00995, 0.3, 1e-6
OVERLAP = 2 * RADIUS - SPACING
REDUCED_RADIUS = RADIUS / 2
CONTACT_RADIUS = math.sqrt(REDUCED_RADIUS * OVERLAP)
# Hertz: F_N = (4/3) E* sqrt(R) d^(3/2), 1/E* = 2 (1 - nu^2) / E (two equal spheres; Johnson, eq. 4.22-4.23)
HERTZ_FORCE = 4 / 3 * YOUNG / (2 * (1 - POISSON ** 2)) * math.sqrt(REDUCED_RADIUS) * OVERLAP ** 1.5
# Mindlin's initial tangential stiffness 8 G* a, 1/G* = 2 (2 - nu) / G (Johnson, eq. 7.41; LAMMPS's `mindlin NULL`)
SHEAR = YOUNG / (2 * (1 + POISSON))
MINDLIN_STIFFNESS = 8 * SHEAR / (2 * (2 - POISSON)) * CONTACT_RADIUS


def bench(*options):
    """The bench's rows as {law: (F_N, |F_t| / (mu F_N) or None without friction)}."""
    done = subprocess.run([sys.executable, str(BENCH), "--side=3", *options], capture_output=True, text=True,
                          timeout=300, env=dict(os.environ))
    assert done.returncode == 0, done.stdout + done.stderr
    rows = {}
    for line in done.stdout.splitlines()[1:]:
        if line.startswith(("granular", "mdr/visco, N")):
            normal, ratio = line[72:].split()[-2:]
            rows[line[:72].strip()] = (float(normal), None if ratio == "-" else float(ratio))
    assert len(rows) == 4, done.stdout
    return rows


def test_gross_slip_reads_hertz_force_and_coulomb_limit():
    # --slide=1: hertz/material slides grossly from step 1, mdr/visco from step 22 (docs/dem-performance.md,
    # "Sliding contacts")
    rows = bench("--steps=30", "--slide=1")
    hertz = rows["granular hertz/material, damping tsuji, tangential mindlin mu 0.3"]
    assert abs(hertz[0] - HERTZ_FORCE) <= 5e-6 * HERTZ_FORCE / 0.01    # printed to 4 digits: 0.04653
    assert hertz[1] == 1.0                                             # |F_t| = mu F_N, to the 4 decimals printed
    assert rows["mdr/visco, N = 20, M = 1, friction 0.3"][1] == 1.0
    assert rows["mdr/visco, N = 20, M = 1, friction 0"][1] is None


def test_stick_reads_mindlin_stiffness():
    # --slide=0.07: hertz/material sticks until step 24; its |F_t| = c V + k_t V t (c the tangential damping), so
    # ten more steps add k_t V 10 dt to it
    speed = 0.07
    ten, twenty = (bench(f"--steps={steps}", f"--slide={speed}")[
        "granular hertz/material, damping tsuji, tangential mindlin mu 0.3"][1] for steps in (10, 20))
    expected = MINDLIN_STIFFNESS * speed * 10 * TIME_STEP / (FRICTION * HERTZ_FORCE)    # 0.0473
    assert twenty < 1.0
    assert abs((twenty - ten) - expected) <= 1e-4    # two values printed to 4 decimals
