"""Argument checking and coercion shared by every function of the package: model
names, real arrays and scalars, counts, the library's bounds, broadcasting back to
shape, and the chunking of vectorised calls."""

from __future__ import annotations

import functools
import warnings

import numpy as np

from . import _wa_f2py as _f
from ._errors import (CAPACITY_TOO_SMALL, INVALID_ARGUMENT, OK, InvalidArgumentError,
                      InvalidTypeError, raise_status)
from ._parallel import points_per_chunk

#: Model names and the library's integer constants (include/wavyadhesion.h).
MODELS = {"westergaard": 0, "jkr": 1, "dw": 2, "md": 3}
_MODEL_NAMES = {code: name for name, code in MODELS.items()}

# Events asked for in a first load_path() call (path_type holds at most 64).
PATH_CAPACITY = 64

# The library's bounds, read from it (wa_params, wa_map): the supported domain
# (WA_ALPHA_MIN ... WA_MU_MAX in include/wavyadhesion.h; a test checks they agree) and
# the size of an adhesion map's grid. Used to refuse bad input before any work or
# allocation; for alpha and mu the library's own check decides and words the message.
_LIMITS = _f.fa_limits()
ALPHA_MIN, ALPHA_MAX, MU_MIN, MU_MAX = (float(v) for v in _LIMITS[:4])
MAP_N_MU_MAX, MAP_N_ALPHA_MAX, MAP_CELLS_MAX = (int(v) for v in _LIMITS[4:])

# The largest value of a C int (an integer the facade passes to Fortran)
C_INT_MAX = 2**31 - 1

def model_name(code: int) -> str:
    return _MODEL_NAMES[code]


def real_scalar(x, name: str) -> float:
    arr = float_array(x, name)
    if arr.ndim != 0:
        raise InvalidArgumentError(f"{name} must be a scalar, got shape {arr.shape}",
                                   INVALID_ARGUMENT)
    return float(arr)


def count_in(value, name: str, lo: int, hi: int) -> int:
    """A count given as an integer in [lo, hi] (an integral float such as 60.0 too),
    checked before anything is allocated. A bool, a non-integral or non-finite number and
    anything but a real number are refused, naming `name` and its range."""
    expected = f"an integer in [{lo}, {hi}]"
    if isinstance(value, (bool, np.bool_)) or not isinstance(
            value, (int, float, np.integer, np.floating)):
        raise InvalidTypeError(f"{name} = {value!r}: must be {expected}", INVALID_ARGUMENT)
    if isinstance(value, (float, np.floating)) and not (np.isfinite(value)
                                                         and float(value).is_integer()):
        raise InvalidArgumentError(f"{name} = {value!r}: must be {expected}",
                                   INVALID_ARGUMENT)
    if not lo <= int(value) <= hi:
        raise InvalidArgumentError(f"{name} = {value!r} is outside [{lo}, {hi}]",
                                   INVALID_ARGUMENT)
    return int(value)


def real_in(value, name: str, lo: float, hi: float) -> float:
    """A real scalar in [lo, hi] (finite), or an error naming `name` and the range."""
    x = real_scalar(value, name)
    if not lo <= x <= hi:
        raise InvalidArgumentError(f"{name} = {value!r} is outside its valid range "
                                   f"[{lo:g}, {hi:g}]", INVALID_ARGUMENT)
    return x


def model_code(model) -> int:
    if not isinstance(model, str):
        raise InvalidTypeError(
            f"model must be a string, one of {', '.join(map(repr, MODELS))}; got "
            f"{type(model).__name__} {model!r}", INVALID_ARGUMENT)
    if model.lower() in MODELS:
        return MODELS[model.lower()]
    raise InvalidArgumentError(
        f"model = {model!r} is not one of {', '.join(map(repr, MODELS))}", INVALID_ARGUMENT
    )


def float_array(x, name: str) -> np.ndarray:
    """x as a float64 array. None (also inside a sequence), complex numbers, strings,
    bytes and masked values are refused with an InvalidTypeError naming the argument
    (numpy would read None as NaN, drop the imaginary part, parse strings and drop
    masks)."""
    if type(x) is float or type(x) is int:                # the common scalar case
        return np.asarray(x, dtype=np.float64)
    if x is None:
        raise InvalidTypeError(f"{name} is None: give a real number or an array of them",
                               INVALID_ARGUMENT)
    if isinstance(x, np.ma.MaskedArray):
        n_masked = int(np.ma.count_masked(x))
        if n_masked:
            raise InvalidTypeError(
                f"{name} is a masked array with {n_masked} masked value(s): masks are not "
                f"supported (pass x.filled(np.nan) or x.compressed())", INVALID_ARGUMENT)
        x = np.ma.getdata(x)
    if isinstance(x, np.ndarray) and x.dtype.kind in "fiub":
        return np.asarray(x, dtype=np.float64)
    try:
        raw = np.asarray(x)
    except (TypeError, ValueError) as exc:
        raise InvalidTypeError(f"{name}: not convertible to float ({exc})",
                               INVALID_ARGUMENT) from None
    kind = raw.dtype.kind
    if kind == "c":
        raise InvalidTypeError(f"{name} is complex ({raw.dtype}): give real numbers (the "
                               f"imaginary part would be lost)", INVALID_ARGUMENT)
    if kind in "USVMm":
        raise InvalidTypeError(f"{name}: {raw.dtype} values are not real numbers",
                               INVALID_ARGUMENT)
    if kind == "O":
        for v in raw.flat:
            if v is None:
                raise InvalidTypeError(f"{name} contains None: give real numbers",
                                       INVALID_ARGUMENT)
            if isinstance(v, (complex, np.complexfloating)):
                raise InvalidTypeError(f"{name} contains a complex number ({v!r})",
                                       INVALID_ARGUMENT)
            if isinstance(v, (str, bytes)):
                raise InvalidTypeError(f"{name} contains a string ({v!r})",
                                       INVALID_ARGUMENT)
    try:
        return np.asarray(raw, dtype=np.float64)
    except (TypeError, ValueError) as exc:
        raise InvalidTypeError(f"{name}: not convertible to float ({exc})",
                               INVALID_ARGUMENT) from None


def chunk_slices(n: int, size: int):
    """Slices of at most `size` covering range(n) (one slice when n <= size)."""
    for start in range(0, n, size):
        yield slice(start, min(start + size, n))


def flat_f64(arr: np.ndarray) -> np.ndarray:
    """Contiguous 1-D float64 view or copy (what the facade takes without copying)."""
    return np.ascontiguousarray(arr, dtype=np.float64).reshape(-1)


def shaped(values: np.ndarray, shape):
    """Back to the broadcast shape; a numpy scalar when the inputs were scalars."""
    out = values.reshape(shape)
    return out[()] if out.ndim == 0 else out


def at_index(index: int, shape) -> str:
    if len(shape) == 0:
        return ""
    return f"at index {tuple(int(i) for i in np.unravel_index(index - 1, shape))}"


def index_text(i: int, shape) -> str:
    """'2' or '1, 0' for the flat index i of an array of `shape` ('' for a scalar)."""
    return ", ".join(str(int(k)) for k in np.unravel_index(i, shape)) if shape else ""


def grown(fortran, capacity, n_index, *args):
    """Call an f2py routine whose first argument is the capacity of its output arrays,
    growing the capacity until the outputs fit (out[n_index] is the count needed);
    raise on failure (status and message are the last two outputs)."""
    while True:
        out = fortran(capacity, *args)
        status, n = out[-2], out[n_index]
        if status == CAPACITY_TOO_SMALL and n > capacity:
            capacity = int(n)
            continue
        if status != OK:
            raise_status(status, out[-1])
        return out


def check_sweep_arguments(code, alpha_f, mu_f, shape):
    """InvalidArgumentError naming the first bad alpha or mu, before any work."""
    with np.errstate(invalid="ignore"):
        bad_alpha = ~((alpha_f >= ALPHA_MIN) & (alpha_f <= ALPHA_MAX))
        bad_mu = ~((mu_f == 0) | ((mu_f >= MU_MIN) & (mu_f <= MU_MAX)))
    for bad in (bad_alpha, bad_mu):
        if bad.any():
            i = int(np.flatnonzero(bad)[0])
            *_, status, message = _f.fa_critical_sweep(code, float(alpha_f[i]),
                                                       np.array([mu_f[i]]))
            if status != OK:
                raise_status(status, message, at_index(i + 1, shape))


def chunk_size_for(chunk_size, executor, seconds_per_point, serial):
    """Points per chunk: `chunk_size` (validated), else `serial` without an executor,
    else enough points for _parallel.chunk_seconds(executor) of work."""
    if chunk_size is None:
        if executor is None:
            return serial
        return points_per_chunk(executor, seconds_per_point, serial)
    if isinstance(chunk_size, (bool, np.bool_)) or not isinstance(
            chunk_size, (int, np.integer)) or chunk_size < 1:
        raise InvalidArgumentError(f"chunk_size = {chunk_size!r} is not a positive integer",
                                   INVALID_ARGUMENT)
    return int(chunk_size)



# GSL must return error codes, not abort() the Python process.
_f.fa_init()


def renamed_keyword(old: str, new: str):
    """Decorator: the keyword `old` still accepted for `new` for one release, with a
    DeprecationWarning (giving both is an error naming them)."""
    def decorate(func):
        @functools.wraps(func)
        def wrapper(*args, **kwargs):
            if old in kwargs:
                if new in kwargs:
                    raise InvalidTypeError(f"{func.__name__}() got both {new!r} and its old "
                                           f"name {old!r}: give {new!r} only", INVALID_ARGUMENT)
                warnings.warn(f"{func.__name__}(): the keyword {old!r} is deprecated, use "
                              f"{new!r} (the old name goes in the next release)",
                              DeprecationWarning, stacklevel=2)
                kwargs[new] = kwargs.pop(old)
            return func(*args, **kwargs)
        return wrapper
    return decorate
