"""Every fit case of examples/fit/ (the real-data fits of docs/examples.md) parses, reads its curves and fits.

A quick test: two Levenberg-Marquardt iterations each (`fit.max_iterations = 2`), 200 elements; the full fits are
scripts/fit_figures. It checks what a user of the examples relies on: the case and its [[fit.data]] are valid, the
curve makes contact, and the result has finite parameters and the documented summary."""

from __future__ import annotations

import math
import pathlib
import tomllib

import pytest

import mdr

EXAMPLES = pathlib.Path(__file__).resolve().parents[2] / "examples" / "fit"
CASES = sorted(EXAMPLES.glob("*.toml"))


def test_there_are_example_fits():
    assert len(CASES) >= 4


@pytest.mark.parametrize("path", CASES, ids=[path.stem for path in CASES])
def test_example_fit_case_parses_and_fits(path):
    with open(path, "rb") as handle:
        case = tomllib.load(handle)
    case["fit"]["max_iterations"] = 2
    case["fit"]["elements"] = 200
    for data in case["fit"]["data"]:
        data["file"] = str((path.parent / data["file"]).resolve())
    result = mdr.fit(case)
    assert result.status in ("converged", "converged, misfit") or result.status.startswith("did not converge"), \
        result.status
    assert set(result.parameters) == set(case["fit"]["free"])
    assert all(math.isfinite(value) for value in result.parameters.values())
    summary = result.summary
    assert summary["points"] > 100 and summary["evaluations"] > 0
    assert 0.0 < summary["noise"] and math.isfinite(summary["residual_to_noise"])
    assert len(result.curves) == len(case["fit"]["data"])
