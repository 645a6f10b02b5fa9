"""`mdr sweep`: grids, deterministic rows whatever the number of jobs, per-row failures, and bad sweep input."""

from __future__ import annotations

import csv

import pytest

from test_bad_input import assert_bad_input

CASE = """
title = "sweep test"
[material]
model = "standard"
G_inf = 1.0e6
G1 = 3.0e6
tau1 = 0.2
[indenter]
shape = "sphere"
R = 0.01
[load]
control = "displacement"
history = [[0.0, 0.0], [1.0, 1.0e-4], [2.0, 0.0]]
[numerics]
elements = 100
time_step = 0.02
"""


def read_rows(path):
    with open(path, newline="", encoding="utf-8") as handle:
        return list(csv.DictReader(handle))


@pytest.fixture
def case_file(workdir):
    path = workdir / "case.toml"
    path.write_text(CASE, encoding="utf-8")
    return path


def test_grid_columns_and_order(run_mdr, case_file, workdir):
    result = run_mdr("sweep", case_file, "--vary", "material.tau1=0.01:1:3:log", "--vary", "material.G1=1e6,2e6",
                     "--out", workdir / "out", "--jobs", "2")
    assert result.returncode == 0, result.stderr
    rows = read_rows(workdir / "out" / "sweep.csv")
    assert list(rows[0])[:3] == ["material.tau1", "material.G1", "max_force"]
    assert list(rows[0])[-1] == "error"
    # The last axis varies fastest; the log grid hits its ends and its geometric middle.
    points = [(float(r["material.tau1"]), float(r["material.G1"])) for r in rows]
    expected = [(t, g) for t in (0.01, 0.1, 1.0) for g in (1e6, 2e6)]
    assert points == pytest.approx(expected, rel=1e-12)
    assert all(r["error"] == "" for r in rows)
    # More relaxation (shorter tau1) or a softer branch: a smaller peak force.
    forces = [float(r["max_force"]) for r in rows]
    assert forces[0] < forces[2] < forces[4] and forces[0] < forces[1]


def test_rows_do_not_depend_on_jobs(run_mdr, case_file, workdir):
    tables = []
    for jobs in ("1", "2"):
        out = workdir / f"out{jobs}"
        assert run_mdr("sweep", case_file, "--vary", "material.tau1=0.05:0.5:5", "--out", out, "--jobs", jobs).returncode == 0
        tables.append([{k: v for k, v in row.items() if k != "wall_seconds"} for row in read_rows(out / "sweep.csv")])
    assert tables[0] == tables[1]


def test_failed_points_keep_their_message_and_the_others_run(run_mdr, case_file, workdir):
    result = run_mdr("sweep", case_file, "--vary", "material.tau1=-0.1,0.1,0.2", "--out", workdir / "out")
    assert result.returncode == 0
    assert "1 of 3 runs failed" in result.stderr
    rows = read_rows(workdir / "out" / "sweep.csv")
    assert "material.tau1 = -0.1: must be > 0" in rows[0]["error"]
    assert rows[0]["max_force"] == "nan"
    assert rows[1]["error"] == "" and float(rows[1]["max_force"]) > 0.0


@pytest.mark.parametrize("spec,fragments", [
    ("material.tau=1:2:3", ["--vary", "material.tau", "no such key"]),
    ("material.model=1:2:3", ["material.model", "not a numeric key"]),
    ("material.tau1=0:1:3:log", ["log grid", "> 0"]),
    ("material.tau1=1:2:0", ["COUNT", "integer"]),
    ("material.tau1=1:x:3", ["'x'", "not a finite number"]),
    ("material.tau1", ["KEY=START:STOP:COUNT"]),
])
def test_bad_sweep_input(run_mdr, case_file, workdir, spec, fragments):
    assert_bad_input(run_mdr("sweep", case_file, "--vary", spec, "--out", workdir / "out"), *fragments)
