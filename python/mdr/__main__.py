"""python3 -m mdr plot DIR: turns a result directory into PNG figures beside its CSV files."""

from __future__ import annotations

import argparse
import os
import sys


def main(argv: list[str] | None = None) -> int:
    """The command line of the package; returns the exit status (2 for bad input)."""
    import matplotlib

    if "MPLBACKEND" not in os.environ:
        matplotlib.use("Agg")  # files only: no window, no display needed
    from . import maps, plot

    parser = argparse.ArgumentParser(prog="python3 -m mdr", description=__doc__)
    commands = parser.add_subparsers(dest="command", required=True)
    plot_command = commands.add_parser("plot", help="write PNG figures for a result directory")
    plot_command.add_argument("directory")
    plot_command.add_argument("--column", help="the column of sweep.csv that sweep.png plots (default: restitution "
                                               "for impacts, else max_force)")
    range_command = commands.add_parser("p1-range", help="tau1 bounds START:STOP giving p1 from P1_MIN to P1_MAX")
    range_command.add_argument("case")
    range_command.add_argument("p1_min", type=float)
    range_command.add_argument("p1_max", type=float)
    map_command = commands.add_parser("restitution-map", help="the figure of e over p1 from a sweep directory")
    map_command.add_argument("directory")
    map_command.add_argument("case")
    map_command.add_argument("--out", required=True)
    args = parser.parse_args(argv)
    try:
        if args.command == "plot":
            for path in plot.plot_directory(args.directory, column=args.column):
                print(path)
        elif args.command == "p1-range":
            scale = maps.p1_scale(maps.read_case(args.case))
            print(f"{args.p1_min / scale!r}:{args.p1_max / scale!r}")
        else:
            sweep = plot.read_csv(os.path.join(args.directory, "sweep.csv"))
            axes = maps.restitution_map(sweep, maps.read_case(args.case))
            print(plot.save(axes, args.out))
    except (OSError, ValueError, KeyError) as error:
        print(f"mdr {args.command}: error: {error}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
