"""What every result type shares: conversion to SI units (:meth:`to_si`), a table
(:meth:`to_dataframe`, pandas imported only then) and a short repr.

A result names its per-point arrays (``_columns``) and its coordinates; the table
:data:`SI_FIELDS` says how each dimensionless quantity becomes an SI one, with the scales
of :class:`~wavyadhesion.Scales`: loads P* times p* [Pa] and times p* L [N/m], widths and
positions times L [m], mean gaps and gaps times Delta [m], energies per area times
p* Delta [J/m^2], slopes dP*/dgbar* times p*/Delta [Pa/m], tractions times p* [Pa].
"""

from __future__ import annotations

from typing import Any, Dict, Iterator, Tuple

import numpy as np

from ._errors import INVALID_ARGUMENT, InvalidArgumentError, InvalidTypeError

__all__ = ["SIValues", "SI_FIELDS", "ResultMixin"]

# (SI name, attribute of Scales giving the factor, unit) for each dimensionless field
SI_FIELDS: Dict[str, Tuple[Tuple[str, str, str], ...]] = {
    "P_star": (("P", "pressure", "Pa"), ("F", "force", "N/m")),
    "a_star": (("a", "length", "m"),),
    "c_star": (("c", "length", "m"),),
    "b_star": (("b", "length", "m"),),
    "x": (("x", "length", "m"),),
    "traction": (("traction", "pressure", "Pa"),),
    "gap": (("gap", "amplitude", "m"),),
    "W_star": (("W", "energy", "J/m^2"),),
    "jump_energy": (("jump_energy", "energy", "J/m^2"),),
    "dPdg_approach": (("dPdg_approach", "stiffness", "Pa/m"),),
    "dPdg_retract": (("dPdg_retract", "stiffness", "Pa/m"),),
}
for _name in ("P_fc", "P_pf", "P_snap", "P_fc_err", "P_pf_err", "P_snap_err", "P_approach",
              "P_retract", "P_jump_in", "P_min",
              "P_contact_lost"):
    SI_FIELDS[_name] = ((_name, "pressure", "Pa"), ("F" + _name[1:], "force", "N/m"))
for _name in ("a_jump_in", "a_P_min"):
    SI_FIELDS[_name] = ((_name, "length", "m"),)
SI_FIELDS["W_star_err"] = (("W_err", "energy", "J/m^2"),)
for _name in ("gbar", "h_min", "h_max", "g_touch", "g_contact", "g_P_min", "g_contact_lost",
              "g_interaction_lost"):
    SI_FIELDS[_name] = ((_name, "amplitude", "m"),)

#: Longest repr of a result (characters)
_REPR_MAX = 300


def _scales_of(params):
    """The Scales of `params` (a Params made by from_dimensional, or a Scales)."""
    scales = getattr(params, "scales", params)
    if scales is None:
        raise InvalidArgumentError(
            "params has no SI scales: make it with Params.from_dimensional(...) (or pass "
            "a Scales)", INVALID_ARGUMENT)
    if not all(hasattr(scales, k) for k in ("pressure", "force", "length", "amplitude",
                                            "energy")):
        raise InvalidTypeError(f"params must be a Params with scales or a Scales, got "
                               f"{type(params).__name__}", INVALID_ARGUMENT)
    return scales


def _summary(value) -> str:
    """A value in a few characters: a number, or an array's size and range."""
    if isinstance(value, (str, int, np.integer)):
        return repr(value) if isinstance(value, str) else str(int(value))
    arr = np.asarray(value)
    if arr.ndim == 0:
        return f"{float(arr):.6g}" if arr.dtype.kind == "f" else str(arr)
    if arr.size == 0:
        return "[]"
    if arr.size == 1:
        return _summary(arr.reshape(-1)[0])
    if arr.dtype.kind == "f":
        with np.errstate(invalid="ignore"):
            finite = arr[np.isfinite(arr)]
        if finite.size and finite.min() == finite.max() == arr.reshape(-1)[0]:
            return f"{'x'.join(map(str, arr.shape))} of {finite.min():.6g}"
        rng = f"{finite.min():.4g}..{finite.max():.4g}" if finite.size else "nan"
        return f"{'x'.join(map(str, arr.shape))} in [{rng}]"
    return f"{'x'.join(map(str, arr.shape))} values"


class SIValues:
    """Quantities in SI units, from a result's :meth:`to_si`: attributes (and ``[name]``)
    hold the values, ``units[name]`` the unit ("1" dimensionless, "" a code or label).

    Loads come twice: as the mean traction in Pa (``P``, ``P_fc``, ...) and as the force
    per period and unit depth in N/m (``F``, ``F_fc``, ...).
    """

    def __init__(self, kind: str, values: Dict[str, Any], units: Dict[str, str]):
        object.__setattr__(self, "kind", kind)
        object.__setattr__(self, "values", dict(values))
        object.__setattr__(self, "units", dict(units))

    def __getattr__(self, name: str) -> Any:
        try:
            return self.__dict__["values"][name]
        except KeyError:
            raise AttributeError(name) from None

    def __setattr__(self, name, value):
        raise AttributeError("SIValues is read-only")

    def __getitem__(self, name: str) -> Any:
        return self.values[name]

    def __iter__(self) -> Iterator[str]:
        return iter(self.values)

    def __dir__(self):
        return list(super().__dir__()) + list(self.values)

    def __repr__(self) -> str:
        parts = [f"{k} [{u}]" for k, u in self.units.items() if u not in ("", "1")]
        return _clip(f"SIValues({self.kind}: {', '.join(parts)})")

    def to_dataframe(self):
        """A pandas DataFrame, columns named ``"name [unit]"`` (per-point values only)."""
        pd = _pandas()
        n = _rows(self.values.values())
        cols = {}
        for k, v in self.values.items():
            if k == "messages":
                continue
            arr = np.asarray(v)
            unit = self.units.get(k, "")
            label = f"{k} [{unit}]" if unit and unit != "1" else k
            if arr.size == n:
                cols[label] = arr.reshape(-1)
            elif arr.ndim == 0:
                cols[label] = np.repeat(arr, n)
        return pd.DataFrame(cols)


def _rows(values) -> int:
    """The number of rows of a table: the largest array size among `values`."""
    return max((np.size(v) for v in values if not isinstance(v, (str, dict))), default=0)


def _clip(text: str) -> str:
    return text if len(text) <= _REPR_MAX else text[:_REPR_MAX - 4] + "...)"


def _pandas():
    try:
        import pandas as pd
    except ImportError:            # optional: only to_dataframe needs it
        raise ImportError("to_dataframe() needs pandas: pip install pandas") from None
    return pd


class ResultMixin:
    """to_si, to_dataframe and a short repr for a result type.

    A subclass lists ``_columns`` (its per-point arrays, table columns in this order),
    ``_coordinates`` (its inputs: model, alpha, mu, ... repeated as columns when scalar)
    and ``_repr_fields`` (what its repr shows).
    """

    _columns: Tuple[str, ...] = ()
    _coordinates: Tuple[str, ...] = ("model", "alpha", "mu")
    _repr_fields: Tuple[str, ...] = ()

    def _field_items(self):
        for name in self._coordinates + self._columns:
            value = getattr(self, name, None)
            if value is not None:
                yield name, value

    def to_dataframe(self):
        """The result as a pandas DataFrame, one row per point (pandas is imported only
        here). Scalar coordinates (model, alpha, mu) are repeated in every row; a failed
        point's message is in the column ``message``."""
        pd = _pandas()
        items = dict(self._field_items())
        n = _rows(v for k, v in items.items() if k in self._columns)
        cols = {}
        for k, v in items.items():
            arr = np.asarray(v)
            if arr.ndim == 0 or isinstance(v, str):
                cols[k] = np.repeat(arr, n)
            elif arr.size == n:
                cols[k] = arr.reshape(-1)
        messages = getattr(self, "messages", None)
        if isinstance(messages, dict) and n:
            text = np.full(n, "", dtype=object)
            shape = np.shape(getattr(self, self._columns[0]))
            for key, message in messages.items():
                flat = key if isinstance(key, (int, np.integer)) else (
                    int(np.ravel_multi_index(key, shape)) if shape else 0)
                text[flat] = message
            cols["message"] = text
        return pd.DataFrame(cols)

    def to_si(self, params) -> SIValues:
        """The result in SI units, with the scales of `params` (a :class:`Params` made by
        :meth:`Params.from_dimensional`, or its :class:`Scales`): loads in Pa (``P``,
        ``P_fc``, ...) and N/m (``F``, ``F_fc``, ...), widths and positions in m, mean gaps
        and gaps in m, energies per area in J/m^2, tractions in Pa. Dimensionless values
        (alpha, mu, W_fraction, loop_area) and codes are kept as they are.

        Raises
        ------
        InvalidArgumentError
            `params` has no scales (``Params(alpha, mu)``).
        """
        scales = _scales_of(params)
        values, units = {}, {}
        for name, value in self._field_items():
            if name in SI_FIELDS:
                for si_name, factor, unit in SI_FIELDS[name]:
                    values[si_name] = np.asarray(value, dtype=float) * getattr(scales, factor)
                    if np.ndim(values[si_name]) == 0:
                        values[si_name] = float(values[si_name])
                    units[si_name] = unit
            else:
                values[name] = value
                kind = np.asarray(value).dtype.kind
                units[name] = "1" if kind == "f" else ""
        for name in ("messages", "status"):
            if getattr(self, name, None) is not None and name not in values:
                values[name], units[name] = getattr(self, name), ""
        return SIValues(type(self).__name__, values, units)

    def __repr__(self) -> str:
        parts = [f"{k}={_summary(getattr(self, k))}" for k in self._repr_fields
                 if getattr(self, k, None) is not None]
        messages = getattr(self, "messages", None)
        if messages:
            parts.append(f"failed={len(messages)}")
        return _clip(f"{type(self).__name__}({', '.join(parts)})")


class TupleCompat:
    """Unpacking, len(), indexing and _asdict() over ``_tuple_fields``: what a result
    that was a named tuple keeps (``x, traction, gap = profile(...)``)."""

    _tuple_fields: Tuple[str, ...] = ()

    def __iter__(self):
        return (getattr(self, k) for k in self._tuple_fields)

    def __len__(self) -> int:
        return len(self._tuple_fields)

    def __getitem__(self, i):
        return tuple(self)[i]

    def _asdict(self) -> dict:
        return {k: getattr(self, k) for k in self._tuple_fields}
