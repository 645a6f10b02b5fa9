"""The helper of `mdr sweep --scheduler` (apps/mdr/scheduled_sweep.cpp): runs the rows of a sweep on a Dask
scheduler for the command line, which keeps the validation, the result directory and sweep.csv.

Protocol: one JSON object on stdin, {"version", "case_text", "source", "specs", "scheduler"}; JSON lines on
stdout: {"progress": [done, total]} (at least every 0.2 s), {"first": i, "rows": [[summary, error], ...]}
(all rows, in order, once the sweep is done), then {"done": {"scheduler", "workers", "tasks", "retried"}}; or
{"error": message} (exit 1), with "value" and "rule" when the scheduler cannot be used (exit 2). Ctrl-C cancels
the tasks and exits 130.
"""

from __future__ import annotations

import json
import sys

ROWS_PER_LINE = 1000


def _emit(message: dict) -> None:
    """Writes `message` as one line of JSON by mdr's one writer (io::to_json: null for a number that is not finite,
    which the command line's parser requires)."""
    try:
        from mdr import _mdr
    except ImportError:  # mdr itself cannot be imported: the message is that error, text only
        sys.stdout.write(json.dumps(message) + "\n")
    else:
        sys.stdout.write(_mdr._to_json(message, -1) + "\n")
    sys.stdout.flush()


def main() -> int:
    request = json.load(sys.stdin)
    try:
        import mdr
        from mdr import distributed

        if mdr.__version__ != request["version"]:
            _emit({"error": f"--scheduler: the Python package mdr {mdr.__version__} ({mdr.__file__}) is not the "
                            f"version of this command line, {request['version']}"})
            return 1
        _, _, outcome = distributed.sweep_rows(request["case_text"], request["source"], request["specs"],
                                               request["scheduler"],
                                               progress=lambda done, total: _emit({"progress": [done, total]}))
    except KeyboardInterrupt:
        return 130
    except ImportError as error:
        _emit({"error": f"--scheduler needs dask.distributed (Debian: python3-distributed) beside mdr: {error}"})
        return 1
    except Exception as error:
        from mdr.distributed import SchedulerError

        if isinstance(error, SchedulerError):
            _emit({"error": str(error), "value": error.address, "rule": error.rule})
            return 2
        _emit({"error": f"--scheduler: {type(error).__name__}: {error}"})
        return 1
    rows = outcome.outputs
    for first in range(0, len(rows), ROWS_PER_LINE):
        _emit({"first": first, "rows": rows[first:first + ROWS_PER_LINE]})
    _emit({"done": {"scheduler": outcome.scheduler, "workers": outcome.workers, "tasks": outcome.tasks,
                    "retried": outcome.retried}})
    return 0


if __name__ == "__main__":
    sys.exit(main())
