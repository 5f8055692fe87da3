"""load_path and critical_forces: values against the command line, broadcasting,
mechanisms, exceptions."""

import numpy as np
import pytest

import wavyadhesion as wa

# `wavyadhesion critical --model M --alpha A --mu U --format csv` (17 significant
# digits: the same doubles to ~1 ulp).
CLI_CRITICAL = [
    ("dw", 0.3, 0.1, 9.7782736093678035e-01, -2.2172639063219639e-02),
    ("dw", 0.3, 1.0, 7.7827360936780365e-01, -8.8714284799719476e-02),
    ("dw", 0.3, 5.0, 3.8750724174362811e-01, -1.1995262953240982e-01),
    ("dw", 0.6, 0.1, 9.6480312942613400e-01, -3.5196870573866043e-02),
    ("dw", 0.6, 1.0, 6.4803129426133954e-01, -2.3352051827366549e-01),
    ("dw", 0.6, 5.0, 0.0, -7.8778223218930721e-01),
    ("dw", 1.0, 0.01, 9.9505230160693392e-01, -4.9476983930660913e-03),
    ("dw", 1.0, 1.0, 5.0523016069339088e-01, -4.9476983930660912e-01),
    ("dw", 1.0, 10.0, 0.0, -3.9513045159115725e+00),
    ("md", 0.3, 1.0, 5.5654721873560731e-01, -9.0525660009991279e-02),
    ("md", 0.3, 5.0, 3.8764647725517604e-01, -1.3466548525864468e+00),
    ("jkr", 0.3, 1.0, 3.8772776072055104e-01, -np.inf),
]


@pytest.mark.parametrize("model, alpha, mu, p_fc, p_pf", CLI_CRITICAL)
def test_critical_values(model, alpha, mu, p_fc, p_pf):
    got_fc, got_pf = wa.critical_forces(model, alpha, mu)
    assert got_fc.shape == () and isinstance(got_fc, np.floating)
    np.testing.assert_allclose([got_fc, got_pf], [p_fc, p_pf], rtol=1e-14, atol=1e-300)
    path = wa.load_path(model, alpha, mu)
    assert (path.P_fc, path.P_pf) == (got_fc, got_pf)


def test_vectorised_equals_scalar_calls():
    alpha = np.array([[0.3], [0.6], [1.0]])
    mu = np.array([0.05, 0.5, 2.0, 4.0])
    crit = wa.critical_forces("dw", alpha, mu)
    assert crit.P_fc.shape == crit.P_pf.shape == crit.fc_mechanism.shape == (3, 4)
    for i in range(3):
        for j in range(4):
            path = wa.load_path("dw", alpha[i, 0], mu[j])
            assert crit.P_fc[i, j] == path.P_fc and crit.P_pf[i, j] == path.P_pf
            assert wa.MECHANISMS[crit.fc_mechanism[i, j]] == path.fc_mechanism
            assert wa.MECHANISMS[crit.pf_mechanism[i, j]] == path.pf_mechanism


def test_one_call_per_alpha_chunk(monkeypatch):
    """Points sharing an alpha go to the facade together, in chunks of _CHUNK_SWEEP mu
    (between chunks Python can raise KeyboardInterrupt)."""
    from wavyadhesion import _loadpath, _wa_f2py as _f
    calls = []
    real = _f.fa_critical_sweep

    def spy(*args):
        calls.append((args[1], len(args[2])))
        return real(*args)

    monkeypatch.setattr(_f, "fa_critical_sweep", spy)
    wa.critical_forces("dw", [0.3, 0.6, 0.3, 0.6], np.linspace(0.1, 3.0, 4))
    assert sorted(calls) == [(0.3, 2), (0.6, 2)]
    calls.clear()
    wa.critical_forces("dw", 0.3, np.logspace(-2, 1, 50))
    chunk = _loadpath._CHUNK_SWEEP
    assert calls == [(0.3, chunk)] * (50 // chunk) + [(0.3, 50 % chunk)]


def test_mechanisms_dw_alpha03():
    """The changes the CLI locates for DW, alpha 0.3: P_pf gradual -> jump case 1 at
    mu = 0.580, P_fc gradual -> jump case 1 at 2.773, P_pf jump case 1 -> case 2 at 4.887."""
    crit = wa.critical_forces("dw", 0.3, [0.57, 0.59, 2.7, 2.85, 4.8, 5.0])
    assert [wa.MECHANISMS[m] for m in crit.fc_mechanism] == [
        "gradual", "gradual", "gradual", "jump_case1", "jump_case1", "jump_case1"]
    assert [wa.MECHANISMS[m] for m in crit.pf_mechanism] == [
        "gradual", "jump_case1", "jump_case1", "jump_case1", "jump_case1", "jump_case2"]


def test_empty_and_broadcast_shapes():
    crit = wa.critical_forces("dw", 0.3, np.empty((0, 3)))
    assert crit.P_fc.shape == (0, 3)
    with pytest.raises(ValueError):
        wa.critical_forces("dw", [0.3, 0.6], [1.0, 2.0, 3.0])


def test_load_path_dw_paper_case():
    """`wavyadhesion path --model dw --alpha 0.3 --mu 5`."""
    path = wa.load_path("dw", 0.3, 5.0)
    assert len(path) == 7
    np.testing.assert_array_equal(path.stage, [1, 1, 1, 1, 2, 2, 2])
    np.testing.assert_array_equal(path.event, [3, 4, 3, 5, 6, 3, 7])
    for name in ("stage", "event", "a_star", "c_star", "P_star"):
        assert getattr(path, name).shape == (7,)
    np.testing.assert_allclose(path.a_star[1], 1.4954454098314016e-01, rtol=1e-12)
    np.testing.assert_allclose(path.P_star[4], -1.0863195316098184e-01, rtol=1e-12)
    np.testing.assert_allclose(path.loop_area, 1.5866561722922617e-01, rtol=1e-3)  # trapezoidal area
    assert path.mechanisms == {"full_contact": "jump_case1", "pull_off": "jump_case2"}
    kinds = [(e.stage, e.kind) for e in path.events]
    assert kinds[-1] == ("unloading", "pull_off")
    assert kinds[3] == ("loading", "full_contact_reached")
    assert path.events[3].P_star == path.P_fc and path.events[-1].P_star == path.P_pf


def test_load_path_jkr():
    path = wa.load_path("jkr", 0.3, 1.0)
    assert np.isneginf(path.P_pf)
    assert path.events[-1].kind == "pull_off"


@pytest.mark.parametrize("model", wa.MODELS)
@pytest.mark.parametrize("alpha, mu, name", [
    (0.0, 1.0, "alpha"), (np.nan, 1.0, "alpha"), (0.3, -1.0, "mu"), (0.3, np.inf, "mu"),
])
def test_invalid_arguments(model, alpha, mu, name):
    with pytest.raises(wa.InvalidArgumentError, match=name):
        wa.load_path(model, alpha, mu)
    with pytest.raises(wa.InvalidArgumentError, match=name):
        wa.critical_forces(model, alpha, mu)


def test_invalid_point_index():
    mu = np.array([[0.5, 1.0], [-2.0, 3.0]])
    with pytest.raises(wa.InvalidArgumentError, match=r"mu .*index \(1, 0\)"):
        wa.critical_forces("dw", 0.3, mu)
    with pytest.raises(wa.InvalidArgumentError, match=r"alpha"):
        wa.critical_forces("dw", [0.3, -0.3], 1.0)


def test_errors_nan_isolates_bad_points():
    crit = wa.critical_forces("dw", 0.3, [1.0, -1.0, 5.0], errors="nan")
    assert np.isnan(crit.P_fc[1]) and crit.fc_mechanism[1] == -1
    assert crit.P_fc[0] == wa.critical_forces("dw", 0.3, 1.0).P_fc
    assert crit.P_pf[2] == wa.critical_forces("dw", 0.3, 5.0).P_pf
    with pytest.raises(ValueError, match="errors"):
        wa.critical_forces("dw", 0.3, 1.0, errors="ignore")


def test_unknown_model():
    with pytest.raises(ValueError, match="model"):
        wa.critical_forces("dww", 0.3, 1.0)
    with pytest.raises(ValueError, match="model"):
        wa.load_path(3, 0.3, 1.0)


@pytest.mark.parametrize("model,alpha,mu", [("dw", 0.3, 5.0), ("md", 0.3, 1.0), ("md", 0.3, 5.0)])
def test_jump_energies_are_released(model, alpha, mu):
    """Each load-control jump from a contact state that lands on the branch (a jump end
    or full contact) releases a finite energy >= 0; every other event carries NaN."""
    path = wa.load_path(model, alpha, mu)
    landing = np.r_[np.isin(path.event[1:], (4, 5)), False]
    starts = (path.event == 3) & landing & (path.a_star > 0)
    assert starts.any()
    assert np.all(np.isfinite(path.jump_energy[starts]))
    assert np.all(path.jump_energy[starts] >= -1e-13)
    assert np.all(np.isnan(path.jump_energy[~starts]))
