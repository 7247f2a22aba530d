"""Heads/tails maps in the plane of initial conditions (flight time T, spin ω): the computation.

Keller (1986) drew the planar toss this way: the face is decided by ω T, so heads and tails
alternate in bands bounded by the hyperbolas ω T = (2n ± ½)π, which thin out as ω and T grow
(REFERENCES §3). Precessing tosses (ωz ≠ 0, or a cone angle ψ < 90°) keep the bands but change
their widths (Diaconis, Holmes & Montgomery 2007).

The map is computed on the midpoint grid of the grid method (method A of Stefan & Cheche): the
pixel (i, j) is the toss at the centre of cell (i, j), so the fraction of heads pixels *is* the
grid probability on that grid. Any :class:`~coinflight.outcomes.base.OutcomeModel` maps (its
:meth:`~coinflight.outcomes.base.OutcomeModel.faces`); :func:`coinflight.plotting.basin.plot_basin`
draws the result.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, Literal

import numpy as np
from numpy.typing import NDArray

from coinflight import _validation as v
from coinflight.core.bands import half_width
from coinflight.core.outcome import EDGE, FACE_NAMES, HEADS, TAILS
from coinflight.outcomes.base import OutcomeModel
from coinflight.outcomes.hand import HAND_CATCH
from coinflight.probability import grid

if TYPE_CHECKING:
    from coinflight.model.coin import Coin

FloatArray = NDArray[np.float64]
FaceArray = NDArray[np.int8]

OutcomeFunction = Callable[["Coin", FloatArray, FloatArray, float, float], FaceArray]
"""(coin, omega (..., 3) rad/s, flight_time (...) s, start_sign, g) -> faces (...) int8: the
signature of :meth:`OutcomeModel.faces <coinflight.outcomes.base.OutcomeModel.faces>`."""

SpinAxis = Literal["x", "precession"]
MAX_BOUNDARIES = 2000
"""Most analytic boundary curves drawn on a map (400 points each): 1,000 bands, already a grey
blur at a figure's size (the paper's Fig 1 has about 20)."""


def midpoints(low: float, high: float, n: int) -> FloatArray:
    """Centres of n equal cells of [low, high]: low + (k + ½)(high − low)/n, k = 0…n−1
    (the unit cells of :func:`coinflight.probability.grid.midpoints`, scaled)."""
    return np.asarray(low + (high - low) * grid.midpoints(n), dtype=np.float64)


@dataclass(frozen=True, eq=False)
class BasinMap:
    """Which face each toss of a (T, ω) grid shows.

    Attributes
    ----------
    flight_time : ndarray, shape (n_t,)
        Cell centres along the flight time axis, s.
    spin : ndarray, shape (n_w,)
        Cell centres along the spin axis, rad/s (ωx0, or the precession rate ωp when ψ is fixed).
    face : ndarray of int8, shape (n_w, n_t)
        Face codes (:mod:`coinflight.core.outcome`): rows follow ``spin``, columns ``flight_time``.
    flight_time_range, spin_range : tuple of float
        The edges of the mapped box.
    axis : {"x", "precession"}
        What the spin axis is.
    omega_y, omega_z : float
        Fixed body spins, rad/s (axis "x").
    psi : float or None
        Fixed cone angle, rad (axis "precession").
    coin : Coin
    start : str
    g : float
    """

    flight_time: FloatArray
    spin: FloatArray
    face: FaceArray
    flight_time_range: tuple[float, float]
    spin_range: tuple[float, float]
    axis: SpinAxis
    omega_y: float
    omega_z: float
    psi: float | None
    coin: Coin
    start: str
    g: float

    @property
    def heads_fraction(self) -> float:
        """Fraction of heads pixels: the grid probability of heads on this grid."""
        return float(np.mean(self.face == HEADS))

    def fraction(self, face: int) -> float:
        """Fraction of pixels showing ``face`` (a code of :mod:`coinflight.core.outcome`)."""
        return float(np.mean(self.face == face))

    @property
    def planar(self) -> bool:
        """True when the coin spins about a diameter (ψ = 90°), Keller's and the paper's case."""
        if self.axis == "precession":
            return self.psi is not None and math.isclose(self.psi, math.pi / 2)
        return self.omega_z == 0.0

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready: the grid and its faces, for drawing the map elsewhere (the web page).

        ``face`` is a list of rows, one per ``spin`` value, each a list of face codes along
        ``flight_time`` (``faces`` names the codes: 0 tails, 1 heads, 2 edge); the fractions
        are those of the grid method on this grid. ``psi_deg`` is the fixed cone angle on a
        precession-rate axis, else None.
        """
        return {
            "flight_time": self.flight_time.tolist(),
            "spin": self.spin.tolist(),
            "axis": self.axis,
            "face": self.face.tolist(),
            "faces": dict(enumerate(FACE_NAMES)),
            "heads_fraction": self.heads_fraction,
            "tails_fraction": self.fraction(TAILS),
            "edge_fraction": self.fraction(EDGE),
            "flight_time_range": list(self.flight_time_range),
            "spin_range": list(self.spin_range),
            "omega_y": self.omega_y,
            "omega_z": self.omega_z,
            "psi_deg": None if self.psi is None else math.degrees(self.psi),
            "planar": self.planar,
            "coin": self.coin.to_dict(),
            "start": self.start,
            "g": self.g,
        }

    def boundaries(self, n_points: int = 400) -> list[tuple[FloatArray, FloatArray]]:
        """Analytic heads/tails boundaries inside the box, as (T, spin) curves.

        Each curve is sampled at ``n_points`` spins; T is NaN where the curve leaves the box.

        Notes
        -----
        The face changes where n(T)·n0 = cos²ψ + sin²ψ cos(ωp T) = 0, that is at
        ωp T = 2πk ± arccos(−cot²ψ) (Diaconis, Holmes & Montgomery 2007), which exists only for
        cot²ψ ≤ 1 (ψ ≥ 45°). Along the spin axis ωp and ψ are known in closed form, so each
        boundary is T(spin) = (2πk ± arccos(−cot²ψ)) / ωp. For a spin about a diameter
        (ωz = 0, ψ = 90°) these are Keller's hyperbolas Ω T = (2k ± ½)π with
        Ω = sqrt(ωx² + ωy²) (Keller 1986; Stefan & Cheche eqs 14-15).
        """
        lo, hi = self.spin_range
        t_lo, t_hi = self.flight_time_range
        w = np.linspace(lo, hi, n_points)
        rate, cot2 = _along_spins(self.coin, w, self.psi, self.omega_y, self.omega_z)
        valid = (cot2 <= 1.0) & (rate > 0)
        if not np.any(valid):
            return []
        widths = half_width(cot2)
        curves: list[tuple[FloatArray, FloatArray]] = []
        k_max = _bound_boundaries(float(np.max(rate[valid])), t_hi)
        for k in range(k_max + 1):
            for sign in (-1.0, 1.0):
                with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
                    t = (2 * math.pi * k + sign * widths) / rate  # inf: off the map
                inside = valid & (t >= t_lo) & (t <= t_hi)
                if np.any(inside):
                    curves.append((np.where(inside, t, np.nan), w))
        return curves


def _along_spins(
    coin: Coin, w: FloatArray, psi: float | None, omega_y: float, omega_z: float
) -> tuple[FloatArray, FloatArray]:
    """Precession rate ωp and cot²ψ at the spins ``w`` of a map's axis (the precession rate
    itself with ``psi`` fixed, else ωx0 with ``omega_y``, ``omega_z``), as
    :meth:`BasinMap.boundaries` takes them."""
    if psi is not None:
        with np.errstate(over="ignore"):  # ψ within 1e-154 rad of 0 or π: cot²ψ = inf
            cot2 = (np.cos(psi) / np.sin(psi)) ** 2
        return w, np.full_like(w, cot2)
    i1, i3 = coin.moments
    perp2 = w * w + omega_y**2
    axial = i3 / i1 * omega_z
    rate = np.sqrt(perp2 + axial * axial)
    with np.errstate(divide="ignore", invalid="ignore"):
        cot2 = np.where(perp2 > 0, axial * axial / perp2, np.inf)
    return rate, cot2


def _bound_boundaries(top: float, t_hi: float) -> int:
    """The last band index k of the boundaries up to precession rate ``top`` and flight time
    ``t_hi``; ValueError, before any curve is made, beyond :data:`MAX_BOUNDARIES` curves."""
    k_max = int(top * t_hi / (2 * math.pi)) + 1
    v.work_bound(
        f"drawing the analytic boundaries of a map up to {top:.3g} rad/s × {t_hi:.3g} s",
        2 * (k_max + 1),
        MAX_BOUNDARIES,
        "curves",
        "draw the map without them (--no-boundaries, boundaries=False) or map smaller spins "
        "or flight times",
    )
    return k_max


def check_boundaries(
    coin: Coin,
    flight_time: tuple[float, float],
    spin: tuple[float, float],
    *,
    omega_y: float = 0.0,
    omega_z: float = 0.0,
    psi: float | None = None,
) -> None:
    """ValueError unless the map's analytic boundaries (:meth:`BasinMap.boundaries`) are at
    most :data:`MAX_BOUNDARIES` curves, from the box alone (before its map is computed), in
    the words :meth:`BasinMap.boundaries` refuses them with. The fastest precession over the
    spin axis is at one of its ends (ωp and cot²ψ are monotone in the spin's size), which
    every sampling of the axis includes."""
    rate, cot2 = _along_spins(coin, np.array(spin, dtype=float), psi, omega_y, omega_z)
    valid = (cot2 <= 1.0) & (rate > 0)
    if np.any(valid):
        _bound_boundaries(float(np.max(rate[valid])), flight_time[1])


def basin_map(
    coin: Coin,
    flight_time: tuple[float, float] = (0.6, 0.9),
    spin: tuple[float, float] = (60.0, 90.0),
    *,
    omega_y: float = 0.0,
    omega_z: float = 0.0,
    psi: float | None = None,
    resolution: tuple[int, int] = (500, 500),
    start: str = "heads",
    g: float = 9.81,
    outcome: OutcomeModel | OutcomeFunction = HAND_CATCH,
    executor: Any = None,
    boundaries: bool = False,
) -> BasinMap:
    """Heads/tails map over a box of flight times and spins.

    Parameters
    ----------
    coin : Coin
    flight_time : (float, float)
        Range of flight times T, s.
    spin : (float, float)
        Range of the spin axis, rad/s: ωx0 (with ``omega_y``, ``omega_z`` fixed), or, when
        ``psi`` is given, the precession rate ωp = |S| / I1.
    omega_y, omega_z : float
        Fixed body spins about the other diameter and about the normal, rad/s.
    psi : float, optional
        Fixed cone angle between the normal and S, rad, in (0, π); then ωx0 = ωp sin ψ,
        ωy0 = 0, ωz0 = ωp cos ψ · I1 / I3 (so that |S| / I1 = ωp and angle(n, S) = ψ).
    resolution : (int, int)
        Cells along T and along the spin axis (≥ 1 each).
    start : {"heads", "tails"}
    g : float
        Gravity, m/s², passed to ``outcome``.
    outcome : OutcomeModel or callable
        Face for each toss of the grid: an outcome model (its
        :meth:`~coinflight.outcomes.base.OutcomeModel.faces`; build one with
        :func:`coinflight.outcomes.outcome_model`) or a function with that signature; default
        the catch in the hand.
    executor : object with ``map``, or a distributed.Client, optional
        Computes the map in stripes of rows (spins), one task each (:data:`STRIPE_CELLS`
        cells), e.g. on a Dask cluster (:mod:`coinflight.probability.distributed`); the map is
        the same as without it. ``outcome`` must then pickle (a model, or a module-level
        function). Default: the whole grid in one call, in this process.
    boundaries : bool
        The map's analytic boundaries will be drawn (:meth:`BasinMap.boundaries`): their
        number is bounded (:func:`check_boundaries`) before the map is computed.

    Returns
    -------
    BasinMap
        ``face`` has shape (resolution[1], resolution[0]).

    Raises
    ------
    ValueError
        Beyond 25 million cells, or, for an outcome model, more tosses than its measured
        :attr:`~coinflight.outcomes.base.OutcomeModel.rate` lands in
        :data:`coinflight._validation.MAX_RUN_SECONDS` (an hour: 252,000 cells with the
        rigid 3-D ending), or, with ``boundaries``, beyond :data:`MAX_BOUNDARIES` curves,
        before anything is allocated.
    """
    from coinflight.model.toss import Toss

    t_lo, t_hi = _range("flight time", flight_time, "s", positive=True)
    w_lo, w_hi = _range("spin", spin, "rad/s", positive=psi is not None)
    n_t, n_w = _resolution(resolution)
    v.finite("omega_y", omega_y, "rad/s")
    v.finite("omega_z", omega_z, "rad/s")
    v.choice("start", start, ("heads", "tails"))
    if psi is not None:
        v.in_range("psi", psi, 0.0, math.pi, "rad")
        if omega_y != 0.0 or omega_z != 0.0:
            raise ValueError("give either a fixed psi or fixed omega_y/omega_z, not both")
    if isinstance(outcome, OutcomeModel):  # each cell a toss, at the model's measured rate
        v.work_bound(
            f"a map of {v.quantity(n_t)}×{v.quantity(n_w)} tosses ({outcome.name})",
            n_t * n_w,
            outcome.rate * v.MAX_RUN_SECONDS,
            "tosses",
            "use a coarser resolution",
            outcome.rate,
        )
    # Validate T, g and start the same way every toss is validated.
    Toss(omega=(w_lo, omega_y, omega_z), flight_time=t_lo, start=start, g=g)  # type: ignore[arg-type]
    if boundaries:
        check_boundaries(
            coin, (t_lo, t_hi), (w_lo, w_hi), omega_y=omega_y, omega_z=omega_z, psi=psi
        )

    t = midpoints(t_lo, t_hi, n_t)
    w = midpoints(w_lo, w_hi, n_w)
    tt, ww = np.meshgrid(t, w)
    if psi is None:
        omega = np.stack([ww, np.full_like(ww, omega_y), np.full_like(ww, omega_z)], axis=-1)
    else:
        i1, i3 = coin.moments
        omega = np.stack(
            [ww * math.sin(psi), np.zeros_like(ww), ww * math.cos(psi) * i1 / i3], axis=-1
        )
    sign = 1.0 if start == "heads" else -1.0
    faces = outcome.faces if isinstance(outcome, OutcomeModel) else outcome
    if executor is None:
        face = np.asarray(faces(coin, omega, tt, sign, g), dtype=np.int8)
    else:
        from coinflight.probability._runner import check_runner, executor_or_threads, run_tasks

        check_runner(executor, None, None)
        rows = max(1, STRIPE_CELLS // n_t)
        starts = range(0, n_w, rows)
        tasks = [(faces, coin, omega[a : a + rows], tt[a : a + rows], sign, g) for a in starts]
        sizes = [min(rows, n_w - a) * n_t for a in starts]
        with executor_or_threads(executor, None) as ex:
            stripes = run_tasks(ex, _stripe, tasks, sizes, None)
        face = np.concatenate([np.asarray(f, dtype=np.int8) for f in stripes], axis=0)
    return BasinMap(
        flight_time=t,
        spin=w,
        face=face,
        flight_time_range=(t_lo, t_hi),
        spin_range=(w_lo, w_hi),
        axis="x" if psi is None else "precession",
        omega_y=float(omega_y),
        omega_z=float(omega_z),
        psi=None if psi is None else float(psi),
        coin=coin,
        start=start,
        g=float(g),
    )


STRIPE_CELLS = 1 << 16
"""Cells per task of a map computed on an executor (whole rows of spins)."""


def _stripe(args: tuple[Any, ...]) -> Any:
    """Faces of one stripe of rows of a map."""
    faces, coin, omega, tt, sign, g = args
    return faces(coin, omega, tt, sign, g)


def _range(name: str, value: tuple[float, float], unit: str, positive: bool) -> tuple[float, float]:
    arr = v.finite(name, value, unit)
    if arr.shape != (2,):
        raise ValueError(f"{name} range must be two numbers (low, high), got {value!r}")
    lo, hi = float(arr[0]), float(arr[1])
    if not lo < hi:
        raise ValueError(f"{name} range must have low < high, got {lo:g}:{hi:g}{_u(unit)}")
    if positive and lo <= 0:
        raise ValueError(f"{name} range must be positive, got {lo:g}:{hi:g}{_u(unit)}")
    return lo, hi


def _u(unit: str) -> str:
    return f" {unit}" if unit else ""


def _resolution(resolution: tuple[int, int]) -> tuple[int, int]:
    try:
        n_t, n_w = (int(x) for x in resolution)
    except (TypeError, ValueError):
        raise TypeError(f"resolution must be two integers, got {resolution!r}") from None
    if n_t < 1 or n_w < 1 or n_t * n_w > 25_000_000:
        raise ValueError(
            f"resolution must be at least 1×1 and at most 25 million cells, got {n_t}×{n_w}"
        )
    return n_t, n_w


__all__ = ["BasinMap", "OutcomeFunction", "basin_map", "midpoints"]
