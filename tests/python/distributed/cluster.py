"""A real Dask cluster on 127.0.0.1 for the tests and the benchmark: `dask scheduler` and `dask worker` processes,
every one stopped on the way out, whatever happened (and each ends by itself if this process is killed: the
scheduler after 120 s idle, the workers 30 s after losing it)."""

from __future__ import annotations

import contextlib
import json
import os
import pathlib
import signal
import subprocess
import tempfile
import time

START_TIMEOUT = 60.0  # seconds for the scheduler and each worker to come up on a loaded 2-core machine


def worker_env() -> dict[str, str]:
    """The environment of the scheduler and workers: the mdr package of the tests (MDR_PYTHONPATH, the build's
    python/ folder; an installed package needs none) and this folder, for the tests' per-curve module."""
    env = dict(os.environ)
    here = str(pathlib.Path(__file__).resolve().parent)
    env["PYTHONPATH"] = os.pathsep.join(p for p in (os.environ.get("MDR_PYTHONPATH"), here, env.get("PYTHONPATH"))
                                        if p)
    env["OMP_NUM_THREADS"] = "1"
    return env


class Cluster:
    """The processes of a running cluster: `address` (tcp://127.0.0.1:PORT), `workers` {name: Popen}."""

    def __init__(self, directory: pathlib.Path, env: dict[str, str]):
        self.directory, self.env = directory, env
        self.scheduler: subprocess.Popen | None = None
        self.workers: dict[str, subprocess.Popen] = {}
        self.address = ""

    def start_scheduler(self) -> None:
        scheduler_file = self.directory / "scheduler.json"
        self.scheduler = self._spawn("scheduler", ["dask", "scheduler", "--host", "127.0.0.1", "--port", "0",
                                                   "--no-dashboard", "--idle-timeout", "120s",
                                                   "--scheduler-file", str(scheduler_file)])
        deadline = time.monotonic() + START_TIMEOUT
        while not scheduler_file.exists() or not scheduler_file.read_text().strip():
            self._check_alive(self.scheduler, "scheduler", deadline)
        time.sleep(0.05)  # the file is written whole, but let it be closed
        self.address = json.loads(scheduler_file.read_text())["address"]

    def start_worker(self, name: str, nthreads: int = 1) -> subprocess.Popen:
        """Starts a worker without nanny (killing it kills the worker) and waits until the scheduler knows it."""
        from distributed import Client

        self.workers[name] = self._spawn(name, ["dask", "worker", self.address, "--name", name, "--nthreads",
                                                str(nthreads), "--no-nanny", "--no-dashboard", "--death-timeout",
                                                "30s", "--local-directory", str(self.directory / name)])
        with Client(self.address, timeout=START_TIMEOUT) as client:
            deadline = time.monotonic() + START_TIMEOUT
            while name not in {w["name"] for w in client.scheduler_info()["workers"].values()}:
                self._check_alive(self.workers[name], name, deadline)
        return self.workers[name]

    def worker_address(self, name: str) -> str:
        from distributed import Client

        with Client(self.address, timeout=START_TIMEOUT) as client:
            return next(a for a, w in client.scheduler_info()["workers"].items() if w["name"] == name)

    def _spawn(self, name: str, command: list[str]) -> subprocess.Popen:
        log = open(self.directory / f"{name}.log", "wb")
        return subprocess.Popen(command, stdout=log, stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL,
                                env=self.env, start_new_session=True)

    def _check_alive(self, process: subprocess.Popen, name: str, deadline: float) -> None:
        if process.poll() is not None or time.monotonic() > deadline:
            log = (self.directory / f"{name}.log").read_text(errors="replace")[-3000:]
            raise RuntimeError(f"dask {name} did not start (exit {process.poll()}):\n{log}")
        time.sleep(0.1)

    def stop(self) -> None:
        processes = [*self.workers.values(), *([self.scheduler] if self.scheduler else [])]
        for process in processes:
            if process.poll() is None:
                process.send_signal(signal.SIGTERM)
        for process in processes:
            try:
                process.wait(timeout=10)
            except subprocess.TimeoutExpired:
                process.kill()
                process.wait(timeout=10)


@contextlib.contextmanager
def local_cluster(workers: int = 2, env: dict[str, str] | None = None, nthreads: int = 1):
    """A scheduler and `workers` workers (named worker-1, ...) on 127.0.0.1; all stopped on exit."""
    with tempfile.TemporaryDirectory(prefix="mdr-dask-") as scratch:
        cluster = Cluster(pathlib.Path(scratch), dict(env or worker_env()))
        try:
            cluster.start_scheduler()
            for i in range(workers):
                cluster.start_worker(f"worker-{i + 1}", nthreads)
            yield cluster
        finally:
            cluster.stop()
