"""ResolutionError: the smooth (LJ) model's grid refusing a request beyond its cap (status 4
from lj_problem) is neither a convergence failure nor silently NaN; critical_forces("lj")
takes n_max. Every refusal here comes before any solve (instant)."""
import math

import numpy as np
import pytest

import wavyadhesion as wa
from wavyadhesion._errors import CAPACITY_TOO_SMALL, raise_status


def needed_n(alpha, mu):
    """The automatic grid's N, from the closed forms (doc/theory.md, "Smooth adhesion"):
    12 points on the interaction zone ell = alpha^2/(2 Sigma0^2), Sigma0 = pi mu
    (alpha^2/32)^(1/3), rounded up to a power of two >= 128."""
    sigma0 = math.pi * mu * (alpha ** 2 / 32) ** (1 / 3)
    ell = alpha ** 2 / (2 * sigma0 ** 2)
    n = 128
    while n < 12 / ell:
        n *= 2
    return n


def test_hierarchy():
    assert issubclass(wa.ResolutionError, wa.InvalidArgumentError)
    assert issubclass(wa.ResolutionError, ValueError)
    assert not issubclass(wa.ResolutionError, wa.ConvergenceError)
    assert not issubclass(wa.ResolutionError, RuntimeError)
    assert "ResolutionError" in wa.__all__


def test_only_lj_problems_refusal_is_a_resolution_error():
    """Status 4 with lj_problem's message ("lj: ...") is the grid's refusal; the trace
    running out of points ("lj_trace: ...") keeps ConvergenceError."""
    with pytest.raises(wa.ResolutionError) as info:
        raise_status(CAPACITY_TOO_SMALL, "lj: n gives more than 8193 unknowns", "at index 2")
    assert info.value.status == CAPACITY_TOO_SMALL
    assert str(info.value) == "lj: n gives more than 8193 unknowns (at index 2)"
    with pytest.raises(wa.ConvergenceError) as info:
        raise_status(CAPACITY_TOO_SMALL, "lj_trace: more than max_points points before "
                     "full contact")
    assert not isinstance(info.value, wa.ResolutionError)


@pytest.mark.parametrize("call", [
    lambda **kw: wa.trace_branch("lj", 0.3, 3.0, **kw),
    lambda **kw: wa.load_path("lj", 0.3, 3.0, **kw),
    lambda **kw: wa.gap_path("lj", 0.3, 3.0, **kw),
    lambda **kw: wa.critical_forces("lj", 0.3, 3.0, **kw),
    lambda **kw: wa.profile("lj", 0.3, 3.0, 0.2, **kw),
], ids=["trace_branch", "load_path", "gap_path", "critical_forces", "profile"])
def test_explicit_n_beyond_the_cap(call):
    """n = 16388 (even: the sinusoid's cap is 16384) and n = 4096 on an uneven profile
    (solved densely: at most 2048) are refused as ResolutionError, caught by
    `except ValueError`; before, ConvergenceError."""
    with pytest.raises(wa.ResolutionError, match="16384") as info:
        call(n=16388)
    assert info.value.status == CAPACITY_TOO_SMALL
    x = np.arange(64) / 64
    try:
        call(n=4096, profile=1 - np.cos(2 * np.pi * (x + 1 / 192)))
    except ValueError as exc:
        assert isinstance(exc, wa.ResolutionError) and "n <= 2048" in str(exc)
    else:
        raise AssertionError("n = 4096 on an uneven profile was accepted")


def test_automatic_grid_beyond_its_cap_names_the_n_needed():
    """alpha 0.3, mu 10: the zone needs N = 8192 (the closed form), above the automatic
    grid's 2048: the message names both and says to pass n."""
    assert needed_n(0.3, 10.0) == 8192
    for call in (wa.trace_branch, wa.load_path, wa.gap_path, wa.critical_forces):
        with pytest.raises(wa.ResolutionError) as info:
            call("lj", 0.3, 10.0)
        text = str(info.value)
        assert "needs N = 8192" in text and "cap of 2048" in text and "pass n" in text
    with pytest.raises(wa.ResolutionError, match="needs N = 8192"):
        wa.profile("lj", 0.3, 10.0, 0.2)


def test_critical_forces_n_max():
    """n_max caps the automatic grid: below the N the zone needs (alpha 0.3, mu 3: 512 by
    the closed form) the point is refused, ResolutionError naming N and the cap, or with
    errors="nan" status 4 and that message while the other points are computed; at the N
    needed the result is the default's, bit for bit (alpha 0.3, mu 1: N = 128)."""
    assert needed_n(0.3, 3.0) == 512 and needed_n(0.3, 1.0) == 128
    with pytest.raises(wa.ResolutionError) as info:
        wa.critical_forces("lj", 0.3, 3.0, n_max=256)
    assert "needs N = 512" in str(info.value) and "cap of 256" in str(info.value)
    r = wa.critical_forces("lj", 0.3, [3.0, 1.0], n_max=256, errors="nan")
    assert list(r.status) == [CAPACITY_TOO_SMALL, 0] and list(r.N) == [0, 128]
    assert "needs N = 512" in r.messages[(0,)] and "cap of 256" in r.messages[(0,)]
    assert math.isnan(r.P_fc_peak[0]) and math.isnan(r.P_fc[0])
    base = wa.critical_forces("lj", 0.3, 1.0)
    capped = wa.critical_forces("lj", 0.3, 1.0, n_max=128)
    for name in ("P_fc", "P_pf", "P_fc_peak", "P_fc_err", "P_fc_peak_err", "W_star", "N"):
        assert getattr(capped, name) == getattr(base, name), name
    # n given: n_max is not used (only checked)
    assert int(wa.critical_forces("lj", 0.3, 1.0, n=256, n_max=128).N) == 256


@pytest.mark.parametrize("kwargs, needle", [
    (dict(model="lj", n_max=64), "n_max"),
    (dict(model="lj", n_max=32768), "n_max"),
    (dict(model="lj", n_max=1.5), "n_max"),
    (dict(model="dw", n_max=1024), "only for model='lj'"),
])
def test_bad_n_max(kwargs, needle):
    model = kwargs.pop("model")
    with pytest.raises(wa.InvalidArgumentError, match=needle) as info:
        wa.critical_forces(model, 0.3, 3.0, **kwargs)
    assert not isinstance(info.value, wa.ResolutionError)


def test_errors_nan_keeps_the_status():
    """errors="nan" sweeps are unchanged: n beyond the cap gives status 4, NaN and the
    library's message for every point, nothing raised."""
    r = wa.critical_forces("lj", 0.3, [3.0, 2.0], n=20000, errors="nan")
    assert list(r.status) == [CAPACITY_TOO_SMALL] * 2 and np.isnan(r.P_fc).all()
    assert "16384" in r.messages[(1,)]
