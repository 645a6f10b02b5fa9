"""A case given as nested dicts as the plain tree that the bindings read without text (python/bindings/case_tree.*,
the same readers and messages as a case file): numpy values become Python numbers and lists, `mdr.Material` and
`mdr.Indenter` objects their tables."""

from __future__ import annotations

from typing import Any, Mapping

import numpy as np

from ._mdr import Indenter, Material, _material_table


def _plain(value: Any, key: str) -> Any:
    if isinstance(value, Material):
        return _plain(_material_table(value), key)  # its model's table, or the series as its own model
    if isinstance(value, Indenter):
        return value.table
    if isinstance(value, Mapping):
        for name in value:
            if not isinstance(name, str):
                raise TypeError(f"{key}{name!r}: keys must be strings")
        return {name: _plain(item, f"{key}{name}.") for name, item in value.items()}
    if isinstance(value, (bool, np.bool_)):
        return bool(value)
    if isinstance(value, (int, np.integer)):
        return int(value)
    if isinstance(value, (float, np.floating)):
        return float(value)
    if isinstance(value, str):
        return value
    if isinstance(value, np.ndarray):
        return _plain(value.tolist(), key)
    if isinstance(value, (list, tuple)):
        return [_plain(item, key) for item in value]
    raise TypeError(f"{key.rstrip('.')}: unsupported value of type {type(value).__name__}")


def plain_tree(case: Mapping[str, Any]) -> dict[str, Any]:
    """The case given as a nested mapping as dicts, lists, bool, int, float and str only."""
    return _plain(case, "")
