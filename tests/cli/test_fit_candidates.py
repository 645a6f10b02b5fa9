"""`mdr fit` with fit.candidates and [fit.spectrum] on Hertz data (closed form): the ranking and the folders of
the result directory, a spectrum's fitted case that runs, and bad candidate input refused with one line."""

from __future__ import annotations

import csv
import json
import pathlib

import pytest

from test_bad_input import assert_bad_input
from test_fit import G_TRUE, write_curve

REPO_ROOT = pathlib.Path(__file__).resolve().parents[2]

# The JPK stress-relaxation record on its power-law probe (examples/fit/jpk-relaxation-power.toml with an elastic
# body and only the probe's n free; docs/performance.md, "A shared parameter on its bound"), two candidates:
# fractional_standard, which contains elastic (G1 -> 0), ends its first fit in a local minimum above it (r/noise
# 770.5 > 767.0).
JPK_CANDIDATES = f"""
title = "JPK cell 1, curve 1: power-law probe, elastic and fractional_standard"
[material]
model = "elastic"
G = 300.0
[indenter]
shape = "power"
c = 5.0e4
n = 2.0
[fit]
free = ["indenter.n"]
bounds = {{ "indenter.n" = [1.05, 6.0] }}
candidates = ["elastic", "fractional_standard"]
[[fit.data]]
file = "{REPO_ROOT / 'examples' / 'data' / 'jpk_sr_cell1-0001.csv'}"
time = "t_s"
piezo = "z_measured_m"
deflection = "deflection_m"
spring_constant = 1.0677
segment_column = "segment"
segments = ["0", "1", "2"]
"""

CASE = """
[material]
model = "elastic"
G = 5.0e4
[indenter]
shape = "sphere"
R = 5.0e-4
[fit]
elements = 300
{extra}
[[fit.data]]
file = "curve.csv"
time = "t"
depth = "depth_um"
force = "force_uN"
units = {{ length = "um", force = "uN" }}
"""


@pytest.fixture
def case(workdir):
    write_curve(workdir / "curve.csv")

    def make(extra):
        path = workdir / "case.toml"
        path.write_text(CASE.format(extra=extra), encoding="utf-8")
        return path

    return make


def test_candidates_are_ranked_and_written_in_folders(run_mdr, case, workdir):
    result = run_mdr("fit", case('candidates = ["standard", "elastic"]'), "--out", workdir / "out", timeout=300)
    assert result.returncode == 0, result.stderr
    assert "preferred: elastic" in result.stdout
    out = workdir / "out"
    ranking = json.loads((out / "ranking.json").read_text())
    assert ranking["criterion"] == "bic" and ranking["preferred"] == "elastic"
    assert [entry["name"] for entry in ranking["candidates"]] == ["elastic", "standard"]
    with open(out / "models.csv", newline="", encoding="utf-8") as handle:
        rows = list(csv.DictReader(handle))
    assert [row["candidate"] for row in rows] == ["elastic", "standard"]
    assert float(rows[0]["delta_bic"]) == 0.0 and float(rows[1]["delta_bic"]) > 0.0
    # standard, which contains elastic, fits at least as well: no local minimum
    assert [row["better_special_case"] for row in rows] == ["", ""]
    assert [entry["better_special_case"] for entry in ranking["candidates"]] == [None, None]
    assert [entry["refitted_from"] for entry in ranking["candidates"]] == [None, None]
    for name in ("elastic", "standard"):
        assert {"fit.json", "fitted.toml", "curves.csv"} <= {p.name for p in (out / name).iterdir()}
    elastic = json.loads((out / "elastic" / "fit.json").read_text())
    assert elastic["parameters"]["material.G"] == pytest.approx(G_TRUE, rel=2e-2)
    # The folders are mdr's (listed file by file in .mdr-result): a re-run may replace them (issue 23), but not a
    # file the user put into one.
    manifest = (out / ".mdr-result").read_text(encoding="utf-8").splitlines()[1:]
    assert "elastic/fit.json" in manifest and "standard/curves.csv" in manifest
    again = run_mdr("fit", workdir / "case.toml", "--out", out, timeout=300)
    assert again.returncode == 0, again.stderr
    (out / "standard" / "notes.txt").write_text("mine\n", encoding="utf-8")
    refused = run_mdr("fit", workdir / "case.toml", "--out", out, timeout=300)
    assert refused.returncode == 2 and "holds standard/notes.txt, which mdr did not write" in refused.stderr
    assert (out / "standard" / "notes.txt").read_text(encoding="utf-8") == "mine\n"


def test_a_spectrum_alone_writes_one_fit_and_its_moduli(run_mdr, case, workdir):
    result = run_mdr("fit", case("[fit.spectrum]\nper_decade = 1"), "--out", workdir / "out", timeout=300)
    assert result.returncode == 0, result.stderr
    out = workdir / "out"
    with open(out / "spectrum.csv", newline="", encoding="utf-8") as handle:
        rows = list(csv.DictReader(handle))
    assert rows[0]["term"] == "G_inf" and len(rows) >= 3
    assert all(float(row["modulus"]) >= 0.0 for row in rows)
    again = run_mdr("run", out / "fitted.toml", "--out", workdir / "again")
    assert again.returncode == 0, again.stderr


@pytest.mark.parametrize("extra, fragments", [
    ('candidates = ["prony9"]', ["fit.candidates[0]", "one of elastic"]),
    ('candidates = ["elastic", "elastic"]', ["fit.candidates[1]", "named twice"]),
    ('candidates = ["standard"]\nfree = ["material.G"]', ["fit.free = material.G", "indenter keys only"]),
    ("[fit.spectrum]\nper_decade = 50", ["fit.spectrum.per_decade = 50", "at most 20"]),
    ("[fit.spectrum]\nsmoothing = -1", ["fit.spectrum.smoothing", ">= 0"]),
])
def test_bad_candidates(run_mdr, case, workdir, extra, fragments):
    assert_bad_input(run_mdr("fit", case(extra), "--out", workdir / "out"), *fragments)


def test_a_candidates_fit_replaces_its_own_result_directory(run_mdr, case, workdir):
    """mdr wrote the candidates' folders, so a second fit into the same directory replaces it (once refused: "holds
    prony2, which mdr did not write"); a file of the user's put into a folder still protects it."""
    path = case('candidates = ["elastic"]')
    assert run_mdr("fit", path, "--out", workdir / "out", timeout=300).returncode == 0
    again = run_mdr("fit", path, "--out", workdir / "out", timeout=300)
    assert again.returncode == 0, again.stderr
    assert (workdir / "out" / "elastic" / "fit.json").is_file()
    (workdir / "out" / "elastic" / "notes.txt").write_text("mine", encoding="utf-8")
    refused = run_mdr("fit", path, "--out", workdir / "out", timeout=300)
    assert refused.returncode == 2, refused.stderr
    assert "holds elastic/notes.txt, which mdr did not write" in refused.stderr, refused.stderr
    assert (workdir / "out" / "elastic" / "notes.txt").read_text(encoding="utf-8") == "mine"


def test_a_fit_above_its_special_case_is_refitted_from_it_and_says_so_in_every_output(run_mdr, workdir):
    """fractional_standard's first fit ends at r/noise 770.5, above elastic (767.0), its special case as G1 -> 0: it
    is fitted again from elastic's solution (G1 on its lower bound) and ends at 66.6, in the other basin."""
    path = workdir / "jpk.toml"
    path.write_text(JPK_CANDIDATES, encoding="utf-8")
    result = run_mdr("fit", path, "--out", workdir / "out", timeout=300)
    assert result.returncode == 0, result.stderr
    out = workdir / "out"
    ranking = json.loads((out / "ranking.json").read_text())
    entries = {entry["name"]: entry for entry in ranking["candidates"]}
    elastic, fractional = entries["elastic"], entries["fractional_standard"]
    assert fractional["refitted_from"] == "elastic" and elastic["refitted_from"] is None
    assert fractional["residual_to_noise"] < 0.1 * elastic["residual_to_noise"]
    assert fractional["better_special_case"] is None and elastic["better_special_case"] is None
    assert ranking["preferred"] == "fractional_standard"
    table_row = next(line for line in result.stdout.splitlines() if line.startswith("  fractional_standard "))
    assert table_row.endswith(", refitted from elastic"), table_row
    with open(out / "models.csv", newline="", encoding="utf-8") as handle:
        rows = {row["candidate"]: row for row in csv.DictReader(handle)}
    assert rows["fractional_standard"]["refitted_from"] == "elastic" and rows["elastic"]["refitted_from"] == ""
    flags = json.loads((out / "fractional_standard" / "fit.json").read_text())["flags"]
    refitted = [flag for flag in flags if flag.startswith("refitted from its special case `elastic`'s solution: "
                                                           "the first fit ended in a local minimum (r/noise ")]
    assert len(refitted) == 1, flags
    first = float(refitted[0].rsplit(" ", 1)[1].rstrip(")"))
    assert first > 1.001 * elastic["residual_to_noise"]  # the local minimum that made it refit
