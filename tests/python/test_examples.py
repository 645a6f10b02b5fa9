"""Every example of docs/examples.md runs and agrees with its closed form (the figure goes to a scratch dir)."""

from __future__ import annotations

import pathlib
import re
import subprocess
import sys

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]

# The largest difference each script prints, against the tolerance of its verification test.
EXAMPLES = {"cone_standard_solid": 1e-5, "creep_kelvin_voigt": 1e-3, "ting_triangle": 1e-4,
            "compressible_punch": 1e-3, "fretting_stick_radius": 1e-2,
            "dynamic_indentation": 1e-3, "afm_gel_units": 1e-5,
            "oblique_restitution": 1e-6, "shore_a_filled_rubber": 1e-3, "afm_creep_pause": 1e-5}


def test_every_example_of_the_docs_is_listed():
    documented = set(re.findall(r"`examples/(\w+)\.py`", (ROOT / "docs" / "examples.md").read_text()))
    assert documented == set(EXAMPLES)


@pytest.mark.parametrize("name", sorted(EXAMPLES))
def test_example_runs_and_matches(name, tmp_path, package_env):
    figure = tmp_path / f"{name}.png"
    completed = subprocess.run(
        [sys.executable, str(ROOT / "examples" / f"{name}.py"), str(ROOT / "examples" / f"{name}.toml"), str(figure)],
        capture_output=True, text=True, env=package_env, timeout=300)
    assert completed.returncode == 0, completed.stderr
    difference = float(re.search(r": ([0-9.e+-]+)\n", completed.stdout).group(1))
    assert difference < EXAMPLES[name], completed.stdout
    assert figure.stat().st_size > 0
