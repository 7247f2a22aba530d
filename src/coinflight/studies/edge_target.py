"""The three-sided coin: the thickness ratio h/d at which a tossed cylinder lands on its edge
with a chosen probability p, as a band over the table's unmeasured parameters.

Yong & Mahadevan (2011, Am. J. Phys. 79:1195; REFERENCES §5) answer p = 1/3 with two closed
forms (:func:`coinflight.studies.edge.ratio_for`): h/d = 1/(2√2) ≈ 0.354 if the coin comes to
rest in a uniformly random orientation (geometric), 1/√3 ≈ 0.577 if it lands dead at a random
angle in its plane of spin (dynamic). :func:`target_ratio` answers it for simulated tosses
landing on a table (:func:`coinflight.studies.edge.simulate_edge`: the flight, the impacts and
the table's rigid ending), for each cell of the box of what nobody measured, and returns the
roots.

Method
------
In one cell, P̂(x) is the edge fraction of the same ``n`` tosses (one seed: common random
numbers, the same ωx and v0 at every ratio x = h/d and in every cell), so P̂ is a step function
of x whose expectation P(x) rises with x. The root of P̂(x) − p is bracketed in u = ln x, from
the dynamic model's root tan(πp/2) by steps of a factor 2 within
:data:`~coinflight.studies.edge.SIM_RATIOS`, then bisected (:func:`scipy.optimize.bisect`,
robust on a step function) to :data:`XTOL` in ln x. Its statistical error is the binomial
error of P at the root over the slope: σ(h/d) = sqrt(p(1 − p)/n) / (dP/dx), the slope from the
same tosses at x·e^(±:data:`SLOPE_STEP`) (a central difference; its error is stated, bounded
as if the two fractions were independent, which common random numbers only make smaller).
Every cell's number of evaluations is bounded before anything runs: at most 1 + the bracket's
steps + the bisection's ⌈log2(ln 2 / XTOL)⌉ + 2, each of ``n`` tosses at the landing
rate (:func:`coinflight.studies.edge.landing_rate`).

The band
--------
Each of restitution e, friction μ and the rolling and pivoting resistance not given is spread
over its plausible range: e 0.3–0.6 and μ 0.05–0.6, the union of the surface presets' ranges
(:func:`coinflight.studies.presets.bouncing_box`), the resistances 1e-5–1e-3 m, both the same
value in a cell
(:data:`coinflight.studies.edge_experiments.RESISTANCE`,
:data:`coinflight.model.surface.DEFAULT_ROLLING_RESISTANCE`). The cells are the box's corners
and its centre (:func:`coinflight.studies.edge_experiments.box_cells`); the band is the lowest
and highest root. P(edge) is not monotonic in e and μ, so the corners' band is a lower bound of
the model's spread. A given value is one point of its dimension (all given: one cell).

The toss matters more than the box: with the human toss preset's wobble (``psi="human"``: an
axial spin putting the normal on a cone of about 82°, fitted to coins, not measured for
cylinders) more thick cylinders stay on edge, and the root moves further than across the
whole box. Its error is the statistical one only: the band's ends are
single cells, and the model's own limits (:mod:`coinflight.studies.edge_experiments`) are not
in it.
"""

from __future__ import annotations

import math
import time
import warnings
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Any

import numpy as np

from coinflight import _validation as v
from coinflight.model.distributions import Distribution
from coinflight.probability import streams
from coinflight.studies.edge_experiments import RESISTANCE, BoxCells, axial_spin, box_cells

XTOL = 2e-3
"""Bisection tolerance in ln(h/d): 0.2 % of the ratio, below the statistical error of any
affordable run (about 1 % at 20,000 tosses per ratio)."""
SLOPE_STEP = 0.1
"""Half-width of the central difference giving dP/d(h/d) at the root, in ln(h/d) (±10 %)."""
BRACKET_FACTOR = 2.0
"""Step of the bracket's search, a factor of h/d."""
DEFAULT_TOSSES = 2_000
"""Tosses per evaluated ratio when none are given (the root to a few per cent)."""
METHOD = (
    "common random numbers (the same tosses at every h/d and cell); root of the edge fraction "
    "minus p bracketed from the dynamic model's root by factors of 2, bisected in ln(h/d) "
    "(scipy.optimize.bisect); error sqrt(p(1-p)/n) / (dP/d(h/d)), the slope a central "
    "difference at h/d x exp(+-0.1)"
)
"""The method, as the JSON states it."""


@dataclass(frozen=True)
class TargetCell:
    """The root in one cell of the box.

    Attributes
    ----------
    parameters : mapping
        The cell's values (name → value, SI): restitution, friction, resistance (m).
    ratio : float
        h/d at which the edge fraction of the ``n`` tosses crosses p.
    stderr : float
        Statistical error of ``ratio``: sqrt(p(1 − p)/n) / ``slope`` (inf when the measured
        slope is not positive).
    slope, slope_stderr : float
        dP/d(h/d) at the root from the same tosses at ratio·e^(±SLOPE_STEP), and its error.
    bracket : (float, float, float, float)
        (x_low, P̂(x_low), x_high, P̂(x_high)): the bracket the bisection started from.
    evaluations : int
        Ratios landed (``n`` tosses each).
    """

    parameters: Mapping[str, float]
    ratio: float
    stderr: float
    slope: float
    slope_stderr: float
    bracket: tuple[float, float, float, float]
    evaluations: int

    def to_dict(self) -> dict[str, Any]:
        lo, p_lo, hi, p_hi = self.bracket
        return {
            **dict(self.parameters),
            "ratio": self.ratio,
            "stderr": self.stderr if math.isfinite(self.stderr) else None,
            "slope": self.slope,
            "slope_stderr": self.slope_stderr,
            "bracket": {"low": lo, "p_low": p_lo, "high": hi, "p_high": p_hi},
            "evaluations": self.evaluations,
        }


@dataclass(frozen=True)
class EdgeTarget(BoxCells[TargetCell]):
    """What :func:`target_ratio` found: the root in each cell (corners first, centre last)."""

    probability: float
    n: int
    seed: int
    setting: Mapping[str, Any]
    box: Mapping[str, tuple[float, float]]
    cells: tuple[TargetCell, ...]
    estimated_seconds: float
    elapsed: float
    method: str = METHOD
    measured: tuple[Mapping[str, Any], ...] = field(default_factory=tuple)

    def value(self, cell: TargetCell) -> float:
        """The cell's root h/d."""
        return cell.ratio

    @property
    def yong_mahadevan(self) -> dict[str, float]:
        """Yong & Mahadevan's closed-form roots at this p (:func:`~coinflight.studies.edge.
        ratio_for`): geometric and dynamic (dead landing)."""
        from coinflight.studies.edge import ratio_for

        p = self.probability
        return {"geometric": ratio_for(p, "geometric"), "dynamic": ratio_for(p, "dynamic")}

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready: p, the band, every cell, the closed forms, the measured rows, the run."""

        def end(c: TargetCell) -> dict[str, Any]:
            return {"ratio": c.ratio, "stderr": c.stderr if math.isfinite(c.stderr) else None}

        return {
            "target": self.probability,
            "band": {"low": end(self.low), "high": end(self.high), "centre": end(self.centre)},
            "yong_mahadevan": self.yong_mahadevan,
            "measured": [dict(m) for m in self.measured],
            "box": {k: list(r) for k, r in self.box.items()},
            "cells": [c.to_dict() for c in self.cells],
            "setting": dict(self.setting),
            "n": self.n,
            "seed": self.seed,
            "method": self.method,
            "estimated_seconds": self.estimated_seconds,
            "elapsed": self.elapsed,
        }


def check_probability(value: object) -> float:
    """A target P(edge): one number strictly between 0 and 1, else TypeError or ValueError."""
    p = v.number("edge probability", value)
    if not 0.0 < p < 1.0:
        raise ValueError(f"edge probability must be strictly between 0 and 1, got {p!r}")
    return float(p)


def target_box(
    restitution: float | None = None,
    friction: float | None = None,
    rolling_resistance: float | None = None,
    pivoting_resistance: float | None = None,
) -> dict[str, tuple[float, float]]:
    """The box of the band: each parameter given is one point (low = high), each not given its
    plausible range (module notes); ``resistance`` (both resistances, the same value) only when
    neither resistance is given; a single one given keeps the other at its range under its own
    name. Restitution 0 (dead landings, which never reach the rigid ending where alone the
    resistances act) has no resistance in its box, and refuses one given (ValueError)."""
    from coinflight.studies.presets import bouncing_box

    e_box, mu_box = bouncing_box()
    box = {
        "restitution": e_box if restitution is None else (restitution, restitution),
        "friction": mu_box if friction is None else (friction, friction),
    }
    if restitution == 0.0:
        for name, value in (("rolling", rolling_resistance), ("pivoting", pivoting_resistance)):
            if value is not None:
                raise ValueError(
                    f"{name} resistance acts on landings that bounce (restitution above 0): "
                    "dead ones (restitution 0) never reach the rigid ending, where the "
                    "resistances act"
                )
        return box
    if rolling_resistance is None and pivoting_resistance is None:
        box["resistance"] = RESISTANCE
    else:
        for name, value in (
            ("rolling_resistance", rolling_resistance),
            ("pivoting_resistance", pivoting_resistance),
        ):
            box[name] = RESISTANCE if value is None else (value, value)
    return box


def max_evaluations(probability: float, low: float) -> int:
    """The most ratios one cell lands: the start, the bracket's steps to the farther end of
    [``low``, 100], the bisection's steps and the slope's two."""
    from coinflight.studies.edge import SIM_RATIOS

    x0 = _start(probability, low)
    steps = max(
        math.ceil(math.log(SIM_RATIOS[1] / x0, BRACKET_FACTOR)),
        math.ceil(math.log(x0 / low, BRACKET_FACTOR)),
        1,
    )
    return 1 + steps + _bisections() + 2


def _bisections() -> int:
    return math.ceil(math.log2(math.log(BRACKET_FACTOR) / XTOL))


def _start(probability: float, low: float) -> float:
    """The dynamic model's root tan(πp/2), inside [``low``, 100]."""
    from coinflight.studies.edge import SIM_RATIOS

    return float(np.clip(math.tan(0.5 * math.pi * probability), low, SIM_RATIOS[1]))


def measured_rows() -> tuple[dict[str, Any], ...]:
    """The measured rows of :func:`coinflight.datasets.edge_experiments` (source, h/d, n,
    fraction and its binomial standard error)."""
    from coinflight.datasets import edge_experiments

    return tuple(
        {
            "source": r.source,
            "ratio": r.ratio,
            "n": r.n,
            "fraction": r.fraction,
            "stderr": r.stderr,
        }
        for r in edge_experiments(kind="measured")
    )


def target_ratio(
    probability: float,
    n: int = DEFAULT_TOSSES,
    seed: streams.SeedLike = None,
    *,
    restitution: float | None = None,
    friction: float | None = None,
    rolling_resistance: float | None = None,
    pivoting_resistance: float | None = None,
    drop_height: float | None = None,
    spin: Distribution | None = None,
    launch_speed: Distribution | None = None,
    corner_radius: float | None = None,
    g: float = 9.81,
    psi: float | str | None = None,
    executor: Any = None,
    progress: Callable[[str], None] | None = None,
) -> EdgeTarget:
    """The thickness ratio h/d at which P(edge) = ``probability``, in each cell of the box of
    the table's unmeasured parameters (module notes: the method, the band, the error).

    Parameters
    ----------
    probability : float
        The target P(edge), strictly between 0 and 1 (1/3: the fair three-sided coin).
    n : int
        Tosses per evaluated ratio (the same tosses at every ratio and in every cell).
    seed : int, optional
        Every draw (reported; fresh from the OS when not given).
    restitution, friction, rolling_resistance, pivoting_resistance : float, optional
        The table's; each one not given is spread over its plausible range (:func:`target_box`).
        Restitution 0 (dead landings) is the setting of
        Yong & Mahadevan's dynamic model, whose root is tan(πp/2).
    drop_height, spin, launch_speed, corner_radius, g
        As :func:`coinflight.studies.edge.simulate_edge` takes them (defaults: its vigorous
        planar tosses, the table 0.5 m below, sharp corners).
    psi : float or "human", optional
        A wobble as well: the precession cone angle ψ in degrees (0 < ψ ≤ 90), or "human",
        the human toss preset's spread of ψ about 82° (:func:`coinflight.studies.
        edge_experiments.axial_spin`, recomputed at each ratio so that ψ, not ωz, is the same
        for every cylinder); default none (planar tosses).
    executor : optional
        Where the tosses run (:func:`~coinflight.studies.edge.simulate_edge`).
    progress : callable, optional
        Called with a short text once every input is checked and the work bounded (the run's
        size and estimated time), then after each cell.

    Raises
    ------
    ValueError
        Before anything runs: a bad value, or the most evaluations over every cell above the
        work bound (:data:`coinflight._validation.MAX_RUN_SECONDS`). After: when the edge
        fraction does not cross p within the ratios a simulation takes (0.001 to 100).
    """
    from scipy.optimize import bisect

    from coinflight.model.surface import Surface
    from coinflight.studies.edge import (
        SIM_DIAMETER,
        SIM_DROP,
        SIM_RATIOS,
        landing_rate,
        simulate_edge,
        simulated_corner_radius,
    )

    p = check_probability(probability)
    n = v.count("tosses per ratio", n, 1, 10**7)
    streams.check_seed(seed)
    drop = SIM_DROP if drop_height is None else drop_height
    corner = 0.0 if corner_radius is None else corner_radius
    low = SIM_RATIOS[0]
    if corner:  # every coin landed needs h/2 ≥ the corner radius: the search starts there
        simulated_corner_radius(corner, [SIM_RATIOS[1]])  # at most the radius, not negative
        low = max(low, 2.0 * corner / SIM_DIAMETER * (1 + 1e-9))
    box = target_box(restitution, friction, rolling_resistance, pivoting_resistance)

    cells = box_cells(box)
    fixed = {"g": g, "drop_height": drop, "spin": spin, "launch_speed": launch_speed,
             "corner_radius": corner}  # fmt: skip

    def kwargs(cell: Mapping[str, float]) -> dict[str, Any]:
        out = {**fixed, "restitution": cell["restitution"], "friction": cell["friction"]}
        if "resistance" in cell:
            out["rolling_resistance"] = out["pivoting_resistance"] = cell["resistance"]
        for name in ("rolling_resistance", "pivoting_resistance"):
            if name in cell:
                out[name] = cell[name]
        return out

    def wobble(x: float) -> Distribution | None:
        """ωz putting a cylinder of ratio ``x`` on the cone ψ (None: planar tosses)."""
        if psi is None:
            return None
        from coinflight.model.distributions import Uniform
        from coinflight.studies.edge import SIM_SPIN

        return axial_spin(x, Uniform(*SIM_SPIN) if spin is None else spin, psi)

    with warnings.catch_warnings():  # a bad ψ refused now (a thin cylinder is meant)
        warnings.simplefilter("ignore", v.PlausibilityWarning)
        wobble(low)
    rates = []
    for cell in cells:  # each cell checked as simulate_edge will check it, before any toss
        kw = kwargs(cell)
        resist = {k: kw[k] for k in ("rolling_resistance", "pivoting_resistance") if k in kw}
        surface = Surface("table", drop, kw["restitution"], kw["friction"], **resist)
        own = spin is None and launch_speed is None and psi is None  # simulate_edge's tosses
        rates.append(landing_rate(surface, own))
    with warnings.catch_warnings():  # the toss setting refused now, if bad (one toss)
        warnings.simplefilter("ignore", v.PlausibilityWarning)
        simulate_edge([low], 1, 0, **kwargs(cells[0]), axial_spin=wobble(low))
    most = max_evaluations(p, low)
    typical = 2 + _bisections() + 2
    seconds = sum(most * n / rate for rate in rates)
    what = (
        f"the ratio for P(edge) = {p:g}: {len(cells)} cells × at most {most} ratios × "
        f"{v.quantity(n)} tosses"
    )
    v.work_bound(what, seconds, v.MAX_RUN_SECONDS, "s", "use fewer tosses per ratio")
    estimate = sum(typical * n / rate for rate in rates)
    if progress is not None:
        progress(f"{what}, about {v.duration(estimate)} (at most {v.duration(seconds)})")
    root = streams.seed_sequence(seed)
    stream = streams.child(root, 0)
    t0 = time.perf_counter()
    found = []
    for cell in cells:
        kw = kwargs(cell)
        memo: dict[float, float] = {}

        def fraction(x: float, kw: dict[str, Any] = kw, memo: dict[float, float] = memo) -> float:
            if x not in memo:
                with warnings.catch_warnings():  # a thick cylinder is meant: not a coin's size
                    warnings.simplefilter("ignore", v.PlausibilityWarning)
                    ((_, est),) = simulate_edge(
                        [x], n, stream, executor=executor, axial_spin=wobble(x), **kw
                    )
                memo[x] = est.p
            return memo[x]

        x_lo = x_hi = _start(p, low)
        while fraction(x_lo) > p and x_lo > low:  # step down until at or below p
            x_hi, x_lo = x_lo, max(low, x_lo / BRACKET_FACTOR)
        while fraction(x_hi) < p and x_hi < SIM_RATIOS[1]:  # step up until at or above p
            x_lo, x_hi = x_hi, min(SIM_RATIOS[1], x_hi * BRACKET_FACTOR)
        if fraction(x_lo) > p or fraction(x_hi) < p:
            edge = x_lo if fraction(x_lo) > p else x_hi
            raise ValueError(
                f"P(edge) = {p:g} is not reached for h/d between {low:g} and "
                f"{SIM_RATIOS[1]:g}: {fraction(edge):g} at h/d {edge:g} ({dict(cell)})"
            )
        if x_lo == x_hi:
            u = math.log(x_lo)
        else:
            u = bisect(lambda u: fraction(math.exp(u)) - p, math.log(x_lo), math.log(x_hi),
                       xtol=XTOL)  # fmt: skip
        x = math.exp(u)
        up, down = x * math.exp(SLOPE_STEP), x * math.exp(-SLOPE_STEP)
        up, down = min(up, SIM_RATIOS[1]), max(down, low)
        p_up, p_down = fraction(up), fraction(down)
        slope = (p_up - p_down) / (up - down)
        slope_se = math.sqrt(p_up * (1 - p_up) / n + p_down * (1 - p_down) / n) / (up - down)
        se = math.sqrt(p * (1 - p) / n) / slope if slope > 0 else math.inf
        bracket = (x_lo, fraction(x_lo), x_hi, fraction(x_hi))
        found.append(
            TargetCell(MappingProxyType(dict(cell)), x, se, slope, slope_se, bracket, len(memo))
        )
        if progress is not None:
            progress(f"{dict(cell)}: h/d {x:.4g} ± {se:.2g}")
    setting = {
        "drop_height": drop,
        "corner_radius": corner,
        "g": g,
        "spin": None if spin is None else spin.to_dict(),
        "launch_speed": None if launch_speed is None else launch_speed.to_dict(),
        "diameter": SIM_DIAMETER,
        "psi": psi,
    }
    return EdgeTarget(
        p,
        n,
        streams.reported_seed(root),
        MappingProxyType(setting),
        MappingProxyType(box),
        tuple(found),
        estimate,
        time.perf_counter() - t0,
        measured=measured_rows(),
    )


__all__ = [
    "BRACKET_FACTOR",
    "DEFAULT_TOSSES",
    "METHOD",
    "SLOPE_STEP",
    "XTOL",
    "EdgeTarget",
    "TargetCell",
    "check_probability",
    "max_evaluations",
    "measured_rows",
    "target_box",
    "target_ratio",
]
