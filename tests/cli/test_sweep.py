"""`mdr sweep`: grids, deterministic rows whatever the number of jobs, per-row failures, and bad sweep input."""

from __future__ import annotations

import csv
import json
import os
import resource
import subprocess

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
    ("material.tau=1:2:3", ["--vary", "material.tau", "no such numeric key"]),
    ("material.model=1:2:3", ["material.model", "no such numeric key"]),
    ("material.tau1=0:1:3:log", ["log grid", "> 0"]),
    ("material.tau1=1:2:0", ["COUNT", "integer"]),
    ("material.tau1=1:x:3", ["'x'", "not a finite number"]),
    # issue 23: strtod's underflow and overflow are told as such, not "not a finite number"
    ("material.tau1=1e-400,1", ["'1e-400'", "underflows to 0"]),
    ("material.tau1=1e400,1", ["'1e400'", "overflows"]),
    ("material.tau1", ["KEY=START:STOP:COUNT"]),
])
def test_bad_sweep_input(run_mdr, case_file, workdir, spec, fragments):
    assert_bad_input(run_mdr("sweep", case_file, "--vary", spec, "--out", workdir / "out"), *fragments)


def test_grid_size_is_computed_without_overflow_and_bounded(run_mdr, case_file, workdir):
    # 524288^4 = 2^76 points wrapped to 0 in 64-bit arithmetic; the bound is checked before anything runs.
    axes = [arg for key in ("material.tau1", "material.G1", "material.G_inf", "indenter.R")
            for arg in ("--vary", f"{key}=1:2:524288")]
    assert_bad_input(run_mdr("sweep", case_file, *axes, "--out", workdir / "out"),
                     "--vary", "7.556e+22 points", "at most 1000000")
    assert_bad_input(run_mdr("sweep", case_file, "--vary", "material.tau1=1:2:1001", "--vary",
                             "material.G1=1:2:1000", "--out", workdir / "out"), "1.001e+06 points")


def test_a_point_whose_result_is_not_finite_becomes_a_row_with_its_reason(run_mdr, case_file, workdir):
    # G_inf = G1 = 1e308: G(0+) overflows to inf and so does the force; the other point still counts.
    case_file.write_text(CASE.replace("G1 = 3.0e6", "G1 = 1.0e308"), encoding="utf-8")
    result = run_mdr("sweep", case_file, "--vary", "material.G_inf=1e6,1e308", "--out", workdir / "out")
    assert result.returncode == 0, result.stderr
    assert "1 of 2 runs failed" in result.stderr
    rows = read_rows(workdir / "out" / "sweep.csv")
    assert rows[0]["error"] == "" and float(rows[0]["max_force"]) > 1e300
    assert "the result is not finite (F = inf" in rows[1]["error"] and rows[1]["max_force"] == "nan"


def test_every_point_failed_exits_non_zero_with_the_table(run_mdr, case_file, workdir):
    result = run_mdr("sweep", case_file, "--vary", "material.tau1=-1,-2", "--out", workdir / "out")
    assert result.returncode == 1
    assert result.stderr_lines[-1].startswith("mdr: error: every one of the 2 runs failed")
    assert "material.tau1 = -1: must be > 0" in result.stderr_lines[-1]
    rows = read_rows(workdir / "out" / "sweep.csv")
    assert [row["error"] != "" for row in rows] == [True, True]


@pytest.mark.skipif(os.environ.get("MDR_SANITIZED") == "1",
                    reason="AddressSanitizer reserves terabytes of address space: no address-space limit possible")
def test_threads_that_cannot_start_give_one_line_not_an_abort(mdr_binary, case_file, workdir):
    """200 thread stacks do not fit into 300 MB of address space: an error line, exit 1, nothing written."""
    def limit_memory():
        resource.setrlimit(resource.RLIMIT_AS, (300 * 2**20, 300 * 2**20))

    completed = subprocess.run([mdr_binary, "sweep", str(case_file), "--vary", "material.G1=1e6:2e6:400",
                                "--jobs", "200", "--out", str(workdir / "out")], cwd=workdir, capture_output=True,
                               text=True, timeout=120, preexec_fn=limit_memory)
    lines = completed.stderr.splitlines()
    assert completed.returncode == 1, completed.stderr
    assert len(lines) == 1 and lines[0].startswith("mdr: error: --jobs = 200: could not start thread"), lines
    assert sorted(p.name for p in workdir.iterdir()) == ["case.toml"]


def test_dotted_keys_reach_array_elements(run_mdr, case_file, workdir):
    # load.history[1][1] is the depth of the second history point: the peak force grows with it.
    out = workdir / "deeper"
    run_mdr("sweep", str(case_file), "--vary", "load.history[1][1]=0.5e-4,1.0e-4", "--out", str(out))
    rows = read_rows(out / "sweep.csv")
    assert [float(row["load.history[1][1]"]) for row in rows] == [0.5e-4, 1.0e-4]
    assert [float(row["max_depth"]) for row in rows] == pytest.approx([0.5e-4, 1.0e-4], rel=1e-12)
    # Hertz-like growth d^1.5 within the viscoelastic spread: the force more than doubles.
    assert float(rows[1]["max_force"]) > 2.5 * float(rows[0]["max_force"])


HARMONIC_CASE = """
[material]
model = "standard"
G_inf = 1.0e6
G1 = 2.0e6
tau1 = 0.01
[indenter]
shape = "sphere"
R = 0.01
[load]
control = "displacement"
history = [[0.0, 0.0], [1.0, 1.0e-4], [3.0, 1.0e-4]]
harmonic = { amplitude = 1.0e-7, frequency = 5.0, start = 1.0, end = 3.0 }
[numerics]
elements = 50
time_step = 0.005
"""


@pytest.mark.parametrize("frequencies", ["0.4,5", "5,0.4"])
def test_columns_are_the_union_of_the_rows_keys(run_mdr, workdir, frequencies):
    """At 0.4 Hz the 2 s of oscillation hold no full cycle, so that summary lacks the dynamic stiffness; at 5 Hz it
    has it. Whatever the order of the points, sweep.csv has every numeric key of either summary (issue 23), with
    `nan` where a point lacks one. Expected: the union of the numeric keys of `mdr run`'s summary.json per point."""
    (workdir / "h.toml").write_text(HARMONIC_CASE, encoding="utf-8")
    expected = set()
    for frequency in ("0.4", "5"):
        case = HARMONIC_CASE.replace("frequency = 5.0", f"frequency = {frequency}")
        (workdir / f"h{frequency}.toml").write_text(case, encoding="utf-8")
        assert run_mdr("run", f"h{frequency}.toml", "--out", f"run{frequency}").returncode == 0
        summary = json.loads((workdir / f"run{frequency}" / "summary.json").read_text(encoding="utf-8"))
        expected |= {k for k, v in summary.items() if isinstance(v, (int, float)) and not isinstance(v, bool)}
    result = run_mdr("sweep", "h.toml", "--vary", f"load.harmonic.frequency={frequencies}", "--out", "out")
    assert result.returncode == 0, result.stderr
    rows = {row["load.harmonic.frequency"]: row for row in read_rows(workdir / "out" / "sweep.csv")}
    assert set(next(iter(rows.values()))) == expected | {"load.harmonic.frequency", "error"}
    assert "storage_stiffness" in expected and float(rows["5"]["storage_stiffness"]) > 0.0
    assert rows["0.4"]["storage_stiffness"] == "nan"


LAYER_CASE = """
[material]
model = "elastic"
G = 1.0e6
[indenter]
shape = "sphere"
R = 0.01
[load]
control = "displacement"
history = [[0.0, 0.0], [1.0, 1.0e-6]]
[layer]
thickness = 1.0e-3
interface = "bonded"
"""


@pytest.mark.parametrize("jobs", ["1", "2"])
def test_a_layer_case_sweeps(run_mdr, workdir, jobs):
    """Every point of a sweep over a [layer] runs (each used to fail: the sweep stopped its runs by a step observer,
    which a layer's drivers refuse). Expected, independently of mdr: an elastic sphere at depth d on a layer of
    h = 1 km is Hertz's, F = (16/3) G sqrt(R) d^(3/2), to 1e-6; at chi = sqrt(R d)/h = 0.1 (h = 1 mm) Dimitriadis'
    bonded series 1 + 1.133 chi + 1.283 chi^2 + 0.769 chi^3 + 0.0975 chi^4 (Biophys. J. 82, 2002, eq. 12) to its
    first order, within 0.35 chi^2 (docs/theory.md eq. L7: their Hertz contact radius)."""
    (workdir / "layer.toml").write_text(LAYER_CASE, encoding="utf-8")
    result = run_mdr("sweep", "layer.toml", "--vary", "layer.thickness=1e3,1e-3", "--jobs", jobs, "--out", "out")
    assert result.returncode == 0, result.stderr
    rows = {float(row["layer.thickness"]): row for row in read_rows(workdir / "out" / "sweep.csv")}
    assert [row["error"] for row in rows.values()] == ["", ""]
    hertz = 16.0 / 3.0 * 1.0e6 * 0.1 * 1.0e-9
    assert float(rows[1e3]["max_force"]) == pytest.approx(hertz, rel=1e-6)
    chi = (0.01 * 1.0e-6) ** 0.5 / 1.0e-3
    series = 1.0 + 1.133 * chi + 1.283 * chi**2 + 0.769 * chi**3 + 0.0975 * chi**4
    assert float(rows[1e-3]["max_force"]) / hertz == pytest.approx(series, abs=0.35 * chi**2)
