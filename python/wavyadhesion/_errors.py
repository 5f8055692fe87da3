"""Exceptions of wavyadhesion and the library's status codes: a non-zero status
from the facade becomes the matching exception."""

from __future__ import annotations

import numpy as np

from . import _wa_f2py as _f

__all__ = ["WavyAdhesionError", "InvalidArgumentError", "InvalidTypeError",
           "ConvergenceError", "NoSolutionError"]

# Status codes of the library (src/wa_status.f90).
OK, INVALID_ARGUMENT, NO_SOLUTION, NOT_CONVERGED = 0, 1, 2, 3
CAPACITY_TOO_SMALL, NUMERICAL_ERROR = 4, 5



class WavyAdhesionError(Exception):
    """Base class of every error raised by wavyadhesion.

    Attributes
    ----------
    status : int
        The library's status code (1 invalid argument, 2 no solution, 3 not
        converged, 5 numerical error).
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


def raise_status(status: int, message, where: str = "") -> None:
    """Raise the exception that matches a non-zero library status."""
    text = message_text(message)
    if not text:
        text = message_text(_f.fa_status_text(status))
    if where:
        text = f"{text} ({where})"
    if status == INVALID_ARGUMENT:
        raise InvalidArgumentError(text, status)
    if status == NO_SOLUTION:
        raise NoSolutionError(text, status)
    raise ConvergenceError(text, status)


