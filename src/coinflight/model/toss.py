"""A toss (initial conditions), its flight and its outcome: the value objects over the kernels."""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property
from typing import TYPE_CHECKING, Literal

import numpy as np
from numpy.typing import ArrayLike, NDArray

from coinflight import _validation as v
from coinflight.core import ballistics, torque_free
from coinflight.core.outcome import FACE_NAMES, face_from_alignment, same_side
from coinflight.model.coin import Coin

if TYPE_CHECKING:
    from scipy.spatial.transform import Rotation

Start = Literal["heads", "tails"]
STANDARD_GRAVITY = 9.81
"""Default g, m/s² (Stefan & Cheche use g without a value; 9.81 is the usual classroom value)."""

GRAVITY = v.Quantity(
    "g", "m/s²", 1e-3, 1e3, (0.1, 300.0), "a surface gravity (0.1 to 300 m/s²; Earth 9.81)"
)
"""g: hard range 0.001 to 1000 m/s² (a small asteroid to beyond the Sun's 274 m/s², so that
T = 2 v0 / g and the apex v0² / 2g stay finite), a warning outside 0.1 to 300 m/s²."""

FLIGHT_TIME = v.Quantity("flight time", "s", 1e-6, 1e4)
"""T: hard range 1 µs to 10⁴ s (with g ≤ 1000 m/s² the apex g T² / 8 stays below 10¹¹ m)."""

FloatArray = NDArray[np.float64]


def check_gravity(g: object) -> float:
    """``g`` inside :data:`GRAVITY`'s hard range (a warning outside its usual one), m/s²."""
    value = GRAVITY.check(g)
    hint = "did you give cm/s²?" if value > GRAVITY.high_usual else ""
    v.warn_outside(GRAVITY, value, hint, stacklevel=4)
    return value


def _together(
    first: str, a: tuple[int, ...], second: str, b: tuple[int, ...], each: str
) -> tuple[int, ...]:
    """The batch shape of two arrays broadcast together, or ValueError naming both: when
    their shapes do not broadcast, and when both have axes but not as many (NumPy would add
    axes on the left: 4 spins and 4 × 1 flight times would make 4 × 4 tosses)."""
    try:
        batch = np.broadcast_shapes(a, b)
    except ValueError:
        raise ValueError(
            f"{first} and {second} do not broadcast together; {each}, a single one, or "
            "shapes NumPy broadcasts"
        ) from None
    if a and b and len(a) != len(b):
        raise ValueError(
            f"{first} and {second} have different numbers of axes, which would broadcast to "
            f"{_tosses(batch)}; {each}, a single one, or both with the same number of axes"
        )
    return batch


def _tosses(shape: tuple[int, ...]) -> str:
    """A batch shape in words: "4 tosses", "4 × 4 tosses"."""
    return " × ".join(str(n) for n in shape) + (" tosses" if shape != (1,) else " toss")


@dataclass(frozen=True, eq=False)
class Toss:
    """Initial conditions of one toss, or of a batch of tosses (arrays broadcast together).

    Parameters
    ----------
    omega : array_like, shape (..., 3)
        Body-frame angular velocity at launch (ωx, ωy, ωz), rad/s. x and y are diameters of the
        coin, z its normal on the heads side.
    flight_time : array_like, shape (...)
        Time T from launch to catch at launch height, s (T = 2 v0 / g).
    start : {"heads", "tails"}
        The face up at launch.
    g : float
        Gravitational acceleration, m/s².

    Examples
    --------
    >>> toss = Toss(omega=(80.0, 0.0, 0.0), flight_time=0.7)
    >>> float(toss.launch_speed)  # v0 = g T / 2 with g = 9.81 m/s²
    3.4335
    """

    omega: FloatArray
    flight_time: FloatArray
    start: Start = "heads"
    g: float = STANDARD_GRAVITY

    def __post_init__(self) -> None:
        omega = v.finite("omega", self.omega, "rad/s")
        if omega.ndim == 0 or omega.shape[-1] != 3:
            raise ValueError(f"omega must have 3 components (ωx, ωy, ωz), got shape {omega.shape}")
        flight_time = FLIGHT_TIME.check_array(self.flight_time)
        g = check_gravity(self.g)
        v.choice("start", self.start, ("heads", "tails"))
        spins = omega.shape[:-1]
        batch = _together(
            f"omega (shape {omega.shape}, {_tosses(spins)})", spins,
            f"flight time (shape {flight_time.shape})", flight_time.shape,
            f"give one flight time per spin (shape {spins})",
        )  # fmt: skip
        if 0 in batch:
            raise ValueError(
                f"omega (shape {omega.shape}) and flight time (shape {flight_time.shape}) "
                "hold no toss; give at least one spin (ωx, ωy, ωz) and one flight time"
            )
        spin, time = np.broadcast_arrays(np.max(np.abs(omega), axis=-1), flight_time)
        if spin.size:
            with np.errstate(over="ignore"):
                k = int(np.argmax(spin * time))  # the toss with the largest phase
            v.phase_budget(spin.flat[k], time.flat[k], "largest spin component × flight time")
        # Private read-only copies: the caller's arrays can change; a validated toss cannot.
        omega, flight_time = omega.copy(), flight_time.copy()
        omega.flags.writeable = False
        flight_time.flags.writeable = False
        object.__setattr__(self, "omega", omega)
        object.__setattr__(self, "flight_time", flight_time)
        object.__setattr__(self, "g", g)

    @classmethod
    def from_launch_speed(
        cls,
        omega: ArrayLike,
        launch_speed: ArrayLike,
        start: Start = "heads",
        g: float = STANDARD_GRAVITY,
    ) -> Toss:
        """Toss from the launch speed v0 of the centre of mass (m/s) instead of the flight time."""
        v0 = v.positive("launch speed", launch_speed, "m/s")
        gg = GRAVITY.check(g)  # the range; Toss warns if g is unusual
        with np.errstate(over="ignore"):
            t = ballistics.flight_time(v0, gg)
        ok = (t >= FLIGHT_TIME.low) & (t <= FLIGHT_TIME.high)
        if not np.all(ok):
            bad = float(np.asarray(v0)[~ok][0] if np.ndim(v0) else v0)
            bad_t = float(np.asarray(t)[~ok][0] if np.ndim(t) else t)
            raise ValueError(
                f"launch speed must give a flight time 2 v0 / g between {FLIGHT_TIME.low:g} and "
                f"{FLIGHT_TIME.high:g} s, got {bad!r} m/s (T = {bad_t:.3g} s at "
                f"g = {gg:g} m/s²)"
            )
        return cls(
            omega=v.as_float_array("omega", omega),
            flight_time=t,
            start=start,
            g=gg,
        )

    @property
    def launch_speed(self) -> FloatArray:
        """v0 = g T / 2, m/s."""
        return ballistics.launch_speed(self.flight_time, self.g)

    @property
    def apex(self) -> FloatArray:
        """Highest point of the centre of mass above launch, v0² / 2g, m."""
        return ballistics.height(self.launch_speed, self.g, 0.5 * self.flight_time)

    @property
    def start_sign(self) -> float:
        """+1 started heads up, −1 tails up."""
        return 1.0 if self.start == "heads" else -1.0

    @property
    def shape(self) -> tuple[int, ...]:
        """Batch shape of the tosses."""
        return np.broadcast_shapes(self.omega.shape[:-1], self.flight_time.shape)


@dataclass(frozen=True, eq=False)
class FlightState:
    """State of a coin in flight at times t (batched like the toss and t).

    Attributes
    ----------
    t : ndarray
        Time since launch, s.
    attitude : scipy.spatial.transform.Rotation
        Body → lab rotation.
    normal : ndarray, shape (..., 3)
        Heads normal n in the lab frame.
    omega : ndarray, shape (..., 3)
        Angular velocity, body frame, rad/s.
    angular_momentum : ndarray, shape (..., 3)
        Angular momentum S about the centre of mass, lab frame, kg m²/s (constant).
    height : ndarray
        Height of the centre of mass above launch, m.
    """

    t: FloatArray
    attitude: Rotation
    normal: FloatArray
    omega: FloatArray
    angular_momentum: FloatArray
    height: FloatArray


@dataclass(frozen=True, eq=False)
class Outcome:
    """What a caught toss shows.

    Attributes
    ----------
    face : ndarray of int8
        Face up at catch, codes of :mod:`coinflight.core.outcome` (1 heads, 0 tails).
    rotations : ndarray
        Turns of the normal about the angular momentum during the flight, ωp T / 2π
        (θ(T)/2π of Stefan & Cheche eqs 11, 15 for a spin about a diameter).
    psi : ndarray
        Precession angle ψ between the heads normal and the angular momentum, rad.
    alignment : ndarray
        n(T)·n0, the cosine of the angle between the coin's planes at launch and at catch.
    """

    face: NDArray[np.int8]
    rotations: FloatArray
    psi: FloatArray
    alignment: FloatArray

    @property
    def face_name(self) -> str:
        """ "heads" or "tails" for a single toss."""
        if self.face.ndim:
            raise TypeError("face_name is for a single toss; use face for a batch")
        return FACE_NAMES[int(self.face)]

    @property
    def same_side(self) -> NDArray[np.bool_]:
        """True where the coin shows the face it started with."""
        return same_side(self.alignment)


@dataclass(frozen=True, eq=False)
class Flight:
    """Torque-free flight of a coin, caught at launch height.

    Examples
    --------
    >>> flight = Flight(Coin.preset("us-quarter"), Toss(omega=(80, 0, 0), flight_time=0.7))
    >>> flight.outcome.face_name, round(float(flight.outcome.rotations), 3)
    ('heads', 8.913)
    """

    coin: Coin
    toss: Toss

    def __post_init__(self) -> None:
        if not isinstance(self.coin, Coin):
            raise TypeError(f"coin must be a Coin, got {type(self.coin).__name__}")
        if not isinstance(self.toss, Toss):
            raise TypeError(f"toss must be a Toss, got {type(self.toss).__name__}")

    def at(self, t: ArrayLike) -> FlightState:
        """State at times 0 ≤ t ≤ 10⁴ s from launch, broadcast against the toss batch (the
        same number of axes, or one of them a single value): the free flight's closed form
        (past the catch at t = T too, as the figures draw the cone); ValueError for a time
        before the launch, or a phase beyond the toss's own budget."""
        t = v.non_negative("t", t, "s")
        if t.size and float(np.max(t)) > FLIGHT_TIME.high:
            raise ValueError(
                f"t must be at most {FLIGHT_TIME.high:g} s (the longest flight time), got "
                f"{float(np.max(t))!r} s"
            )
        if t.size and self.toss.omega.size:
            spin = float(np.max(np.abs(self.toss.omega)))
            v.phase_budget(spin, float(np.max(t)), "largest spin component × t")
        _together(
            f"the toss batch ({_tosses(self.toss.shape)})", self.toss.shape,
            f"t (shape {t.shape})", t.shape, f"give one t per toss (shape {self.toss.shape})",
        )  # fmt: skip
        i1, i3 = self.coin.moments
        w0 = self.toss.omega
        att = torque_free.attitude(w0, i1, i3, t, self.toss.start_sign)
        shape = np.broadcast_shapes(w0.shape[:-1], t.shape)
        normal = att.apply([0.0, 0.0, 1.0]).reshape(*shape, 3)
        r0 = torque_free.initial_attitude(self.toss.start_sign)
        m_lab = r0.apply(torque_free.angular_momentum_body(w0, i1, i3).reshape(-1, 3))
        return FlightState(
            t=t,
            attitude=att,
            normal=normal,
            omega=torque_free.body_angular_velocity(w0, i1, i3, t),
            angular_momentum=np.broadcast_to(m_lab.reshape(*w0.shape), (*shape, 3)),
            height=ballistics.height(self.toss.launch_speed, self.toss.g, t),
        )

    @cached_property
    def catch(self) -> FlightState:
        """State at the catch, t = T."""
        return self.at(self.toss.flight_time)

    @cached_property
    def outcome(self) -> Outcome:
        """Face up at catch, rotations and precession angle."""
        i1, i3 = self.coin.moments
        w = self.toss.omega
        t = self.toss.flight_time
        alignment = np.asarray(
            torque_free.normal_alignment(w[..., 0], w[..., 1], w[..., 2], t, i1, i3)
        )
        return Outcome(
            face=face_from_alignment(alignment, self.toss.start_sign),
            rotations=torque_free.rotations(w, i1, i3, t),
            psi=torque_free.cone_angle(w, i1, i3),
            alignment=alignment,
        )


__all__ = ["FLIGHT_TIME", "GRAVITY", "STANDARD_GRAVITY", "Flight", "FlightState", "Outcome", "Toss"]
