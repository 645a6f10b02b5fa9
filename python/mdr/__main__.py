"""python3 -m mdr plot DIR: turns a result directory into PNG figures beside its CSV files."""

from __future__ import annotations

import argparse
import sys

from . import plot


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python3 -m mdr", description=__doc__)
    commands = parser.add_subparsers(dest="command", required=True)
    plot_command = commands.add_parser("plot", help="write PNG figures for a result directory")
    plot_command.add_argument("directory")
    args = parser.parse_args(argv)
    try:
        written = plot.plot_directory(args.directory)
    except (OSError, ValueError) as error:
        print(f"mdr plot: error: {error}", file=sys.stderr)
        return 2
    for path in written:
        print(path)
    return 0


if __name__ == "__main__":
    sys.exit(main())
