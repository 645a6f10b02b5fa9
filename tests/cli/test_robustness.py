"""Inputs from the ASan/UBSan build and the fuzz campaign of issue 15 that used to crash, hang for hours or print
wrong numbers with exit 0. Each must now end within seconds, with one clear line (exit 2) or with a correct result
— by general rules (a step-count estimate checked before the run, numbers a double cannot hold refused as such,
results checked for finiteness and admissibility), not one patch per input."""

from __future__ import annotations

import csv
import json
import math
import pathlib
import time

import pytest

from test_bad_input import INDENTER, LOAD, MATERIAL, assert_bad_input, case_text, sub

IMPACT_LOAD = '[load]\ncontrol = "impact"\nvelocity = {v}\n'
SPHERE_WITH_MASS = INDENTER + "mass = 0.03\n"


def timed(run_case, text, **kwargs):
    start = time.monotonic()
    result = run_case(text, timeout=60, **kwargs)
    assert time.monotonic() - start < 15.0, "took longer than seconds"
    return result


# (id, case text, fragments of the error line)
REFUSED = [
    ("integer-beyond-2^53", case_text(material=sub(MATERIAL, "G_inf = 1.0e6", "G_inf = 9007199254740993")),
     ["material.G_inf = 9007199254740993", "cannot hold exactly", "9007199254740992"]),
    ("harmonic-of-10-MHz-over-a-second",
     case_text(load=LOAD + "end = 1.0\n", numerics="",
               extra="[tangential]\nfriction = 0.3\namplitude = 1e-7\nfrequency = 1e7\nstart = 0.5\nend = 1.0\n"),
     ["numerics.max_element_steps = 1e+11", "exceeded", "element-steps", "numerics.time_step"]),
    ("history-over-1e308-seconds",
     case_text(load='[load]\ncontrol = "displacement"\nhistory = [[-1e308, 0.0], [1e308, 1.0e-4]]\n', numerics=""),
     ["load.history", "larger than a double can hold"]),
    # Found by the fuzzer: the approach's rate, 1e308 m over 0.5 s, overflows (it ended in F = nan at t = 0.5 s).
    ("history-rate-over-a-double",
     case_text(load='[load]\ncontrol = "displacement"\nhistory = [[0.0, -1e308], [0.5, 5.0e-5]]\nend = 2.0\n',
               numerics=""),
     ["load.history[1].value = 5e-05", "rate from the previous point", "larger than a double can hold"]),
    ("time-step-of-1e-15-s", case_text(numerics="[numerics]\ntime_step = 1e-15\n"),
     ["numerics.max_element_steps", "1e+15 steps", "numerics.time_step"]),
    # The steps graded towards a force's zero (cuts_towards_zeros) are counted before they are made: made first,
    # these 1.5e12 cuts ended in std::bad_alloc after seconds.
    ("force-ramp-to-zero-at-a-1e-13-s-step",
     case_text(load='[load]\ncontrol = "force"\nhistory = [[0.0, 0.0], [0.5, 0.1], [1.0, 0.0]]\n',
               numerics="[numerics]\ntime_step = 1e-13\n"),
     ["numerics.max_element_steps", "steps", "numerics.time_step"]),
    # Depths of 1e-240 m: the forces underflow and the indenter never rebounds within the default time limit.
    ("impact-at-1e-300-m/s", case_text(indenter=SPHERE_WITH_MASS, load=IMPACT_LOAD.format(v="1e-300"), numerics=""),
     ["load.end", "the contact has not ended"]),
    ("fluid-impact-with-a-late-end",
     case_text(material='[material]\nmodel = "viscous"\neta = 1.0e3\n', indenter=SPHERE_WITH_MASS,
               load='[load]\ncontrol = "impact"\nvelocity = 1e-3\nend = 1e9\n',
               numerics="[numerics]\nmax_element_steps = 1e8\n"),
     ["material.eta = 1000", "purely viscous", "never rebounds"]),
    ("tiny-memory-bound", case_text(numerics="[numerics]\nelements = 50\ntime_step = 0.01\nmax_memory = 1000\n"),
     ["numerics.max_memory = 1e+03", "bytes", "numerics.output_every"]),
    ("non-finite-result", case_text(material=sub(sub(MATERIAL, "G_inf = 1.0e6", "G_inf = 1e308"), "G1 = 2.0e6",
                                                  "G1 = 1e308")),
     ["the result is not finite", "F = inf"]),
]


@pytest.mark.parametrize("name,text,fragments", REFUSED, ids=[r[0] for r in REFUSED])
def test_refused_within_seconds(run_case, name, text, fragments):
    result = timed(run_case, text)
    if name == "non-finite-result":  # not bad input: a failure of the computation, exit 1
        assert result.returncode == 1 and len(result.stderr_lines) == 1, result.stderr
        assert all(fragment in result.stderr for fragment in fragments), result.stderr
        assert not result.out.exists()
    else:
        assert_bad_input(result, *fragments)


def test_check_applies_the_same_bounds(run_case):
    result = timed(run_case, case_text(numerics="[numerics]\ntime_step = 1e-15\n"), command="check")
    assert_bad_input(result, "numerics.max_element_steps")


def test_a_raised_bound_lets_a_user_who_means_it_go_ahead(run_case):
    # 1e5 steps x 50 elements = 5e6 element-steps: refused under a bound of 1e6, run under the default.
    numerics = "[numerics]\nelements = 50\ntime_step = 1e-5\n"
    assert_bad_input(timed(run_case, case_text(numerics=numerics + "max_element_steps = 1e6\n")),
                     "numerics.max_element_steps = 1e+06", "5e+06 element-steps")
    result = timed(run_case, case_text(numerics=numerics))
    assert result.returncode == 0, result.stderr


def read_history(directory):
    with open(directory / "history.csv", newline="", encoding="utf-8") as handle:
        return list(csv.DictReader(handle))


@pytest.mark.parametrize("shape", ['shape = "sphere"\nR = 0.01', 'shape = "flat"\na = 0.01',
                                   'shape = "cone"\nslope_deg = 10'])
def test_elastic_impact_at_1e_30_m_per_s_has_restitution_one(run_case, workdir, shape):
    """An elastic body returns all the energy whatever the speed: e = 1 (was 1.0012 for the punch)."""
    text = case_text(material='[material]\nmodel = "elastic"\nG = 1.0e6\n',
                     indenter=f"[indenter]\n{shape}\nmass = 0.03\n", load=IMPACT_LOAD.format(v="1e-30"), numerics="")
    result = timed(run_case, text)
    assert result.returncode == 0, result.stderr
    summary = json.loads((workdir / "out" / "summary.json").read_text(encoding="utf-8"))
    assert summary["restitution"] == pytest.approx(1.0, abs=1e-6)


def test_viscoelastic_impact_at_1e_30_m_per_s_returns_at_most_its_energy(run_case, workdir):
    text = case_text(indenter=SPHERE_WITH_MASS, load=IMPACT_LOAD.format(v="1e-30"), numerics="")
    result = timed(run_case, text)
    assert result.returncode == 0, result.stderr
    summary = json.loads((workdir / "out" / "summary.json").read_text(encoding="utf-8"))
    assert 0.0 <= summary["restitution"] <= 1.0


def test_overdamped_giant_punch_is_refused_not_a_negative_restitution(run_case):
    """A punch of 9e8 m on a soft Kelvin-Voigt body is braked within m / (8 eta a) = 4e-15 s, far below its elastic
    contact time: resolved on that scale it needs ~1e13 element-steps, and says so (it reported e < 0 before)."""
    text = case_text(material='[material]\nmodel = "kelvin_voigt"\nG = 1.0e3\neta = 1.0e3\n',
                     indenter='[indenter]\nshape = "flat"\na = 9e8\nmass = 0.03\n', load=IMPACT_LOAD.format(v="0.1"),
                     numerics="")
    assert_bad_input(timed(run_case, text), "numerics.max_element_steps", "element-steps")


@pytest.mark.parametrize("extra", ["[output]\nsnapshots = [5e-324]\n",
                                   "[tangential]\nfriction = 0.3\nhistory = [[1.0, 0.0], [1e308, 1e-6]]\n"])
def test_extreme_times_never_write_nan(run_case, workdir, extra):
    result = timed(run_case, case_text(numerics="", extra=extra))
    if result.returncode != 0:
        assert len(result.stderr_lines) == 1 and not result.out.exists(), result.stderr
        return
    for row in read_history(workdir / "out"):
        assert all(math.isfinite(float(value)) for value in row.values()), row


FUZZ_CORPUS = pathlib.Path(__file__).resolve().parents[1] / "fuzz" / "corpus"


@pytest.mark.parametrize("name", ["regression_tangential_force_hang"])
def test_fuzzer_findings_end_within_seconds(run_case, name):
    result = timed(run_case, (FUZZ_CORPUS / f"{name}.toml").read_text(encoding="utf-8"))
    if result.returncode != 0:
        assert result.stderr_lines[-1].startswith("mdr: error: "), result.stderr
        assert not result.out.exists()
