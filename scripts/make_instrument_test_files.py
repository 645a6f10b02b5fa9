#!/usr/bin/env python3
"""Builds bad instrument files for the readers' tests, and a large JPK map for timing, from the vendor files.

  make_instrument_test_files.py bad OUTDIR   the bad files of tests/data/instrument (a JPK map missing a channel
                                            of one pixel, a JPK archive whose member inflates to 300 MiB, an AFM
                                            Workshop mapping without its pixel 05)
  make_instrument_test_files.py map N OUT    a JPK map of N curves: the vendor map's pixel 109 copied N times on a
                                         ceil(sqrt(N))^2 grid (positions rewritten to each pixel's centre)
  make_instrument_test_files.py forcevolume COLUMNS ROWS OUT
                                            a Bruker NanoScope force volume of COLUMNS x ROWS curves from the vendor
                                            single curve, by the layout docs/instrument-files.md documents: the
                                            height image (pixel k holds k), then curve k (the vendor curve's stored
                                            integers times k + 1), one after the other
"""
import math
import pathlib
import struct
import sys
import zipfile

VENDOR = pathlib.Path(__file__).resolve().parent.parent / "examples" / "data" / "vendor"
VENDOR_MAP = VENDOR / "fmt-jpk-fd_map-data-reference-points.jpk-force-map"
WORKSHOP_MAP = VENDOR / "fmt-afm-workshop-fd_mapping_16_2018-08-01_13.07.zip"
VENDOR_SPM = VENDOR / "20200904_Egel4-Z1.0_00025.spm"
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


def replaced_once(text, old, new):
    if old not in text:
        raise KeyError(old)
    return text.replace(old, new, 1)


def force_volume(columns, rows, out):
    """The vendor single curve's header made a force volume (NanoScope 9.2: 4-byte integers): `Start context` FVOL
    and `Operating mode` Force Volume, the scan list's `Samps/line` and the force list's `force/line` = columns, the
    scan list's `Lines` = rows, a `*Ciao image list` (the height image, which the Bruker help's "Force Volume Image
    File Format" puts first) of columns x rows pixels, then the curves, each as the vendor's: 1024 extend integers
    stored from the turnaround back, then 1024 retract integers."""
    vendor = VENDOR_SPM.read_bytes()
    data_offset = 80960  # the vendor's header length (`\Data length` of the file list) and data offset
    curve_bytes = 8192
    end = b"\\*File list end\r\n"
    header = vendor[:vendor.index(end)].decode("latin-1")
    curves = columns * rows
    image_bytes = 4 * curves
    header = replaced_once(header, "\\Start context: FOL\r\n", "\\Start context: FVOL\r\n")
    header = replaced_once(header, "\\Operating mode: Force\r\n", "\\Operating mode: Force Volume\r\n")
    header = replaced_once(header, "\\Samps/line: 256\r\n", f"\\Samps/line: {columns}\r\n")
    header = replaced_once(header, "\\Lines: 256\r\n", f"\\Lines: {rows}\r\n")
    header = replaced_once(header, "\\force/line: 16\r\n", f"\\force/line: {columns}\r\n")
    header = replaced_once(header, "\\Data offset: 80960\r\n", f"\\Data offset: {data_offset + image_bytes}\r\n")
    header = replaced_once(header, "\\Data length: 8192\r\n", f"\\Data length: {curves * curve_bytes}\r\n")
    image_list = (f"\\*Ciao image list\r\n\\Data offset: {data_offset}\r\n\\Data length: {image_bytes}\r\n"
                  f"\\Bytes/pixel: 4\r\n\\Samps/line: {columns}\r\n\\Number of lines: {rows}\r\n"
                  "\\Scan Size: 2000 2000 nm\r\n\\@2:Image Data: S [Height] \"Height\"\r\n")
    header = replaced_once(header, "\\*Ciao force image list\r\n", image_list + "\\*Ciao force image list\r\n")
    head = (header.encode("latin-1") + end + b"\x1a").ljust(data_offset, b"\0")
    if len(head) != data_offset:
        raise ValueError("the header outgrew the vendor's data offset")
    stored = struct.unpack_from("<2048i", vendor, data_offset)
    image = struct.pack(f"<{curves}i", *range(curves))
    data = b"".join(struct.pack("<2048i", *(value * (k + 1) for value in stored)) for k in range(curves))
    pathlib.Path(out).write_bytes(head + image + data)


if __name__ == "__main__":
    if sys.argv[1] == "bad":
        bad(sys.argv[2])
    elif sys.argv[1] == "forcevolume":
        force_volume(int(sys.argv[2]), int(sys.argv[3]), sys.argv[4])
    else:
        big_map(int(sys.argv[2]), sys.argv[3])
