"""The bad-input contract of the command line (docs: case-format.md, "Runs that fail ..."):
exit status 2, exactly one stderr line `mdr: error: key = value: rule` naming the key, the value and the rule,
nothing on stdout, and no result directory (nor a `.DIR.partial-*` leftover). Plus the good paths."""

from __future__ import annotations

import csv
import json
import math
import pathlib
import subprocess
import time

import pytest

REPO_ROOT = pathlib.Path(__file__).resolve().parents[2]
PREFIX = "mdr: error: "

# A small, fast, valid case; tests replace one piece of it at a time.
MATERIAL = '[material]\nmodel = "standard"\nG_inf = 1.0e6\nG1 = 2.0e6\ntau1 = 0.1\n'
INDENTER = '[indenter]\nshape = "sphere"\nR = 0.01\n'
LOAD = '[load]\ncontrol = "displacement"\nhistory = [[0.0, 0.0], [1.0, 1.0e-4]]\n'
NUMERICS = '[numerics]\nelements = 50\ntime_step = 0.01\n'
TITLE = 'title = "cli test"\n'


def case_text(*, title=TITLE, material=MATERIAL, indenter=INDENTER, load=LOAD, numerics=NUMERICS, extra=""):
    """A case file with the given sections (pass "" to leave one out); `extra` goes after the last table."""
    return "\n".join(part for part in (title, material, indenter, load, numerics, extra) if part)


def assert_bad_input(result, *fragments):
    """The whole failure contract; `fragments` must all appear in the one error line."""
    lines = result.stderr_lines
    assert len(lines) == 1, f"expected one stderr line, got {len(lines)}:\n{result.stderr}"
    line = lines[0]
    assert line.startswith(PREFIX), line
    for fragment in fragments:
        assert fragment in line, f"{fragment!r} not in {line!r}"
    assert result.returncode == 2, f"exit status {result.returncode}, stderr: {result.stderr}"
    assert result.stdout.strip() == "", result.stdout
    out: pathlib.Path = result.out
    assert not out.exists(), f"{out} was created by a failing run"
    leftovers = sorted(p.name for p in out.parent.glob(f".{out.name}.mdr-*"))
    assert leftovers == [], leftovers


def sub(section: str, old: str, new: str) -> str:
    assert old in section, (old, section)
    return section.replace(old, new)


# (id, case text, fragments of the error line)
BAD_CASES = [
    # unknown keys, with the nearest known key suggested
    ("unknown-top-level", case_text(title='titel = "x"\n'),
     ["titel = ", "x", "unknown key", "'title'"]),
    ("unknown-top-level-table", case_text(extra="[numeric]\nelements = 50\n"),
     ["numeric = [...]: unknown key", "'numerics'"]),
    # a misspelt table prints as [...], not as its re-rendered contents
    ("unknown-table-with-content", case_text(load=sub(LOAD, "[load]", "[lod]")),
     ["lod = [...]: unknown key; did you mean 'load'?"]),
    ("unknown-array-of-tables", case_text(extra="[[numeric]]\nelements = 50\n"),
     ["numeric = [...]: unknown key; did you mean 'numerics'?"]),
    ("unknown-material-key", case_text(material=sub(MATERIAL, "G_inf", "Ginf")),
     ["material.Ginf", "unknown key", "'G_inf'"]),
    ("unknown-material-key-for-model", case_text(material=MATERIAL + "eta = 5\n"),
     ["material.eta", "= 5", "unknown key"]),
    ("unknown-indenter-key", case_text(indenter=INDENTER + "mas = 2\n"),
     ["indenter.mas", "= 2", "unknown key", "'mass'"]),
    ("unknown-load-key", case_text(load=sub(LOAD, "history", "histroy")),
     ["load.histroy", "unknown key", "'history'"]),
    ("unknown-numerics-key", case_text(numerics=sub(NUMERICS, "elements", "element")),
     ["numerics.element", "= 50", "unknown key", "'elements'"]),
    ("unknown-output-key", case_text(extra="[output]\nsnapshot = [0.5]\n"),
     ["output.snapshot", "unknown key", "'snapshots'"]),
    # unknown names
    ("unknown-model", case_text(material=sub(MATERIAL, '"standard"', '"kelvin"')),
     ["material.model", '"kelvin"', "unknown model", "standard", "kelvin_voigt"]),
    ("unknown-shape", case_text(indenter=sub(INDENTER, '"sphere"', '"ball"')),
     ["indenter.shape", '"ball"', "unknown shape", "sphere"]),
    ("unknown-control", case_text(load=sub(LOAD, '"displacement"', '"position"')),
     ["load.control", '"position"', "unknown control", "displacement"]),
    ("unknown-interpolation",
     case_text(indenter='[indenter]\nshape = "profile"\nr = [0.0, 0.001, 0.002]\nf = [0.0, 1e-5, 4e-5]\n'
                        'interpolation = "spline"\n'),
     ["indenter.interpolation", '"spline"', "must be monotone_cubic or linear"]),
    ("interpolation-without-table", case_text(indenter=INDENTER + 'interpolation = "linear"\n'),
     ["indenter.interpolation", "unknown key"]),
    # moduli and times: negative, zero, NaN, infinite
    ("negative-modulus", case_text(material=sub(MATERIAL, "G_inf = 1.0e6", "G_inf = -1")),
     ["material.G_inf", "= -1", "must be > 0"]),
    ("zero-modulus", case_text(material=sub(MATERIAL, "G1 = 2.0e6", "G1 = 0")),
     ["material.G1", "= 0", "must be > 0"]),
    ("nan-time", case_text(material=sub(MATERIAL, "tau1 = 0.1", "tau1 = nan")),
     ["material.tau1", "nan", "must be finite"]),
    ("inf-time", case_text(material=sub(MATERIAL, "tau1 = 0.1", "tau1 = inf")),
     ["material.tau1", "inf", "must be finite"]),
    ("zero-time", case_text(material=sub(MATERIAL, "tau1 = 0.1", "tau1 = 0.0")),
     ["material.tau1", "= 0", "must be > 0"]),
    ("negative-inf-elastic", case_text(material='[material]\nmodel = "elastic"\nG = -inf\n'),
     ["material.G", "-inf", "must be finite"]),
    ("maxwell-negative-tau", case_text(material='[material]\nmodel = "maxwell"\nG = 1e6\ntau = -2\n'),
     ["material.tau", "= -2", "must be > 0"]),
    ("viscous-zero-eta", case_text(material='[material]\nmodel = "viscous"\neta = 0\n'),
     ["material.eta", "= 0", "must be > 0"]),
    ("prony-negative-term-time",
     case_text(material='[material]\nmodel = "prony"\nG_inf = 1e6\nterms = [[1e6, 0.1], [2e6, -3]]\n'),
     ["material.terms[1]", "-3", "must be > 0"]),
    ("prony-nan-term-modulus",
     case_text(material='[material]\nmodel = "prony"\nG_inf = 1e6\nterms = [[nan, 0.1]]\n'),
     ["material.terms[0]", "nan", "must be finite"]),
    ("prony-term-not-a-pair",
     case_text(material='[material]\nmodel = "prony"\nG_inf = 1e6\nterms = [[1e6, 0.1, 3]]\n'),
     ["material.terms[0]", "pairs"]),
    ("negative-bulk-modulus", case_text(material='[material]\nmodel = "elastic"\nG = 1e6\nK = -5\n'),
     ["material.K", "= -5", "must be > 0"]),
    ("negative-sphere-radius", case_text(indenter=sub(INDENTER, "R = 0.01", "R = -0.01")),
     ["indenter.R", "-0.01", "must be > 0"]),
    # types
    ("string-for-number", case_text(material=sub(MATERIAL, "G_inf = 1.0e6", 'G_inf = "1e6"')),
     ["material.G_inf", "1e6", "must be a number"]),
    ("number-for-string", case_text(material=sub(MATERIAL, '"standard"', "3")),
     ["material.model", "= 3", "must be a string"]),
    ("table-is-a-number", case_text(material="material = 5\n"),
     ["material", "= 5", "must be a table"]),
    ("history-is-a-string", case_text(load='[load]\ncontrol = "displacement"\nhistory = "ramp"\n'),
     ["load.history", "ramp", "pairs"]),
    ("history-point-of-strings", case_text(load='[load]\ncontrol = "displacement"\nhistory = [["0", "1"]]\n'),
     ["load.history[0]", "must be a number"]),
    ("history-nan", case_text(load='[load]\ncontrol = "displacement"\nhistory = [[0.0, 0.0], [1.0, nan]]\n'),
     ["load.history[1]", "nan", "must be finite"]),
    # missing pieces
    ("missing-material", case_text(material=""), ["material", "(missing)", "is required"]),
    ("missing-indenter", case_text(indenter=""), ["indenter", "(missing)", "is required"]),
    ("missing-load", case_text(load=""), ["load", "(missing)", "is required"]),
    ("missing-history", case_text(load='[load]\ncontrol = "displacement"\n'),
     ["load.history", "(missing)", "is required"]),
    ("missing-model", case_text(material="[material]\nG = 1e6\n"), ["material.model", "(missing)", "is required"]),
    ("missing-modulus", case_text(material='[material]\nmodel = "standard"\nG_inf = 1e6\ntau1 = 0.1\n'),
     ["material.G1", "(missing)", "is required"]),
    ("missing-shape", case_text(indenter="[indenter]\nR = 0.01\n"), ["indenter.shape", "(missing)", "is required"]),
    ("empty-history", case_text(load='[load]\ncontrol = "displacement"\nhistory = []\n'),
     ["load.history", "at least one point"]),
    # malformed TOML: the line and column of the syntax error
    ("malformed-toml", case_text(material=sub(MATERIAL, "G1 = 2.0e6", "G1 = = 2.0e6")),
     ["case.toml", "line 6, column 6", "malformed TOML"]),
    ("malformed-toml-unclosed-array", case_text(load='[load]\ncontrol = "displacement"\nhistory = [[0.0, 0.0]\n'),
     ["case.toml", "line", "column", "malformed TOML"]),
    ("duplicate-key", case_text(material=MATERIAL + "G1 = 3.0e6\n"),
     ["case.toml", "line", "malformed TOML"]),
    # load histories
    ("history-backwards", case_text(load='[load]\ncontrol = "displacement"\n'
                                         'history = [[0.0, 0.0], [1.0, 1e-4], [0.5, 0.0]]\n'),
     ["load.history[2].t", "0.5", "backwards"]),
    ("negative-force", case_text(load='[load]\ncontrol = "force"\nhistory = [[0.0, 0.0], [1.0, -2.0]]\n'),
     ["load.history[1].F", "-2", "must be >= 0"]),
    ("kelvin-voigt-depth-jump",
     case_text(material='[material]\nmodel = "kelvin_voigt"\nG = 1e6\neta = 1e4\n',
               load='[load]\ncontrol = "displacement"\nhistory = [[0.0, 0.0], [0.0, 1e-4], [1.0, 1e-4]]\n'),
     ["load.history", "jump", "eta"]),
    ("end-before-start", case_text(load=LOAD + "end = -1.0\n"), ["load.end", "-1", "must be after"]),
    ("velocity-without-impact", case_text(load=LOAD + "velocity = 1.0\n"), ["load.velocity", "impact"]),
    # tabulated profiles
    ("profile-r-not-ascending",
     case_text(indenter='[indenter]\nshape = "profile"\nr = [0.0, 2e-3, 1e-3]\nf = [0.0, 1e-4, 2e-4]\n'),
     ["indenter.r[2]", "0.001", "ascending"]),
    ("profile-f0-not-zero",
     case_text(indenter='[indenter]\nshape = "profile"\nr = [0.0, 1e-3, 2e-3]\nf = [1e-5, 1e-4, 2e-4]\n'),
     ["indenter.f[0]", "1e-05", "must be 0"]),
    ("profile-f-decreasing",
     case_text(indenter='[indenter]\nshape = "profile"\nr = [0.0, 1e-3, 2e-3]\nf = [0.0, 2e-4, 1e-4]\n'),
     ["indenter.f[2]", "0.0001", "non-decreasing"]),
    ("profile-lengths-differ",
     case_text(indenter='[indenter]\nshape = "profile"\nr = [0.0, 1e-3, 2e-3]\nf = [0.0, 1e-4]\n'),
     ["indenter.f", "size 2", "as many points as r"]),
    ("profile-r-missing", case_text(indenter='[indenter]\nshape = "profile"\nf = [0.0, 1e-4]\n'),
     ["indenter.r", "(missing)", "is required"]),
    # cones
    ("cone-slope-zero", case_text(indenter='[indenter]\nshape = "cone"\nslope_deg = 0\n'),
     ["indenter.slope_deg", "= 0", "must be > 0"]),
    ("cone-slope-ninety", case_text(indenter='[indenter]\nshape = "cone"\nslope_deg = 90\n'),
     ["indenter.slope_deg", "= 90", "must be < 90"]),
    # snapshots
    ("snapshot-after-end", case_text(extra="[output]\nsnapshots = [0.5, 2.0]\n"),
     ["output.snapshots[1]", "= 2", "within the simulated time"]),
    ("snapshot-before-start", case_text(extra="[output]\nsnapshots = [-0.5]\n"),
     ["output.snapshots[0]", "-0.5", "within the simulated time"]),
    # issue 23: a subnormal snapshot time is refused at validation, naming the key (it ran into "not finite")
    ("snapshot-subnormal", case_text(extra="[output]\nsnapshots = [5e-324]\n"),
     ["output.snapshots[0]", "5e-324", "is subnormal", "normal number"]),
    # issue 23: a value is echoed on one line, control characters escaped (a newline, a terminal escape)
    ("model-with-control-characters", case_text(material='[material]\nmodel = "max\\nwell\\u001b[2J"\n'),
     ["material.model = \"max\\nwell\\x1b[2J\"", "unknown model"]),
    # issue 23: toml++ reads 1e-400 as 0; the key is named with what was written, not "= 0: must be > 0"
    ("underflow-to-zero", case_text(extra="[output]\nsnapshots = [1e-400]\n"),
     ["output.snapshots[0] = 1e-400", "underflows to 0"]),
    ("model-with-a-nul", case_text(material='[material]\nmodel = "max\\u0000well"\n'),
     ["material.model = \"max\\x00well\"", "unknown model"]),
    # numerics
    ("elements-zero", case_text(numerics="[numerics]\nelements = 0\n"),
     ["numerics.elements", "= 0", "integer >= 1"]),
    ("elements-fractional", case_text(numerics="[numerics]\nelements = 2.5\n"),
     ["numerics.elements", "2.5", "integer >= 1"]),
    ("elements-negative", case_text(numerics="[numerics]\nelements = -10\n"),
     ["numerics.elements", "-10", "integer >= 1"]),
    ("time-step-zero", case_text(numerics="[numerics]\ntime_step = 0.0\n"),
     ["numerics.time_step", "= 0", "must be > 0"]),
    ("output-every-zero", case_text(numerics="[numerics]\noutput_every = 0\n"),
     ["numerics.output_every", "= 0", "integer >= 1"]),
    # tangential loading (more in test_tangential_input.py)
    ("tangential", case_text(extra='[tangential]\nfriction = -0.3\ncontrol = "displacement"\n'
                                   'history = [[0.0, 0.0], [1.0, 1e-6]]\n'),
     ["tangential.friction", "-0.3", "must be >= 0"]),
    # a contact that outgrows a tabulated profile: an error, not a silent clamp at the table's end
    ("profile-too-short", case_text(indenter='[indenter]\nshape = "profile"\nr = [0.0, 2e-4, 4e-4]\n'
                                             'f = [0.0, 2e-6, 8e-6]\n'),
     ["indenter.r", "0.0004", "beyond the last tabulated radius"]),
    ("impact-profile-too-short", case_text(indenter='[indenter]\nshape = "profile"\nr = [0.0, 2e-4, 4e-4]\n'
                                                    'f = [0.0, 2e-6, 8e-6]\nmass = 0.03\n',
                                           load='[load]\ncontrol = "impact"\nvelocity = 0.1\n', numerics=""),
     ["indenter.r", "beyond the last tabulated radius"]),
    # compressible bodies (eq. 56)
    ("bulk-modulus-zero", case_text(material=MATERIAL + "K = 0.0\n"), ["material.K", "= 0", "must be > 0"]),
    ("bulk-modulus-nan", case_text(material=MATERIAL + "K = nan\n"), ["material.K", "nan"]),
    ("bulk-table-without-model", case_text(material=MATERIAL + "[material.bulk]\nK = 3.0e6\n"),
     ["material.bulk.model", "needs a model"]),
    ("bulk-both", case_text(material=MATERIAL + 'K = 3.0e6\n[material.bulk]\nmodel = "elastic"\nK = 3.0e6\n'),
     ["material.K", "either K or [material.bulk]"]),
    ("bulk-viscosity-negative",
     case_text(material=MATERIAL + '[material.bulk]\nmodel = "kelvin_voigt"\nK = 3.0e6\neta = -1.0\n'),
     ["material.bulk.eta", "-1", "must be > 0"]),
    # a compressible layer needs K(t)/G(t) constant in time (docs/theory.md eq. L20)
    ("layer-elastic-bulk-relaxing-shear",
     case_text(material=MATERIAL + "K = 3.0e6\n", extra='[layer]\nthickness = 1.0e-3\ninterface = "bonded"\n'),
     ["material.K = 3000000", "K(t)/G(t) must be constant in time on a [layer]"]),
    ("layer-bulk-of-another-time",
     case_text(material=MATERIAL + '[material.bulk]\nmodel = "standard"\nK_inf = 3.0e6\nK1 = 6.0e6\ntau1 = 0.3\n',
               extra='[layer]\nthickness = 1.0e-3\ninterface = "bonded"\n'),
     ["material.bulk", "K(t)/G(t) must be constant in time on a [layer]"]),
    # impact
    ("impact-with-history", case_text(indenter=INDENTER + "mass = 0.03\n",
                                      load='[load]\ncontrol = "impact"\nvelocity = 1.0\n'
                                           'history = [[0.0, 0.0], [1.0, 1e-4]]\n'),
     ["load.history", "impact"]),
    ("impact-purely-viscous", case_text(material='[material]\nmodel = "viscous"\neta = 100.0\n',
                                        indenter=INDENTER + "mass = 0.01\n",
                                        load='[load]\ncontrol = "impact"\nvelocity = 0.1\n'),
     ["material.eta = 100", "purely viscous", "never rebounds"]),
    ("impact-zero-mass", case_text(indenter=INDENTER + "mass = 0.0\n",
                                   load='[load]\ncontrol = "impact"\nvelocity = 1.0\n'),
     ["indenter.mass", "= 0", "must be > 0"]),
    ("impact-missing-mass", case_text(load='[load]\ncontrol = "impact"\nvelocity = 1.0\n'),
     ["indenter.mass", "required"]),
    ("impact-negative-velocity", case_text(indenter=INDENTER + "mass = 0.03\n",
                                           load='[load]\ncontrol = "impact"\nvelocity = -1.0\n'),
     ["load.velocity", "-1", "must be > 0"]),
    ("impact-no-rebound", case_text(material='[material]\nmodel = "maxwell"\nG = 1.0e6\ntau = 1.0e-6\n',
                                    indenter=INDENTER + "mass = 0.01\n",
                                    load='[load]\ncontrol = "impact"\nvelocity = 0.1\nend = 0.01\n', numerics=""),
     ["load.end", "0.01", "not ended"]),
]


@pytest.mark.parametrize("text,fragments", [case[1:] for case in BAD_CASES], ids=[case[0] for case in BAD_CASES])
def test_run_refuses_bad_case(run_case, text, fragments):
    assert_bad_input(run_case(text), *fragments)


@pytest.mark.parametrize("case_id", ["unknown-material-key", "nan-time", "malformed-toml", "history-backwards",
                                     "profile-f-decreasing", "tangential", "impact-with-history", "elements-zero"])
def test_check_and_material_refuse_the_same_way(run_case, case_id):
    text, fragments = next(case[1:] for case in BAD_CASES if case[0] == case_id)
    run_line = run_case(text).stderr
    for command in ("check", "material"):
        result = run_case(text, command=command)
        assert_bad_input(result, *fragments)
        assert result.stderr == run_line, command


def test_enormous_element_count_is_refused_quickly(run_case):
    text = case_text(numerics="[numerics]\nelements = 1000000000000\n")
    start = time.monotonic()
    result = run_case(text, timeout=30)
    elapsed = time.monotonic() - start
    assert_bad_input(result, "numerics.elements", "1000000000000")
    assert elapsed < 10.0, f"took {elapsed:.1f} s to refuse"


def test_enormous_element_count_as_float_is_refused(run_case):
    assert_bad_input(run_case(case_text(numerics="[numerics]\nelements = 1e12\n"), timeout=30),
                     "numerics.elements", "integer >= 1")


def test_missing_case_file(run_mdr, workdir):
    result = run_mdr("run", "no-such-case.toml", "--out", workdir / "out", out=workdir / "out")
    assert_bad_input(result, "case", "no-such-case.toml", "cannot be read")
    result = run_mdr("check", "no-such-case.toml", out=workdir / "out")
    assert_bad_input(result, "case", "no-such-case.toml", "cannot be read")


@pytest.mark.parametrize("option,value,fragment", [("--times", "1,abc", "abc"), ("--times", "0.1,-1", "-1"),
                                                    ("--omegas", "1,,2", "--omegas"),
                                                    ("--omegas", "nan", "nan")])
def test_material_bad_list(run_case, option, value, fragment):
    result = run_case(case_text(), command="material", extra_args=(option, value))
    assert_bad_input(result, option, fragment)


def test_failed_run_leaves_an_earlier_result_alone(run_case, workdir):
    # A failing run must not write into DIR; an existing DIR from an earlier run keeps its content.
    good = run_case(case_text())
    assert good.returncode == 0, good.stderr
    before = sorted(p.name for p in good.out.iterdir())
    bad = run_case(case_text(material=sub(MATERIAL, "G_inf", "Ginf")))
    assert bad.returncode == 2
    assert len(bad.stderr_lines) == 1
    assert sorted(p.name for p in good.out.iterdir()) == before
    assert list(workdir.glob(".out.mdr-*")) == []


# ---------------------------------------------------------------------------------------------------------------
# The good paths


def read_csv(path: pathlib.Path) -> tuple[list[str], list[list[float]]]:
    with open(path, newline="", encoding="utf-8") as handle:
        rows = list(csv.reader(handle))
    return rows[0], [[float(x) for x in row] for row in rows[1:]]


def test_check_prints_one_ok_line(run_case):
    result = run_case(case_text(), command="check")
    assert result.returncode == 0, result.stderr
    lines = result.stdout.splitlines()
    assert len(lines) == 1 and lines[0].startswith("ok:"), result.stdout
    assert result.stderr == ""
    assert not result.out.exists()


def test_check_default_example(run_mdr):
    result = run_mdr("check", REPO_ROOT / "examples" / "default.toml")
    assert result.returncode == 0, result.stderr
    assert result.stdout.startswith("ok:") and len(result.stdout.splitlines()) == 1


@pytest.fixture(scope="module")
def default_run(mdr_binary, tmp_path_factory):
    """The bundled default case, run once into a fresh directory."""
    out = tmp_path_factory.mktemp("default") / "result"
    completed = subprocess.run([mdr_binary, "run", REPO_ROOT / "examples" / "default.toml", "--out", out],
                               capture_output=True, text=True, timeout=120)
    return completed, out


def test_run_default_example_writes_the_result_files(default_run):
    completed, out = default_run
    assert completed.returncode == 0, completed.stderr
    assert sorted(p.name for p in out.iterdir()) == [".mdr-result", "history.csv", "profiles.csv", "summary.json"]
    assert list(out.parent.glob(".*partial*")) == []

    header, rows = read_csv(out / "history.csv")
    assert header == ["t", "d", "F", "a"]
    assert len(rows) > 10 and all(len(row) == 4 for row in rows)
    assert all(math.isfinite(x) for row in rows for x in row)
    times = [row[0] for row in rows]
    assert times == sorted(times) and times[0] == 0.0 and times[-1] == pytest.approx(1.0)
    assert max(row[2] for row in rows) > 0.0

    summary = json.loads((out / "summary.json").read_text())
    for key in ("case", "max_force", "max_depth", "max_radius", "steps", "elements", "wall_seconds"):
        assert key in summary, key
    assert summary["case"] == "steel sphere on rubber: load and unload"
    assert summary["max_force"] == max(row[2] for row in rows)
    assert summary["max_depth"] == pytest.approx(2.0e-4, rel=1e-12)
    assert summary["max_radius"] == max(row[3] for row in rows)
    assert isinstance(summary["steps"], int) and summary["steps"] > 0
    assert isinstance(summary["elements"], int) and summary["elements"] > 0
    assert summary["wall_seconds"] >= 0.0

    header, rows = read_csv(out / "profiles.csv")
    assert header[:3] == ["t", "r", "p"]
    snapshot_times = sorted({row[0] for row in rows})
    assert snapshot_times == pytest.approx([0.25, 0.5, 0.6])
    assert all(row[2] >= 0.0 for row in rows)


def test_run_reports_on_stdout_only(default_run):
    completed, out = default_run
    assert str(out) in completed.stdout
    assert "mdr: error" not in completed.stderr


def test_rerun_replaces_its_own_directory_and_no_other(run_case, workdir):
    out = workdir / "out"
    result = run_case(case_text())
    assert result.returncode == 0, result.stderr
    assert sorted(p.name for p in out.iterdir()) == [".mdr-result", "history.csv", "summary.json"]
    again = run_case(case_text())
    assert again.returncode == 0, again.stderr
    assert sorted(p.name for p in out.iterdir()) == [".mdr-result", "history.csv", "summary.json"]
    assert list(workdir.glob(".out.mdr-*")) == []
    (out / "stale.txt").write_text("written by the user")
    refused = run_case(case_text())
    assert refused.returncode == 2 and "holds stale.txt, which mdr did not write" in refused.stderr
    assert (out / "stale.txt").read_text() == "written by the user"


def test_depth_never_reaching_contact_gives_zero_force(run_case):
    load = '[load]\ncontrol = "displacement"\nhistory = [[0.0, 0.0], [0.5, -1e-4], [1.0, 0.0]]\n'
    result = run_case(case_text(load=load))
    assert result.returncode == 0, result.stderr
    header, rows = read_csv(result.out / "history.csv")
    assert header == ["t", "d", "F", "a"]
    assert rows and all(row[2] == 0.0 and row[3] == 0.0 for row in rows)
    summary = json.loads((result.out / "summary.json").read_text())
    assert summary["max_force"] == 0.0 and summary["max_radius"] == 0.0


def test_material_writes_functions_and_dynamic(run_case):
    result = run_case(case_text(), command="material")
    assert result.returncode == 0, result.stderr
    header, rows = read_csv(result.out / "functions.csv")
    assert header[:3] == ["t", "G", "J"]
    assert len(rows) > 2
    header, rows = read_csv(result.out / "dynamic.csv")
    assert header == ["omega", "storage", "loss"]
    assert len(rows) > 2


def test_material_at_given_times_matches_the_standard_solid(run_case):
    G_inf, G1, tau1 = 1.0e6, 2.0e6, 0.1
    result = run_case(case_text(), command="material", extra_args=("--times", "0.01,0.1,1", "--omegas", "1,10"))
    assert result.returncode == 0, result.stderr
    header, rows = read_csv(result.out / "functions.csv")
    assert [row[0] for row in rows] == [0.01, 0.1, 1.0]
    for t, G, J in (row[:3] for row in rows):
        assert G == pytest.approx(G_inf + G1 * math.exp(-t / tau1), rel=1e-12)
        retardation = (G_inf + G1) * tau1 / G_inf
        assert J == pytest.approx((1 - G1 / (G_inf + G1) * math.exp(-t / retardation)) / G_inf, rel=1e-12)
    header, rows = read_csv(result.out / "dynamic.csv")
    assert [row[0] for row in rows] == [1.0, 10.0]
    for omega, storage, loss in rows:
        x = omega * tau1
        assert storage == pytest.approx(G_inf + G1 * x * x / (1 + x * x), rel=1e-12)
        assert loss == pytest.approx(G1 * x / (1 + x * x), rel=1e-12)


@pytest.mark.parametrize("flag", ["--version", "--help"])
def test_version_and_help(run_mdr, flag):
    result = run_mdr(flag)
    assert result.returncode == 0, result.stderr
    assert result.stdout.strip()
    if flag == "--version":
        assert result.stdout.startswith("mdr ")


@pytest.mark.parametrize("command", ["run", "check", "material"])
def test_help_on_each_command(run_mdr, command):
    result = run_mdr(command, "--help")
    assert result.returncode == 0, result.stderr
    assert command in result.stdout


def test_no_command_is_a_usage_error(run_mdr):
    result = run_mdr()
    assert result.returncode != 0
    assert result.stderr.strip()


def test_tiny_time_step_is_refused_quickly(run_case):
    # 1e12 steps over 1 s: the run would exhaust memory or never end; it must be refused at once.
    start = time.monotonic()
    result = run_case(case_text(numerics="[numerics]\ntime_step = 1e-12\n"), timeout=30)
    assert_bad_input(result, "numerics.time_step", "1e-12", "steps")
    assert time.monotonic() - start < 10.0


def test_cone_by_half_angle_matches_sneddon(run_case, workdir):
    """A cone given by its half-angle alpha (between flank and axis): the elastic force of eq. 24-25,
    F = 8 G d^2 / (pi tan(90 deg - alpha)), and the description prints both angles."""
    text = case_text(material='[material]\nmodel = "elastic"\nG = 1.0e6\n',
                     indenter='[indenter]\nshape = "cone"\nhalf_angle_deg = 70.3\n', numerics="")
    result = run_case(text)
    assert result.returncode == 0, result.stderr
    assert "cone slope_deg = 19.7 (half_angle_deg = 70.3) " in result.stdout
    summary = json.loads((workdir / "out" / "summary.json").read_text(encoding="utf-8"))
    expected = 8.0 * 1.0e6 * 1.0e-4**2 * math.tan(math.radians(70.3)) / math.pi
    assert summary["max_force"] == pytest.approx(expected, rel=1e-4)


@pytest.mark.parametrize("keys,fragments", [
    ("slope_deg = 20\nhalf_angle_deg = 70\n", ["indenter.slope_deg", "given with half_angle_deg", "one of"]),
    ("", ["indenter.slope_deg", "(missing)", "half_angle_deg"]),
    ("half_angle_deg = 0\n", ["indenter.half_angle_deg", "= 0", "must be > 0"]),
    ("half_angle_deg = 90\n", ["indenter.half_angle_deg", "= 90", "must be < 90"]),
])
def test_cone_angles_bad_input(run_case, keys, fragments):
    assert_bad_input(run_case(case_text(indenter=f'[indenter]\nshape = "cone"\n{keys}')), *fragments)
