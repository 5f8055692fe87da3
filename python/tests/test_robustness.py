"""Issue 9: inputs numpy would silently misread (None, complex, masked, strings), work
split into chunks (results unchanged, Ctrl-C honoured between chunks) and sweeps that
keep every good point."""

import signal
import subprocess
import sys
import textwrap
import time

import numpy as np
import pytest

import wavyadhesion as wa
from wavyadhesion import (_args, _equilibrium, _gapcritical, _loadpath, _profile,
                          _wa_f2py as _f)


def _small_chunks(monkeypatch, points, sweep):
    for module in (_equilibrium, _profile):
        monkeypatch.setattr(module, "_CHUNK_POINTS", points)
    for module in (_loadpath, _gapcritical):
        monkeypatch.setattr(module, "_CHUNK_SWEEP", sweep)


def test_invalid_type_error_is_type_and_value_error():
    assert issubclass(wa.InvalidTypeError, TypeError)
    assert issubclass(wa.InvalidTypeError, wa.InvalidArgumentError)
    assert issubclass(wa.InvalidTypeError, ValueError)


CALLS = {
    "westergaard_load": lambda **k: wa.westergaard_load(k["a"]),
    "jkr_load": lambda **k: wa.jkr_load(k["alpha"], k["a"]),
    "equilibrium": lambda **k: wa.equilibrium("dw", k["alpha"], k["mu"], k["a"]),
    "critical_forces": lambda **k: wa.critical_forces("dw", k["alpha"], k["mu"]),
    "roots": lambda **k: wa.roots("dw", k["alpha"], k["mu"], k["a"]),
    "trace_branch": lambda **k: wa.trace_branch("dw", k["alpha"], k["mu"]),
    "load_path": lambda **k: wa.load_path("dw", k["alpha"], k["mu"]),
    "Params": lambda **k: wa.Params(k["alpha"], k["mu"]),
}
ARGS = {
    "westergaard_load": ["a"], "jkr_load": ["alpha", "a"],
    "equilibrium": ["alpha", "mu", "a"], "critical_forces": ["alpha", "mu"],
    "roots": ["alpha", "mu", "a"], "trace_branch": ["alpha", "mu"],
    "load_path": ["alpha", "mu"], "Params": ["alpha", "mu"],
}
GOOD = {"alpha": 0.3, "mu": 1.0, "a": 0.2}
BAD = {
    "None": None,
    "complex": 0.2 + 0j,
    "complex array": np.array([0.2, 0.3], dtype=complex),
    "None in a list": [0.2, None],
    "complex in a list": [0.2, 1j],
    "string": "0.2",
    "string array": np.array(["0.2"]),
    "bytes": b"0.2",
    "masked": np.ma.masked_array([0.2, 0.3], mask=[False, True]),
}
SCALAR_ONLY = {"roots", "trace_branch", "load_path", "Params"}


@pytest.mark.parametrize("bad", BAD)
@pytest.mark.parametrize("func", CALLS)
def test_misreadable_inputs_raise_type_error_naming_argument(func, bad):
    for name in ARGS[func]:
        kwargs = dict(GOOD, **{name: BAD[bad]})
        with pytest.raises(TypeError) as info:
            CALLS[func](**kwargs)
        assert name in str(info.value), (func, bad, str(info.value))
        assert isinstance(info.value, wa.InvalidArgumentError)
        assert " = nan" not in str(info.value).lower()      # None was read as NaN


@pytest.mark.parametrize("func", sorted(set(CALLS) - SCALAR_ONLY))
def test_masked_array_without_masked_values_is_plain_data(func):
    for name in ARGS[func]:
        plain = CALLS[func](**dict(GOOD, **{name: np.array([GOOD[name]] * 2)}))
        masked = CALLS[func](**dict(GOOD, **{name: np.ma.masked_array([GOOD[name]] * 2)}))
        np.testing.assert_array_equal(np.asarray(tuple(plain) if func == "equilibrium"
                                                 or func == "critical_forces" else plain),
                                      np.asarray(tuple(masked) if func == "equilibrium"
                                                 or func == "critical_forces" else masked))


@pytest.mark.parametrize("model", [None, 2, 2.0, b"dw"])
def test_model_must_be_a_string(model):
    with pytest.raises(TypeError, match="model"):
        wa.equilibrium(model, 0.3, 1.0, 0.2)


def test_params_errors_name_the_argument():
    with pytest.raises(TypeError, match="alpha"):
        wa.Params(None, 1.0)
    with pytest.raises(TypeError, match="mu"):
        wa.Params(0.3, "one")
    with pytest.raises(wa.InvalidArgumentError, match="alpha must be a scalar"):
        wa.Params([0.3, 0.4], 1.0)


@pytest.mark.parametrize("name", ["Estar", "period", "amplitude", "work_of_adhesion",
                                  "peak_stress"])
@pytest.mark.parametrize("bad", [None, 1j, "1e6", [1.0, 2.0]])
def test_from_dimensional_errors_name_the_argument(name, bad):
    base = dict(Estar=1e6, period=1e-3, amplitude=1e-5, work_of_adhesion=0.05,
                peak_stress=1e5)
    if name == "Estar" and bad is None:     # None means "not given": use the moduli
        with pytest.raises(wa.InvalidArgumentError, match="E1, nu1, E2, nu2"):
            wa.Params.from_dimensional(**dict(base, Estar=None))
        return
    with pytest.raises(wa.InvalidArgumentError, match=name):
        wa.Params.from_dimensional(**dict(base, **{name: bad}))


@pytest.mark.parametrize("name", ["E1", "nu1", "E2", "nu2"])
def test_from_dimensional_moduli_errors_name_the_argument(name):
    moduli = dict(E1=1e6, nu1=0.3, E2=1e9, nu2=0.3)
    base = dict(period=1e-3, amplitude=1e-5, work_of_adhesion=0.05, peak_stress=1e5)
    with pytest.raises(TypeError, match=name):
        wa.Params.from_dimensional(**base, **dict(moduli, **{name: 1j}))
    with pytest.raises(wa.InvalidArgumentError, match=f"missing: {name}"):
        wa.Params.from_dimensional(**base, **dict(moduli, **{name: None}))


# --- chunking ------------------------------------------------------------------------------

@pytest.fixture
def small_chunks(monkeypatch):
    _small_chunks(monkeypatch, 7, 3)


def test_chunked_results_equal_one_call(monkeypatch):
    a = np.linspace(0.01, 0.49, 50).reshape(5, 10)
    alpha = np.linspace(0.2, 0.4, 10)
    whole = wa.equilibrium("md", alpha, 1.0, a)
    jkr = wa.jkr_load(alpha, a)
    wl = wa.westergaard_load(a)
    crit = wa.critical_forces("dw", [[0.3], [0.6]], np.linspace(0.1, 5, 8))
    _small_chunks(monkeypatch, 7, 3)
    chunked = wa.equilibrium("md", alpha, 1.0, a)
    for x, y in zip(whole, chunked):
        np.testing.assert_array_equal(x, y)
    np.testing.assert_array_equal(jkr, wa.jkr_load(alpha, a))
    np.testing.assert_array_equal(wl, wa.westergaard_load(a))
    crit2 = wa.critical_forces("dw", [[0.3], [0.6]], np.linspace(0.1, 5, 8))
    for name in ("P_fc", "P_pf", "fc_mechanism", "pf_mechanism", "status"):
        np.testing.assert_array_equal(getattr(crit, name), getattr(crit2, name))


def test_chunked_error_index(small_chunks):
    a = np.full((4, 5), 0.2)
    a[3, 1] = 0.9                                     # flat index 16: third chunk of 7
    with pytest.raises(wa.InvalidArgumentError, match=r"index \(3, 1\)"):
        wa.equilibrium("dw", 0.3, 1.0, a)
    with pytest.raises(wa.InvalidArgumentError, match=r"index \(3, 1\)"):
        wa.westergaard_load(a)
    with pytest.raises(wa.InvalidArgumentError, match=r"index \(3, 1\)"):
        wa.jkr_load(0.3, a)
    eq = wa.equilibrium("dw", 0.3, 1.0, a, errors="nan")
    assert np.isnan(eq.P_star[3, 1]) and np.isfinite(np.delete(eq.P_star.ravel(), 16)).all()
    mu = np.ones((2, 4))
    mu[1, 2] = -1.0
    with pytest.raises(wa.InvalidArgumentError, match=r"mu .*index \(1, 2\)"):
        wa.critical_forces("dw", 0.3, mu)
    crit = wa.critical_forces("dw", 0.3, mu, errors="nan")
    assert crit.status[1, 2] == 1 and np.isnan(crit.P_fc[1, 2])
    assert "mu" in crit.messages[(1, 2)]
    assert (crit.status == 0).sum() == 7 and np.isfinite(crit.P_fc[crit.ok]).all()


# --- sweeps keep every good point --------------------------------------------------------

@pytest.mark.parametrize("model, alpha, mu", [
    ("md", 1.0, [0.5, 0.79369860901363931, 2.0]),      # issue 9 item 4
    ("dw", 0.3, [1.0, 0.0, 5.0]),                       # issue 9 item 3
])
def test_failing_point_gives_nan_and_status(model, alpha, mu):
    crit = wa.critical_forces(model, alpha, mu, errors="nan")
    for i, m in enumerate(mu):
        try:
            ref = wa.load_path(model, alpha, m)
        except wa.ConvergenceError as exc:
            assert crit.status[i] == exc.status != 0
            assert np.isnan(crit.P_fc[i]) and np.isnan(crit.P_pf[i])
            assert crit.fc_mechanism[i] == crit.pf_mechanism[i] == -1
            assert crit.messages[(i,)] == exc.message       # the library's own message
            with pytest.raises(wa.ConvergenceError, match=rf"index \({i},\).*mu = {m!r}"):
                wa.critical_forces(model, alpha, mu)
        else:
            assert crit.status[i] == 0 and (i,) not in crit.messages
            assert (crit.P_fc[i], crit.P_pf[i]) == (ref.P_fc, ref.P_pf)
    assert crit.ok.sum() >= 2


def test_scalar_critical_forces_status():
    crit = wa.critical_forces("dw", 0.3, 1.0)
    assert crit.status == 0 and crit.messages == {} and crit.ok
    assert np.ndim(crit.status) == 0


# --- Ctrl-C ------------------------------------------------------------------------------

LONG_CALLS = {
    # ~2e6 MD points (~20 s in one call here), 489 chunks
    "equilibrium": ("_f.fa_equilibrium",
                    "wa.equilibrium('md', 0.3, 1.0, np.tile(np.linspace(0.01, 0.49, 1000), "
                    "2000))"),
    # 2000 MD mu (~40 s), 125 chunks
    "critical_forces": ("_f.fa_critical_sweep",
                        "wa.critical_forces('md', 0.3, np.linspace(0.1, 5.0, 2000))"),
}


@pytest.mark.parametrize("func", LONG_CALLS)
def test_long_call_is_interruptible(func):
    target, call = LONG_CALLS[func]
    code = textwrap.dedent(f"""
        import sys, numpy as np, wavyadhesion as wa
        from wavyadhesion import _wa_f2py as _f
        calls = [0]
        real = {target}
        def spy(*args):
            calls[0] += 1
            if calls[0] == 2:
                print("started", flush=True)
            return real(*args)
        setattr(_f, "{target.split('.')[1]}", spy)
        try:
            {call}
        except KeyboardInterrupt:
            print("interrupted after", calls[0], "calls", flush=True)
            sys.exit(130)
        print("finished", calls[0], flush=True)
    """)
    proc = subprocess.Popen([sys.executable, "-c", code], stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True)
    try:
        assert proc.stdout.readline().strip() == "started"
        time.sleep(0.2)
        proc.send_signal(signal.SIGINT)
        out, err = proc.communicate(timeout=120)
    finally:
        proc.kill()
    assert proc.returncode == 130, (out, err)
    calls = int(out.split()[2])
    total = 489 if func == "equilibrium" else 125
    print(func, out.strip())
    assert 2 <= calls < total / 2, out


@pytest.mark.parametrize("mu, text", [(-1e300, "-1.00000E+300"), (-1e-310, "-1.00000E-310"),
                                      (-2.5, "-2.50000E+00")])
def test_messages_keep_the_exponent_letter(mu, text):
    # es12.5 printed 1e300 as "1.00000+300" (issue 9 item 8)
    with pytest.raises(wa.InvalidArgumentError) as info:
        wa.equilibrium("dw", 0.3, mu, 0.2)
    assert f"mu = {text} is outside" in str(info.value)


def test_domain_bounds_equal_the_header(repo):
    """critical_forces finds the first bad point with these bounds (the library decides)."""
    import re
    header = (repo / "include" / "wavyadhesion.h").read_text()
    c = dict(re.findall(r"#define\s+(WA_(?:ALPHA|MU)_M(?:IN|AX))\s+(\S+)", header))
    assert (_args.ALPHA_MIN, _args.ALPHA_MAX, _args.MU_MIN, _args.MU_MAX) == tuple(
        float(c[k]) for k in ("WA_ALPHA_MIN", "WA_ALPHA_MAX", "WA_MU_MIN", "WA_MU_MAX"))


@pytest.mark.parametrize("alpha, mu, name, index", [
    ([0.3, 2e12], 1.0, "alpha", "(1,)"), (0.3, [1.0, 1e-200], "mu", "(1,)"),
    ([0.3, 0.6], [[1.0, 1.0], [1e101, 1.0]], "mu", "(1, 0)"),
])
def test_sweep_domain_checked_before_any_work(monkeypatch, alpha, mu, name, index):
    calls = []
    real = _f.fa_critical_sweep

    def spy(code, a, m):
        calls.append(len(m))
        return real(code, a, m)

    monkeypatch.setattr(_f, "fa_critical_sweep", spy)
    monkeypatch.setattr(_loadpath, "_CHUNK_SWEEP", 1)
    with pytest.raises(wa.InvalidArgumentError, match=rf"{name} .*index \{index[:-1]}\)"):
        wa.critical_forces("dw", alpha, mu)
    assert calls == [1]                  # only the call that words the message


# ---- issue 2: MD at huge Sigma0 blamed an argument the caller never passed ----------

REPRO_MD = (194144313374.73993, 256617602357780.94)


@pytest.mark.parametrize("call", [
    lambda a, m: wa.trace_branch("md", a, m),
    lambda a, m: wa.critical_forces("md", a, m),
    lambda a, m: wa.gap_path("md", a, m),
    lambda a, m: wa.gap_law("md", a, m, [0.5, 2.0]),
    lambda a, m: wa.gap_critical("md", a, m),
], ids=["trace_branch", "critical_forces", "gap_path", "gap_law", "gap_critical"])
def test_md_huge_sigma0_is_an_honest_numerical_error(call):
    """Formerly InvalidArgumentError "c_star = 5.00000E-01 is outside its valid range"."""
    with pytest.raises(wa.ConvergenceError) as info:
        call(*REPRO_MD)
    assert not isinstance(info.value, wa.InvalidArgumentError)
    assert info.value.status == 5
    assert "closer than 1e-15 to a* = 1/2" in info.value.message


# ---- issue 7: Westergaard and JKR profiles at extreme a* ---------------------------

def test_jkr_profile_tiny_a_star_reproducer():
    """wa_profile(1, 5.53e-07, 1.3, 5.59e-266, 5.59e-266) was NUMERICAL_ERROR; values from
    test/data/separation_tiny.txt (mpmath, tools/reference/make_tiny_contact_reference.py)."""
    a = 5.59e-266
    prof = wa.profile("jkr", 5.53e-07, 1.3, a, a, x=[0.0, 2 * a, 0.25])
    expected_t = -1.3196060288092605297e+126
    expected_g = 6.1039062979136195849e-139
    assert prof.traction[0] == pytest.approx(expected_t, rel=1e-13)
    assert prof.gap[1] == pytest.approx(expected_g, rel=1e-13)
    assert prof.gap[2] == pytest.approx(1.0, rel=1e-15)


@pytest.mark.parametrize("a", [5e-324, 1e-300, 1e-266])
def test_westergaard_profile_tiny_a_star_is_finite(a):
    prof = wa.profile("westergaard", 0.3, 0.0, a, a, x=[0.0, 0.25, 0.5])
    assert np.all(np.isfinite(prof.traction)) and np.all(np.isfinite(prof.gap))
    assert prof.traction[0] == pytest.approx(2 * np.pi * a, rel=1e-13, abs=1e-320)
    assert prof.gap[1] == pytest.approx(1.0, rel=1e-15)
