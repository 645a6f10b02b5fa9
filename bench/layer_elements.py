#!/usr/bin/python3
"""A layer's `[numerics] elements`: force-controlled cases on a layer at default numerics and at 48 to 400 elements,
CPU per run.

    bench/layer_elements.py MDR [MDR ...] [--runs 3] [--elements 48,100,200,400]

Two cases of tests/verification (a standard solid with a parallel dashpot, a sphere, bonded incompressible layers):
`reload`, a thick layer's creep-recovery with a ride at zero force and a reload (test_layer_regrowing_dashpot.cpp,
TheReloadAfterARideIsSecondOrderInTheTimeStep: the run of Ting's class finds the regrowth at 1.5 s and the cells run
the case again from the start, `elements` setting both the Gauss nodes and the cells), and `creep`, a creep-recovery
on 3 µm that stays in Ting's class (test_layer_gauss_nodes.cpp: `elements` sets the Gauss nodes alone). Each binary
runs each case and count `--runs` times, interleaved (binary by binary, case by case, so that a change of the host's
load hits all alike); the CPU time of the children (user + system, program start included) is reported per run.
docs/performance.md, "A layer's `elements`", records the results.
"""
import argparse
import pathlib
import resource
import subprocess
import tempfile

MATERIAL = '[material]\nmodel = "prony"\n'
CASES = {
    "reload": MATERIAL + """G_inf = 1.0e3
terms = [[3.0e3, 0.2]]
eta = 50.0
[indenter]
shape = "sphere"
R = 1.0e-5
[load]
control = "force"
history = [[0.0, 0.0], [0.5, 3.0e-8], [1.0, 0.0], [1.5, 0.0], [2.0, 2.0e-8]]
[layer]
thickness = 1.0e3
interface = "bonded"
""",
    "creep": 'units = "um-nN-s"\n' + MATERIAL + """G_inf = 0.3
terms = [[0.7, 1.0]]
eta = 0.05
[indenter]
shape = "sphere"
R = 5.0
[load]
control = "force"
history = [[0.0, 0.0], [0.5, 2.0], [5.0, 2.0], [5.5, 0.0], [8.0, 0.0]]
[layer]
thickness = 3.0
interface = "bonded"
""",
}


def cpu_seconds():
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("binaries", nargs="+", help="mdr binaries to compare")
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--elements", default="48,100,200,400", help="comma-separated counts (besides the default)")
    args = parser.parse_args()
    counts = [None] + [int(count) for count in args.elements.split(",")]
    with tempfile.TemporaryDirectory() as work:
        cases = {}
        for name, text in CASES.items():
            for count in counts:
                numerics = "" if count is None else f"[numerics]\nelements = {count}\n"
                path = pathlib.Path(work) / f"{name}_{count or 'default'}.toml"
                path.write_text(text + numerics)
                cases[name, count] = path
        seconds = {(binary, key): 0.0 for binary in args.binaries for key in cases}
        for _ in range(args.runs):
            for binary in args.binaries:
                for key, path in cases.items():
                    out = pathlib.Path(work) / "out"
                    before = cpu_seconds()
                    subprocess.run([binary, "run", str(path), "-o", str(out)], check=True, capture_output=True)
                    seconds[binary, key] += cpu_seconds() - before
        for binary in args.binaries:
            for (name, count) in cases:
                label = "default" if count is None else f"elements = {count}"
                print(f"{binary}\t{name}\t{label}\t{seconds[binary, (name, count)] / args.runs:.3f} s")


if __name__ == "__main__":
    main()
