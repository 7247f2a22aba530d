"""Reproduce Stefan & Cheche, "Coin toss modeling": every number it states, beside coinflight's.

The paper's numbers (section 3, REFERENCES §1) are kept here as data with their source. The
comparison itself is computed by the library: rotations and faces by the closed form
(:mod:`coinflight.core.torque_free`) and by the paper's own Euler-matrix construction
(:mod:`coinflight.core.paper`); probabilities by :func:`coinflight.probability.estimate`,
method A (grid of 5000 intervals), method B (100 intervals, random events) and exact.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np

from coinflight.core import paper as paper_kernels
from coinflight.core.outcome import FACE_NAMES
from coinflight.model.coin import Coin
from coinflight.model.toss import Flight, Toss

if TYPE_CHECKING:
    from coinflight.model.ensemble import TossDistribution
    from coinflight.probability import ProbabilityResult
    from coinflight.probability.convergence import Convergence

Step = Callable[[str], None]
"""Called with a short description each time a step of the reproduction finishes."""

METHOD_A_INTERVALS = 5000
"""Stefan & Cheche §3: "5000 intervals for method A (total number of configurations is 5000²)"."""
METHOD_B_INTERVALS = 100
"""Stefan & Cheche §3: "100 intervals for method B"."""
METHOD_B_EVENTS = 10**6
"""Events drawn for method B. The paper does not say how many; its plots grow the number."""
DEFAULT_SEED = 20240601


@dataclass(frozen=True)
class RotationCase:
    """A toss whose number of rotations the paper prints (text of Figs 2c-d, 3c-f).

    ``paper_face`` is the face the paper's text says ends up ("heads"/"tails"), None where it
    says nothing.
    """

    figure: str
    omega_x: float
    omega_y: float
    flight_time: float
    paper_rotations: float
    decimals: int
    paper_face: str | None
    quote: str


ROTATION_CASES = (
    # Stefan & Cheche §3: "The number of rotations in the time interval T is 8.913 and 17.189"
    # and "In Fig. 2c the coin ends with head down and in Fig. 2d the coin ends with head up".
    RotationCase("2c", 80.0, 0.0, 0.7, 8.913, 3, "tails", "the coin ends with head down"),
    RotationCase("2d", 120.0, 0.0, 0.9, 17.189, 3, "heads", "the coin ends with head up"),
    # Stefan & Cheche §3: "the number of rotations ... is 9.059 and 9.8142, 10.569, and 11.324".
    RotationCase("3c", 90.0, 30.0, 0.6, 9.059, 3, None, ""),
    RotationCase("3d", 90.0, 30.0, 0.65, 9.8142, 4, None, ""),
    RotationCase("3e", 90.0, 30.0, 0.7, 10.569, 3, None, ""),
    RotationCase("3f", 90.0, 30.0, 0.75, 11.324, 3, None, ""),
)


@dataclass(frozen=True)
class ProbabilityCase:
    """A probability figure of the paper: ranges of ωx0 and T (flight times), fixed ωy0."""

    figure: str
    omega_x: tuple[float, float]
    omega_y: float
    flight_time: tuple[float, float]
    paper_says: str = "tends to the unbiased value of 50%"


PROBABILITY_CASES = (
    # Stefan & Cheche §3 (REFERENCES §1). The paper writes "T = v0/g ∈ [0.6, 0.9] s"; its
    # flight time (eq 11) is 2 v0/g and its rotation counts use T itself: the ranges are
    # flight times.
    ProbabilityCase("2a", (60.0, 90.0), 0.0, (0.6, 0.9)),
    ProbabilityCase("2b", (90.0, 120.0), 0.0, (0.6, 0.9)),
    ProbabilityCase("3a", (60.0, 90.0), 10.0, (0.6, 0.9)),
    ProbabilityCase("3b", (60.0, 90.0), 60.0, (0.6, 0.9)),
)


@dataclass(frozen=True)
class RotationRow:
    """What coinflight computes for one :class:`RotationCase`.

    Attributes
    ----------
    rotations : float
        ωp T / 2π by the closed form.
    rotations_paper_formula : float
        θ(T)/2π with θ(T) = T sqrt(ωx0² + ωy0²) (eqs 11, 15).
    theta_mod_deg : float
        θ(T) mod 360°, degrees.
    cos_theta : float
        cos θ(T) (eq 14).
    cos_theta_construction : float
        n(r_A0, r_B0)·n(r_A, r_B) by the paper's Euler matrix (eqs 12-13).
    cos_theta_closed_form : float
        n(T)·n0 by coinflight's general closed form.
    s_dot_n : float
        Ŝ·n at the catch ("Diaconis' theorem": 0 in case b).
    face : str
        Face up by eq 14 (heads iff cos θ > 0, started heads up).
    """

    case: RotationCase
    rotations: float
    rotations_paper_formula: float
    theta_mod_deg: float
    cos_theta: float
    cos_theta_construction: float
    cos_theta_closed_form: float
    s_dot_n: float
    face: str

    @property
    def rotations_agree(self) -> bool:
        """True when coinflight's count rounds to the paper's printed digits."""
        return round(self.rotations, self.case.decimals) == self.case.paper_rotations

    @property
    def face_agrees(self) -> bool | None:
        """Whether the paper's stated face matches eq 14; None where the paper states none."""
        if self.case.paper_face is None:
            return None
        return self.case.paper_face == self.face


@dataclass(frozen=True)
class ProbabilityRow:
    """Method A, method B and the exact value for one :class:`ProbabilityCase`.

    ``method_b_limit`` is the grid value on method B's 100 × 100 grid: what method B tends to
    as its number of events grows. ``convergence`` holds both methods' series for growing
    sizes (the curves of the paper's figure).
    """

    case: ProbabilityCase
    exact: ProbabilityResult
    method_a: ProbabilityResult
    method_b: ProbabilityResult
    method_b_limit: ProbabilityResult
    convergence: Convergence

    def error_at(self, method: str, samples: int) -> tuple[int, float]:
        """(size, |p − exact|) of the ``method`` estimate whose sample count is nearest."""
        series = self.convergence.series(method)
        best = min(series, key=lambda p: abs(math.log(p.samples / samples)))
        return best.samples, abs(best.p_heads - self.exact.p_heads)


@dataclass(frozen=True)
class PaperNumbers:
    """Every comparison of the reproduction report."""

    coin: Coin
    rotations: tuple[RotationRow, ...]
    probabilities: tuple[ProbabilityRow, ...]
    seed: int
    method_b_events: int
    timings: dict[str, float] = field(default_factory=dict, compare=False)


def rotation_row(case: RotationCase, coin: Coin) -> RotationRow:
    """Compute one :class:`RotationRow` (cheap)."""
    toss = Toss(omega=(case.omega_x, case.omega_y, 0.0), flight_time=case.flight_time)  # type: ignore[arg-type]
    flight = Flight(coin, toss)
    out = flight.outcome
    theta = float(paper_kernels.rotation_angle(case.omega_x, case.omega_y, case.flight_time))
    s = np.asarray(flight.catch.angular_momentum, dtype=float)
    n = np.asarray(flight.catch.normal, dtype=float)
    return RotationRow(
        case=case,
        rotations=float(out.rotations),
        rotations_paper_formula=theta / (2.0 * math.pi),
        theta_mod_deg=math.degrees(theta % (2.0 * math.pi)),
        cos_theta=math.cos(theta),
        cos_theta_construction=float(
            paper_kernels.dihedral_cosine(case.omega_x, case.omega_y, case.flight_time)
        ),
        cos_theta_closed_form=float(out.alignment),
        s_dot_n=float(s @ n / np.linalg.norm(s)),
        face=FACE_NAMES[int(out.face)],
    )


def distribution(case: ProbabilityCase, coin: Coin) -> TossDistribution:
    """The :class:`~coinflight.model.ensemble.TossDistribution` of a probability figure."""
    from coinflight.model.distributions import Fixed, Uniform
    from coinflight.model.ensemble import TossDistribution

    return TossDistribution(
        Uniform(*case.omega_x),
        Fixed(case.omega_y),
        Fixed(0.0),
        Uniform(*case.flight_time),
        coin=coin,
    )


def _event_sizes(events: int) -> tuple[int, ...]:
    """Method B's series: the default sizes below ``events``, then ``events``."""
    from coinflight.probability.convergence import DEFAULT_EVENT_SIZES

    return (*(n for n in DEFAULT_EVENT_SIZES if n < events), events)


def probability_row(
    case: ProbabilityCase,
    coin: Coin,
    seed: int,
    events: int = METHOD_B_EVENTS,
    progress: Callable[[int], None] | None = None,
) -> ProbabilityRow:
    """Exact, method A (5000 intervals), method B (100 intervals, ``events`` draws), series;
    ``progress`` is called with the work units done (:func:`paper_work` counts them)."""
    from coinflight.probability import estimate
    from coinflight.probability.convergence import DEFAULT_GRID_SIZES, convergence

    dist = distribution(case, coin)
    return ProbabilityRow(
        convergence=convergence(
            dist,
            ("grid", "monte-carlo"),
            grid_sizes=DEFAULT_GRID_SIZES,
            event_sizes=_event_sizes(events),
            seed=seed,
            grid_cells=METHOD_B_INTERVALS,
            progress=progress,
        ),
        case=case,
        exact=estimate(dist, "exact"),
        method_a=estimate(dist, "grid", n=METHOD_A_INTERVALS, progress=progress),
        method_b=estimate(
            dist,
            "monte-carlo",
            n=events,
            seed=seed,
            grid_cells=METHOD_B_INTERVALS,
            progress=progress,
        ),
        method_b_limit=estimate(dist, "grid", n=METHOD_B_INTERVALS, progress=progress),
    )


def paper_work(events: int = METHOD_B_EVENTS, coin: Coin | None = None) -> int:
    """Work units the probability rows of :func:`paper_numbers` report through ``progress``
    (each estimator's own units: grid cells, Monte Carlo events), counted before any runs:
    the total of a progress bar."""
    from coinflight.probability import registry
    from coinflight.probability.convergence import DEFAULT_GRID_SIZES, work_total

    coin = coin if coin is not None else Coin.preset("us-quarter")
    grid, monte_carlo = registry.get("grid"), registry.get("monte-carlo")
    total = 0
    for case in PROBABILITY_CASES:
        dist = distribution(case, coin)
        k = len(dist.ranged)
        total += work_total(
            dist,
            ("grid", "monte-carlo"),
            grid_sizes=DEFAULT_GRID_SIZES,
            event_sizes=_event_sizes(events),
        )
        total += grid.work_units(k, METHOD_A_INTERVALS) + grid.work_units(k, METHOD_B_INTERVALS)
        total += monte_carlo.work_units(k, events)
    return total


def paper_numbers(
    coin: Coin | None = None,
    seed: int = DEFAULT_SEED,
    events: int = METHOD_B_EVENTS,
    step: Step | None = None,
    progress: Callable[[int], None] | None = None,
) -> PaperNumbers:
    """Every number of the reproduction report.

    Parameters
    ----------
    coin : Coin, optional
        The coin (default the US quarter; the paper names none, and for a spin about a diameter
        the outcome does not depend on the coin).
    seed : int
        Seed of method B's random events, reported.
    events : int
        Number of method B events per figure.
    step : callable, optional
        Progress: called after each computed row.
    progress : callable, optional
        Called with the work units done as the rows' estimates go (:func:`paper_work`).
    """
    import time

    coin = coin if coin is not None else Coin.preset("us-quarter")
    timings: dict[str, float] = {}
    t0 = time.perf_counter()
    rotations = tuple(rotation_row(c, coin) for c in ROTATION_CASES)
    timings["rotations"] = time.perf_counter() - t0
    if step:
        step("rotations and faces")
    probabilities = []
    for c in PROBABILITY_CASES:
        t0 = time.perf_counter()
        probabilities.append(probability_row(c, coin, seed, events, progress))
        timings[f"probability {c.figure}"] = time.perf_counter() - t0
        if step:
            step(f"probabilities of Fig {c.figure}")
    return PaperNumbers(
        coin=coin,
        rotations=rotations,
        probabilities=tuple(probabilities),
        seed=seed,
        method_b_events=events,
        timings=timings,
    )


__all__ = [
    "DEFAULT_SEED",
    "METHOD_A_INTERVALS",
    "METHOD_B_EVENTS",
    "METHOD_B_INTERVALS",
    "PROBABILITY_CASES",
    "ROTATION_CASES",
    "PaperNumbers",
    "ProbabilityCase",
    "ProbabilityRow",
    "RotationCase",
    "RotationRow",
    "distribution",
    "paper_numbers",
    "paper_work",
    "probability_row",
    "rotation_row",
]
