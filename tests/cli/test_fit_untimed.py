"""`mdr fit` on instrument files that record no time (AFM Workshop .csv, NT-MDT Nova .txt; docs/instrument-files.md):
an elastic material is fitted with the rows' index as time, checked against an independent numpy least-squares
Hertz fit of the same rows; a time-dependent material is refused naming the file."""

from __future__ import annotations

import csv
import json
import math
import pathlib

import numpy as np
import pytest

from test_bad_input import assert_bad_input

VENDOR = pathlib.Path(__file__).resolve().parents[2] / "examples" / "data" / "vendor"
AFM_WORKSHOP = VENDOR / "fmt-afm-workshop-fd_single_2018-08-01_13.06.09.csv"
NOVA = VENDOR / "fmt-ntmdt-txt-fd_2015_01_17_gel4-0,1_mQ_adh_6B_Curve_DFL_Height_51.txt"
RADIUS = 5.0e-6


def afm_workshop_rows(path, sensitivity):
    """Height [m] and deflection [m] in measurement order (extend, then retract), as docs/instrument-files.md
    documents: height = -Z-Sense, deflection = T-B x sensitivity."""
    lines = path.read_text().splitlines()
    start = next(i for i, line in enumerate(lines) if line.startswith("Extend Z-Sense(nm)")) + 1
    rows = [line.split(",") for line in lines[start:] if line.strip()]
    height, deflection = [], []
    for column in (0, 2):
        for row in rows:
            if row[column].strip():
                height.append(-1e-9 * float(row[column]))
                deflection.append(float(row[column + 1]) * sensitivity)
    return np.array(height), np.array(deflection)


def nova_rows(path, sensitivity):
    """Height [m] and deflection [m] in measurement order: the extend is the rows in reverse, the retract the rows
    in order; deflection = DFL [nA] x 1e-9 x sensitivity (docs/instrument-files.md)."""
    values = np.array([[float(field.replace(",", ".")) for field in line.split("\t")]
                       for line in path.read_text().splitlines() if line.strip()])
    height = np.concatenate([values[::-1, 0], values[:, 0]]) * 1e-9
    deflection = np.concatenate([values[::-1, 1], values[:, 2]]) * 1e-9 * sensitivity
    return height, deflection


def hertz_fit(height, deflection, spring_constant):
    """Least squares of F = b + (16/3) G sqrt(R) d^(3/2) (Hertz, E* = 4 G for an incompressible body) over every
    row, linear in G and b; depth d = (h_0 + x_0) - (h + x) below the first row's tip height, F = k x."""
    force = spring_constant * deflection
    depth = (height[0] + deflection[0]) - (height + deflection)
    shape = 16.0 / 3.0 * math.sqrt(RADIUS) * np.maximum(depth, 0.0) ** 1.5
    design = np.column_stack([shape, np.ones_like(shape)])
    (modulus, baseline), *_ = np.linalg.lstsq(design, force, rcond=None)
    return modulus, baseline


def case(material, path, spring_constant, sensitivity):
    return f"""
[material]
{material}

[indenter]
shape = "sphere"
R = {RADIUS}

[fit]
free = ["material.G"]
contact_point = "fixed"
baseline = "fit"

[[fit.data]]
file = "{path}"
spring_constant = {spring_constant}
sensitivity = {sensitivity}
until = "end"
"""


@pytest.mark.parametrize("path, spring_constant, sensitivity, rows", [
    (AFM_WORKSHOP, 0.1, 50e-9, afm_workshop_rows),
    (NOVA, 0.055, 61.0, nova_rows),
])
def test_an_elastic_hertz_fit_of_a_file_without_time_matches_numpy(run_mdr, workdir, path, spring_constant,
                                                                   sensitivity, rows):
    (workdir / "case.toml").write_text(case('model = "elastic"\nG = 1000.0', path, spring_constant, sensitivity))
    result = run_mdr("fit", "case.toml", "--out", "out", timeout=300)
    assert result.returncode == 0, result.stderr
    summary = json.loads((workdir / "out" / "fit.json").read_text())
    modulus, baseline = hertz_fit(*rows(path, sensitivity), spring_constant)
    assert math.isclose(summary["parameters"]["material.G"], modulus, rel_tol=1e-6), (summary["parameters"], modulus)
    assert math.isclose(summary["curves"][0]["baseline"], baseline, rel_tol=1e-6)
    assert "no time recorded: fitted as elastic, rows in measurement order (time = row number)" in \
        summary["curves"][0]["flags"]
    # The made-up time is left out of curves.csv (t = nan), and no G(t) over it is written.
    with open(workdir / "out" / "curves.csv", newline="", encoding="utf-8") as handle:
        rows_written = list(csv.reader(handle))
    assert rows_written[0] == ["curve", "t", "measured", "model", "residual", "drive"]
    assert len(rows_written) > 1 and all(row[1] == "nan" for row in rows_written[1:])
    assert not (workdir / "out" / "functions.csv").exists()


def test_a_standard_solid_on_a_file_without_time_is_refused_naming_it(run_mdr, workdir):
    material = 'model = "standard"\nG_inf = 300.0\nG1 = 300.0\ntau1 = 1.0'
    (workdir / "case.toml").write_text(case(material, AFM_WORKSHOP, 0.1, 50e-9).replace(
        'free = ["material.G"]', 'free = ["material.G_inf"]'))
    result = run_mdr("fit", "case.toml", "--out", "out")
    assert_bad_input(result, f'fit.data[0].file = "{AFM_WORKSHOP.name}":', "records no time",
                     "the material depends on time", 'an elastic model (model = "elastic") can be fitted')
    assert not (workdir / "out").exists()


AFM_WORKSHOP_MAP = VENDOR / "fmt-afm-workshop-fd_mapping_16_2018-08-01_13.07.zip"


def test_an_afm_workshop_map_fits_an_elastic_material_and_refuses_a_standard_solid(run_mdr, workdir):
    (workdir / "elastic.toml").write_text(case('model = "elastic"\nG = 1000.0', "map.zip", 0.1, 50e-9))
    result = run_mdr("fit", "elastic.toml", "--map", str(AFM_WORKSHOP_MAP), "--out", "map", timeout=300)
    assert result.returncode == 0, result.stderr
    with open(workdir / "map" / "map.csv", newline="", encoding="utf-8") as handle:
        pixels = list(csv.DictReader(handle))
    assert len(pixels) == 16
    assert all("no time recorded: fitted as elastic" in pixel["flags"] for pixel in pixels)
    # A time-dependent material: refused once, before any pixel, and nothing written.
    material = 'model = "standard"\nG_inf = 300.0\nG1 = 300.0\ntau1 = 1.0'
    (workdir / "standard.toml").write_text(case(material, "map.zip", 0.1, 50e-9).replace(
        'free = ["material.G"]', 'free = ["material.G_inf"]'))
    result = run_mdr("fit", "standard.toml", "--map", str(AFM_WORKSHOP_MAP), "--out", "map2")
    assert_bad_input(result, f'fit.data[0].file = "{AFM_WORKSHOP_MAP.name}":', "the material depends on time")
    assert not (workdir / "map2").exists()
