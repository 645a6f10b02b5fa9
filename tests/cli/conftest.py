"""Fixtures for the command-line tests: the mdr binary (env MDR_BINARY), a scratch directory, and a helper that
writes a case file and runs mdr on it."""

from __future__ import annotations

import os
import pathlib
import subprocess
from dataclasses import dataclass

import pytest


@dataclass
class Completed:
    returncode: int
    stdout: str
    stderr: str
    out: pathlib.Path

    @property
    def stderr_lines(self) -> list[str]:
        return self.stderr.splitlines()


@pytest.fixture(scope="session")
def mdr_binary() -> str:
    binary = os.environ.get("MDR_BINARY")
    if not binary:
        pytest.fail("set MDR_BINARY to the mdr executable (ctest does this)")
    if not os.access(binary, os.X_OK):
        pytest.fail(f"MDR_BINARY = {binary}: not an executable file")
    return binary


@pytest.fixture
def workdir(tmp_path) -> pathlib.Path:
    return tmp_path


@pytest.fixture
def run_mdr(mdr_binary, workdir):
    """run_mdr(*args, timeout=...) runs mdr with the arguments as given, in the scratch directory."""

    def run(*args, timeout=60, out=None):
        completed = subprocess.run([mdr_binary, *map(str, args)], cwd=workdir, capture_output=True, text=True,
                                   timeout=timeout)
        return Completed(completed.returncode, completed.stdout, completed.stderr,
                         pathlib.Path(out) if out is not None else workdir / "out")

    return run


@pytest.fixture
def run_case(run_mdr, workdir):
    """run_case(text, command="run", extra_args=()) writes `text` as case.toml and runs `mdr COMMAND case.toml`,
    with `--out DIR` for run and material (DIR = workdir/out, which does not exist beforehand)."""

    def run(text: str, command: str = "run", extra_args=(), timeout=60):
        case = workdir / "case.toml"
        case.write_text(text, encoding="utf-8")
        out = workdir / "out"
        args = [command, case]
        if command in ("run", "material"):
            args += ["--out", out]
        return run_mdr(*args, *extra_args, timeout=timeout, out=out)

    return run
