"""Result types: coordinates, SI conversion, tables, short reprs, progress, the renamed
keyword, the annotations and the module structure."""

import ast
import inspect
import math
import sys
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import numpy as np
import pytest

import wavyadhesion as wa

# SI inputs: E* = 1 MPa, L = 1 mm, Delta = 10 um, dgamma = 0.05 J/m^2, sigma0 = 0.1 MPa
SI = dict(Estar=1e6, period=1e-3, amplitude=1e-5, work_of_adhesion=0.05, peak_stress=1e5)
# the scales by hand (p* = pi E* Delta / L)
P_STAR = math.pi * 1e6 * 1e-5 / 1e-3
L, DELTA = 1e-3, 1e-5


@pytest.fixture(scope="module")
def params():
    return wa.Params.from_dimensional(**SI)


# --- one name per quantity ------------------------------------------------------------

@pytest.mark.parametrize("call", [
    lambda **k: wa.equilibrium("dw", 0.3, 1.0, **k),
    lambda **k: wa.jkr_load(0.3, **k),
    lambda **k: wa.westergaard_load(**k),
])
def test_old_keyword_a_still_works_with_a_warning(call):
    a = [0.1, 0.2, 0.3]
    new = call(a_star=a)
    with pytest.warns(DeprecationWarning, match="'a' is deprecated, use 'a_star'"):
        old = call(a=a)
    for x, y in zip(np.atleast_1d(new) if isinstance(new, np.ndarray) else new,
                    np.atleast_1d(old) if isinstance(old, np.ndarray) else old):
        np.testing.assert_array_equal(x, y)
    with pytest.raises(TypeError, match="both 'a_star' and its old name 'a'"):
        call(a=a, a_star=a)


def test_equilibrium_signature_names_a_star():
    for func in (wa.equilibrium, wa.jkr_load, wa.westergaard_load, wa.roots, wa.profile):
        assert "a_star" in inspect.signature(func).parameters, func.__name__
        assert "a" not in inspect.signature(func).parameters, func.__name__


# --- coordinates ---------------------------------------------------------------------

def test_results_carry_their_coordinates():
    a = np.linspace(0.1, 0.4, 4)
    eq = wa.equilibrium("DW", [[0.3], [0.6]], 1.0, a)
    assert eq.model == "dw" and eq.a_star.shape == eq.alpha.shape == eq.mu.shape == (2, 4)
    np.testing.assert_array_equal(eq.a_star[1], a)
    np.testing.assert_array_equal(eq.alpha[:, 0], [0.3, 0.6])
    c_star, P_star, zone, gbar = eq                    # still unpacks as before
    np.testing.assert_array_equal(P_star, eq.P_star)
    assert len(eq) == 4 and eq[1] is eq.P_star
    crit = wa.critical_forces("dw", [[0.3], [0.6]], [1.0, 2.0, 5.0])
    np.testing.assert_array_equal(crit.mu[1], [1.0, 2.0, 5.0])
    np.testing.assert_array_equal(crit.alpha[:, 2], [0.3, 0.6])
    P_fc, P_pf = crit
    gc = wa.gap_critical("dw", 0.3, [1.0, 2.0])
    np.testing.assert_array_equal(gc.mu, [1.0, 2.0])
    assert gc.model == "dw" and wa.GAP_CRITICAL_FIELDS == wa.GapCritical._fields[:10]
    assert wa.energy_lost("dw", 0.3, 1.0).model == "dw"
    law = wa.gap_law("md", 0.3, 1.0, [0.5])
    assert (law.model, law.alpha, law.mu) == ("md", 0.3, 1.0)
    path = wa.gap_path("md", 0.3, 1.0)
    assert (path.model, path.alpha, path.mu) == ("md", 0.3, 1.0)
    x, t, h = prof = wa.profile("dw", 0.3, 1.0, 0.2)
    state = wa.roots("dw", 0.3, 1.0, 0.2)[0]
    assert prof.c_star == pytest.approx(state.c_star, rel=1e-13)
    assert prof.P_star == pytest.approx(state.P_star, rel=1e-13)
    assert (prof.a_star, prof.zone_case, prof.gbar) == (0.2, state.zone_case, state.gbar)


# --- SI units ------------------------------------------------------------------------

def test_scales_carry_every_scale(params):
    s = params.scales
    assert s.pressure == pytest.approx(P_STAR, rel=1e-15)
    assert s.force == pytest.approx(P_STAR * L, rel=1e-15)
    assert (s.length, s.amplitude) == (L, DELTA)
    assert s.energy == pytest.approx(P_STAR * DELTA, rel=1e-15)
    assert s.stiffness == pytest.approx(P_STAR / DELTA, rel=1e-15)
    # built from the five original values, the amplitude is derived
    old = wa.Scales(s.estar, s.pressure, s.force, s.length, s.radius)
    assert old.amplitude == pytest.approx(DELTA, rel=1e-15)


def test_to_si_against_hand_conversion(params):
    crit = wa.critical_forces("dw", params.alpha, [params.mu, 2 * params.mu])
    si = crit.to_si(params)
    np.testing.assert_allclose(si.P_pf, crit.P_pf * P_STAR, rtol=1e-15)
    np.testing.assert_allclose(si.F_pf, crit.P_pf * P_STAR * L, rtol=1e-15)
    assert si.units["F_pf"] == "N/m" and si.units["P_fc"] == "Pa"
    np.testing.assert_array_equal(si.mu, crit.mu)          # dimensionless: kept
    law = wa.gap_law("md", params.alpha, params.mu, np.linspace(0, 1.5, 31))
    si = law.to_si(params)
    assert si.W == pytest.approx(law.W_star * P_STAR * DELTA, rel=1e-15)
    assert si.units["W"] == "J/m^2" and si.units["gbar"] == "m"
    np.testing.assert_allclose(si.gbar, law.gbar * DELTA, rtol=1e-15)
    np.testing.assert_allclose(si.F_retract, law.P_retract * P_STAR * L, rtol=1e-15)
    np.testing.assert_allclose(si.dPdg_approach, law.dPdg_approach * P_STAR / DELTA,
                               rtol=1e-15)
    prof = wa.profile("dw", params.alpha, params.mu, 0.2)
    si = prof.to_si(params.scales)                       # a Scales works too
    np.testing.assert_allclose(si.x, prof.x * L, rtol=1e-15)
    np.testing.assert_allclose(si.traction, prof.traction * P_STAR, rtol=1e-15)
    np.testing.assert_allclose(si.gap, prof.gap * DELTA, rtol=1e-15)
    assert si.a == pytest.approx(0.2 * L, rel=1e-15)
    path = wa.gap_path("md", params.alpha, params.mu)
    si = path.to_si(params)
    np.testing.assert_allclose(si.gbar, path.gbar * DELTA, rtol=1e-15)
    assert si.g_touch == pytest.approx(path.g_touch * DELTA, rel=1e-15)
    b = wa.trace_branch("dw", params.alpha, params.mu).to_si(params)
    assert b.units["a"] == b.units["c"] == "m" and b.units["F"] == "N/m"
    lp = wa.load_path("dw", params.alpha, params.mu)
    assert lp.to_si(params).F_pf == pytest.approx(lp.P_pf * P_STAR * L, rel=1e-15)
    e = wa.energy_lost("dw", params.alpha, params.mu).to_si(params)
    assert e.units["W"] == "J/m^2"
    g = wa.gap_critical("dw", params.alpha, params.mu).to_si(params)
    assert g.units["g_touch"] == "m" and g.units["F_min"] == "N/m"
    eq = wa.equilibrium("dw", params.alpha, params.mu, [0.1, 0.2]).to_si(params)
    np.testing.assert_allclose(eq.a, [0.1 * L, 0.2 * L], rtol=1e-15)


def test_to_si_needs_scales():
    crit = wa.critical_forces("dw", 0.3, 1.0)
    with pytest.raises(wa.InvalidArgumentError, match="from_dimensional"):
        crit.to_si(wa.Params(0.3, 1.0))
    with pytest.raises(TypeError, match="Params with scales or a Scales"):
        crit.to_si(3.0)


# --- reprs and tables ----------------------------------------------------------------

def test_reprs_are_short():
    results = [
        wa.trace_branch("md", 0.3, 5.0),
        wa.load_path("dw", 0.3, 5.0),
        wa.critical_forces("dw", [[0.3], [0.6]], np.logspace(-2, 1, 100), errors="nan"),
        wa.equilibrium("md", 0.3, 1.0, np.linspace(0.01, 0.49, 500)),
        wa.profile("dw", 0.3, 1.0, 0.2),
        wa.gap_law("md", 0.3, 1.0, np.linspace(0, 1.5, 1000)),
        wa.gap_path("md", 0.3, 1.0),
        wa.gap_critical("dw", 0.3, np.linspace(0.5, 2, 20)),
        wa.energy_lost("dw", 0.3, [1.0, 10.0]),
        wa.adhesion_map("dw", (0.1, 1.0, 3), (0.1, 10.0, 4)),
    ]
    for r in results:
        text = repr(r)
        assert len(text) <= 300 and text.startswith(type(r).__name__ + "("), text
    assert "P_fc=" in repr(results[1]) and "folds_P=" in repr(results[0])
    assert "mu=5" in repr(results[0])


def test_to_dataframe():
    pd = pytest.importorskip("pandas")
    crit = wa.critical_forces("dw", 0.3, [1.0, -1.0, 2.0], errors="nan")
    df = crit.to_dataframe()
    assert isinstance(df, pd.DataFrame) and len(df) == 3
    assert list(df.columns[:4]) == ["model", "alpha", "mu", "P_fc"]
    assert df["message"][1] == crit.messages[(1,)] and df["message"][0] == ""
    b = wa.trace_branch("dw", 0.3, 5.0)
    df = b.to_dataframe()
    assert len(df) == len(b) and (df["alpha"] == 0.3).all()
    params = wa.Params.from_dimensional(**SI)
    df = wa.gap_law("md", 0.3, 1.0, [0.2, 0.5]).to_si(params).to_dataframe()
    assert "gbar [m]" in df.columns and "F_retract [N/m]" in df.columns
    gc = wa.gap_critical("dw", 0.3, [1.0, -1.0], errors="nan").to_dataframe()
    assert gc["message"][1] and gc["status"][1] == 1
    amap = wa.adhesion_map("dw", (0.1, 1.0, 3), (0.1, 10.0, 4))
    assert len(amap.to_dataframe()) == 12


def test_to_dataframe_without_pandas(monkeypatch):
    monkeypatch.setitem(sys.modules, "pandas", None)       # import pandas fails
    with pytest.raises(ImportError, match="pip install pandas"):
        wa.critical_forces("dw", 0.3, 1.0).to_dataframe()


def test_pandas_not_imported():
    import subprocess
    code = ("import sys, numpy as np, wavyadhesion as wa; "
            "r = wa.critical_forces('dw', 0.3, [1.0, 2.0]); repr(r); "
            "r.to_si(wa.Params.from_dimensional(Estar=1e6, period=1e-3, amplitude=1e-5, "
            "work_of_adhesion=0.05, peak_stress=1e5)); print('pandas' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True)
    assert out.stdout.strip() == "False"


# --- progress ------------------------------------------------------------------------

SWEEPS = {
    "critical_forces": lambda **k: wa.critical_forces("dw", 0.3, np.linspace(0.5, 3, 40), **k),
    "energy_lost": lambda **k: wa.energy_lost("dw", 0.3, np.linspace(0.5, 3, 40), **k),
    "gap_critical": lambda **k: wa.gap_critical("dw", 0.3, np.linspace(0.5, 3, 40), **k),
    "adhesion_map": lambda **k: wa.adhesion_map("dw", (0.1, 1.0, 3), (0.1, 10.0, 4),
                                                forces=True, **k),
}


@pytest.mark.parametrize("name", SWEEPS)
@pytest.mark.parametrize("parallel", [False, True])
def test_progress_callable(name, parallel):
    calls = []
    kwargs = {"progress": lambda done, total: calls.append((done, total))}
    if parallel and name != "gap_critical":
        with ThreadPoolExecutor(2) as ex:
            result = SWEEPS[name](executor=ex, **kwargs)
    else:
        result = SWEEPS[name](**kwargs)
    done = [d for d, _ in calls]
    total = calls[0][1]
    assert calls[0][0] == 0 and done[-1] == total and len(calls) >= 2
    assert done == sorted(done) and all(t == total for _, t in calls)
    assert total == (1 + 3 if name == "adhesion_map" else 40)
    # the same results as without progress
    plain = SWEEPS[name]()
    for field in ("P_fc", "W_star", "g_touch", "fc_region"):
        if hasattr(result, field):
            np.testing.assert_array_equal(getattr(result, field), getattr(plain, field))


def test_progress_true_without_tqdm_writes_a_line(monkeypatch, capsys):
    monkeypatch.setitem(sys.modules, "tqdm", None)
    monkeypatch.setitem(sys.modules, "tqdm.auto", None)
    wa.critical_forces("dw", 0.3, np.linspace(0.5, 3, 40), progress=True)
    err = capsys.readouterr().err
    assert "critical_forces: 0/40" in err and err.endswith("critical_forces: 40/40\n")


def test_progress_refuses_other_values():
    with pytest.raises(TypeError, match="progress = 'yes'"):
        wa.critical_forces("dw", 0.3, [1.0, 2.0], progress="yes")


# --- exceptions, annotations, structure ------------------------------------------------

def test_convergence_error_is_a_runtime_error():
    assert issubclass(wa.ConvergenceError, RuntimeError)
    assert issubclass(wa.NoSolutionError, RuntimeError)
    with pytest.raises(RuntimeError):
        wa.profile("dw", 0.3, 1.0, 0.0)                   # DW has no state at a* = 0


def _public_functions():
    import wavyadhesion.plotting as plotting
    funcs = [getattr(wa, n) for n in wa.__all__ if inspect.isfunction(getattr(wa, n))]
    funcs += [getattr(plotting, n) for n in plotting.__all__]
    funcs.append(wa.Params.from_dimensional)
    return funcs


def test_every_public_function_is_annotated():
    funcs = _public_functions()
    assert len(funcs) >= 20
    for func in funcs:
        sig = inspect.signature(inspect.unwrap(func))
        missing = [p for p in sig.parameters if p != "cls"
                   and sig.parameters[p].annotation is inspect.Parameter.empty]
        assert not missing, f"{func.__name__}: {missing} not annotated"
        assert sig.return_annotation is not inspect.Signature.empty, func.__name__


def test_modules_import_no_private_names_of_each_other():
    """A module imports only public names of its siblings (and the extension itself)."""
    package = Path(wa.__file__).parent
    for path in package.glob("*.py"):
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, ast.ImportFrom) and node.level == 1:
                for alias in node.names:
                    assert not alias.name.startswith("_") or (
                        node.module is None and alias.name == "_wa_f2py"), (
                        f"{path.name} imports {alias.name} from .{node.module}")
