"""wavyadhesion.gap_path: the event list of a gap-controlled cycle, equal to the CLI's
and consistent with gap_law (doc/user-guide.md, "Gap control")."""

import numpy as np
import pytest

import wavyadhesion as wa


def test_md_event_sequence_and_energy():
    path = wa.gap_path("md", 0.3, 1.0)
    # touch, jump onto the no-contact states, contact made, ..., interaction lost
    assert path.events[0][:2] == ("approach", "touch")
    assert path.events[-1][:2] == ("retraction", "interaction_lost")
    assert len(path.event) == 14
    assert path.gbar[0] == pytest.approx(1.0 + 2.0 * 0.15939878537739166, rel=1e-12)
    law = wa.gap_law("md", 0.3, 1.0, [0.5])
    assert path.W_star == law.W_star
    assert path.W_fraction == pytest.approx(path.W_star / (np.pi * 0.3**2 / 2), rel=1e-14)


def test_jumps_keep_gbar():
    path = wa.gap_path("dw", 0.3, 1.0)
    starts = np.nonzero(path.event == 3)[0]
    assert starts.size > 0
    for k in starts:
        assert path.event[k + 1] == 4
        assert path.gbar[k + 1] == pytest.approx(path.gbar[k], abs=1e-12)


def test_westergaard_has_no_hysteresis():
    path = wa.gap_path("westergaard", 0.3, 1.0)
    assert path.W_star == 0.0
    assert not np.any(path.event == 3)


@pytest.mark.parametrize("args", [("dw", -1.0, 1.0), ("dw", 0.3, float("nan")),
                                  ("nope", 0.3, 1.0), ("md", 0.3, -1.0)])
def test_bad_input(args):
    with pytest.raises(wa.InvalidArgumentError):
        wa.gap_path(*args)
