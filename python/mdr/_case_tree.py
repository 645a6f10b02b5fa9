"""A case given as nested dicts as the plain tree that the bindings read without text (python/bindings/case_tree.*,
the same readers and messages as a case file): numpy values become Python numbers and lists, `mdr.Material` and
`mdr.Indenter` objects their tables."""

from __future__ import annotations

from typing import Any, Mapping

import numpy as np

from ._mdr import Indenter, Material


def material_table(material: Material) -> dict[str, Any]:
    """The `[material]` table of a Material: for an `mdr.ConvertedMaterial` the model it was built from (its name,
    parameters and tolerance), which the case converts again over its own window and harmonic frequencies, exactly
    as the same table given as a dict; else its named model where one fits (elastic, viscous, kelvin_voigt), else
    a Prony series (with its parallel dashpot `eta` where it has one)."""
    if material._definition is not None:
        return material._definition
    terms = [[modulus, time] for modulus, time in material.terms]
    if not terms:
        if material.eta == 0.0:
            return {"model": "elastic", "G": material.G_inf}
        if material.G_inf == 0.0:
            return {"model": "viscous", "eta": material.eta}
        return {"model": "kelvin_voigt", "G": material.G_inf, "eta": material.eta}
    table = {"model": "prony", "G_inf": material.G_inf, "terms": terms}
    if material.eta > 0.0:
        table["eta"] = material.eta
    return table


def _plain(value: Any, key: str) -> Any:
    if isinstance(value, Material):
        return material_table(value)
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
