"""Rows a converted material does not certify (issue 23): after a jump in the load, the rows closer to it than the
material window's start (material_window[0]) are outside the series' certificate: a power law's creep J(0+) = 0
where the series' is 1 / G(0) > 0, so the row at a force jump showed 59% of the final depth where the exact depth
is 0 (beta = 0.05), with nothing in summary.json to say so. summary.json now counts them in
material_uncertified_rows; a ramp, which the window reaches into, has none."""

from __future__ import annotations

import csv
import json

import pytest

CASE = """[material]
model = "power_law"
G0 = 1.0e3
beta = {beta}
[indenter]
shape = "sphere"
R = 1.0e-5
[load]
control = "force"
history = {history}
[numerics]
elements = 200
"""


def uncertified(out):
    summary = json.loads((out / "summary.json").read_text())
    with open(out / "history.csv", newline="", encoding="utf-8") as handle:
        times = [float(row["t"]) for row in csv.DictReader(handle)]
    return summary, times


@pytest.mark.parametrize("beta", [0.05, 0.2])
def test_rows_after_a_force_jump_before_the_window_are_counted(run_case, beta):
    completed = run_case(CASE.format(beta=beta, history="[[0.0, 1.0e-6], [10.0, 1.0e-6]]"))
    assert completed.returncode == 0, completed.stderr
    summary, times = uncertified(completed.out)
    shortest = summary["material_window"][0]
    # The jump is at t = 0; the first row (t = 0) is the undeformed state before it, exact; then the rows after it
    # closer than the window's start, the row at t = 0+ first.
    assert times[:2] == [0.0, 0.0]
    expected = sum(1 for t in times[1:] if t < shortest)
    assert expected >= 1
    assert summary["material_uncertified_rows"] == expected


def test_a_ramp_leaves_no_row_uncertified(run_case):
    completed = run_case(CASE.format(beta=0.2, history="[[0.0, 0.0], [1.0e-3, 1.0e-6], [10.0, 1.0e-6]]"))
    assert completed.returncode == 0, completed.stderr
    summary, _ = uncertified(completed.out)
    assert "material_uncertified_rows" not in summary
