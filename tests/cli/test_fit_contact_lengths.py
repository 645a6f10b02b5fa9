"""Issue 24, units cannot slip on an indenter without a tip size: a cone or a flat punch has no radius to compare the
depths with, so a curve's largest indentation and its contact radius are held to the lengths of indentation contacts
(0.1 nm to 10 cm, include/mdr/fit/plausibility.hpp). Before, lengths in the wrong unit on a cone gave only a misfit
flag. Curves from closed forms (Sneddon's cone, the flat punch), never from mdr."""

from __future__ import annotations

import csv
import math
import random
import re

import pytest

from test_fit_workflow import DEPTH_CASE, fit_flags

# um-nN-s: G in kPa, lengths in um, forces in nN; E* = 4G (nu = 0.5).
G_TRUE = 0.2
SLOPE = math.radians(90.0 - 35.0)   # half_angle_deg = 35: the flank's angle to the surface
PUNCH_RADIUS = 2.0                  # um


def cone_force(depth):
    """Sneddon's cone, F = 2 E* d^2 / (pi tan(slope)) (eq. 24, 25: a = 2d / (pi tan(slope)), F = E* a d)."""
    return 8.0 * G_TRUE * max(depth, 0.0) ** 2 / (math.pi * math.tan(SLOPE))


def punch_force(depth):
    """The flat punch, F = 2 E* b d."""
    return 8.0 * G_TRUE * PUNCH_RADIUS * max(depth, 0.0)


def write_curve(path, force, length_scale=1.0, contact=1.0, seed=5, rows=300):
    """depth (um times length_scale) and force (nN) columns, contact `contact` um after the first row, 3 um deep."""
    generator = random.Random(seed)
    with open(path, "w", newline="", encoding="utf-8") as handle:
        writer = csv.writer(handle)
        writer.writerow(["t", "d", "F"])
        for i in range(rows):
            t = i / (rows - 1)
            depth = -contact + (contact + 3.0) * t
            writer.writerow([t, (depth + contact) * length_scale, force(depth) + generator.gauss(0.0, 0.002)])


CONE_CASE = DEPTH_CASE.replace('shape = "sphere"\nR = 5.0', 'shape = "cone"\nhalf_angle_deg = 35.0')
PUNCH_CASE = DEPTH_CASE.replace('shape = "sphere"\nR = 5.0', 'shape = "flat"\na = {radius}')
LENGTH_RULE = "is outside the lengths of indentation contacts (1e-10 m to 0.1 m, AFM to macroscopic indentation)"


def unit_flags(curve_flags):
    return [flag for flag in curve_flags if "lengths of indentation contacts" in flag]


def test_a_sane_cone_fit_has_no_flag(run_mdr, workdir):
    import json
    write_curve(workdir / "hertz.csv", cone_force)
    flags, curve_flags, _ = fit_flags(run_mdr, workdir, CONE_CASE.format(data="", fit=""))
    assert flags == [] and curve_flags == []
    fitted = json.loads((workdir / "out" / "fit.json").read_text())["parameters"]["material.G"]
    assert fitted == pytest.approx(G_TRUE, rel=1e-2)


def test_metres_read_as_micrometres_on_a_cone_are_flagged(run_mdr, workdir):
    """The issue's trap on a cone: a um-nN-s case whose file holds metres and leaves out units.length reads 3e-6 m as
    3e-6 um (3e-12 m, a hundredth of an atom's size): flagged on the curve and the console, naming the key to set."""
    write_curve(workdir / "hertz.csv", cone_force, length_scale=1e-6)
    _, curve_flags, stdout = fit_flags(run_mdr, workdir, CONE_CASE.format(data="", fit=""))
    (flag,) = unit_flags(curve_flags)
    # About 3 to 4 (1e-6 um): from the fitted contact, which such a fit may put at the record's first row.
    shown = r"largest indentation [234](\.\d+)?e-06 µm \([234](\.\d+)?e-12 m\) "
    assert re.match(shown + re.escape(LENGTH_RULE), flag)
    assert "units.length" in flag and "flag (hertz): largest indentation" in stdout
    # The same file with its unit stated: no flag.
    _, curve_flags, _ = fit_flags(run_mdr, workdir, CONE_CASE.format(data='units = { length = "m" }', fit=""))
    assert curve_flags == []


def test_micrometres_read_as_metres_on_a_cone_are_flagged(run_mdr, workdir):
    """The reverse: an SI case reading a file's micrometres as metres indents 3 m."""
    write_curve(workdir / "hertz.csv", cone_force)
    _, curve_flags, _ = fit_flags(run_mdr, workdir, CONE_CASE.format(data="", fit="").replace('units = "um-nN-s"', ""))
    (flag,) = unit_flags(curve_flags)
    assert re.match(r"largest indentation [234](\.\d+)? m \([234](\.\d+)? m\) " + re.escape(LENGTH_RULE), flag)
    assert "units.length" in flag


def test_a_flat_punch_radius_in_another_unit_is_flagged(run_mdr, workdir):
    """A depth of 3 um is plausible; a punch radius of 2e-6 um (metres written in a um-nN-s case) is not: its
    contact radius is flagged, naming the indenter. Before, only the misfit and G at its bound said that something
    was wrong, none naming a unit."""
    write_curve(workdir / "hertz.csv", punch_force)
    _, curve_flags, _ = fit_flags(run_mdr, workdir, PUNCH_CASE.format(data="", fit="", radius=PUNCH_RADIUS))
    assert curve_flags == []
    _, curve_flags, _ = fit_flags(run_mdr, workdir, PUNCH_CASE.format(data="", fit="", radius=PUNCH_RADIUS * 1e-6))
    (flag,) = unit_flags(curve_flags)
    assert re.match(r"the contact radius 2e-06 µm \(2e-12 m\) at the largest indentation [234](\.\d+)? µm", flag)
    assert LENGTH_RULE in flag and "[indenter]" in flag
