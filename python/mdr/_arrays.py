"""The one check of the array arguments of the mdr package: real numbers (float16/32/64 and integers become float64;
bool, complex, text and objects are refused), the dimensions asked for (never flattened), a message naming the
argument. The result is C-contiguous float64, the same array when it already is one (no copy), so the bindings
take it without a copy through Python lists (python/bindings/arrays.hpp)."""

from __future__ import annotations

from typing import Any

import numpy as np

_KIND_NAMES = {"b": "booleans", "c": "complex numbers", "U": "text", "S": "bytes", "O": "objects (None, mixed types)",
               "M": "dates", "m": "time deltas", "V": "records"}
_WANTED = {0: "a real number", 1: "a 1-D array of real numbers", 2: "a 2-D array of real numbers"}


def real_array(value: Any, key: str, *, dims: tuple[int, ...] = (1,)) -> np.ndarray:
    """`value` as a C-contiguous float64 array with one of the numbers of dimensions `dims` (0: a number).

    Raises TypeError naming `key` for a value that is not real numbers, and ValueError naming `key` and its shape
    for another number of dimensions.
    """
    wanted = " or ".join(_WANTED[n] for n in dims)
    if value is None or isinstance(value, (str, bytes)):
        raise TypeError(f"{key} = {value!r}: must be {wanted}")
    try:
        array = np.asarray(value)
    except ValueError:  # a ragged nesting, which numpy cannot make an array of
        raise ValueError(f"{key}: a ragged sequence; must be {wanted}") from None
    if array.dtype.kind not in "fiu":
        what = _KIND_NAMES.get(array.dtype.kind, "values")
        raise TypeError(f"{key}: {what} (dtype {array.dtype}); must be {wanted}")
    if array.ndim not in dims:
        shape = "a number" if array.ndim == 0 else f"a {array.ndim}-D array of shape {array.shape}"
        raise ValueError(f"{key}: {shape}; must be {wanted}" + (" (never flattened)" if array.ndim > 1 else ""))
    return array.astype(np.float64, order="C", copy=False)


def real_number(value: Any, key: str) -> float:
    """`value` as a float: a real number (a Python or numpy number, or a 0-D array), else TypeError or ValueError
    naming `key` as for `real_array`."""
    return float(real_array(value, key, dims=(0,)))
