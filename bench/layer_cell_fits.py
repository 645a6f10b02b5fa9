#!/usr/bin/python3
"""Fits on a layer's cells (issue 28: "a fit of a 2 000-point curve on a layer within 1 s"): the curves that the fast
Ting-class layer model cannot take run `drivers::LayerCells` from the start (docs/theory.md, "Fits on a layer").
Two 2001-point records made by `mdr run` on a bonded layer (standard solid G_inf = 1 kPa, G1 = 3 kPa, tau1 = 0.2 s,
sphere R = 10 um, h = 2 um): a load-unload-reload under displacement control (1 um, back to 0.4 um, to 1 um, unload;
the force fitted) and a creep under force control (30 nN held 1.5 s, then 10 nN held; the depth fitted), each fitted
with G_inf, G1, tau1 free from starts 2x, 1.5x, 2x off, then with h free too (from 1.5x). CPU time of each `mdr fit`
process (getrusage of the children), its fit.json's wall time, iterations and model runs.
Usage: bench/layer_cell_fits.py [mdr ...] [--rounds N] [--json results.json]   (several binaries alternate in each
round, so that builds compare under the same load, and each fitted value is compared with the first binary's;
results.json: every fit.json by binary, record and round)
"""
from __future__ import annotations

import argparse
import json
import pathlib
import resource
import subprocess
import tempfile

ROOT = pathlib.Path(__file__).resolve().parent.parent
BODY = """
[material]
model = "standard"
G_inf = {G_inf}
G1 = {G1}
tau1 = {tau1}
[indenter]
shape = "sphere"
R = 1.0e-5
[layer]
thickness = {thickness}
interface = "bonded"
"""
TRUTH = {"G_inf": 1.0e3, "G1": 3.0e3, "tau1": 0.2, "thickness": 2.0e-6}
START = {"G_inf": 2.0e3, "G1": 2.0e3, "tau1": 0.4}
RECORDS = {
    "reload": ('control = "displacement"\n'
               "history = [[0.0, 0.0], [1.0, 1.0e-6], [1.5, 0.4e-6], [2.5, 1.0e-6], [3.0, 0.0]]", "force"),
    "creep": ('control = "force"\n'
              "history = [[0.0, 0.0], [0.01, 3.0e-8], [1.5, 3.0e-8], [1.51, 1.0e-8], [3.0, 1.0e-8]]", "depth"),
}
FREE = ["material.G_inf", "material.G1", "material.tau1"]


def mdr(binary: str, *arguments) -> float:
    """Runs mdr, returns its CPU time [s]."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run([binary, *map(str, arguments)], check=True, stdout=subprocess.DEVNULL)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return after.ru_utime - before.ru_utime + after.ru_stime - before.ru_stime


def make_record(binary: str, name: str, folder: pathlib.Path) -> pathlib.Path:
    load, _ = RECORDS[name]
    case = folder / f"{name}-truth.toml"
    case.write_text(BODY.format(**TRUTH) + f"[load]\n{load}\n[numerics]\ntime_step = 1.5e-3\n")
    mdr(binary, "run", case, "--out", folder / f"{name}-data")
    return folder / f"{name}-data" / "history.csv"


def fit(binary: str, name: str, thickness_free: bool, record: pathlib.Path, folder: pathlib.Path) -> dict:
    _, fitted = RECORDS[name]
    free = FREE + (["layer.thickness"] if thickness_free else [])
    start = dict(TRUTH, **START, thickness=3.0e-6 if thickness_free else TRUTH["thickness"])
    case = folder / "case.toml"
    case.write_text(BODY.format(**start) + f'[fit]\nfree = {json.dumps(free)}\ncontact_point = "fixed"\n'
                    f'baseline = "fixed"\nfitted = "{fitted}"\n[[fit.data]]\nfile = "{record}"\n'
                    'time = "t"\ndepth = "d"\nforce = "F"\nuntil = "end"\n')
    cpu = mdr(binary, "fit", case, "--out", folder / "out")
    summary = json.loads((folder / "out" / "fit.json").read_text())
    summary["cpu_seconds"] = cpu
    return summary


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("binaries", nargs="*", default=[str(ROOT / "build" / "bin" / "mdr")])
    parser.add_argument("--rounds", type=int, default=1)
    parser.add_argument("--json")
    options = parser.parse_args()
    results: dict = {}
    print(f"{'binary':<28} {'record':<7} {'h':<5} {'round':>5} {'cpu s':>6} {'wall s':>6} {'iter':>4} {'runs':>4} "
          "status")
    with tempfile.TemporaryDirectory() as scratch:
        folder = pathlib.Path(scratch)
        records = {name: make_record(options.binaries[0], name, folder) for name in RECORDS}
        for round_index in range(options.rounds):
            for name in RECORDS:
                for thickness_free in (False, True):
                    for binary in options.binaries:
                        summary = fit(binary, name, thickness_free, records[name], folder)
                        label = "free" if thickness_free else "fixed"
                        results.setdefault(binary, {}).setdefault(f"{name}/{label}", []).append(summary)
                        print(f"{binary[-28:]:<28} {name:<7} {label:<5} {round_index:5d} "
                              f"{summary['cpu_seconds']:6.2f} {summary['wall_seconds']:6.2f} "
                              f"{summary['iterations']:4d} {summary['evaluations']:4d} {summary['status']}",
                              flush=True)
    first = options.binaries[0]
    for binary in options.binaries[1:]:  # the fitted values against the first binary's, fit by fit
        for fit_name, summaries in results[binary].items():
            difference = max(abs(summary["parameters"][key] / reference["parameters"][key] - 1.0)
                             for summary, reference in zip(summaries, results[first][fit_name])
                             for key in summary["parameters"])
            print(f"{binary[-28:]:<28} {fit_name:<13} largest relative difference of a fitted value from "
                  f"{first[-28:]}: {difference:.1e}")
    if options.json:
        pathlib.Path(options.json).write_text(json.dumps(results, indent=1))


if __name__ == "__main__":
    main()
