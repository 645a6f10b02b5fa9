"""A user's files are sacred: `--out` is only ever created or replaced when it is a result directory that mdr
wrote itself; refusals come before any computing; temporary directories never outlive a run, also when it is
interrupted (SIGINT, SIGTERM) or when an earlier run was killed.

Every scenario runs inside a scratch directory holding sentinel files; after each command the whole scratch tree is
compared byte for byte with what it must be. No test names a real system path."""

from __future__ import annotations

import json
import os
import pathlib
import signal
import subprocess
import sys
import time

import pytest

from test_sweep import CASE

PREFIX = "mdr: error: "


# Minutes of work at these numerics: long enough to be interrupted on any machine.
LONG_CASE = CASE.replace("elements = 100", "elements = 400000").replace("time_step = 0.02", "time_step = 1e-5")


def tree(root: pathlib.Path) -> dict[str, bytes | str]:
    """Every entry below `root`: a file's bytes, or the kind of anything else."""
    entries: dict[str, bytes | str] = {}
    for path in sorted(root.rglob("*")):
        name = str(path.relative_to(root))
        if path.is_symlink():
            entries[name] = "link -> " + os.readlink(path)
        elif path.is_dir():
            entries[name] = "dir"
        elif path.is_file():
            entries[name] = path.read_bytes()
        else:
            entries[name] = "special"
    return entries


@pytest.fixture
def scratch(workdir) -> pathlib.Path:
    """A scratch tree: the case, sentinel files of the user, and `work/` where mdr is started."""
    (workdir / "case.toml").write_text(CASE, encoding="utf-8")
    (workdir / "notes.txt").write_text("the user's notes\n", encoding="utf-8")
    (workdir / "data").mkdir()
    (workdir / "data" / "measured.csv").write_bytes(b"t,F\n0,0\n1,2.5\n")
    (workdir / "work").mkdir()
    (workdir / "work" / "sentinel.txt").write_text("keep me\n", encoding="utf-8")
    return workdir


def mdr_in(mdr_binary, cwd: pathlib.Path, *args, timeout=60):
    return subprocess.run([mdr_binary, *map(str, args)], cwd=cwd, capture_output=True, text=True, timeout=timeout)


def assert_refused(completed, *fragments):
    lines = completed.stderr.splitlines()
    assert completed.returncode == 2, completed.stderr
    assert len(lines) == 1 and lines[0].startswith(PREFIX + "--out = "), completed.stderr
    for fragment in fragments:
        assert fragment in lines[0], (fragment, lines[0])
    assert completed.stdout == ""


COMMANDS = {
    "run": lambda case, out: ["run", case, "--out", out],
    "material": lambda case, out: ["material", case, "--out", out],
    "sweep": lambda case, out: ["sweep", case, "--vary", "material.tau1=0.1,0.2", "--out", out],
}


def user_directory(scratch):
    (scratch / "work" / "mine").mkdir()
    (scratch / "work" / "mine" / "thesis.tex").write_text("chapter 1\n", encoding="utf-8")
    return "mine", ["did not write", ".mdr-result"]


def result_with_foreign_file(scratch, mdr_binary):
    assert mdr_in(mdr_binary, scratch / "work", "run", "../case.toml", "--out", "res").returncode == 0
    (scratch / "work" / "res" / "my-analysis.csv").write_text("1,2\n", encoding="utf-8")
    return "res", ["holds my-analysis.csv", "did not write"]


def result_with_subdirectory(scratch, mdr_binary):
    assert mdr_in(mdr_binary, scratch / "work", "run", "../case.toml", "--out", "res").returncode == 0
    (scratch / "work" / "res" / "figures").mkdir()
    return "res", ["holds figures", "did not write"]


def manifest_folder(scratch):
    """A folder named like mdr's mark, holding a file of the user's: not mdr's mark (issue 23)."""
    (scratch / "work" / "res" / ".mdr-result").mkdir(parents=True)
    (scratch / "work" / "res" / ".mdr-result" / "thesis.tex").write_text("chapter 1\n", encoding="utf-8")
    return "res", ["holds .mdr-result, which is not a regular file"]


def manifest_link(scratch):
    """A link named like mdr's mark, to a list of the user's files: never followed (issue 23)."""
    (scratch / "work" / "res").mkdir()
    (scratch / "work" / "res" / "thesis.tex").write_text("chapter 1\n", encoding="utf-8")
    (scratch / "list.txt").write_text("# mdr result directory\nthesis.tex\n", encoding="utf-8")
    (scratch / "work" / "res" / ".mdr-result").symlink_to(scratch / "list.txt")
    return "res", ["holds .mdr-result, which is not a regular file"]


def link_to_result(scratch, mdr_binary):
    assert mdr_in(mdr_binary, scratch / "work", "run", "../case.toml", "--out", "res").returncode == 0
    (scratch / "work" / "link").symlink_to("res")
    return "link", ["symbolic link"]


def fifo(scratch):
    os.mkfifo(scratch / "work" / "pipe")
    return "pipe", ["existing file or device"]


# (id, setup(scratch, mdr_binary) -> (--out as given from work/, fragments of the error line))
REFUSALS = [
    ("working-directory", lambda s, b: (".", ["working directory"])),
    ("working-directory-slash", lambda s, b: ("./", ["working directory"])),
    ("parent", lambda s, b: ("..", ["working directory or one of its parents"])),
    ("grandparent-absolute", lambda s, b: (str(s.parent), ["working directory or one of its parents"])),
    ("directory-of-the-case", lambda s, b: ("../data/..", ["working directory or one of its parents"])),
    ("existing-file", lambda s, b: ("sentinel.txt", ["existing file"])),
    ("the-case-file", lambda s, b: ("../case.toml", ["existing file"])),
    ("special-file", lambda s, b: fifo(s)),
    ("below-a-file", lambda s, b: ("sentinel.txt/out", ["not a directory"])),
    ("user-directory", lambda s, b: user_directory(s)),
    ("result-with-a-foreign-file", result_with_foreign_file),
    ("result-with-a-subdirectory", result_with_subdirectory),
    ("symbolic-link", link_to_result),
    ("manifest-folder", lambda s, b: manifest_folder(s)),
    ("manifest-link", lambda s, b: manifest_link(s)),
    ("empty", lambda s, b: ("", ["must name a directory"])),
]


@pytest.mark.parametrize("command", sorted(COMMANDS))
@pytest.mark.parametrize("name,setup", REFUSALS, ids=[r[0] for r in REFUSALS])
def test_refused_without_touching_anything(mdr_binary, scratch, command, name, setup):
    out, fragments = setup(scratch, mdr_binary)
    before = tree(scratch)
    started = time.monotonic()
    completed = mdr_in(mdr_binary, scratch / "work", *COMMANDS[command]("../case.toml", out))
    assert_refused(completed, *fragments)
    assert tree(scratch) == before
    assert time.monotonic() - started < 5.0  # refused before any computing


def test_directory_of_the_case_file_is_protected(mdr_binary, scratch):
    """Not the working directory nor one of its parents, but it holds the input: refused all the same."""
    (scratch / "data" / "case.toml").write_text(CASE, encoding="utf-8")
    before = tree(scratch)
    for out in ("../data", "../data/"):
        assert_refused(mdr_in(mdr_binary, scratch / "work", "run", "../data/case.toml", "--out", out), "input file")
    assert tree(scratch) == before


def test_result_directory_is_created_and_replaced_also_with_a_trailing_slash(mdr_binary, scratch):
    work = scratch / "work"
    first = mdr_in(mdr_binary, work, "run", "../case.toml", "--out", "res")
    assert first.returncode == 0, first.stderr
    manifest = (work / "res" / ".mdr-result").read_text(encoding="utf-8").splitlines()
    assert manifest[0].startswith("#") and sorted(manifest[1:]) == ["history.csv", "summary.json"]
    first_force = json.loads((work / "res" / "summary.json").read_text(encoding="utf-8"))["max_force"]
    (scratch / "case.toml").write_text(CASE.replace("G1 = 3.0e6", "G1 = 5.0e6"), encoding="utf-8")
    second = mdr_in(mdr_binary, work, "run", "../case.toml", "--out", "res/")
    assert second.returncode == 0, second.stderr
    assert json.loads((work / "res" / "summary.json").read_text(encoding="utf-8"))["max_force"] > first_force
    assert sorted(p.name for p in work.iterdir()) == ["res", "sentinel.txt"]
    assert sorted(p.name for p in (work / "res").iterdir()) == [".mdr-result", "history.csv", "summary.json"]
    # Another command's result directory of mdr may be replaced too.
    assert mdr_in(mdr_binary, work, "material", "../case.toml", "--out", "res").returncode == 0
    assert sorted(p.name for p in (work / "res").iterdir()) == [".mdr-result", "dynamic.csv", "functions.csv",
                                                                 "summary.json"]
    assert (work / "sentinel.txt").read_text(encoding="utf-8") == "keep me\n"


@pytest.mark.skipif(not (pathlib.Path(os.environ.get("MDR_PYTHONPATH", "/nonexistent")) / "mdr").is_dir(),
                    reason="the Python package is not built here (MDR_BUILD_PYTHON=OFF, e.g. the sanitizer build)")
def test_figures_of_the_plot_command_keep_the_directory_replaceable(mdr_binary, scratch):
    work = scratch / "work"
    assert mdr_in(mdr_binary, work, "run", "../case.toml", "--out", "res").returncode == 0
    environment = dict(os.environ, PYTHONPATH=os.environ["MDR_PYTHONPATH"], MPLBACKEND="Agg")
    plotted = subprocess.run([sys.executable, "-m", "mdr", "plot", "res"], cwd=work, capture_output=True, text=True,
                             env=environment, timeout=120)
    assert plotted.returncode == 0, plotted.stderr
    assert "force_depth.png" in (work / "res" / ".mdr-result").read_text(encoding="utf-8")
    again = mdr_in(mdr_binary, work, "run", "../case.toml", "--out", "res")
    assert again.returncode == 0, again.stderr
    assert not (work / "res" / "force_depth.png").exists()
    # A figure name taken by a file of the user's is never overwritten.
    (work / "res" / "force_depth.png").write_bytes(b"the user's picture")
    refused = subprocess.run([sys.executable, "-m", "mdr", "plot", "res"], cwd=work, capture_output=True, text=True,
                             env=environment, timeout=120)
    assert refused.returncode == 2 and "not written by mdr" in refused.stderr
    assert (work / "res" / "force_depth.png").read_bytes() == b"the user's picture"


def dead_pid() -> int:
    child = subprocess.Popen([sys.executable, "-c", "pass"])
    child.wait()
    return child.pid


def test_temporaries_of_killed_runs_are_removed_and_nothing_else(mdr_binary, scratch):
    work = scratch / "work"
    stale = work / f".res.mdr-partial-{dead_pid()}-0"
    stale.mkdir()
    (stale / ".mdr-result").write_text("# mdr result directory\nhistory.csv\n", encoding="utf-8")
    (stale / "history.csv").write_text("t,d,F,a\n", encoding="utf-8")
    running = work / f".res.mdr-partial-{os.getpid()}-0"  # its process still runs: not stale
    running.mkdir()
    (running / ".mdr-result").write_text("# mdr result directory\n", encoding="utf-8")
    unmarked = work / f".res.mdr-partial-{dead_pid()}-1"  # no manifest: not recognised as mdr's
    unmarked.mkdir()
    (unmarked / "precious.txt").write_text("x\n", encoding="utf-8")
    # Stale, but holding a file its manifest does not list (nor the ../ path it does): only the listed file goes.
    mixed = work / f".res.mdr-partial-{dead_pid()}-2"
    mixed.mkdir()
    (mixed / ".mdr-result").write_text("# mdr result directory\nhistory.csv\n../sentinel.txt\n", encoding="utf-8")
    (mixed / "history.csv").write_text("t,d,F,a\n", encoding="utf-8")
    (mixed / "thesis.tex").write_text("chapter 1\n", encoding="utf-8")
    completed = mdr_in(mdr_binary, work, "run", "../case.toml", "--out", "res")
    assert completed.returncode == 0, completed.stderr
    assert not stale.exists()
    assert running.exists() and (unmarked / "precious.txt").read_text(encoding="utf-8") == "x\n"
    assert sorted(p.name for p in mixed.iterdir()) == ["thesis.tex"]
    assert (work / "sentinel.txt").read_text(encoding="utf-8") == "keep me\n"
    assert f"left {mixed}" in completed.stderr


@pytest.mark.parametrize("signal_number", [signal.SIGINT, signal.SIGTERM])
@pytest.mark.parametrize("command", ["run", "sweep"])
def test_interrupted_runs_leave_nothing(mdr_binary, scratch, signal_number, command):
    (scratch / "case.toml").write_text(LONG_CASE, encoding="utf-8")
    before = tree(scratch)
    arguments = COMMANDS[command]("../case.toml", "res")
    process = subprocess.Popen([mdr_binary, *map(str, arguments)], cwd=scratch / "work", stdout=subprocess.PIPE,
                               stderr=subprocess.PIPE, text=True)
    time.sleep(1.5)
    assert process.poll() is None, "the long case ended before it could be interrupted"
    interrupted_at = time.monotonic()
    process.send_signal(signal_number)
    stdout, stderr = process.communicate(timeout=60)
    assert time.monotonic() - interrupted_at < 10.0
    assert process.returncode == 128 + signal_number
    assert stderr.splitlines()[-1] == "mdr: interrupted; no result was written"
    assert stdout == ""
    assert tree(scratch) == before
