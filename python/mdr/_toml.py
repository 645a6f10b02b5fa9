"""Writes a case given as nested dicts as TOML text, so that dict cases go through the same parser as files."""

from __future__ import annotations

import json
import math
from typing import Any, Mapping

import numpy as np


def _value(value: Any, key: str) -> str:
    if isinstance(value, (bool, np.bool_)):
        return "true" if value else "false"
    if isinstance(value, (int, np.integer)):
        return str(int(value))
    if isinstance(value, (float, np.floating)):
        number = float(value)
        if math.isnan(number):
            return "nan"
        if math.isinf(number):
            return "inf" if number > 0 else "-inf"
        return repr(number)
    if isinstance(value, str):
        return json.dumps(value)
    if isinstance(value, np.ndarray):
        return _value(value.tolist(), key)
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(_value(item, key) for item in value) + "]"
    raise TypeError(f"{key}: unsupported value of type {type(value).__name__}")


def to_toml(case: Mapping[str, Any], prefix: str = "") -> str:
    """TOML text for a nested mapping: scalars and arrays first, then sub-tables as [a.b] headers."""
    lines = []
    tables = []
    for key, value in case.items():
        if not isinstance(key, str):
            raise TypeError(f"{prefix}{key}: keys must be strings")
        if isinstance(value, Mapping):
            tables.append((key, value))
        else:
            lines.append(f"{key} = {_value(value, prefix + key)}")
    text = "\n".join(lines) + ("\n" if lines else "")
    for key, value in tables:
        name = prefix + key
        text += f"\n[{name}]\n" + to_toml(value, name + ".")
    return text
