"""mdr.fit_map(case, "map.jpk-force-map"): the same per-pixel outputs as `mdr fit CASE --map FILE`'s map.csv, with
the same columns (both run mdr/fitcase/map_fit.hpp); a failed pixel is a row with its reason."""

from __future__ import annotations

import csv
import json
import os
import math
import subprocess
import zipfile

import numpy as np
import pytest

import mdr
from conftest import REPO_ROOT

MAP = REPO_ROOT / "examples" / "data" / "vendor" / "fmt-jpk-fd_map-data-reference-points.jpk-force-map"
BROKEN = REPO_ROOT / "tests" / "data" / "instrument" / "missing-channel.jpk-force-map"
CASE = {
    "material": {"model": "elastic", "G": 1000.0},
    "indenter": {"shape": "sphere", "R": 5.0e-6},
    "fit": {"free": ["material.G"], "data": [{"file": "map.jpk-force-map", "segments": ["extend"]}]},
}
#: CASE as a case file, for the command line.
CASE_TOML = """
[material]
model = "elastic"
G = 1000.0

[indenter]
shape = "sphere"
R = 5.0e-6

[fit]
free = ["material.G"]

[[fit.data]]
file = "map.jpk-force-map"
segments = ["extend"]
"""


def test_the_columns_and_values_of_the_command_lines_map_csv(mdr_binary, tmp_path):
    (tmp_path / "case.toml").write_text(CASE_TOML)
    subprocess.run([mdr_binary, "fit", "case.toml", "--map", MAP, "--out", "out"], cwd=tmp_path, check=True,
                   capture_output=True, timeout=300)
    with open(tmp_path / "out" / "map.csv", newline="") as handle:
        rows = list(csv.DictReader(handle))
    table = mdr.fit_map(CASE, MAP, out=tmp_path / "py")
    assert list(table.columns) == list(rows[0].keys())
    assert table.grid == (25, 25) and table.size == (5e-4, 5e-4)  # grid.ilength, grid.ulength of the header
    for name, values in table.columns.items():
        for value, row in zip(values, rows):
            if isinstance(value, str):
                assert value == row[name]
            else:
                assert value == float(row[name]) or (math.isnan(value) and row[name] in ("", "nan")), name
    assert (tmp_path / "py" / "map.csv").read_text() == (tmp_path / "out" / "map.csv").read_text()
    python_summary = json.loads((tmp_path / "py" / "map.json").read_text())
    cli_summary = json.loads((tmp_path / "out" / "map.json").read_text())
    assert {k: v for k, v in python_summary.items() if k != "source"} == \
        {k: v for k, v in cli_summary.items() if k != "source"}
    assert (tmp_path / "py" / "map_material.G.png").exists()


def test_arguments_of_stacks_are_refused_with_an_instrument_file():
    with pytest.raises(ValueError, match="^time: not used with an instrument file"):
        mdr.fit_map(CASE, MAP, time=[0.0, 1.0])


@pytest.mark.parametrize("jobs", [0, -1, 1.5, True, "2"])
def test_jobs_that_are_no_number_of_threads_are_refused_naming_jobs(jobs):
    with pytest.raises(ValueError, match=r"^jobs = .*: must be an integer >= 1"):
        mdr.fit_map(CASE, MAP, jobs=jobs)


@pytest.mark.filterwarnings("ignore:jobs = 3. more than the:RuntimeWarning")
def test_pixels_on_threads_give_the_bytes_of_one_thread_in_the_files_order(mdr_binary, tmp_path):
    # The 3 pixels fit to different G (and the broken map's middle one fails): a row in another's place would show.
    for name, source in (("map", MAP), ("broken", BROKEN)):
        tables = []
        for jobs in (1, 3):
            mdr.fit_map(CASE, source, jobs=jobs, out=tmp_path / f"py-{name}-{jobs}", figures=False)
            tables.append((tmp_path / f"py-{name}-{jobs}" / "map.csv").read_bytes())
        (tmp_path / "case.toml").write_text(CASE_TOML)
        for jobs in ("1", "3"):
            completed = subprocess.run([mdr_binary, "fit", "case.toml", "--map", source, "--out", f"cli-{name}-{jobs}",
                                        "--jobs", jobs], cwd=tmp_path, capture_output=True, text=True, timeout=300)
            assert completed.returncode in (0, 1), completed.stderr
            threads = min(int(jobs), len(os.sched_getaffinity(0)))  # and at most the 3 pixels
            assert completed.stdout.splitlines()[0].endswith(f"({threads} thread(s))"), completed.stdout
            tables.append((tmp_path / f"cli-{name}-{jobs}" / "map.csv").read_bytes())
        assert all(table == tables[0] for table in tables), name
        rows = list(csv.DictReader(tables[0].decode().splitlines()))
        assert [row["index"] for row in rows] == ["0", "1", "2"]
        if name == "map":
            assert len({row["material.G"] for row in rows}) == 3


@pytest.mark.parametrize("jobs", ["0", "-2", "two", ""])
def test_the_command_line_refuses_jobs_that_are_no_number_of_threads(mdr_binary, tmp_path, jobs):
    (tmp_path / "case.toml").write_text(CASE_TOML)
    completed = subprocess.run([mdr_binary, "fit", "case.toml", "--map", MAP, "--out", "out", "--jobs", jobs],
                               cwd=tmp_path, capture_output=True, text=True, timeout=60)
    assert completed.returncode == 2
    assert completed.stderr.splitlines() == [f"mdr: error: --jobs = {jobs}: must be a whole number >= 1 (threads)"]
    assert sorted(p.name for p in tmp_path.iterdir()) == ["case.toml"]


def test_colour_bar_units_come_from_the_registry_of_the_cases_model(tmp_path):
    # A Prony series: terms[0][0] is a modulus (Pa) and terms[0][1] a relaxation time (s), as the model's registry
    # row states ("Pa, s"); a rule on key names gave the time no unit. power_law's beta is an exponent: no unit.
    from mdr.map_figures import map_heat_maps

    prony = {"material": {"model": "prony", "G_inf": 500.0, "terms": [[500.0, 0.1]]},
             "indenter": {"shape": "sphere", "R": 5.0e-6},
             "fit": {"free": ["material.G_inf", "material.terms[0][0]", "material.terms[0][1]"],
                     "data": [{"file": "map.jpk-force-map", "segments": ["extend"]}]}}
    mdr.fit_map(prony, MAP, out=tmp_path / "prony", figures=False, jobs=1)
    units = json.loads((tmp_path / "prony" / "map.json").read_text())["column_units"]
    assert units["material.terms[0][1]"] == units["material.terms[0][1]_stderr"] == "s"
    assert units["material.terms[0][0]"] == units["E_material.terms[0][0]"] == units["material.G_inf"] == "Pa"
    assert (units["x"], units["contact_height"], units["noise"], units["residual_to_noise"]) == ("m", "m", "N", "1")
    labels = {name: figure.axes[1].get_ylabel() for name, figure in map_heat_maps(str(tmp_path / "prony"))}
    assert labels["material.terms[0][1]"] == "material.terms[0][1] [s]"
    assert labels["residual_to_noise"] == "residual_to_noise"

    with_units = dict(prony, units="um-nN-s", material={"model": "power_law", "G0": 1.0, "beta": 0.2},
                      indenter={"shape": "sphere", "R": 5.0},
                      fit={"free": ["material.G0", "material.beta"], "bounds": {"material.beta": [0.05, 0.95]},
                           "data": prony["fit"]["data"]})
    mdr.fit_map(with_units, MAP, out=tmp_path / "power", figures=False, jobs=1)
    units = json.loads((tmp_path / "power" / "map.json").read_text())["column_units"]
    assert (units["material.G0"], units["material.beta"], units["contact_height"], units["noise"]) == \
        ("kPa", "1", "µm", "nN")
    labels = {name: figure.axes[1].get_ylabel() for name, figure in map_heat_maps(str(tmp_path / "power"))}
    assert labels["material.G0"] == "material.G0 [kPa]" and labels["material.beta"] == "material.beta"


def test_a_failed_pixel_is_a_row_with_its_reason():
    table = mdr.fit_map(CASE, BROKEN)
    assert list(table.columns["status"][[0, 2]]) != ["failed", "failed"]
    assert table.columns["status"][1] == "failed"
    assert "vDeflection.dat" in table.columns["failure"][1]
    assert np.isnan(table.columns["material.G"][1])


def test_a_bad_case_is_refused_naming_the_key():
    case = dict(CASE, fit={"free": ["material.G"], "data": [{"file": "x.csv", "time": "t", "depth": "d",
                                                              "force": "f"}]})
    with pytest.raises(ValueError, match="--map"):
        mdr.fit_map(case, MAP)


def test_heat_maps_on_the_physical_grid_with_units_and_failed_pixels(mdr_binary, tmp_path):
    from mdr.map_figures import map_heat_maps

    (tmp_path / "case.toml").write_text(CASE_TOML)
    subprocess.run([mdr_binary, "fit", "case.toml", "--map", BROKEN, "--out", "out"], cwd=tmp_path,
                   capture_output=True, timeout=300)
    figures = dict(map_heat_maps(str(tmp_path / "out")))
    assert {"material.G", "E_material.G", "contact_height", "residual_to_noise"} <= set(figures)
    axes, colour_bar = figures["material.G"].axes
    assert colour_bar.get_ylabel() == "material.G [Pa]"
    assert figures["contact_height"].axes[1].get_ylabel() == "contact_height [m]"
    assert axes.get_xlabel() == "x [µm]"
    # The 25 x 25 grid of 20 µm pixels: pixel (column 9, row 4) at x = -1219.77 µm (its header) puts the grid's
    # low-x edge at -1219.77 - 9.5 x 20 µm.
    left, right, _, _ = axes.images[0].get_extent()
    assert math.isclose(left, -1219.765625 - 190.0) and math.isclose(right - left, 500.0)
    assert "1 failed" in axes.get_title()  # its curve could not be read: no place, no cross
    assert np.count_nonzero(np.isfinite(axes.images[0].get_array().filled(np.nan))) == 2
    written = mdr.plot.plot_directory(str(tmp_path / "out"))
    assert sorted(os.path.basename(p) for p in written) == sorted(f"map_{name}.png" for name in figures)


def test_heat_maps_mark_the_pixels_whose_fit_did_not_converge(tmp_path):
    # One iteration: the two readable pixels stop short, their values where the fit stopped; drawn, but marked
    # and counted, never passed off as results beside the converged ones.
    from mdr.map_figures import map_heat_maps

    mdr.fit_map(dict(CASE, fit=dict(CASE["fit"], max_iterations=1)), BROKEN, out=tmp_path / "out", figures=False,
                jobs=1)
    axes = dict(map_heat_maps(str(tmp_path / "out")))["material.G"].axes[0]
    assert axes.get_title().endswith("(2 of 625 pixels, 1 failed, 2 not converged)")
    marks = {collection.get_label(): len(collection.get_offsets()) for collection in axes.collections}
    assert marks == {"not converged": 2}  # the failed curve could not be read: no place, no cross


def test_out_holding_a_file_mdr_did_not_write_is_refused_and_left_as_it_was(tmp_path):
    out = tmp_path / "out"
    out.mkdir()
    (out / "map.csv").write_text("the user's own table\n")
    with pytest.raises(ValueError, match="^out = "):
        mdr.fit_map(CASE, MAP, out=out, figures=False)
    assert sorted(p.name for p in out.iterdir()) == ["map.csv"]
    assert (out / "map.csv").read_text() == "the user's own table\n"
    table = mdr.fit_map(CASE, MAP, out=tmp_path / "new", figures=False)  # a new folder is mdr's
    assert (tmp_path / "new" / "map.csv").exists() and len(table.columns["index"]) == 3


def test_an_unreadable_first_curve_is_a_failed_row_and_the_columns_keep_their_order(tmp_path):
    # The map without pixel 0's (index/109) retract deflection: that curve cannot be read, the others can.
    first_unreadable = tmp_path / "first-unreadable.jpk-force-map"
    with zipfile.ZipFile(MAP) as source, zipfile.ZipFile(first_unreadable, "w", zipfile.ZIP_DEFLATED) as copy:
        for member in source.infolist():
            if member.filename != "index/109/segments/1/channels/vDeflection.dat":
                copy.writestr(member, source.read(member.filename))
    table = mdr.fit_map(CASE, first_unreadable, out=tmp_path / "out", figures=False)
    assert list(table.columns["status"][:1]) == ["failed"]
    assert "index/109/segments/1/channels/vDeflection.dat" in table.columns["failure"][0]
    assert all(status.startswith("converged") for status in table.columns["status"][1:])
    assert table.grid == (25, 25) and table.size == (5e-4, 5e-4)  # the grid that pixel 1's header states
    # The rule of docs/instrument-to-map.md: place, the fit's columns, then status, flags, failure.
    assert list(table.columns) == ["index", "column", "row", "x", "y", "material.G", "material.G_stderr",
                                   "E_material.G", "E_material.G_stderr", "contact_height", "residual_to_noise",
                                   "noise", "status", "flags", "failure"]
    # map.csv is written from the same rows (fitcase::map_rows): the failed first row cuts none of its columns.
    assert (tmp_path / "out" / "map.csv").read_text().splitlines()[0].split(",") == list(table.columns)
    summary = json.loads((tmp_path / "out" / "map.json").read_text())
    assert (summary["pixels"], summary["failed"], summary["columns"]) == (3, 1, 25)


def test_a_map_without_time_and_a_time_dependent_material_is_refused_naming_the_file(tmp_path):
    # An AFM Workshop map records no time: an elastic material is fitted, a standard solid refused before any pixel.
    workshop = REPO_ROOT / "examples" / "data" / "vendor" / "fmt-afm-workshop-fd_mapping_16_2018-08-01_13.07.zip"
    data = [{"file": "map.zip", "spring_constant": 0.1, "sensitivity": 50e-9}]
    case = dict(CASE, material={"model": "standard", "G_inf": 300.0, "G1": 300.0, "tau1": 1.0},
                fit={"free": ["material.G_inf"], "data": data})
    with pytest.raises(ValueError, match=r'^fit\.data\[0\]\.file = "fmt-afm-workshop.*the material depends on time'):
        mdr.fit_map(case, workshop, out=tmp_path / "standard")
    assert not (tmp_path / "standard").exists()
