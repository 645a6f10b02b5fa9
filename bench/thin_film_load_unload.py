#!/usr/bin/python3
"""Issue 28's thin films: a load-unload of a colloidal probe on bonded layers against the half-space, CPU per run.

    bench/thin_film_load_unload.py MDR [MDR ...] [--runs 5]

A Prony body (G_inf = 300 Pa, two branches), sphere R = 500 µm, ramp to d = 0.2 µm in 1 s, hold to 2 s, unload to 0
at 3 s (default numerics), on bonded incompressible layers h = 2, 1, 0.5, 0.305 µm (a/h up to 9, 19, 39, 64; the
thinnest a run accepts: its widest prepared contact, 3 half-space radii, is 98 thicknesses) and on the half-space.
Each binary runs each case `--runs` times, interleaved (binary by binary, case by case, so that a change of the
host's load hits all alike); the CPU time of the children (user + system, program start included) is
reported per run with its ratio to the half-space of the same binary. docs/performance.md, "A layer of finite
thickness", records the results.
"""
import argparse
import pathlib
import resource
import subprocess
import tempfile

CASE = """title = "colloidal probe on a thin film"
[material]
model = "prony"
G_inf = 300.0
terms = [[700.0, 0.1], [400.0, 1.0]]
[indenter]
shape = "sphere"
R = 500e-6
[load]
control = "displacement"
history = [[0.0, 0.0], [1.0, 0.2e-6], [2.0, 0.2e-6], [3.0, 0.0]]
"""
LAYERS = {"half-space": None, "h = 2 µm": 2e-6, "h = 1 µm": 1e-6, "h = 0.5 µm": 0.5e-6, "h = 0.305 µm": 0.305e-6}


def cpu_seconds():
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("binaries", nargs="+", help="mdr binaries to compare")
    parser.add_argument("--runs", type=int, default=5)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as work:
        cases = {}
        for name, thickness in LAYERS.items():
            text = CASE + ("" if thickness is None else f'[layer]\nthickness = {thickness!r}\ninterface = "bonded"\n')
            path = pathlib.Path(work) / f"case{len(cases)}.toml"
            path.write_text(text)
            cases[name] = path
        seconds = {(binary, name): 0.0 for binary in args.binaries for name in cases}
        for _ in range(args.runs):
            for binary in args.binaries:
                for name, path in cases.items():
                    out = pathlib.Path(work) / "out"
                    before = cpu_seconds()
                    subprocess.run([binary, "run", str(path), "-o", str(out)], check=True, capture_output=True)
                    seconds[binary, name] += cpu_seconds() - before
        for binary in args.binaries:
            half_space = seconds[binary, "half-space"]
            for name in cases:
                per_run = seconds[binary, name] / args.runs
                print(f"{binary}\t{name}\t{per_run:.3f} s\t{seconds[binary, name] / half_space:.1f}x")


if __name__ == "__main__":
    main()
