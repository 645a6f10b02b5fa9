"""`[[fit.data]] file = "x.jpk-force"`: a fit case on an instrument file (docs/case-format.md, "Instrument
files"), checked against the same record's CSV export (examples/data/jpk_sr_cell1-0001.csv, converted from the same
member cell1-0001.jpk-force of afmformats' 10.1002_btm2.10294_fig5d-cell1.zip by a script of its own, not by mdr:
examples/data/README.md and the .json sidecar)."""

from __future__ import annotations

import json
import math
import pathlib

import pytest

from test_bad_input import assert_bad_input

REPO_ROOT = pathlib.Path(__file__).resolve().parents[2]
VENDOR = REPO_ROOT / "examples" / "data" / "vendor"
MAP = VENDOR / "fmt-jpk-fd_map-data-reference-points.jpk-force-map"

MODEL = """
[material]
model = "standard"
G_inf = 300.0
G1 = 300.0
tau1 = 1.0

[indenter]
shape = "cone"
half_angle_deg = 35.0

[fit]
free = ["material.G_inf", "material.G1", "material.tau1"]
bounds = { "material.tau1" = [1.0e-3, 300.0] }
"""

CSV_DATA = f"""
[[fit.data]]
file = "{REPO_ROOT / 'examples' / 'data' / 'jpk_sr_cell1-0001.csv'}"
time = "t_s"
piezo = "z_measured_m"
deflection = "deflection_m"
spring_constant = 1.0677
segment_column = "segment_name"
segments = ["pause", "extend"]
"""

INSTRUMENT_DATA = f"""
[[fit.data]]
file = "{VENDOR / 'cell1-0001.jpk-force'}"
segments = ["pause", "extend"]
"""


def fit(run_mdr, workdir, text, name):
    (workdir / f"{name}.toml").write_text(text)
    result = run_mdr("fit", f"{name}.toml", "--out", name, timeout=300)
    assert result.returncode == 0, result.stderr
    return json.loads((workdir / name / "fit.json").read_text())


def test_a_jpk_force_file_fits_as_its_csv_export(run_mdr, workdir):
    from_file = fit(run_mdr, workdir, MODEL + INSTRUMENT_DATA, "instrument")
    from_csv = fit(run_mdr, workdir, MODEL + CSV_DATA, "csv")
    # The CSV holds 10 significant digits of the same samples (and k = 1.0677 as the file states it).
    for key, value in from_csv["parameters"].items():
        assert math.isclose(from_file["parameters"][key], value, rel_tol=1e-6), key
    assert from_file["curves"][0]["name"] == "cell1-0001"


@pytest.mark.parametrize("data, fragments", [
    (f'file = "{MAP}"\ncurve = 3\n', ["fit.data[0].curve = 3", "must be < 3"]),
    (f'file = "{MAP}"\n', ["fit.data[0].curve", "is required", "map of 3 curves"]),
    (f'file = "{MAP}"\ncurve = -1\n', ["fit.data[0].curve = -1", "must be an integer >= 0"]),
    (f'file = "{VENDOR / "cell1-0001.jpk-force"}"\nsegments = ["hold"]\n',
     ["fit.data[0].segments = \"hold\"", "pause, extend, pause, retract"]),
    (f'file = "{VENDOR / "cell1-0001.jpk-force"}"\nspring_constant = 1.0\n',
     ["fit.data[0].spring_constant = 1:", "states its own spring constant"]),
    (f'file = "{VENDOR / "cell1-0001.jpk-force"}"\nunits = {{ length = "nm" }}\n',
     ["fit.data[0].units", "stated by the instrument file"]),
    (f'file = "{VENDOR / "fmt-afm-workshop-fd_single_2018-08-01_13.06.09.csv"}"\n',
     ["fit.data[0].spring_constant = (missing):", "records no spring constant"]),
    (f'file = "{VENDOR / "fmt-afm-workshop-fd_single_2018-08-01_13.06.09.csv"}"\nspring_constant = 0.1\n'
     'sensitivity = 50e-9\n',
     ["fit.data[0].file = \"fmt-afm-workshop-fd_single_2018-08-01_13.06.09.csv\":", "records no time",
      "a viscoelastic fit needs each row's time"]),
    (f'file = "{VENDOR / "fmt-ntmdt-txt-fd_2015_01_17_gel4-0,1_mQ_adh_6B_Curve_DFL_Height_51.txt"}"\n'
     'spring_constant = 0.055\nsensitivity = 61.0\n', ["fit.data[0].file", "records no time"]),
    (f'file = "{VENDOR / "cell1-0001.jpk-force"}"\nsensitivity = 0.0\n',
     ["fit.data[0].sensitivity = 0:", "must be > 0"]),
    (f'file = "{REPO_ROOT / "examples" / "data" / "jpk_sr_cell1-0001.csv"}"\ntime = "t_s"\nsensitivity = 1e-7\n',
     ["fit.data[0].sensitivity =", "is for an instrument file"]),
    (f'file = "{REPO_ROOT / "examples" / "data" / "jpk_sr_cell1-0001.csv"}"\ntime = "t_s"\ncurve = 0\n',
     ["fit.data[0].curve", "instrument file"]),
])
def test_instrument_data_refused_with_its_key(run_mdr, workdir, data, fragments):
    (workdir / "case.toml").write_text(MODEL + "\n[[fit.data]]\n" + data)
    result = run_mdr("fit", "case.toml", "--out", "out")
    assert_bad_input(result, *fragments)
    assert not (workdir / "out").exists()


MAP_CASE = """
[material]
model = "elastic"
G = 1000.0

[indenter]
shape = "sphere"
R = 5.0e-6

[fit]
free = ["material.G"]

[[fit.data]]
file = "map.jpk-force-map"   # replaced by --map
segments = ["extend"]
"""


def read_table(path):
    import csv
    with open(path, newline="") as table:
        return list(csv.DictReader(table))


def test_a_map_gives_one_row_per_pixel_and_its_grid(run_mdr, workdir):
    (workdir / "case.toml").write_text(MAP_CASE.replace('"SI"', '"SI"'))
    result = run_mdr("fit", "case.toml", "--map", MAP, "--out", "out", timeout=300)
    assert result.returncode in (0, 1), result.stderr
    rows = read_table(workdir / "out" / "map.csv")
    # The archive holds the pixels index/109, 129 and 416 of the 25 x 25 grid (position-index); 129 lies in an odd
    # row of the meander, so its column counts from the other side: 24 - 129 % 25 = 20.
    assert [(r["index"], r["column"], r["row"]) for r in rows] == [("0", "9", "4"), ("1", "20", "5"),
                                                                   ("2", "16", "16")]
    assert float(rows[0]["x"]) == -0.0012197656250000001  # index/109/header.properties, position.x (m)
    for row in rows:
        assert row["status"].startswith("converged"), row
        assert float(row["material.G"]) > 0 and float(row["material.G_stderr"]) > 0
        assert math.isclose(float(row["E_material.G"]), 3.0 * float(row["material.G"]), rel_tol=1e-12)  # nu = 0.5
        assert math.isfinite(float(row["contact_height"]))
        assert row["failure"] == ""
    summary = json.loads((workdir / "out" / "map.json").read_text())
    assert (summary["columns"], summary["rows"], summary["size"]) == (25, 25, [5e-4, 5e-4])  # grid.*length
    assert summary["pixel_size"] == [2e-5, 2e-5]


def test_a_pixel_without_its_data_is_a_failed_row_not_an_abort(run_mdr, workdir):
    broken = REPO_ROOT / "tests" / "data" / "instrument" / "missing-channel.jpk-force-map"
    (workdir / "case.toml").write_text(MAP_CASE)
    result = run_mdr("fit", "case.toml", "--map", broken, "--out", "out", timeout=300)
    assert result.returncode == 1, result.stderr  # written, but not every pixel converged
    rows = read_table(workdir / "out" / "map.csv")
    assert [r["status"] for r in rows][1] == "failed"
    assert "index/129/segments/1/channels/vDeflection.dat" in rows[1]["failure"]
    assert rows[0]["status"].startswith("converged") and rows[2]["status"].startswith("converged")


def test_a_map_case_with_columns_is_refused(run_mdr, workdir):
    (workdir / "case.toml").write_text(MAP_CASE.replace('segments = ["extend"]', 'time = "t"\ndepth = "d"\n'
                                                        'force = "f"'))
    result = run_mdr("fit", "case.toml", "--map", MAP, "--out", "out")
    assert_bad_input(result, "--map", "must name no column")
    assert not (workdir / "out").exists()


def test_ctrl_c_stops_a_map_and_leaves_nothing(mdr_binary, workdir):
    import signal
    import subprocess
    import sys
    import time

    # 64 copies of the vendor map's pixel 109 (scripts/make_instrument_test_files.py), fitted with a standard solid
    # on 20 000 elements: ~0.25 s of fitting each (10 s for the map on 2 threads here), where the elastic MAP_CASE
    # takes ~20 ms a pixel and could end before the interrupt.
    subprocess.run([sys.executable, REPO_ROOT / "scripts" / "make_instrument_test_files.py", "map", "64",
                    workdir / "big.jpk-force-map"], check=True, capture_output=True, timeout=120)
    slow_case = MAP_CASE.replace('model = "elastic"\nG = 1000.0', 'model = "standard"\nG_inf = 1000.0\nG1 = 1000.0\n'
                                 'tau1 = 0.01').replace('free = ["material.G"]', 'free = ["material.G_inf", '
                                                        '"material.G1", "material.tau1"]\nelements = 20000')
    assert slow_case.count("20000") == 1 and "standard" in slow_case
    (workdir / "case.toml").write_text(slow_case)
    process = subprocess.Popen([mdr_binary, "fit", "case.toml", "--map", "big.jpk-force-map", "--out", "out"],
                               cwd=workdir, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    time.sleep(2.0)
    assert process.poll() is None, "the map ended before it could be interrupted"
    process.send_signal(signal.SIGINT)
    stdout, stderr = process.communicate(timeout=60)
    assert process.returncode == 128 + signal.SIGINT
    assert stderr.replace("\r", "\n").splitlines()[-1] == "mdr: interrupted; no result was written"
    assert not (workdir / "out").exists()


def test_a_case_in_micrometres_gets_the_files_si_values_converted(run_mdr, workdir):
    # um-nN-s: lengths in µm, forces in nN, moduli in kPa (nN/µm²). The same map fitted in SI and there must give
    # the same material and positions, scaled by the units alone.
    (workdir / "si.toml").write_text(MAP_CASE)
    micro = MAP_CASE.replace("G = 1000.0", "G = 1.0").replace("R = 5.0e-6", "R = 5.0")
    (workdir / "um.toml").write_text('units = "um-nN-s"\n' + micro)
    for name in ("si", "um"):
        result = run_mdr("fit", f"{name}.toml", "--map", MAP, "--out", name, timeout=300)
        assert result.returncode == 0, result.stderr
    si, um = read_table(workdir / "si" / "map.csv"), read_table(workdir / "um" / "map.csv")
    for a, b in zip(si, um):
        assert math.isclose(float(b["x"]), float(a["x"]) * 1e6, rel_tol=1e-12)
        assert math.isclose(float(b["contact_height"]), float(a["contact_height"]) * 1e6, rel_tol=1e-6)
        assert math.isclose(float(b["material.G"]), float(a["material.G"]) * 1e-3, rel_tol=1e-5)
    assert json.loads((workdir / "um" / "map.json").read_text())["size"] == pytest.approx([500.0, 500.0], rel=1e-12)
