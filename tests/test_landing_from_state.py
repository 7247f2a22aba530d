"""Landing.from_state and Landing.at: a landing started from any state, followed in time.

The checks are independent of the kernel they test where they can be: the flight against the
closed-form torque-free flight of :class:`coinflight.model.toss.Flight` (DHM 2007's solution
in the body frame, core.torque_free) and the ballistic formula; the landing from a toss's
launch state against the toss's own landing (core.bounce.land); energy against its
definition.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from coinflight.core.bounce import CONTACT_GAP
from coinflight.core.impact import resting_face
from coinflight.core.outcome import Status
from coinflight.model.coin import Coin
from coinflight.model.surface import Surface
from coinflight.model.toss import Flight, Toss
from coinflight.outcomes.table import Landing, contact_record

G = 9.81
NICKEL = Coin.preset("us-nickel")
TABLE = Surface("table", drop_height=0.3, restitution=0.5, friction=0.3)


def _launch(toss: Toss, surface: Surface) -> dict[str, object]:
    """The state a toss starts from: at the drop height above the table, heads up, rising at
    v0, spinning at its body ω (the body frame is the lab's at launch, heads up)."""
    return {
        "position": (0.0, 0.0, surface.drop_height),
        "orientation": Rotation.identity(),
        "velocity": (0.0, 0.0, float(toss.launch_speed)),
        "angular_velocity": tuple(float(x) for x in toss.omega),
    }


def _energy(states, coin: Coin) -> np.ndarray:
    """½ m v² + ½ ω·L + m g z, J."""
    m = coin.mass
    kinetic = 0.5 * m * np.sum(states.velocity**2, axis=-1)
    rotation = 0.5 * np.sum(states.angular_velocity * states.angular_momentum, axis=-1)
    return kinetic + rotation + m * G * states.position[..., 2]


TOSSES = [(38.0, 2.0, 1.0, 0.45), (60.0, -5.0, 9.0, 0.5), (25.0, 0.5, -0.3, 0.4)]


@pytest.mark.parametrize(("wx", "wy", "wz", "flight_time"), TOSSES)
def test_from_the_launch_state_it_lands_as_the_toss(wx, wy, wz, flight_time):
    # Same physics from the same state: face, bounces and times agree with the toss's landing
    # (the contact search starts at the apex for a toss, at 0 here: the roots agree to the
    # contact search's tolerance, not to the bit).
    toss = Toss((wx, wy, wz), flight_time)
    landing = Landing(NICKEL, toss, TABLE)
    started = Landing.from_state(NICKEL, TABLE, **_launch(toss, TABLE))
    assert started.outcome.face_name == landing.outcome.face_name
    assert int(started.outcome.bounces) == int(landing.outcome.bounces)
    assert started.outcome.status_name == landing.outcome.status_name
    assert float(started.outcome.first_contact) == pytest.approx(
        float(landing.outcome.first_contact), abs=1e-9
    )
    assert float(started.outcome.settle_time) == pytest.approx(
        float(landing.outcome.settle_time), abs=1e-6
    )


@pytest.mark.parametrize(("wx", "wy", "wz", "flight_time"), TOSSES)
def test_the_first_flight_is_the_closed_form_one(wx, wy, wz, flight_time):
    toss = Toss((wx, wy, wz), flight_time)
    started = Landing.from_state(NICKEL, TABLE, **_launch(toss, TABLE))
    first = float(started.outcome.first_contact)
    t = np.linspace(0.0, first, 50, endpoint=False)
    got = started.at(t)
    flight = Flight(NICKEL, toss).at(t)
    np.testing.assert_allclose(got.normal, flight.normal, atol=1e-9)
    np.testing.assert_allclose(got.angular_momentum, flight.angular_momentum, rtol=1e-12)
    v0 = float(toss.launch_speed)
    np.testing.assert_allclose(got.position[:, 2], TABLE.drop_height + v0 * t - 0.5 * G * t**2)
    np.testing.assert_allclose(got.velocity[:, 2], v0 - G * t)
    # ω = I⁻¹ L: the body's spin seen in the lab.
    lab = flight.attitude.apply(flight.omega)
    np.testing.assert_allclose(got.angular_velocity, lab, atol=1e-9)


def _tumbling_landing(rng: np.random.Generator, height: float) -> Landing:
    """A nickel started ``height`` m up (its centre), at a random attitude, tumbling at about
    40 rad/s and moving at about 0.5 m/s, drawn from ``rng``."""
    w = rng.normal(0.0, 40.0, 3)
    return Landing.from_state(
        NICKEL,
        TABLE,
        position=(0.0, 0.0, height),
        orientation=Rotation.random(random_state=rng),
        velocity=rng.normal(0.0, 0.5, 3),
        angular_velocity=w,
    )


def test_energy_never_grows_along_a_landing():
    rng = np.random.default_rng(5)
    for _ in range(20):
        landing = _tumbling_landing(rng, 0.2)
        t = np.linspace(0.0, landing.followed_until, 400)
        energy = _energy(landing.at(t), NICKEL)
        assert np.all(np.diff(energy) <= 1e-12 * energy[0]), np.max(np.diff(energy))
        # In flight it is conserved (no contact between two samples most of the time).
        assert np.isclose(energy[1], energy[0], rtol=1e-12) or landing.outcome.first_contact < t[1]


def test_every_time_lies_on_the_one_motion_the_outcome_comes_from():
    """Landing.at reaches each time by the ending's run from its start stopped there, the
    uninterrupted run's steps up to the last: the state at a time is the same bit for bit
    whatever other times are asked for, every time up to followed_until is followed (a roll
    stopped and carried on at each time would part from the run, chaotic, and settle at
    another time), and at followed_until the coin is in the well of the outcome's face."""
    rng = np.random.default_rng(8)
    checked = 0
    for _ in range(12):
        landing = _tumbling_landing(rng, 0.15)
        out = landing.outcome
        until = landing.followed_until
        t = np.linspace(0.0, until, 40)
        states = landing.at(t)
        for i in (13, 29, 39):
            one = landing.at(t[i])
            np.testing.assert_array_equal(one.position, states.position[i])
            np.testing.assert_array_equal(one.normal, states.normal[i])
            np.testing.assert_array_equal(one.angular_momentum, states.angular_momentum[i])
        if int(out.status) == Status.SETTLED_CONTACT:
            nz = float(states.normal[-1, 2])
            assert resting_face(nz, contact_record(NICKEL, TABLE, G).edge_sine) == int(out.face)
            checked += 1
    assert checked >= 6


def test_times_keep_their_order_and_shape():
    landing = Landing.from_state(
        NICKEL,
        TABLE,
        position=(0.01, -0.02, 0.2),
        orientation=Rotation.from_euler("xy", [30.0, 10.0], degrees=True),
        velocity=(0.1, 0.0, 0.0),
        angular_velocity=(20.0, 3.0, 1.0),
    )
    t = np.array([[0.15, 0.05], [0.0, 0.1]])
    states = landing.at(t)
    assert states.position.shape == (2, 2, 3)
    for index in np.ndindex(t.shape):
        one = landing.at(t[index])
        np.testing.assert_array_equal(states.position[index], one.position)
        np.testing.assert_array_equal(states.normal[index], one.normal)
    np.testing.assert_allclose(states.position[1, 0], (0.01, -0.02, 0.2))
    # Horizontal motion at constant velocity before the first contact.
    np.testing.assert_allclose(states.position[0, 1, 0], 0.01 + 0.1 * 0.05)


def test_a_coin_at_rest_on_its_face_is_accepted_and_handed_to_the_ending():
    # Touching the table (gap 0), not approaching: no impact, the verdict of a landing decides
    # at once (at rest below its well's barrier: settled, on its face).
    for angle, face in ((0.0, "heads"), (180.0, "tails")):
        landing = Landing.from_state(
            NICKEL,
            TABLE,
            position=(0.0, 0.0, 0.5 * NICKEL.thickness),
            orientation=Rotation.from_euler("x", angle, degrees=True),
            velocity=(0.0, 0.0, 0.0),
            angular_velocity=(0.0, 0.0, 0.0),
        )
        assert landing.outcome.face_name == face
        assert int(landing.outcome.bounces) == 0
        assert float(landing.outcome.first_contact) == 0.0


def test_a_coin_touching_and_approaching_strikes_at_once():
    landing = Landing.from_state(
        NICKEL,
        TABLE,
        position=(0.0, 0.0, 0.5 * NICKEL.thickness),
        orientation=Rotation.identity(),
        velocity=(0.0, 0.0, -2.0),
        angular_velocity=(0.0, 0.0, 0.0),
    )
    assert float(landing.outcome.first_contact) == 0.0
    after = landing.at([0.0])
    # The state at an impact's time is the one after it: flat, it rebounds at e × 2 m/s.
    assert after.velocity[0, 2] == pytest.approx(0.5 * 2.0, rel=1e-12)
    assert landing.outcome.face_name == "heads"


def test_the_lowest_point_may_not_start_below_the_table():
    tilt = Rotation.from_euler("x", 30.0, degrees=True)
    n = tilt.apply((0.0, 0.0, 1.0))
    depth = NICKEL.radius * np.sqrt(1.0 - n[2] ** 2) + 0.5 * NICKEL.thickness * abs(n[2])
    kwargs = {"orientation": tilt, "velocity": (0, 0, 0), "angular_velocity": (0, 0, 0)}
    Landing.from_state(NICKEL, TABLE, position=(0.0, 0.0, depth), **kwargs)  # touching: fine
    Landing.from_state(NICKEL, TABLE, position=(0.0, 0.0, depth - 0.5 * CONTACT_GAP), **kwargs)
    with pytest.raises(ValueError, match=r"position z = .* below the table"):
        Landing.from_state(NICKEL, TABLE, position=(0.0, 0.0, depth - 1e-6), **kwargs)


@pytest.mark.parametrize(
    ("change", "error", "words"),
    [
        ({"position": (0.0, np.nan, 0.3)}, ValueError, "position must be finite"),
        ({"velocity": (0.0, 0.0, np.inf)}, ValueError, "velocity must be finite"),
        ({"angular_velocity": (1.0, 2.0)}, ValueError, "angular_velocity must have 3"),
        ({"position": [[0.0, 0.0, 0.3]]}, ValueError, "position must have 3"),
        ({"orientation": np.eye(3)}, TypeError, "orientation must be a scipy"),
        ({"orientation": Rotation.random(3, random_state=1)}, ValueError, "one rotation"),
        ({"g": -1.0}, ValueError, "g"),
    ],
)
def test_bad_states_are_refused_naming_the_value(change, error, words):
    kwargs = {
        "position": (0.0, 0.0, 0.3),
        "orientation": Rotation.identity(),
        "velocity": (0.0, 0.0, 0.0),
        "angular_velocity": (0.0, 0.0, 0.0),
    }
    kwargs.update(change)
    with pytest.raises(error, match=words):
        Landing.from_state(NICKEL, TABLE, **kwargs)


def test_times_outside_what_is_followed_are_refused():
    landing = Landing.from_state(
        NICKEL,
        TABLE,
        position=(0.0, 0.0, 0.2),
        orientation=Rotation.from_euler("x", 20.0, degrees=True),
        velocity=(0.0, 0.0, 0.0),
        angular_velocity=(5.0, 0.0, 0.0),
    )
    with pytest.raises(ValueError, match="times must be non-negative"):
        landing.at([-0.1])
    with pytest.raises(ValueError, match="times must be at most"):
        landing.at([landing.followed_until + 1.0])
    with pytest.raises(TypeError, match="from_state"):
        Landing(NICKEL, Toss((30.0, 0.0, 0.0), 0.5), TABLE).at([0.1])
    with pytest.raises(ValueError, match="kind 'table'"):
        Landing.from_state(
            NICKEL,
            Surface("hand"),
            position=(0.0, 0.0, 0.2),
            orientation=Rotation.identity(),
            velocity=(0.0, 0.0, 0.0),
            angular_velocity=(0.0, 0.0, 0.0),
        )


@pytest.mark.parametrize("resistance", [0.0, 1e-4])
def test_a_coin_rolling_upright_on_its_band_is_followed_along_its_roll(resistance):
    """A nickel upright on its edge band, rolling straight at ω_a = 20 rad/s: Landing.at gives
    the closed-form roll at every time (the state at a time inside the band's roll is that
    roll's, not the state it entered it in). Without rolling resistance it rolls at r ω_a to
    the ending's limit (unsettled, on edge); with ℓ it slows at ℓ m g r / (I3 + m r²)
    (d/dt of (I3 + m r²) ω_a = −ℓ m g, a rigid wheel's rolling resistance) and settles on
    edge."""
    r, m = NICKEL.radius, NICKEL.mass
    i3 = float(NICKEL.moments[1])
    table = Surface("table", 0.3, 0.5, 0.3, resistance, resistance)
    rate = 20.0
    landing = Landing.from_state(
        NICKEL,
        table,
        position=(0.0, 0.0, r),
        orientation=Rotation.from_euler("y", 90.0, degrees=True),  # heads normal along +x
        velocity=(0.0, -r * rate, 0.0),  # rolling along n × z
        angular_velocity=(rate, 0.0, 0.0),
    )
    assert landing.outcome.face_name == "edge"
    t = np.array([0.0, 0.5, 1.0, 2.0])
    slowing = resistance * m * G * r / (i3 + m * r * r)  # m/s², along the roll
    expected = r * rate * t - 0.5 * slowing * t**2
    states = landing.at(t)
    np.testing.assert_allclose(-states.position[:, 1], expected, rtol=1e-9, atol=1e-12)
    np.testing.assert_allclose(states.position[:, 0], 0.0, atol=1e-12)
    np.testing.assert_allclose(states.normal[:, 2], 0.0, atol=1e-12)
    if resistance == 0.0:
        assert int(landing.outcome.status) == Status.UNSETTLED
    else:
        assert int(landing.outcome.status) == Status.SETTLED_CONTACT
