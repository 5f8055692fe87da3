"""Exceptions of wavyadhesion and the library's status codes: a non-zero status
from the facade becomes the matching exception."""

from __future__ import annotations

import numpy as np

from . import _wa_f2py as _f

__all__ = ["WavyAdhesionError", "InvalidArgumentError", "InvalidTypeError",
           "ResolutionError", "ConvergenceError", "NoSolutionError"]

# Status codes of the library (src/wa_status.f90).
OK, INVALID_ARGUMENT, NO_SOLUTION, NOT_CONVERGED = 0, 1, 2, 3
CAPACITY_TOO_SMALL, NUMERICAL_ERROR = 4, 5
# The prefix of lj_problem's messages: with status 4 it refuses a grid beyond its cap (an
# explicit n, or the automatic grid's zone needing more than its cap); the trace's own
# status 4 (more points than it holds) says "lj_trace: ".
_LJ_GRID_PREFIX = "lj: "


class WavyAdhesionError(Exception):
    """Base class of every error raised by wavyadhesion.

    Attributes
    ----------
    status : int
        The library's status code (1 invalid argument, 2 no solution, 3 not
        converged, 4 an LJ grid beyond its cap (:class:`ResolutionError`), 5 numerical
        error).
    message : str
        The library's message, naming the argument or the step that failed.
    """

    def __init__(self, message: str, status: int):
        super().__init__(message)
        self.status = status
        self.message = message


class InvalidArgumentError(WavyAdhesionError, ValueError):
    """An argument is NaN, infinite or outside its valid range (status 1)."""


class InvalidTypeError(InvalidArgumentError, TypeError):
    """An argument has the wrong type (None, complex, a string, a masked array with
    masked values): also a TypeError, and an InvalidArgumentError (status 1)."""


class ResolutionError(InvalidArgumentError):
    """The smooth (LJ) model's grid refuses the request (status 4): an explicit ``n``
    beyond the grid's cap (16384 points per period on an even profile, 8192 otherwise,
    2048 on an uneven one), or an automatic grid whose interaction zone needs more points
    than its cap (2048, or ``n_max``). Nothing failed to converge: the request is beyond
    the solver's resolution; the message names the N needed or the cap (and says to pass
    ``n`` where that helps). Also an :class:`InvalidArgumentError` and a ValueError."""


class ConvergenceError(WavyAdhesionError, RuntimeError):
    """A numerical failure: an iteration did not converge (status 3), a numerical
    building block failed (status 5), or no solution was found (status 2, see
    :class:`NoSolutionError`). Also a RuntimeError (as scipy's convergence errors
    are)."""


class NoSolutionError(ConvergenceError):
    """The equations have no solution of the kind asked for (status 2)."""


def message_text(message) -> str:
    if isinstance(message, (bytes, np.bytes_)):
        message = message.decode("ascii", "replace")
    elif isinstance(message, np.ndarray):
        message = message.tobytes().decode("ascii", "replace")
    return str(message).strip("\x00 ").strip()


def is_grid_refusal(status: int, text: str) -> bool:
    """True for lj_problem's refusal of a grid beyond its cap (status 4, "lj: ...")."""
    return status == CAPACITY_TOO_SMALL and text.startswith(_LJ_GRID_PREFIX)


def raise_status(status: int, message, where: str = "") -> None:
    """Raise the exception that matches a non-zero library status."""
    text = message_text(message)
    if not text:
        text = message_text(_f.fa_status_text(status))
    refused = is_grid_refusal(status, text)
    if where:
        text = f"{text} ({where})"
    if refused:
        raise ResolutionError(text, status)
    if status == INVALID_ARGUMENT:
        raise InvalidArgumentError(text, status)
    if status == NO_SOLUTION:
        raise NoSolutionError(text, status)
    raise ConvergenceError(text, status)


