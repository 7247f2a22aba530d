"""Flight with air drag: the drag-free limit is the closed form; drag shortens the flight."""

from __future__ import annotations

import numpy as np
import pytest

from coinflight import Coin, Flight, Toss
from coinflight.core import drag
from coinflight.model.surface import Drag

COIN = Coin.preset("us-quarter")
I1, I3 = COIN.moments


def _model(cd=0.0, k=0.0):
    return drag.DragModel(COIN.mass, COIN.radius, (I1, I1, I3), 9.81, cd, k, 1.2)


@pytest.mark.parametrize(
    ("omega", "start"),
    [((80.0, 0.0, 0.0), 1.0), ((90.0, 30.0, 0.0), 1.0), ((60.0, 10.0, 40.0), -1.0)],
)
def test_zero_drag_is_the_closed_form(omega, start):
    toss = Toss(omega=omega, flight_time=0.7, start="heads" if start > 0 else "tails")
    t = np.linspace(0.0, 0.7, 15)
    states = drag.fly(_model(), omega, float(toss.launch_speed), t, start)
    exact = Flight(COIN, toss).at(t)
    np.testing.assert_allclose(drag.normal(states[:, 9:13]), exact.normal, atol=1e-9)
    np.testing.assert_allclose(states[:, 2], exact.height, atol=1e-9)
    np.testing.assert_allclose(states[:, 6:9], exact.omega, atol=1e-9 * 100)


def test_zero_drag_catch_is_at_T():
    t_catch, _ = drag.catch(_model(), (80.0, 0.0, 0.0), 0.5 * 9.81 * 0.7)
    assert t_catch == pytest.approx(0.7, abs=1e-9)


def test_drag_shortens_the_flight_and_damping_slows_the_spin():
    v0 = 0.5 * 9.81 * 0.7
    t_free, _ = drag.catch(_model(), (80.0, 0.0, 0.0), v0)
    t_drag, _ = drag.catch(_model(cd=1.17), (80.0, 0.0, 0.0), v0)
    assert t_drag < t_free
    # Pure damping −k ω about a diameter: ω(t) = ω0 exp(−k t / I1).
    k = 1e-8
    t = np.array([0.0, 0.3])
    states = drag.fly(_model(k=k), (80.0, 0.0, 0.0), v0, t)
    assert states[-1, 6] == pytest.approx(80.0 * np.exp(-k * 0.3 / I1), rel=1e-9)


@pytest.mark.parametrize(
    ("kwargs", "match"),
    [
        ({"coefficient": -1.0}, r"drag coefficient must be between 0 and 10, got -1.0"),
        (
            {"spin_damping": -1e-9},
            r"spin damping must be between 0 and 0.001 \(in N m s\)",
        ),
        ({"air_density": 0.0}, r"air density must be between 1e-06 and 10000 \(in kg/m³\), got 0"),
    ],
)
def test_bad_drag(kwargs, match):
    with pytest.raises(ValueError, match=match):
        Drag(**kwargs)
