"""`mdr sweep --scheduler tcp://HOST:PORT` against a real Dask scheduler and two workers: the same sweep.csv as the
local sweep (but the measured wall_seconds), scheduler.json with the tasks and retries, one-line refusals with
nothing written, and Ctrl-C leaving no directory behind."""

from __future__ import annotations

import csv
import io
import json
import os
import signal
import subprocess
import sys
import time

import pytest
import tomli_w

from cluster import worker_env

VARY = ["--vary", "material.tau1=1e-5:1e-1:60:log", "--vary", "material.G1=1e6,3e6"]


@pytest.fixture(scope="module")
def binary() -> str:
    binary = os.environ.get("MDR_BINARY")
    if not binary:
        pytest.fail("set MDR_BINARY to the mdr executable (ctest does this)")
    return binary


@pytest.fixture
def scratch(tmp_path, light_case):
    (tmp_path / "case.toml").write_text(tomli_w.dumps(light_case))
    return tmp_path


def cli_env() -> dict[str, str]:
    env = worker_env()
    env["MDR_PYTHON"] = sys.executable  # the python3 that has numpy and the built package
    return env


def run(binary, *args, cwd, env=None, timeout=120):
    return subprocess.run([binary, *args], cwd=cwd, env=env or cli_env(), capture_output=True, text=True,
                          timeout=timeout)


def table_without_wall_time(path) -> list[list[str]]:
    rows = list(csv.reader(io.StringIO(path.read_text())))
    column = rows[0].index("wall_seconds")
    return [row[:column] + row[column + 1:] for row in rows]


def test_the_scheduled_sweep_writes_the_local_table(binary, cluster, scratch):
    local = run(binary, "sweep", "case.toml", *VARY, "--out", "local", cwd=scratch)
    assert local.returncode == 0, local.stderr
    remote = run(binary, "sweep", "case.toml", *VARY, "--out", "remote", "--scheduler", cluster.address, cwd=scratch)
    assert remote.returncode == 0, remote.stderr
    assert f"120 runs on {cluster.address} (2 workers," in remote.stdout
    assert table_without_wall_time(scratch / "local" / "sweep.csv") == table_without_wall_time(
        scratch / "remote" / "sweep.csv")
    batch = json.loads((scratch / "remote" / "scheduler.json").read_text())
    assert batch["scheduler"] == cluster.address and batch["workers"] == 2 and batch["retried_tasks"] == 0
    assert 1 < batch["tasks"] < 120
    assert sorted(os.listdir(scratch / "remote")) == [".mdr-result", "scheduler.json", "sweep.csv"]


def test_refusals_are_one_line_and_write_nothing(binary, cluster, scratch):
    env = dict(cli_env(), DASK_DISTRIBUTED__COMM__TIMEOUTS__CONNECT="1s")
    unreachable = run(binary, "sweep", "case.toml", *VARY, "--out", "res", "--scheduler", "tcp://127.0.0.1:1",
                      cwd=scratch, env=env)
    assert unreachable.returncode == 2
    assert unreachable.stderr.startswith("mdr: error: --scheduler = tcp://127.0.0.1:1: no Dask scheduler answered")
    assert unreachable.stderr.count("\n") == 1
    both = run(binary, "sweep", "case.toml", *VARY, "--out", "res", "--jobs", "2", "--scheduler", cluster.address,
               cwd=scratch)
    assert both.returncode == 2 and "excludes" in both.stderr
    no_python = run(binary, "sweep", "case.toml", *VARY, "--out", "res", "--scheduler", cluster.address, cwd=scratch,
                    env=dict(cli_env(), MDR_PYTHON=str(scratch / "no-such-python")))
    assert no_python.returncode == 1 and no_python.stderr.count("\n") == 1
    assert "cannot start the Python helper" in no_python.stderr
    bad_key = run(binary, "sweep", "case.toml", "--vary", "material.nope=1,2", "--out", "res", "--scheduler",
                  cluster.address, cwd=scratch)
    assert bad_key.returncode == 2 and "no such numeric key" in bad_key.stderr
    assert sorted(os.listdir(scratch)) == ["case.toml"]


@pytest.mark.parametrize("how", ["ctrl-c", "sigterm"])
def test_an_interruption_leaves_no_directory_and_no_task(binary, cluster, scratch, light_case, how):
    """Ctrl-C reaches the command line and its helper (the process group); SIGTERM only the command line, which
    then stops its helper itself."""
    from distributed import Client

    slow = dict(light_case, numerics={"elements": 100, "time_step": 1.0e-6})  # ~0.1 s a run
    (scratch / "case.toml").write_text(tomli_w.dumps(slow))
    process = subprocess.Popen([binary, "sweep", "case.toml", "--vary", "material.tau1=1e-5:1e-1:600:log", "--out",
                                "res", "--scheduler", cluster.address], cwd=scratch, env=cli_env(),
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, start_new_session=True)
    try:
        with Client(cluster.address) as client:
            deadline = time.monotonic() + 60
            started = False
            while not started and time.monotonic() < deadline and process.poll() is None:
                started = any(client.processing().values())
                time.sleep(0.05)
            assert started, f"the sweep never started: {process.poll()}"
            if how == "ctrl-c":
                os.killpg(process.pid, signal.SIGINT)  # as a terminal does: the command line and its helper
            else:
                process.send_signal(signal.SIGTERM)
            _, err = process.communicate(timeout=30)
            assert process.returncode == (130 if how == "ctrl-c" else 143)
            assert err.splitlines()[-1] == "mdr: interrupted; no result was written"
            deadline = time.monotonic() + 10
            while any(client.processing().values()) and time.monotonic() < deadline:
                time.sleep(0.1)
            assert not any(client.processing().values())
    finally:
        if process.poll() is None:
            os.killpg(process.pid, signal.SIGKILL)
            process.wait()
    assert sorted(os.listdir(scratch)) == ["case.toml"]
    helpers = subprocess.run(["pgrep", "-s", str(process.pid)], capture_output=True, text=True).stdout.split()
    assert helpers == []  # the helper (same session) has ended too
