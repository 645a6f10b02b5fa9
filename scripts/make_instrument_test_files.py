#!/usr/bin/env python3
"""Builds bad instrument files for the readers' tests, and a large JPK map for timing, from the vendor files.

  make_instrument_test_files.py bad OUTDIR   the bad files of tests/data/instrument (a JPK map missing a channel
                                            of one pixel, a JPK archive whose member inflates to 300 MiB, an AFM
                                            Workshop mapping without its pixel 05)
  make_instrument_test_files.py map N OUT    a JPK map of N curves: the vendor map's pixel 109 copied N times on a
                                         ceil(sqrt(N))^2 grid (positions rewritten to each pixel's centre)
"""
import math
import pathlib
import sys
import zipfile

VENDOR = pathlib.Path(__file__).resolve().parent.parent / "examples" / "data" / "vendor"
VENDOR_MAP = VENDOR / "fmt-jpk-fd_map-data-reference-points.jpk-force-map"
WORKSHOP_MAP = VENDOR / "fmt-afm-workshop-fd_mapping_16_2018-08-01_13.07.zip"
GRID = "force-scan-map.position-pattern.grid."


def set_property(text, key, value):
    lines = text.splitlines()
    for number, line in enumerate(lines):
        if line.startswith(key + "="):
            lines[number] = f"{key}={value}"
            return "\n".join(lines) + "\n"
    raise KeyError(key)


def bad(outdir):
    outdir = pathlib.Path(outdir)
    with zipfile.ZipFile(VENDOR_MAP) as source, \
            zipfile.ZipFile(outdir / "missing-channel.jpk-force-map", "w", zipfile.ZIP_DEFLATED) as target:
        for info in source.infolist():
            if info.filename != "index/129/segments/1/channels/vDeflection.dat":
                target.writestr(info.filename, source.read(info.filename))
    with zipfile.ZipFile(outdir / "bomb.jpk-force", "w", zipfile.ZIP_DEFLATED, compresslevel=9) as target:
        target.writestr("header.properties", b"#" * (300 << 20))
    with zipfile.ZipFile(WORKSHOP_MAP) as source, \
            zipfile.ZipFile(outdir / "afm-workshop-missing-pixel.zip", "w", zipfile.ZIP_DEFLATED) as target:
        for info in source.infolist():
            if not info.filename.endswith("13.07.05.csv"):
                target.writestr(info.filename, source.read(info.filename))


def big_map(count, out):
    side = math.isqrt(count - 1) + 1
    with zipfile.ZipFile(VENDOR_MAP) as source, zipfile.ZipFile(out, "w", zipfile.ZIP_DEFLATED) as target:
        header = source.read("header.properties").decode("latin-1")
        length = float(header.split(GRID + "ulength=")[1].split("\n")[0])
        x0 = float(header.split(GRID + "xcenter=")[1].split("\n")[0]) - length / 2
        y0 = float(header.split(GRID + "ycenter=")[1].split("\n")[0]) - length / 2
        header = set_property(header, "force-scan-map.indexes.max", count - 1)
        header = set_property(header, GRID + "ilength", side)
        header = set_property(header, GRID + "jlength", side)
        target.writestr("header.properties", header)
        target.writestr("shared-data/header.properties", source.read("shared-data/header.properties"))
        members = [n for n in source.namelist() if n.startswith("index/109/") and not n.endswith("/")]
        series = source.read("index/109/header.properties").decode("latin-1")
        blobs = {n: source.read(n) for n in members}
        for index in range(count):
            x = x0 + (index % side + 0.5) * length / side
            y = y0 + (index // side + 0.5) * length / side
            text = set_property(series, "force-scan-series.header.position.x", repr(x))
            text = set_property(text, "force-scan-series.header.position.y", repr(y))
            text = set_property(text, "force-scan-series.header.position-index", index)
            for name in members:
                target_name = f"index/{index}/" + name[len("index/109/"):]
                target.writestr(target_name, text if name.endswith("/header.properties") and
                                name.count("/") == 2 else blobs[name])


if __name__ == "__main__":
    if sys.argv[1] == "bad":
        bad(sys.argv[2])
    else:
        big_map(int(sys.argv[2]), sys.argv[3])
