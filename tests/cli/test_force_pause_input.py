"""The bad-input contract of constant-force pauses under spring control (`[load] force_pauses`, docs:
case-format.md; issue 11), in the style of test_bad_input.py: exit status 2, one stderr line naming the key, the
value and the rule, no result directory. Plus the good path: the base column follows the feedback."""

from __future__ import annotations

import csv

import pytest

from test_bad_input import assert_bad_input

HEAD = ('[material]\nmodel = "standard"\nG_inf = 1.0e6\nG1 = 2.0e6\ntau1 = 1.0\n'
        '[indenter]\nshape = "sphere"\nR = 0.01\n')
HISTORY = "history = [[0.0, 0.0], [1.0, 1.0e-4], [4.0, 1.0e-4], [5.0, -5.0e-5]]\n"
NUMERICS = "[numerics]\nelements = 200\n"


def pause_case(pauses: str, control: str = '"spring"\nspring_constant = 2.0e4', history: str = HISTORY,
               extra: str = "") -> str:
    return HEAD + f"[load]\ncontrol = {control}\n{history}force_pauses = {pauses}\n{extra}" + NUMERICS


BAD_CASES = [
    ("force-control", pause_case("[[1.0, 4.0]]", control='"force"', history="history = [[0.0, 0.0], [1.0, 1.0]]\n"),
     ["load.force_pauses", 'only with control = "spring"']),
    ("displacement-control", pause_case("[[1.0, 4.0]]", control='"displacement"'),
     ["load.force_pauses", 'only with control = "spring"']),
    ("at-the-first-time", pause_case("[[0.0, 4.0]]"),
     ["load.force_pauses[0] = [0, 4]", "must start after the history's first time 0"]),
    ("end-before-start", pause_case("[[3.0, 2.0]]"), ["load.force_pauses[0] = [3, 2]", "must end after it starts"]),
    ("empty", pause_case("[[2.0, 2.0]]"), ["load.force_pauses[0] = [2, 2]", "must end after it starts"]),
    ("beyond-the-end", pause_case("[[1.0, 6.0]]"), ["load.force_pauses[0] = [1, 6]", "must end by the end of the run",
                                                   "load.end = 5"]),
    ("not-a-number", pause_case("[[nan, 2.0]]"), ["load.force_pauses[0].start = nan", "must be finite"]),
    ("infinite-end", pause_case("[[1.0, inf]]"), ["load.force_pauses[0].end = inf", "must be finite"]),
    ("overlapping", pause_case("[[1.0, 3.0], [2.0, 4.0]]"),
     ["load.force_pauses[1] = [2, 4]", "must start after the previous pause ends at 3"]),
    ("touching", pause_case("[[1.0, 2.0], [2.0, 4.0]]"),
     ["load.force_pauses[1] = [2, 4]", "must start after the previous pause ends at 2"]),
    ("out-of-order", pause_case("[[3.0, 4.0], [1.0, 2.0]]"),
     ["load.force_pauses[1] = [1, 2]", "must start after the previous pause ends at 4"]),
    ("during-a-harmonic",
     pause_case("[[1.0, 4.0]]", extra="harmonic = { amplitude = 1e-6, frequency = 2.0, start = 3.0, end = 5.0 }\n"),
     ["load.force_pauses[0] = [1, 4]", "overlaps load.harmonic", "cannot follow a harmonic"]),
    ("before-contact",
     pause_case("[[0.25, 4.0]]", history="history = [[0.0, -1.0e-4], [1.0, 1.0e-4], [4.0, 1.0e-4]]\n"),
     ["load.force_pauses[0] = [0.25, 4]", "the force at its start is 0 (no contact)"]),
    ("not-pairs", pause_case("[1.0, 4.0]"), ["load.force_pauses"]),
    ("not-an-array", pause_case('"1 to 4"'), ["load.force_pauses"]),
    ("with-shore", '[material]\nmodel = "elastic"\nG = 1.0e6\n[load]\ncontrol = "shore"\nscale = "A"\n'
     "force_pauses = [[1.0, 2.0]]\n", ["load.force_pauses", 'only with control = "spring", not "shore"']),
]


@pytest.mark.parametrize("text,fragments", [case[1:] for case in BAD_CASES], ids=[case[0] for case in BAD_CASES])
def test_run_refuses_bad_force_pause(run_case, text, fragments):
    assert_bad_input(run_case(text), *fragments)


@pytest.mark.parametrize("case_id", ["force-control", "overlapping", "during-a-harmonic"])
def test_check_refuses_the_same_way(run_case, case_id):
    text, fragments = next(case[1:] for case in BAD_CASES if case[0] == case_id)
    assert_bad_input(run_case(text, command="check"), *fragments)


def test_pause_holds_the_force_and_the_base_resumes_from_where_it_got(run_case):
    result = run_case(pause_case("[[1.0, 4.0]]"))
    assert result.returncode == 0, result.stderr
    with open(result.out / "history.csv", newline="") as file:
        rows = [{key: float(value) for key, value in row.items()} for row in csv.DictReader(file)]
    assert "z" in rows[0]
    pause = [row for row in rows if 1.0 <= row["t"] <= 4.0]
    held = pause[0]["F"]
    assert all(row["F"] == pytest.approx(held, rel=1e-12) for row in pause)
    assert all(row["z"] == pytest.approx(row["d"] + held / 2.0e4, rel=1e-12) for row in pause)
    assert pause[-1]["d"] > 1.2 * pause[0]["d"]  # it crept
    z_end = pause[-1]["z"]
    for row in rows:
        if row["t"] > 4.0:  # the retract of 1.5e-4 per second from the z reached
            assert row["z"] == pytest.approx(z_end - 1.5e-4 * (row["t"] - 4.0), abs=1e-16)
