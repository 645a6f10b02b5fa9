"""Force curves from AFM instrument files (JPK, Bruker NanoScope, Asylum, Chiaro, AFM Workshop, NT-MDT).

The readers are the C++ library's (docs/instrument-files.md); this module only gives them a Python signature.
"""

from __future__ import annotations

import os
from typing import Optional, Union

from . import _mdr
from ._mdr import Curve

__all__ = ["read_curves", "Curve"]


def read_curves(path: Union[str, os.PathLike], *, spring_constant: Optional[float] = None,
                sensitivity: Optional[float] = None) -> list[Curve]:
    """Every force curve of an instrument file, in SI units.

    Parameters
    ----------
    path : str or os.PathLike
        The file; its ending picks the format (``.jpk-force``, ``.jpk-force-map``, ``.jpk-qi-data``, ``.spm``,
        ``.ibw``, ``.txt``, ``.csv``, ``.zip``), checked against its first bytes.
    spring_constant : float, optional
        N/m, only for files that record no calibration (AFM Workshop, NT-MDT); refused for the others.
    sensitivity : float, optional
        m/V (m/A for NT-MDT), only for files that record no calibration.

    Returns
    -------
    list of mdr.Curve
        One per curve, a map's in the file's order. Each has numpy arrays ``time`` [s], ``force`` [N],
        ``height`` [m] (larger = farther from the sample), ``deflection`` [m], ``segment`` (index into
        ``segment_names``: ``"extend"``, ``"pause"``, ``"retract"``), and ``spring_constant`` [N/m],
        ``sensitivity``, ``position`` ((x, y) [m] for a curve of a map, else None), ``pixel``, ``metadata``
        (the header as the file states it), ``height_channel``, ``source``.

    Raises
    ------
    mdr.InvalidInput
        Naming the file (or ``spring_constant`` / ``sensitivity``) and what is wrong.

    Examples
    --------
    >>> curve = mdr.read_curves("examples/data/vendor/fmt-jpk-fd_spot3-0192.jpk-force")[0]
    >>> curve.segment_names, curve.force.shape, round(curve.spring_constant, 4)
    (['extend', 'retract'], (4000,), 0.0435)
    """
    return _mdr._read_curves(os.fspath(path), 0.0 if spring_constant is None else float(spring_constant),
                             0.0 if sensitivity is None else float(sensitivity))
