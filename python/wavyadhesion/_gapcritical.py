"""Critical values under gap (mean-gap) control: the Fortran ``gap_critical_sweep``
(module wa_gapcritical), the counterpart of :func:`critical_forces` for displacement
control."""

from __future__ import annotations

from typing import Any, Callable, NamedTuple, Optional, Union

import numpy as np
from numpy.typing import ArrayLike

from . import _wa_f2py as _f
from ._args import (ALPHA_MAX, ALPHA_MIN, MU_MAX, MU_MIN, at_index, check_sweep_arguments,
                    chunk_slices, flat_f64, float_array, model_code, model_name, shaped)
from ._errors import INVALID_ARGUMENT, OK, InvalidArgumentError, message_text, raise_status
from ._parallel import make_progress
from ._results import ResultMixin

# mu per facade call (one alpha): Ctrl-C is seen between two calls (~0.3 s for MD)
_CHUNK_SWEEP = 16

#: The fields of GapCritical that hold values, in the order of the Fortran
#: ``gap_critical_names`` and the C ``WA_GAP_CRITICAL_*`` indices.
GAP_CRITICAL_FIELDS = ("g_touch", "P_jump_in", "a_jump_in", "g_contact", "P_min", "g_P_min",
                       "a_P_min", "g_contact_lost", "P_contact_lost", "g_interaction_lost")


class GapCritical(NamedTuple):
    """Critical values of the gap-controlled cycle (doc/user-guide.md, "Gap control").
    Arrays of the broadcast shape of alpha and mu (numpy scalars when both are scalars);
    NaN where a point failed (``status`` nonzero, ``messages`` says why)."""
    #: Approach: gbar* where the surfaces first interact (P* = 0 above; 1 except MD)
    g_touch: np.ndarray
    #: P* where the approach lands when it jumps at g_touch (0: no jump)
    P_jump_in: np.ndarray
    #: a* there (0: no jump, or MD landing on its states without contact)
    a_jump_in: np.ndarray
    #: gbar* where contact is first made on the approach
    g_contact: np.ndarray
    #: Retraction: the most tensile load (JKR: -inf, at full contact)
    P_min: np.ndarray
    #: its gbar* (JKR: 0)
    g_P_min: np.ndarray
    #: its a* (JKR: 1/2)
    a_P_min: np.ndarray
    #: gbar* where contact is lost for good on the retraction
    g_contact_lost: np.ndarray
    #: P* of the last state with contact there
    P_contact_lost: np.ndarray
    #: gbar* beyond which P* = 0 on the retraction
    g_interaction_lost: np.ndarray
    #: library status of each point (0 = computed)
    status: np.ndarray
    #: index (into the flattened points) -> message, for each failed point
    messages: dict
    #: alpha and mu broadcast to the shape of the values (the coordinates), the model
    alpha: Optional[np.ndarray] = None
    mu: Optional[np.ndarray] = None
    model: Optional[str] = None

    to_si = ResultMixin.to_si
    to_dataframe = ResultMixin.to_dataframe
    _field_items = ResultMixin._field_items
    __repr__ = ResultMixin.__repr__
    _columns = ("alpha", "mu") + GAP_CRITICAL_FIELDS + ("status",)
    _coordinates = ("model",)
    _repr_fields = ("model", "alpha", "mu", "g_touch", "P_min")


def _gap_chunk(code, alpha, mu_f, idx, values, status_out, messages, errors, shape):
    """One facade call for the points `idx` (one alpha, at most _CHUNK_SWEEP of them);
    a failed point keeps NaN and gets its status and its own message (errors="raise":
    the first one raises)."""
    vals, rows, ifail, status, message = _f.fa_gap_critical_sweep(
        code, alpha, np.ascontiguousarray(mu_f[idx]))
    if status == INVALID_ARGUMENT and (rows == INVALID_ARGUMENT).all():
        # this alpha or one of its mu was refused: nothing computed for its points
        where = int(idx[ifail - 1]) if ifail > 0 else int(idx[0])
        if errors == "raise":
            raise_status(status, message, at_index(where + 1, shape))
        status_out[idx] = status
        for i in idx:
            messages[int(i)] = message_text(message)
        return
    values[:, idx] = vals
    status_out[idx] = rows
    for j in np.flatnonzero(rows != OK):
        i = int(idx[j])
        # the sweep's message is about its first failing row: ask this row's own (as
        # critical_forces does; failures are rare), so that it does not depend on chunks
        row_status, text = _f.fa_gap_critical_message(code, alpha, float(mu_f[i]))
        text = message_text(text) or message_text(_f.fa_status_text(int(rows[j])))
        text = f"alpha = {alpha!r}, mu = {float(mu_f[i])!r}: {text}"
        if errors == "raise":
            raise_status(int(rows[j]), text, at_index(i + 1, shape))
        messages[i] = text


def gap_critical(model: str, alpha: ArrayLike, mu: ArrayLike, *, errors: str = "raise",
                 progress: Union[bool, Callable[[int, int], Any], None] = None
                 ) -> GapCritical:
    """Critical values under gap (mean-gap) control, vectorised over mu and broadcast
    with alpha: where the approach first feels the surface and jumps in (a jump under gap
    control keeps gbar*), where contact is made, the most tensile load on the retraction
    and where contact and interaction are lost. The Fortran ``gap_critical_sweep`` (GIL
    released) runs in calls of at most 16 mu that share an alpha; Ctrl-C
    (KeyboardInterrupt) takes effect between two calls (within ~0.3 s for MD).

    Parameters
    ----------
    model : {"westergaard", "jkr", "dw", "md"}
        The contact model.
    alpha : array_like
        Johnson's parameter, alpha > 0.
    mu : array_like
        Transition parameter, mu >= 0; broadcast with `alpha`.
    errors : {"raise", "nan"}, optional
        "raise" (default): raise at the first point that fails (an invalid alpha or mu
        before any work). "nan": every point is computed; a failed or invalid one gets
        NaN values and its status and message.
    progress : bool or callable, optional
        True: a progress bar on stderr (tqdm when installed, else a plain line); a
        callable: called as ``progress(done, total)`` (points) after each chunk, in
        order. None (default): nothing.

    Returns
    -------
    GapCritical
        The ten values (fields named as in GAP_CRITICAL_FIELDS), ``status``,
        ``messages`` and the coordinates ``alpha``, ``mu`` (broadcast), ``model``.

    Raises
    ------
    InvalidArgumentError
        Unknown model or ``errors``; (errors="raise") alpha outside [1e-12, 1e12], mu
        outside 0 or [1e-100, 1e100], NaN or infinite values, an empty mu.
    ConvergenceError
        (errors="raise") The branch or the gap-controlled cycle of a point failed.

    Examples
    --------
    >>> g = gap_critical("westergaard", 0.3, 1.0)
    >>> float(g.g_touch), float(g.P_jump_in), float(g.g_contact_lost)
    (1.0, 0.0, 1.0)
    """
    code = model_code(model)
    if errors not in ("raise", "nan"):
        raise InvalidArgumentError(f"errors = {errors!r} is not 'raise' or 'nan'",
                                   INVALID_ARGUMENT)
    alpha_b, mu_b = np.broadcast_arrays(float_array(alpha, "alpha"), float_array(mu, "mu"))
    shape = mu_b.shape
    alpha_f, mu_f = flat_f64(alpha_b), flat_f64(mu_b)
    if mu_f.size == 0:
        raise InvalidArgumentError("mu is empty: give at least one value", INVALID_ARGUMENT)
    values = np.full((len(GAP_CRITICAL_FIELDS), mu_f.size), np.nan)
    status_out = np.zeros(mu_f.size, dtype=np.int32)
    messages = {}
    if errors == "raise":
        check_sweep_arguments(code, alpha_f, mu_f, shape)   # every point before any work
    with np.errstate(invalid="ignore"):
        bad = ~((alpha_f >= ALPHA_MIN) & (alpha_f <= ALPHA_MAX) &
                ((mu_f == 0) | ((mu_f >= MU_MIN) & (mu_f <= MU_MAX))))
    for i in np.flatnonzero(bad):                       # errors="nan": NaN rows, reasons
        *_, status, message = _f.fa_gap_critical_sweep(code, float(alpha_f[i]),
                                                       np.array([mu_f[i]]))
        status_out[i] = status
        messages[int(i)] = message_text(message)
    uniq, inverse = np.unique(alpha_f[~bad], return_inverse=True)
    inverse = inverse.reshape(-1)
    good = np.flatnonzero(~bad)
    report = make_progress(progress, mu_f.size, "gap_critical")
    try:
        if report is not None:
            report.update(int(bad.sum()))
        for k, value in enumerate(uniq):
            group = good[inverse == k]
            for sl in chunk_slices(group.size, _CHUNK_SWEEP):  # Ctrl-C is seen between chunks
                _gap_chunk(code, float(value), mu_f, group[sl], values, status_out,
                           messages, errors, shape)
                if report is not None:
                    report.update(sl.stop - sl.start)
    finally:
        if report is not None:
            report.close()
    fields = [shaped(values[k], shape) for k in range(len(GAP_CRITICAL_FIELDS))]
    return GapCritical(*fields, shaped(status_out, shape), messages,
                       shaped(alpha_f.copy(), shape), shaped(mu_f.copy(), shape),
                       model_name(code))
