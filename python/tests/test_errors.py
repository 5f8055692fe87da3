"""Every exception path of the Python layer."""

import numpy as np
import pytest

import wavyadhesion as wa
from wavyadhesion import _errors


def test_hierarchy():
    assert issubclass(wa.InvalidArgumentError, wa.WavyAdhesionError)
    assert issubclass(wa.InvalidArgumentError, ValueError)
    assert issubclass(wa.ConvergenceError, wa.WavyAdhesionError)
    assert issubclass(wa.NoSolutionError, wa.ConvergenceError)
    assert not issubclass(wa.ConvergenceError, ValueError)


@pytest.mark.parametrize("a", [-0.1, 0.51, np.nan, np.inf])
def test_westergaard_bad_a(a):
    with pytest.raises(wa.InvalidArgumentError, match=r"a_star .*\[0, 1/2\]") as info:
        wa.westergaard_load([0.1, a])
    assert info.value.status == 1
    assert "index (1,)" in str(info.value)


@pytest.mark.parametrize("alpha, a", [(-1.0, 0.2), (np.nan, 0.2), (0.3, 0.6)])
def test_jkr_bad_arguments(alpha, a):
    with pytest.raises(ValueError):
        wa.jkr_load(alpha, a)


@pytest.mark.parametrize("model", wa.MODELS)
@pytest.mark.parametrize("alpha, mu, a, name", [
    (0.0, 1.0, 0.2, "alpha"), (-0.3, 1.0, 0.2, "alpha"), (np.nan, 1.0, 0.2, "alpha"),
    (np.inf, 1.0, 0.2, "alpha"), (0.3, -1.0, 0.2, "mu"), (0.3, np.inf, 0.2, "mu"),
    (0.3, 1.0, -0.01, "a_star"), (0.3, 1.0, 0.7, "a_star"), (0.3, 1.0, np.nan, "a_star"),
])
def test_equilibrium_bad_arguments(model, alpha, mu, a, name):
    with pytest.raises(wa.InvalidArgumentError, match=name) as info:
        wa.equilibrium(model, alpha, mu, a)
    assert info.value.status == 1 and info.value.message
    with pytest.raises(ValueError, match=name):
        wa.roots(model, alpha, mu, a)


def test_error_reports_first_failed_index():
    a = np.full((2, 3), 0.2)
    a[1, 2] = 0.9
    a[1, 1] = -1.0
    with pytest.raises(wa.InvalidArgumentError, match=r"index \(1, 1\)"):
        wa.equilibrium("dw", 0.3, 1.0, a)


@pytest.mark.parametrize("model", ["DWW", "", 2, None])
def test_unknown_model(model):
    with pytest.raises(wa.InvalidArgumentError, match="model"):
        wa.equilibrium(model, 0.3, 1.0, 0.2)
    with pytest.raises(wa.InvalidArgumentError, match="model"):
        wa.roots(model, 0.3, 1.0, 0.2)


def test_bad_errors_option():
    with pytest.raises(ValueError, match="errors"):
        wa.equilibrium("dw", 0.3, 1.0, 0.2, errors="ignore")


def test_non_numeric_input():
    with pytest.raises(wa.InvalidArgumentError, match="a"):
        wa.equilibrium("dw", 0.3, 1.0, "x")


def test_roots_needs_scalars():
    with pytest.raises(wa.InvalidArgumentError, match="scalar"):
        wa.roots("dw", 0.3, 1.0, [0.1, 0.2])


def test_incompatible_shapes():
    with pytest.raises(ValueError):
        wa.equilibrium("dw", [0.3, 0.4], 1.0, [0.1, 0.2, 0.3])


@pytest.mark.parametrize("status, cls", [
    (1, wa.InvalidArgumentError), (2, wa.NoSolutionError), (3, wa.ConvergenceError),
    (5, wa.ConvergenceError), (42, wa.ConvergenceError),
])
def test_status_mapping(status, cls):
    """Numerical failures cannot be provoked on demand: check the mapping itself, and
    that the library's fixed text is used when a failure brings no message."""
    with pytest.raises(cls) as info:
        _errors.raise_status(status, b" " * 256)
    assert info.value.status == status
    assert info.value.message  # the status text, never empty


def test_params_errors():
    with pytest.raises(wa.InvalidArgumentError, match="alpha"):
        wa.Params(0.0, 1.0)
    with pytest.raises(wa.InvalidArgumentError, match="mu"):
        wa.Params(0.3, -2.0)
    with pytest.raises(ValueError):
        wa.Params(0.3, float("nan"))


def test_dimensional_errors():
    base = dict(period=1e-3, amplitude=1e-5, work_of_adhesion=0.05, peak_stress=1e5)
    with pytest.raises(wa.InvalidArgumentError, match="Estar"):
        wa.Params.from_dimensional(**base)
    with pytest.raises(wa.InvalidArgumentError, match="not both"):
        wa.Params.from_dimensional(Estar=1e6, E1=1e6, nu1=0.3, E2=1e9, nu2=0.3, **base)
    with pytest.raises(wa.InvalidArgumentError, match="nu1"):
        wa.Params.from_dimensional(E1=1e6, nu1=0.7, E2=1e9, nu2=0.3, **base)
    with pytest.raises(wa.InvalidArgumentError, match="E2"):
        wa.Params.from_dimensional(E1=1e6, nu1=0.3, E2=-1.0, nu2=0.3, **base)
    with pytest.raises(wa.InvalidArgumentError, match="period"):
        wa.Params.from_dimensional(Estar=1e6, **{**base, "period": 0.0})
    with pytest.raises(wa.InvalidArgumentError, match="peak_stress"):
        wa.Params.from_dimensional(Estar=1e6, **{**base, "peak_stress": -1.0})
