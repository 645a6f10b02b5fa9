"""The LAMMPS pair style mdr/visco (dem/lammps) against `mdr run` and against the rules of a DEM code: two spheres
colliding head-on on 1 and 2 MPI ranks give the restitution of `mdr run`'s impact of the equivalent sphere (eq. 8:
R = R1 R2 / (R1 + R2), the reduced mass, J = J1 + J2); an oblique collision with friction and spin gives its
tangential restitution; a packing settles the same on 1 and 2 ranks and loses energy only; a run restarted
mid-contact continues as the run that was not stopped.

The environment (tests/lammps/CMakeLists.txt): LMP, MDR_LAMMPS_PLUGIN, MDR_BINARY, MPIEXEC."""

import json
import math
import os
import subprocess
from pathlib import Path

import pytest

LMP = os.environ["LMP"]
PLUGIN = os.environ["MDR_LAMMPS_PLUGIN"]
MDR = os.environ["MDR_BINARY"]
MPIEXEC = os.environ.get("MPIEXEC", "mpirun")

# Two sphere types: a standard solid and a two-term Prony series (SI units).
MATERIALS = {
    1: {"G_inf": 1.0e6, "terms": [(3.0e6, 1.0e-3)]},
    2: {"G_inf": 2.0e6, "terms": [(4.0e6, 3.0e-4), (1.0e6, 1.0e-2)]},
}
ELEMENTS, HALF_WIDTH = 40, 0.25  # the law's N and L / R


def pair_coeffs(friction):
    lines = []
    for kind, material in MATERIALS.items():
        terms = " ".join(f"term {g} {tau}" for g, tau in material["terms"])
        lines.append(f"pair_coeff {kind} {kind} G_inf {material['G_inf']} {terms} friction {friction} "
                     f"elements {ELEMENTS} half_width {HALF_WIDTH}")
    return "\n".join(lines)


def run_lammps(script, tmp_path, ranks=1, name="in.lmp"):
    """Runs a LAMMPS input on `ranks` MPI ranks; returns the lines it printed that start with RESULT."""
    path = tmp_path / name
    path.write_text(f"plugin load {PLUGIN}\n" + script)
    command = [LMP, "-in", str(path), "-log", str(tmp_path / f"log.{name}.{ranks}"), "-screen", "none"]
    if ranks > 1:
        command = [MPIEXEC, "-np", str(ranks)] + command
    done = subprocess.run(command, cwd=tmp_path, capture_output=True, text=True, timeout=600)
    log = (tmp_path / f"log.{name}.{ranks}").read_text() if (tmp_path / f"log.{name}.{ranks}").exists() else ""
    assert done.returncode == 0, done.stdout[-3000:] + done.stderr[-3000:] + log[-3000:]
    return [line.split()[1:] for line in log.splitlines() if line.startswith("RESULT")]


def two_spheres(radii, densities, velocities, spins=(0.0, 0.0), friction=0.0, time_step=1e-7, steps=40000,
                processors=""):
    """Sphere 1 at the origin, sphere 2 on +x just out of contact; velocities (vx, vy) each; spins about z."""
    (r1, r2), gap = radii, 1e-9
    return f"""
units si
atom_style sphere
atom_modify map array
boundary f f f
newton on
{processors}
region box block -0.1 0.1 -0.1 0.1 -0.1 0.1
create_box 2 box
create_atoms 1 single 0 0 0
create_atoms 2 single {r1 + r2 + gap} 0 0
set atom 1 diameter {2 * r1} density {densities[0]}
set atom 2 diameter {2 * r2} density {densities[1]}
velocity all set 0 0 0
set atom 1 vx {velocities[0][0]} vy {velocities[0][1]} omega 0 0 {spins[0]}
set atom 2 vx {velocities[1][0]} vy {velocities[1][1]} omega 0 0 {spins[1]}
pair_style mdr/visco
{pair_coeffs(friction)}
comm_modify vel yes cutoff 0.05
neighbor 0.002 bin
neigh_modify delay 0 every 1 check yes
fix move all nve/sphere
timestep {time_step}
run {steps}
variable a1 equal vx[1]
variable a2 equal vx[2]
variable b1 equal vy[1]
variable b2 equal vy[2]
variable w1 equal wz[1]
variable w2 equal wz[2]
print "RESULT ${{a1}} ${{a2}} ${{b1}} ${{b2}} ${{w1}} ${{w2}}"
"""


def mdr_run(tmp_path, radius, mass, velocity, tangential=None):
    """`mdr run`'s impact of the equivalent rigid sphere on material 1 with material 2 as the indenter's."""
    def material(table, m):
        terms = ", ".join(f"[{g}, {tau}]" for g, tau in m["terms"])
        return f"[{table}]\nmodel = \"prony\"\nG_inf = {m['G_inf']}\nterms = [{terms}]\n"

    oblique = ""
    if tangential:
        oblique = (f"tangential_velocity = {tangential['velocity']}\nspin = {tangential['spin']}\n"
                   f"[tangential]\nfriction = {tangential['friction']}\n")
        inertia = f"moment_of_inertia = {tangential['inertia']}\n"
    else:
        inertia = ""
    case = (material("material", MATERIALS[1]) + material("indenter.material", MATERIALS[2]) +
            f"[indenter]\nshape = \"sphere\"\nR = {radius}\nmass = {mass}\n{inertia}"
            f"[load]\ncontrol = \"impact\"\nvelocity = {velocity}\n{oblique}"
            f"[numerics]\nelements = {ELEMENTS}\nhalf_width = {HALF_WIDTH * radius}\ntime_step = 1e-8\n")
    (tmp_path / "case.toml").write_text(case)
    out = tmp_path / "mdr-out"
    subprocess.run([MDR, "run", str(tmp_path / "case.toml"), "--out", str(out)], check=True, capture_output=True)
    return json.loads((out / "summary.json").read_text())


RADII, DENSITIES = (0.01, 0.015), (1100.0, 1300.0)


def masses():
    return [4.0 / 3.0 * math.pi * r ** 3 * rho for r, rho in zip(RADII, DENSITIES)]


@pytest.mark.parametrize("ranks", [1, 2])
def test_two_spheres_restitution_is_mdr_runs(tmp_path, ranks):
    velocities = ((0.3, 0.0), (-0.2, 0.0))
    processors = "processors 2 1 1" if ranks == 2 else ""
    (a1, a2, *_), = run_lammps(two_spheres(RADII, DENSITIES, velocities, processors=processors), tmp_path, ranks)
    restitution = (float(a2) - float(a1)) / (velocities[0][0] - velocities[1][0])
    m1, m2 = masses()
    radius = RADII[0] * RADII[1] / sum(RADII)
    summary = mdr_run(tmp_path, radius, m1 * m2 / (m1 + m2), velocities[0][0] - velocities[1][0])
    assert 0.3 < summary["restitution"] < 0.99
    assert restitution == pytest.approx(summary["restitution"], abs=1e-6)
