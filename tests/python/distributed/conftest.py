"""Fixtures of the distributed tests: the built mdr package on sys.path, a real Dask cluster (a scheduler and two
workers on 127.0.0.1, started once for the session and stopped whatever happens), a light restitution case."""

from __future__ import annotations

import os
import pathlib
import sys

import pytest

HERE = pathlib.Path(__file__).resolve().parent
REPO_ROOT = HERE.parents[2]
_package_path = os.environ.get("MDR_PYTHONPATH")
for path in (str(HERE), _package_path):
    if path and path not in sys.path:
        sys.path.insert(0, path)
os.environ.setdefault("MPLBACKEND", "Agg")

from cluster import local_cluster, worker_env  # noqa: E402


@pytest.fixture(scope="session")
def cluster():
    with local_cluster(workers=2, env=worker_env()) as running:
        yield running


@pytest.fixture(scope="session")
def light_case() -> dict:
    """The restitution-map impact (examples/restitution_map.toml) at coarse numerics: about 1 ms a run."""
    import tomllib

    with open(REPO_ROOT / "examples" / "restitution_map.toml", "rb") as handle:
        case = tomllib.load(handle)
    case["numerics"] = {"elements": 100, "time_step": 5.0e-5}
    return case
