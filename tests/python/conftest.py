"""Makes the built `mdr` package importable (env MDR_PYTHONPATH, the build's python/ folder) and provides the
command-line binary (env MDR_BINARY) for the tests that compare the two."""

from __future__ import annotations

import os
import pathlib
import sys

import pytest

REPO_ROOT = pathlib.Path(__file__).resolve().parents[2]

_package_path = os.environ.get("MDR_PYTHONPATH")
if _package_path:
    sys.path.insert(0, _package_path)
os.environ.setdefault("MPLBACKEND", "Agg")


@pytest.fixture(scope="session")
def mdr_binary() -> str:
    binary = os.environ.get("MDR_BINARY")
    if not binary:
        pytest.fail("set MDR_BINARY to the mdr executable (ctest does this)")
    if not os.access(binary, os.X_OK):
        pytest.fail(f"MDR_BINARY = {binary}: not an executable file")
    return binary


@pytest.fixture(scope="session")
def package_env() -> dict[str, str]:
    """The environment for a subprocess that imports the same mdr package as these tests."""
    env = dict(os.environ)
    if _package_path:
        env["PYTHONPATH"] = _package_path + os.pathsep + env.get("PYTHONPATH", "")
    env["MPLBACKEND"] = "Agg"
    return env
