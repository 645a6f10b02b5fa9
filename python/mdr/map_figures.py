"""Heat maps of a map fit's result directory (``mdr fit CASE --map FILE --out DIR``: map.csv and map.json), drawn
by ``python3 -m mdr plot DIR``: one figure per output on the map's physical grid, axes in µm, colour bars with the
output's unit (map.json's ``column_units``, which the C++ takes from the registry that defines each key), failed
pixels crossed and pixels whose fit did not converge marked."""

from __future__ import annotations

import json
import os

import numpy as np

#: The columns of map.csv that are not drawn: the pixel's place and its text. The ``_stderr`` columns are not drawn
#: either (beside their values they would double the figures; they are in map.csv).
NOT_DRAWN = ("index", "column", "row", "x", "y", "status", "flags", "failure")


def is_result(status):
    """Whether a fit's `status` (a str, or an array of them: True per entry) is a result: "converged", or
    "converged, misfit" (its flag says so); any other status says why the fit stopped short, where its values are not
    a result."""
    return np.char.startswith(np.asarray(status, dtype=str), "converged")


def map_heat_maps(directory: str) -> list[tuple[str, object]]:
    """The heat maps of the map fit in `directory`: ``[(name, figure)]``, one per drawn column of map.csv (every
    free key, ``E_`` key, ``contact_height``, ``residual_to_noise``, ``noise``; NOT_DRAWN and ``_stderr`` columns
    left out). Each pixel is drawn where its ``column`` and ``row`` put it on the grid of map.json; the axes are
    the positions in µm (the pixel centres taken from map.csv's x, y); a pixel the file lacks is left white, a
    failed pixel is marked with a red cross where its place is known (a curve that could not be read has none:
    the title counts every failed pixel), and a pixel whose fit stopped without converging (its ``status`` says
    why; its values are where the fit stopped, not a result) with an orange plus over its colour, counted in the
    title as "not converged"."""
    from matplotlib.figure import Figure  # no pyplot: no GUI backend, safe in any thread
    from .plot import read_csv

    table = read_csv(os.path.join(directory, "map.csv"))
    with open(os.path.join(directory, "map.json"), encoding="utf-8") as handle:
        summary = json.load(handle)
    units = summary.get("column_units", {})
    columns, rows = max(int(summary["columns"]), 1), max(int(summary["rows"]), 1)
    to_um = float(summary.get("length_size", 1.0)) * 1e6
    pixel_x, pixel_y = (float(p) * to_um for p in summary["pixel_size"])
    def numbers(values) -> np.ndarray:  # an empty field (a value the pixel lacks) is NaN
        return np.array([float(v) if str(v) != "" else np.nan for v in values], dtype=float)

    placed = np.isfinite(numbers(table["column"]))  # a pixel whose curve could not be read has no place
    column_index = np.nan_to_num(numbers(table["column"])).astype(int)[placed]
    row_index = np.nan_to_num(numbers(table["row"])).astype(int)[placed]
    x, y = numbers(table["x"])[placed] * to_um, numbers(table["y"])[placed] * to_um
    # The grid's low corner from the pixels' centres (every pixel gives the same one, up to rounding).
    x0 = float(np.median(x - column_index * pixel_x)) if pixel_x > 0 else 0.0
    y0 = float(np.median(y - row_index * pixel_y)) if pixel_y > 0 else 0.0
    extent = (x0 - pixel_x / 2, x0 + (columns - 0.5) * pixel_x, y0 - pixel_y / 2, y0 + (rows - 0.5) * pixel_y) \
        if pixel_x > 0 and pixel_y > 0 else None
    status = np.asarray(table["status"])
    all_failed = status == "failed"
    failed = all_failed[placed]
    stopped = ~all_failed & ~is_result(status)
    figures = []
    for name, values in table.items():
        if name in NOT_DRAWN or name.endswith("_stderr"):
            continue
        grid = np.full((rows, columns), np.nan)
        grid[row_index, column_index] = numbers(values)[placed]
        figure = Figure(figsize=(5.5, 4.5))
        axes = figure.add_subplot()
        image = axes.imshow(np.ma.masked_invalid(grid), origin="lower", interpolation="nearest", cmap="viridis",
                            extent=extent)
        unit = units.get(name, "")  # "1": a ratio or an exponent, drawn without a unit
        figure.colorbar(image, ax=axes, label=f"{name} [{unit}]" if unit not in ("", "1") else name)
        mark_pixels(axes, x if extent else column_index, y if extent else row_index, failed, stopped[placed])
        drawn = np.count_nonzero(np.isfinite(grid))
        short = f", {int(stopped.sum())} not converged" if stopped.any() else ""
        axes.set(xlabel="x [µm]" if extent else "column", ylabel="y [µm]" if extent else "row",
                 title=f"{name} ({drawn} of {rows * columns} pixels, {int(all_failed.sum())} failed{short})")
        figure.tight_layout()
        figures.append((name, figure))
    return figures


def mark_pixels(axes, x: np.ndarray, y: np.ndarray, failed: np.ndarray, not_converged: np.ndarray) -> None:
    """Marks the pixels that are no results on the heat map `axes`, as every heat map of mdr does (map_heat_maps,
    mdr.curve_maps.heat_map): a red cross where `failed` (no values), an orange plus where `not_converged` (the
    values where the fit stopped), at the pixels' `x`, `y` (arrays, one entry a pixel, like the two masks), with a
    legend when any pixel is marked."""
    for where, marker, colour, label in ((failed, "x", "red", "failed"), (not_converged, "+", "orange",
                                                                           "not converged")):
        if where.any():
            axes.scatter(x[where], y[where], marker=marker, color=colour, s=30, label=label)
    if failed.any() or not_converged.any():
        axes.legend(loc="upper right", fontsize="small")
