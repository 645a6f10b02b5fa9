#!/usr/bin/python3
"""Byte-identity harness: run every example and fuzz-corpus case with two mdr binaries and compare the outputs.

    tests/support/compare_outputs.py OLD_MDR NEW_MDR [--keep DIR] [--only SUBSTRING]

Each case is run by both binaries into its own temporary directory: `mdr run` and `mdr material` for a contact
case, `mdr fit` for a case with a [fit] table, `mdr sweep` for the sweeps listed in SWEEPS. The exit codes, stderr
and every output file (same names, same bytes) must agree. The only differences allowed are the wall times: the
JSON key `wall_seconds` (summary.json, fit.json, candidates), the CSV column `wall_seconds` (sweep.csv,
ranking.csv), and the progress lines on stderr (they tell the seconds so far or left). Exit 0 when everything is
identical, 1 otherwise (one line per difference), 2 on bad arguments.
"""
import argparse
import csv
import io
import pathlib
import re
import subprocess
import sys
import tempfile
import tomllib

REPO = pathlib.Path(__file__).resolve().parents[2]
WALL_TIME_FIELDS = {"wall_seconds"}
# Progress reports on stderr tell the time they were made: `mdr: fit iteration 5, chi^2 = 1e9, 7 s so far`,
# `mdr sweep: 2/4 runs, 27.8 runs/s, 0 s left`. They are dropped before stderr is compared.
PROGRESS_LINE = re.compile(r"^mdr.*(?:s so far|s left)\r?(?:\n|$)", re.MULTILINE)
WALL_TIME_JSON = re.compile(rb'"(' + b"|".join(f.encode() for f in WALL_TIME_FIELDS) + rb')"\s*:\s*[-+0-9.eE]+')
# Sweeps over the example cases: (case, --vary arguments). The harmonic sweep lists its frequencies in both orders.
SWEEPS = [
    ("examples/restitution_map.toml", ["material.tau1=1e-4:1e-2:3:log", "material.G1=1e6,3e6"]),
    ("examples/dynamic_indentation.toml", ["load.harmonic.frequency=0.4,5"]),
    ("examples/dynamic_indentation.toml", ["load.harmonic.frequency=5,0.4"]),
    ("examples/cone_standard_solid.toml", ["material.tau1=0.01,0.1"]),
]


def case_files():
    """Every example case and every fuzz-corpus case, as paths relative to the repository."""
    found = sorted(REPO.glob("examples/**/*.toml")) + sorted(REPO.glob("tests/fuzz/corpus/*.toml"))
    found += sorted(REPO.glob("tests/fuzz/fit_corpus/*/case.toml"))
    return [path.relative_to(REPO) for path in found]


def commands(case):
    """The mdr commands (argument lists without the output directory) that a case is run with."""
    with open(REPO / case, "rb") as handle:
        try:
            has_fit = "fit" in tomllib.load(handle)
        except tomllib.TOMLDecodeError:
            has_fit = False
    if has_fit:
        return [["fit", str(case)]]
    return [["run", str(case)], ["material", str(case)]]


def without_wall_time(path):
    """The file's bytes, or for JSON and CSV its content with the wall-time fields removed."""
    data = path.read_bytes()
    if path.suffix == ".json":
        # The value of a wall-time key becomes a placeholder; every other byte stays as written.
        return WALL_TIME_JSON.sub(rb'"\1": WALL', data)
    if path.suffix == ".csv":
        rows = list(csv.reader(io.StringIO(data.decode())))
        if rows and WALL_TIME_FIELDS & set(rows[0]):
            keep = [i for i, name in enumerate(rows[0]) if name not in WALL_TIME_FIELDS]
            return "\n".join(",".join(row[i] for i in keep if i < len(row)) for row in rows).encode()
    return data


def run(binary, arguments, out):
    done = subprocess.run([binary, *arguments, "--out", str(out)], cwd=REPO, capture_output=True, timeout=600)
    stderr = PROGRESS_LINE.sub("", done.stderr.decode().replace(str(out), "OUT"))
    files = {p.relative_to(out): p for p in sorted(out.rglob("*")) if p.is_file()} if out.exists() else {}
    return done.returncode, stderr, files


def compare(old, new, arguments, scratch):
    """Lines naming every difference between the two binaries' runs of one command."""
    label = " ".join(arguments)
    old_code, old_err, old_files = run(old, arguments, scratch / "old")
    new_code, new_err, new_files = run(new, arguments, scratch / "new")
    problems = []
    if old_code != new_code:
        problems.append(f"{label}: exit code {old_code} -> {new_code}")
    if old_err != new_err:
        problems.append(f"{label}: stderr differs:\n  old: {old_err.strip()}\n  new: {new_err.strip()}")
    for name in sorted(set(old_files) | set(new_files)):
        if name not in new_files or name not in old_files:
            problems.append(f"{label}: {name} only in {'old' if name in old_files else 'new'}")
        elif without_wall_time(old_files[name]) != without_wall_time(new_files[name]):
            problems.append(f"{label}: {name} differs")
    return problems, len(old_files)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("old", help="the reference mdr binary")
    parser.add_argument("new", help="the mdr binary under test")
    parser.add_argument("--keep", help="keep the outputs under this directory")
    parser.add_argument("--only", default="", help="only the commands whose arguments contain this text")
    options = parser.parse_args()
    for binary in (options.old, options.new):
        if not pathlib.Path(binary).is_file():
            print(f"compare_outputs: {binary}: no such file", file=sys.stderr)
            return 2
    jobs = [arguments for case in case_files() for arguments in commands(case)]
    jobs += [["sweep", case, "--jobs", "1", *[part for vary in varies for part in ("--vary", vary)]]
             for case, varies in SWEEPS]
    jobs = [arguments for arguments in jobs if options.only in " ".join(arguments)]
    base = pathlib.Path(options.keep or tempfile.mkdtemp(prefix="mdr-compare-"))
    problems, file_count = [], 0
    for index, arguments in enumerate(jobs):
        scratch = base / f"{index:03d}"
        scratch.mkdir(parents=True, exist_ok=True)
        found, count = compare(pathlib.Path(options.old).resolve(), pathlib.Path(options.new).resolve(),
                               arguments, scratch)
        problems += found
        file_count += count
        print(f"{'DIFF' if found else 'same'}  {' '.join(arguments)}  ({count} files)", flush=True)
    for problem in problems:
        print(problem)
    print(f"{len(jobs)} commands, {file_count} output files compared, {len(problems)} differences"
          f" (ignored: {', '.join(sorted(WALL_TIME_FIELDS))})")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
