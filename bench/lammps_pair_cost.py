"""Cost per contact-step of the LAMMPS pair style mdr/visco against LAMMPS's `granular hertz/material` with a damping
model, with friction (mu = 0.3, hertz/material's tangential model Mindlin's) and without (mu = 0, its tangential
model linear_nohistory with mu = 0), each ratio to the hertz/material variant of the same friction, in one run on the
same machine: a periodic simple-cubic lattice of 8000 spheres, each pressed into its six
neighbours (24000 contacts, all alive every step), with random velocities but no integrator, so that every contact
is stepped with a tangential increment and the contact set never changes (a tiny one: `velocity all create 1e-6` is
1 uK, about 1e-13 m/s, so every contact sticks; docs/dem-performance.md). Pair time from LAMMPS's timing
breakdown over steps x contacts; memory per rank from its log.

    LMP=.../lmp MDR_LAMMPS_PLUGIN=.../mdrviscoplugin.so python3 bench/lammps_pair_cost.py [N] [M] [--callgrind]
        [--slide=V]

--callgrind counts instructions instead (valgrind's callgrind, deterministic, so comparable on a loaded host): the
pair styles' compute functions, inclusive, on an 8^3 lattice (1536 contacts) over 50 steps (51 computes with the
setup's), per contact-step.

--cache-sim counts, with callgrind's cache simulation of this host's L1d (48 kB) and L2 (2 MB) as its last
level and no prefetching, the bytes the compute functions bring from beyond the L2 (64 bytes a missed line, reads and
write-allocates) per contact-step: the bytes a step touches where its data is not cached.

--side=S --steps=T time an S^3 lattice (3 S^3 contacts) over T steps instead of the 20^3 one over 200: with S = 5
(375 contacts, 0.5 MB of mdr/visco history at N = 20, M = 1) every contact's state stays in a core's 2 MB L2
cache, with S = 20 (33 MB) it does not, with S = 40 (261 MB) it exceeds the L3 too (docs/dem-performance.md, "Is
the step memory-bound?"). --warmup=K runs K steps before the timed ones (every contact's first, non-composed steps
and the history pages' first touch then fall outside the timing: a held contact's step). --skin=S sets the
neighbour skin [m] (0.0005: only the six touching neighbours are listed; 0.005 lists the twelve face-diagonal ones
too, out of contact, as a packing lists more neighbours than contacts). --plugin=PATH times that mdr/visco plugin instead of $MDR_LAMMPS_PLUGIN.

--slide=V makes every contact slide at V [m/s]: each sphere spins at omega = V / (2 sqrt(2) R) (1, 1, 1), R its
radius (`set type 1 omega`; still no integrator, so the overlaps stay fixed). Both pair styles step a contact with
the contact points' relative velocity v_i - v_j + (r_i w_i + r_j w_j) x n, n from i to j (pair granular's vtr,
pair mdr/visco's `turned`), here (2 R w) x n: a tangential velocity of magnitude V at each of the three lattice
directions (its twist, w . n, neither style reads). The table then adds, at the last step, a contact's normal force
F_N and, with friction, |F_t| / (mu F_N) (1: gross slip; below 1: stick or partial slip), both from the pressure
tensor and the lattice's symmetry (spacing d, S^3 contacts along each axis in a volume S^3 d^3): the contacts along
x alone give P_xx = F_N / d^2 and |P_xy| = |P_xz| = |F_t| / (sqrt(2) d^2), the tangential force being along
(0, 1, -1) / sqrt(2) (so F_N = d^2 (P_xx + P_yy + P_zz) / 3, |F_t| = sqrt(2) d^2 (|P_xy| + |P_xz| + |P_yz|) / 3).
With mu = 0.3, N = 20, M = 1 (docs/dem-performance.md, "Sliding contacts"), mdr/visco's contacts with --slide=1
stick for two steps, slip partially in steps 3-21 and slip grossly from step 22 (hertz/material's from step 1, its
tangential damping alone above mu F_N); with --slide=0.07 they stick for 27 steps and slip partially from step 28 to step 254
(hertz/material's stick until step 24 and slip grossly from step 25).
"""

import math
import os
import re
import subprocess
import sys
import tempfile
from pathlib import Path

CACHE_SIM = "--cache-sim" in sys.argv
CALLGRIND = "--callgrind" in sys.argv or CACHE_SIM
OPTIONS = dict(a[2:].split("=", 1) for a in sys.argv[1:] if a.startswith("--") and "=" in a)
ARGS = [a for a in sys.argv[1:] if not a.startswith("--")]
LMP, PLUGIN = os.environ["LMP"], OPTIONS.get("plugin") or os.environ["MDR_LAMMPS_PLUGIN"]
ELEMENTS = int(ARGS[0]) if len(ARGS) > 0 else 20
TERMS = int(ARGS[1]) if len(ARGS) > 1 else 1
STEPS, SIDE = (50, 8) if CALLGRIND else (200, 20)
STEPS, SIDE = int(OPTIONS.get("steps", STEPS)), int(OPTIONS.get("side", SIDE))
SKIN = OPTIONS.get("skin", "0.0005")
WARMUP = f"run {OPTIONS['warmup']}\n" if "warmup" in OPTIONS else ""
# The pair's computes in a callgrind run: each `run K` computes once at its setup and once a step.
PAIR_COMPUTES = STEPS + 1 + (int(OPTIONS["warmup"]) + 1 if "warmup" in OPTIONS else 0)


def sliding_speed(text):
    """--slide's V [m/s]: a finite number; otherwise one line on stderr and a non-zero exit."""
    try:
        value = float(text)
    except ValueError:
        value = math.nan
    if not math.isfinite(value):
        sys.exit(f"--slide={text}: must be a finite speed in m/s")
    return value


SLIDE = sliding_speed(OPTIONS["slide"]) if "slide" in OPTIONS else None
RADIUS, SPACING, FRICTION = 0.005, 0.00995, 0.3    # [m], [m]: each sphere pressed 50 um into its six neighbours
# --slide: every sphere's spin [rad/s] and the pressure tensor's columns, which give F_N and |F_t| (the docstring)
SPIN = "" if SLIDE is None else ("set type 1 omega {0} {0} {0}\n".format(SLIDE / (2 * 2 ** 0.5 * RADIUS))
                                 + "thermo_style custom step c_contacts pxx pyy pzz pxy pxz pyz\n")

LATTICE = f"""
units si
atom_style sphere
boundary p p p
newton on
lattice sc {SPACING}
region box block 0 {SIDE} 0 {SIDE} 0 {SIDE} units lattice
create_box 1 box
create_atoms 1 box
set type 1 diameter {2 * RADIUS} density 1100
velocity all create 1e-6 4928 loop geom
comm_modify vel yes
neighbor {SKIN} bin
neigh_modify one 50 page 5000
timestep 1e-6
compute touching all contact/atom
compute contacts all reduce sum c_touching
thermo_style custom step c_contacts
""" + SPIN

COMPUTES = {"granular": "*PairGranular::compute*", "mdr/visco": "*PairMdrVisco::compute*"}
TERM_LIST = " ".join(f"term 1e6 {1e-4 * 10 ** k}" for k in range(TERMS))
# Each mdr/visco law beside the hertz/material variant that does the same work: with friction, its damping and
# Mindlin's tangential model with the same mu; without, its damping and a tangential model of mu = 0 (pair granular
# needs one; linear_nohistory keeps no history). The ratio of each row is to the hertz/material row of its pair.
PAIRS = [
    (FRICTION,
     (f"granular hertz/material, damping tsuji, tangential mindlin mu {FRICTION}",
      f"pair_style granular\npair_coeff * * hertz/material 3e6 0.5 0.49 tangential mindlin NULL 1.0 {FRICTION} "
      "damping tsuji\n"),
     (f"mdr/visco, N = {ELEMENTS}, M = {TERMS}, friction {FRICTION}",
      f"pair_style mdr/visco\npair_coeff 1 1 G_inf 1e6 {TERM_LIST} friction {FRICTION} elements {ELEMENTS} "
      "half_width 0.2\n")),
    (0.0,
     ("granular hertz/material, damping tsuji, tangential linear_nohistory mu 0",
      "pair_style granular\npair_coeff * * hertz/material 3e6 0.5 0.49 tangential linear_nohistory 0.0 0.0 "
      "damping tsuji\n"),
     (f"mdr/visco, N = {ELEMENTS}, M = {TERMS}, friction 0",
      f"pair_style mdr/visco\npair_coeff 1 1 G_inf 1e6 {TERM_LIST} friction 0 elements {ELEMENTS} "
      "half_width 0.2\n")),
]


def run(law):
    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / "in.lmp"
        path.write_text(f"plugin load {PLUGIN}\n" + LATTICE + law + WARMUP + f"run {STEPS}\n")
        command = [LMP, "-in", str(path), "-log", str(Path(folder) / "log"), "-screen", "none"]
        counts = Path(folder) / "callgrind.out"
        if CALLGRIND:
            style = law.split()[1]
            command = ["valgrind", "--tool=callgrind", f"--callgrind-out-file={counts}",
                       f"--toggle-collect={COMPUTES[style]}"] + command
            if CACHE_SIM:
                command[2:2] = ["--cache-sim=yes", "--D1=49152,12,64", "--LL=2097152,16,64"]
        subprocess.run(command, check=True, cwd=folder, stderr=subprocess.DEVNULL if CALLGRIND else None)
        log = (Path(folder) / "log").read_text()
        if CALLGRIND:
            totals = re.search(r"^totals: (\d+)", counts.read_text(), re.M) or re.search(
                r"^summary: (\d+)", counts.read_text(), re.M)
            instructions = float(totals.group(1))
            if CACHE_SIM:  # the last level's data misses, read and write, in lines of 64 bytes
                text = counts.read_text()
                events = re.search(r"^events: (.*)$", text, re.M).group(1).split()
                values = (re.search(r"^totals: (.*)$", text, re.M) or re.search(r"^summary: (.*)$", text, re.M))
                value = dict(zip(events, map(float, values.group(1).split())))
                instructions = 64.0 * (value.get("DLmr", 0.0) + value.get("DLmw", 0.0))
    # the last thermo row: step, touching flags (two per contact), and with --slide the pressure tensor
    last = [float(value) for value in re.findall(r"^[ \t]*\d+((?:[ \t]+[\d.e+-]+)+)[ \t]*$", log, re.M)[-1].split()]
    contacts = last[0] / 2
    # with --slide, a contact's F_N and |F_t| at the last step from the pressure tensor (the docstring)
    forces = None if SLIDE is None else (SPACING ** 2 * sum(last[1:4]) / 3,
                                         2 ** 0.5 * SPACING ** 2 * sum(abs(p) for p in last[4:7]) / 3)
    memory = float(re.search(r"Per MPI rank memory allocation \(min/avg/max\) = [\d.]+ \| ([\d.]+)", log).group(1))
    if CALLGRIND:
        return instructions / (PAIR_COMPUTES * contacts), contacts, memory, forces
    pair = float(re.findall(r"^Pair\s*\|\s*[\d.e+-]+\s*\|\s*([\d.e+-]+)", log, re.M)[-1])
    return pair / (STEPS * contacts), contacts, memory, forces


state = 2 * TERMS * TERMS + 16 * TERMS + 31 + ELEMENTS * (3 * TERMS + 4)  # ContactLaw::state_size
unit, scale = ("L2-missed bytes", 1.0) if CACHE_SIM else ("instructions", 1.0) if CALLGRIND else ("ns", 1e9)
sliding = f" {'F_N [N]':>9s} {'|F_t|/(mu F_N)':>14s}" if SLIDE is not None else ""
print(f"{'law':72s} {unit + '/contact-step':>24s} {'ratio':>6s} {'contacts':>9s} {'MB/rank':>8s}" + sliding)
for mu, (base_name, base_law), (name, law) in PAIRS:
    base = run(base_law)
    for label, (cost, contacts, memory, forces) in ((base_name, base), (name, run(law))):
        row = f"{label:72s} {cost * scale:24.1f} {cost / base[0]:6.2f} {contacts:9.0f} {memory:8.1f}"
        if forces:  # 1: gross slip; below: stick or partial slip; "-" without friction
            normal, tangential = forces
            row += f" {normal:9.4g} {f'{tangential / (mu * normal):.4f}' if mu else '-':>14s}"
        print(row)
print(f"mdr/visco history per contact: {state} doubles = {state * 8} bytes (2 M^2 + 16 M + 31 + N (3 M + 4))")
