"""Thick cylinders against experiments: measured edge fractions beside the table landing's band.

For each experiment (a record: h/d, throws ``n``, ``edges`` on edge, the setting the source
describes) the study simulates that setting with
:func:`coinflight.studies.edge.simulate_edge` (the full flight, Stronge's impacts, then the
rigid 3-D phase carries the coin to rest) and returns P(edge) as a **band** over what nobody
measured: the restitution e and friction μ over the surface presets' box
(:func:`coinflight.studies.presets.bouncing_box`), the cylinder's diameter and the table's
drop when the source does not give them, and the rolling and pivoting resistance. The band's
cells are the box's corners and its centre (or a finer grid, ``points``); each reports p, s.e.
and n. The measured fraction with its 95 % (Wilson) interval is then *inside*, *above* or
*below* that band. No parameter is tuned to the data: the result is whatever it is.

Settings (:data:`SETTINGS`; the models of *how* the throws were made, not data):

``hand-table``
    A person flips the cylinder onto a table: spin about a diameter and launch speed of the
    project's human toss (:func:`coinflight.studies.presets.human`: ωx ~ Normal(238.8, 23.9)
    rad/s, v0 ~ Normal(2.4, 0.24) m/s, DHM via Keller, REFERENCES §2), released
    :data:`HAND_DROP` m above the table (our assumption: a hand over a table, seated to
    standing), the diameter :data:`HAND_DIAMETER` m when the source does not give it (our
    assumption: coin-sized to a large draughts piece). By default the tosses are planar (no
    axial spin ωz); ``psi`` adds the wobble of a precessing toss (below).

A cylinder of diameter D is simulated at that size (``simulate_edge``'s ``diameter``).

Wobble (:func:`axial_spin`, :func:`wobble_sweep`). A hand-flipped thick cylinder probably
does not spin about a diameter only: with an axial spin ωz its normal precesses on a cone of
angle ψ about the angular momentum, cot ψ = I3 ωz / (I1 ωx) (Diaconis, Holmes & Montgomery
2007, §2), the launch face up more of the flight, and it lands at a more random orientation
("volumetric" rotation, Gaek & Sukhov 2024, arXiv:2401.03557). ``psi="human"`` takes the human
toss preset's relation (ωz ~ Normal(μ, μ/2), μ at ψ0 = 82.05°, fitted there to *coins'*
same-side rate); a number is one ψ at the median ωx. **A cylinder's ψ is not measured**: the
sweep states ψ, it does not fit it.

What it finds is recomputed by ``coinflight landing-report`` ("Thick cylinders against
experiments", planar tosses and the human preset's wobble), with its caveats; the
documentation's physics page ("Published edge experiments") discusses it. Cost: a landing
carried to rest is slow (:func:`coinflight.outcomes.table.rigid_rate` at each cell's
resistance, the rate the work bound takes; planar tosses, which fall flat soon, run far faster,
tosses with a wobble roll longer); a run whose estimated time exceeds the work bound
(:data:`coinflight._validation.MAX_RUN_SECONDS`) is refused before it starts.
"""

from __future__ import annotations

import itertools
import math
import time
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Any, Generic, Literal, TypeVar

import numpy as np

from coinflight import _validation as v
from coinflight.model.distributions import Distribution
from coinflight.model.surface import RESISTANCE_BAND
from coinflight.probability import streams
from coinflight.probability.result import BinomialEstimate
from coinflight.studies.presets import HUMAN_PSI

Verdict = Literal["inside", "above", "below", "too few tosses to judge"]

MIN_TOSSES_TO_JUDGE = 100
"""Tosses per cell below which a band that overlaps a measured point says "too few tosses to
judge", not "inside": with fewer, one cell's P(edge) is uncertain by up to ±0.1 (2 s.e. at
p = ½, 2·½/√n), and a band of a few tosses per cell (0.000 to 0.500 from four) spans the
measured points by its noise alone. A band wholly above or below a point still says so."""

HAND_DROP = (0.2, 0.5)
"""Height of the releasing hand above the table, m (our assumption, no source gives it)."""
HAND_DIAMETER = (0.02, 0.05)
"""Diameter of a hand-flipped cylinder when the source does not give it, m (our assumption)."""
RESISTANCE = RESISTANCE_BAND
"""Rolling and pivoting resistance of the landing, m, both the same value in a cell
(nobody measured them for a coin; :class:`coinflight.model.surface.Surface`); the band's centre
is their geometric mean."""
MAX_TOSSES = 10**7
"""Most tosses per cell (the work bound limits the whole run as well)."""


@dataclass(frozen=True)
class Setting:
    """How the throws of an experiment were made, as far as its source says.

    Attributes
    ----------
    name : str
    description : str
        One sentence, with the sources of each number.
    spin : Distribution
        Spin about a diameter, rad/s (the scale of the real cylinder: unchanged by size).
    launch_speed : Distribution
        Upward launch speed of the real cylinder, m/s (positive with certainty).
    drop_height : (float, float)
        The table lies this far below the release, m: a range (its ends are band cells) or
        equal ends for a height the source gives.
    diameter : (float, float)
        Diameter of the cylinder when the record does not give it, m.
    """

    name: str
    description: str
    spin: Distribution
    launch_speed: Distribution
    drop_height: tuple[float, float]
    diameter: tuple[float, float]


def _hand_table() -> Setting:
    from coinflight.studies.presets import HUMAN_LAUNCH_SPEED, HUMAN_SPIN, human

    toss = human()
    assert toss.launch_speed is not None  # the preset is built from its launch speed
    return Setting(
        "hand-table",
        f"flipped by hand onto a table: ωx and v0 of the human toss preset "
        f"(ωx ~ N({HUMAN_SPIN:.1f}, {0.1 * HUMAN_SPIN:.1f}) rad/s, v0 ~ N({HUMAN_LAUNCH_SPEED:g}, "
        f"{0.1 * HUMAN_LAUNCH_SPEED:g}) m/s: DHM via Keller), released {HAND_DROP[0]:g}–"
        f"{HAND_DROP[1]:g} m above the table (our assumption)",
        toss.omega_x,
        toss.launch_speed,
        HAND_DROP,
        HAND_DIAMETER,
    )


SETTINGS: Mapping[str, Callable[[], Setting]] = MappingProxyType({"hand-table": _hand_table})
"""Settings by name, each a factory (see the module notes for every number)."""


def setting(name: str) -> Setting:
    """The setting ``name`` (a key of :data:`SETTINGS`), else a ValueError listing them."""
    return v.known("experiment setting", name, SETTINGS)()


@dataclass(frozen=True)
class Experiment:
    """One measured edge fraction: ``edges`` of ``n`` throws of cylinders of ratio h/d.

    ``setting`` names a :data:`SETTINGS` entry; ``diameter`` and ``drop_height`` (m) are the
    source's when it gives them (else None: the setting's range is a band dimension);
    ``label`` and ``source`` say where the numbers come from.
    """

    label: str
    ratio: float
    n: int
    edges: int
    setting: str
    source: str = ""
    diameter: float | None = None
    drop_height: float | None = None
    edges_derived: bool = False
    """True when the source gives only the fraction and ``edges`` is round(fraction × n),
    not a count (shown as "≈" in the table, ``edges_derived`` in the JSON)."""

    def __post_init__(self) -> None:
        from coinflight.studies.edge import check_ratios

        check_ratios(self.ratio)
        v.count("throws of an experiment", self.n, 1)
        v.count("edges of an experiment", self.edges, 0, self.n)
        v.known("experiment setting", self.setting, SETTINGS)
        for name in ("diameter", "drop_height"):
            value = getattr(self, name)
            if value is not None and not (math.isfinite(value) and value > 0):
                raise ValueError(f"{name} of an experiment must be positive (m), got {value!r}")

    @property
    def observed(self) -> BinomialEstimate:
        """The measured fraction (its ``ci95`` is the Wilson 95 % interval)."""
        return BinomialEstimate(self.edges, self.n)


SOURCE_SETTINGS: Mapping[str, str] = MappingProxyType({"standup_maths_2018": "hand-table"})
"""The setting that simulates each source of :mod:`coinflight.datasets.edges` (our reading of
its description): Stand-up Maths' hand flips (Parker & Hunt 2018) onto a table."""


def from_dataset(records: Sequence[Any]) -> tuple[list[Experiment], list[str]]:
    """The records of :func:`coinflight.datasets.edge_experiments` that can be compared, as
    :class:`Experiment` s, and one line for each one left out (why).

    Kept: ``kind == "measured"`` with a number of throws and a source in
    :data:`SOURCE_SETTINGS`. A record giving the fraction but not the count gets edges =
    round(fraction × n), marked ``edges_derived`` (exact only if the fraction was printed to
    1/n, which the source does not say).
    """
    kept: list[Experiment] = []
    left: list[str] = []
    for r in records:
        what = f"{r.source} h/d {r.ratio:g}"
        if r.kind != "measured":
            left.append(f"{what}: {r.kind}, not a measurement")
        elif r.n is None:
            left.append(f"{what}: no number of throws")
        elif r.source not in SOURCE_SETTINGS:
            left.append(f"{what}: no setting simulates this source yet")
        else:
            derived = r.edges is None
            edges = round(r.fraction * r.n) if derived else r.edges
            kept.append(
                Experiment(
                    f"{r.source} h/d {r.ratio:.3f}",
                    r.ratio,
                    r.n,
                    edges,
                    SOURCE_SETTINGS[r.source],
                    r.citation,
                    edges_derived=derived,
                )
            )
    return kept, left


@dataclass(frozen=True)
class Cell:
    """P(edge) at one point of the unmeasured parameters' box (``parameters``: name → value,
    SI units, the real cylinder's)."""

    parameters: Mapping[str, float]
    estimate: BinomialEstimate

    @property
    def p(self) -> float:
        return self.estimate.p

    @property
    def stderr(self) -> float:
        return self.estimate.stderr

    @property
    def n(self) -> int:
        return self.estimate.n


CellT = TypeVar("CellT")


class BoxCells(Generic[CellT]):
    """Results over the cells of a box (:func:`box_cells`: corners first, the centre last),
    each cell with one value the box spans (:meth:`value`): its lowest and highest cell and
    its centre."""

    cells: tuple[CellT, ...]

    def value(self, cell: CellT) -> float:
        """The value by which the cells are ordered."""
        raise NotImplementedError

    @property
    def low(self) -> CellT:
        """The cell of lowest :meth:`value`."""
        return min(self.cells, key=self.value)

    @property
    def high(self) -> CellT:
        """The cell of highest :meth:`value`."""
        return max(self.cells, key=self.value)

    @property
    def centre(self) -> CellT:
        """The box's centre (the only cell when every parameter was given)."""
        return self.cells[-1]


@dataclass(frozen=True)
class Band(BoxCells[Cell]):
    """P(edge) over the box: its cells (corners first, the centre last)."""

    cells: tuple[Cell, ...]

    def value(self, cell: Cell) -> float:
        """P(edge) of the cell."""
        return cell.p

    def verdict(self, observed: BinomialEstimate) -> Verdict:
        """``"above"`` when the measured 95 % interval lies above the band's top (its highest
        cell + 2 s.e.), ``"below"`` when it lies below the band's bottom (lowest cell − 2 s.e.),
        else ``"inside"`` (they overlap), or ``"too few tosses to judge"`` when they overlap
        but a cell has fewer than :data:`MIN_TOSSES_TO_JUDGE` tosses."""
        lo, hi = observed.ci95
        if lo > self.high.p + 2.0 * self.high.stderr:
            return "above"
        if hi < self.low.p - 2.0 * self.low.stderr:
            return "below"
        if min(cell.n for cell in self.cells) < MIN_TOSSES_TO_JUDGE:
            return "too few tosses to judge"
        return "inside"

    def gap(self, observed: BinomialEstimate) -> float:
        """Measured fraction minus the nearest end of the band (0 inside [low, high])."""
        p = observed.p
        return max(0.0, p - self.high.p) - max(0.0, self.low.p - p)


@dataclass(frozen=True)
class Comparison:
    """One experiment beside its simulated band over the box ``box``."""

    experiment: Experiment
    setting: Setting
    band: Band
    box: Mapping[str, tuple[float, float]] = field(default_factory=dict)
    """The ranges of the unmeasured parameters (:func:`experiment_box`)."""


@dataclass(frozen=True)
class EdgeExperiments:
    """What :func:`edge_experiments` computed: one :class:`Comparison` per experiment."""

    comparisons: tuple[Comparison, ...]
    n: int
    seed: int
    elapsed: float
    points: int = 2
    psi: float | str | None = None
    """The wobble of every toss (:func:`axial_spin`; None: planar tosses)."""

    HEADER = (
        "experiment",
        "h/d",
        "measured ± s.e. (95 % CI)",
        "model band: low – high (± s.e.)",
        "centre ± s.e.",
        "cells × n",
        "measured vs band",
        "gap",
    )
    """Column names of :meth:`table`."""

    def table(self) -> list[tuple[str, ...]]:
        """One row per experiment (columns :attr:`HEADER`), as text: the driver's and the
        landing report's table."""
        rows: list[tuple[str, ...]] = []
        for c in self.comparisons:
            obs = c.experiment.observed
            lo, hi = obs.ci95
            b = c.band
            rows.append(
                (
                    c.experiment.label,
                    f"{c.experiment.ratio:g}",
                    f"{obs.p:.3f} ± {obs.stderr:.3f} ({lo:.3f}–{hi:.3f}), "
                    f"{'≈' if c.experiment.edges_derived else ''}"
                    f"{c.experiment.edges}/{c.experiment.n}",
                    f"{b.low.p:.3f} ± {b.low.stderr:.3f} – {b.high.p:.3f} ± {b.high.stderr:.3f}",
                    f"{b.centre.p:.3f} ± {b.centre.stderr:.3f}",
                    f"{len(b.cells)} × {b.centre.n:,}",
                    b.verdict(obs),
                    f"{b.gap(obs):+.3f}",
                )
            )
        return rows

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready: every cell of every band, the measured fractions and the verdicts."""

        def band(b: Band, obs: BinomialEstimate) -> dict[str, Any]:
            return {
                "low": b.low.p,
                "low_stderr": b.low.stderr,
                "high": b.high.p,
                "high_stderr": b.high.stderr,
                "verdict": b.verdict(obs),
                "gap": b.gap(obs),
                "cells": [
                    {
                        **dict(c.parameters),
                        "p_edge": c.p,
                        "stderr": c.stderr,
                        "n": c.n,
                    }
                    for c in b.cells
                ],
            }

        return {
            "seed": self.seed,
            "n": self.n,
            "psi": self.psi,
            "points": self.points,
            "elapsed": self.elapsed,
            "experiments": [
                {
                    "label": c.experiment.label,
                    "source": c.experiment.source,
                    "ratio": c.experiment.ratio,
                    "n": c.experiment.n,
                    "edges": c.experiment.edges,
                    "edges_derived": c.experiment.edges_derived,
                    "fraction": c.experiment.observed.p,
                    "stderr": c.experiment.observed.stderr,
                    "ci95": list(c.experiment.observed.ci95),
                    "setting": c.setting.name,
                    "setting_description": c.setting.description,
                    "box": {k: list(r) for k, r in c.box.items()},
                    "band": band(c.band, c.experiment.observed),
                }
                for c in self.comparisons
            ],
        }


def _landing_seconds(cells: Sequence[Mapping[str, float]], n: int) -> float:
    """Seconds of ``n`` landings carried to rest in each of ``cells``, for the work bounds: at
    each cell's ``resistance`` (m; the surfaces' default where it has none), the rate of
    :func:`coinflight.outcomes.table.rigid_rate`."""
    from coinflight.outcomes.table import RIGID_RESISTANCE, rigid_rate

    ell = np.array([cell.get("resistance", RIGID_RESISTANCE) for cell in cells], dtype=float)
    return float(np.sum(n / rigid_rate(ell, ell)))


def box_cells(ranges: Mapping[str, tuple[float, float]], points: int = 2) -> list[dict[str, float]]:
    """The cells of the box ``ranges`` (name → (low, high)): ``points`` values per parameter,
    ends included (2: the corners), every combination, and the box's centre last when it is
    not among them. A range of equal ends is one value. The values are evenly spaced, except
    a resistance's (a name ending in ``resistance``: geometric, the range spans two decades),
    whose centre is the geometric mean."""
    points = v.count("points per parameter", points, 2, 9)
    names = list(ranges)

    def values(name: str, lo: float, hi: float) -> list[float]:
        if lo == hi:
            return [float(lo)]
        if name.endswith("resistance"):
            return [float(x) for x in np.geomspace(lo, hi, points)]
        return [float(x) for x in np.linspace(lo, hi, points)]

    axes = [values(k, lo, hi) for k, (lo, hi) in ranges.items()]
    cells = [dict(zip(names, corner, strict=True)) for corner in itertools.product(*axes)]
    centre = {
        k: a[len(a) // 2] if len(a) % 2 else math.nan for k, a in zip(names, axes, strict=True)
    }
    if any(math.isnan(c) for c in centre.values()):
        centre = {
            k: math.sqrt(lo * hi) if k.endswith("resistance") else 0.5 * (lo + hi)
            for k, (lo, hi) in ranges.items()
        }
        cells.append(centre)
    else:  # odd points: the centre is a grid cell; put it last
        cells.remove(centre)
        cells.append(centre)
    return cells


def experiment_box(
    experiment: Experiment,
    the_setting: Setting,
    restitution: tuple[float, float] | None = None,
    friction: tuple[float, float] | None = None,
) -> dict[str, tuple[float, float]]:
    """The unmeasured parameters' ranges for one experiment: e and μ (default the surface
    presets' box, :func:`coinflight.studies.presets.bouncing_box`), the diameter and the drop
    (the record's when it gives them, else the setting's), and the rolling and pivoting
    resistance (:data:`RESISTANCE`)."""
    from coinflight.studies.presets import bouncing_box

    e_box, mu_box = bouncing_box()
    d = experiment.diameter
    h = experiment.drop_height
    out = {
        "restitution": e_box if restitution is None else restitution,
        "friction": mu_box if friction is None else friction,
        "diameter": the_setting.diameter if d is None else (d, d),
        "drop_height": the_setting.drop_height if h is None else (h, h),
        "resistance": RESISTANCE,
    }
    return out


def _checked(
    experiments: Sequence[Experiment], n: int, seed: streams.SeedLike
) -> tuple[tuple[Experiment, ...], int, dict[str, Setting]]:
    """The arguments :func:`edge_experiments` and :func:`wobble_sweep` share, checked: the
    experiments (at least one), tosses per cell, the seed; and the experiments' settings by
    name."""
    items = tuple(experiments)
    if not items:
        raise ValueError("give at least one experiment")
    for item in items:
        v.instance("experiment", item, Experiment, "an Experiment")
    n = v.count("tosses per cell", n, 1, MAX_TOSSES)
    streams.check_seed(seed)
    return items, n, {name: setting(name) for name in {x.setting for x in items}}


def _cell_checked(point: Mapping[str, float], g: float) -> None:
    """One cell's landing checked as :func:`~coinflight.studies.edge.simulate_edge` will check
    it (g, diameter, the table's e, μ, drop and resistances), so that a refusal
    comes before ``progress`` is first called and any toss runs."""
    from coinflight.model.surface import Surface
    from coinflight.model.toss import check_gravity
    from coinflight.studies.edge import check_diameter

    check_gravity(g)
    check_diameter(point["diameter"])
    resist = point.get("resistance")
    extra = {} if resist is None else {"rolling_resistance": resist, "pivoting_resistance": resist}
    Surface(
        "table",
        drop_height=point["drop_height"],
        restitution=point["restitution"],
        friction=point["friction"],
        **extra,
    )


def _cell_edge(
    ratio: float,
    n: int,
    seed: streams.SeedLike,
    g: float,
    cell: Mapping[str, float],
    the_setting: Setting,
    axial: Distribution | None,
    resistance: float | None,
) -> BinomialEstimate:
    """P(edge) of ``n`` tosses of h/d ``ratio`` (:func:`~coinflight.studies.edge.simulate_edge`)
    at one ``cell`` of a box (restitution, friction, drop_height, diameter), thrown as
    ``the_setting`` says, ωz drawn from ``axial`` (None: none), rolling and pivoting resistance
    ``resistance`` m (None: the surface's default)."""
    from coinflight.studies.edge import simulate_edge

    ((_, estimate),) = simulate_edge(
        [ratio],
        n,
        seed,
        g=g,
        restitution=cell["restitution"],
        friction=cell["friction"],
        drop_height=cell["drop_height"],
        diameter=cell["diameter"],
        spin=the_setting.spin,
        launch_speed=the_setting.launch_speed,
        axial_spin=axial,
        rolling_resistance=resistance,
        pivoting_resistance=resistance,
    )
    return estimate


def edge_experiments(
    experiments: Sequence[Experiment],
    n: int,
    seed: streams.SeedLike = None,
    *,
    points: int = 2,
    restitution: tuple[float, float] | None = None,
    friction: tuple[float, float] | None = None,
    g: float = 9.81,
    psi: float | Literal["human"] | None = None,
    progress: Callable[[str], None] | None = None,
) -> EdgeExperiments:
    """Each experiment's setting simulated over the unmeasured parameters' box.

    Parameters
    ----------
    experiments : sequence of Experiment
        The measured points (data are an argument: none is written in this module).
    n : int
        Tosses per cell of :func:`experiment_box`.
    seed : int, optional
        Every draw: experiment i takes child i, the same tosses in every cell (common random
        numbers).
    points : int
        Values per parameter of the box (2: corners and centre; 3: a 3 × 3 × … grid). The
        landing's P(edge) is not monotonic in e and μ, so more points widen the band towards
        its true extent, at points⁵ cells.
    restitution, friction : (float, float), optional
        Replace the surface presets' ranges (e.g. (0, 0) and a sticking friction for the
        dead-landing check).
    g : float
        Gravitational acceleration of the real throws, m/s².
    psi : float or "human", optional
        A wobble as well (:func:`axial_spin`): the precession cone angle ψ in degrees (0 < ψ
        ≤ 90; 90 is no axial spin), or ``"human"`` for the human toss preset's spread of ψ
        about 82°; default none (planar tosses). The same for every cell; each cell's
        parameters then include ``psi`` (degrees, the typical ψ).
    progress : callable, optional
        Called with a short text first once every input is checked and the work bounded,
        before any toss (the run's size), then after each band.

    Raises
    ------
    ValueError
        Before anything runs: no experiments, sizes out of range, or the whole run above the
        work bound (:data:`coinflight._validation.MAX_RUN_SECONDS` at
        :func:`coinflight.outcomes.table.rigid_rate` at each cell's resistance).
    """
    items, n, settings = _checked(experiments, n, seed)
    boxes = [experiment_box(x, settings[x.setting], restitution, friction) for x in items]
    points = v.count("points per parameter", points, 2, 9)
    if psi is not None:
        axial_spin(items[0].ratio, settings[items[0].setting].spin, psi)  # refuse a bad ψ now
    for box in boxes:
        for point in box_cells(box, points):
            _cell_checked(point, g)
    tosses = sum(len(box_cells(b, points)) for b in boxes) * n
    seconds = sum(_landing_seconds(box_cells(b, points), n) for b in boxes)
    what = f"edge experiments: {len(items)} experiments, {tosses:,} tosses"
    v.work_bound(what, seconds, v.MAX_RUN_SECONDS, "s", "use fewer tosses per cell (n)")
    if progress is not None:
        progress(f"{what}, about {v.duration(seconds)}")
    t0 = time.perf_counter()
    root = streams.seed_sequence(seed)
    comparisons = []
    for i, (x, box) in enumerate(zip(items, boxes, strict=True)):
        the_setting = settings[x.setting]
        child = streams.child(root, i)
        wz = None if psi is None else axial_spin(x.ratio, the_setting.spin, psi)
        extra = {} if psi is None else {"psi": HUMAN_PSI_DEGREES if psi == "human" else psi}
        cells = []
        for point in box_cells(box, points):
            estimate = _cell_edge(
                x.ratio, n, child, g, point, the_setting, wz, point.get("resistance")
            )
            cells.append(Cell(MappingProxyType({**point, **extra}), estimate))
        if progress is not None:
            progress(x.label)
        comparisons.append(Comparison(x, the_setting, Band(tuple(cells)), MappingProxyType(box)))
    return EdgeExperiments(
        tuple(comparisons),
        n,
        streams.reported_seed(root),
        time.perf_counter() - t0,
        points,
        psi,
    )


HUMAN_PSI_DEGREES = math.degrees(HUMAN_PSI)
"""The human toss preset's typical cone angle ψ, degrees
(:data:`~coinflight.studies.presets.HUMAN_PSI`, fitted there to coins' same-side rate; a
cylinder's ψ is not measured)."""


def axial_spin(ratio: float, spin: Distribution, psi: float | str) -> Distribution:
    """The axial spin ωz (rad/s) that tilts a cylinder of ratio h/d spinning at ``spin`` (ωx,
    its median) onto a precession cone of angle ψ: ωz = (I1/I3) ωx cot ψ (Diaconis, Holmes &
    Montgomery 2007, §2; :func:`coinflight.core.precession.axial_spin`), I1/I3 the uniform
    cylinder's (independent of its size and mass).

    ``psi``: degrees, 0 < ψ ≤ 90, one ωz (a :class:`~coinflight.model.distributions.Fixed`;
    ψ then varies a little with each toss's ωx), or ``"human"``: the human toss preset's
    relation (:func:`coinflight.studies.presets.human`: ωz ~ Normal(μ, μ/2) with μ at ψ0 =
    82.05°, so the same spread of ψ as the preset's coins).
    """
    from coinflight.core import precession
    from coinflight.model.distributions import Fixed, Normal
    from coinflight.studies.presets import HUMAN_COT_PSI_RELATIVE_SD

    v.instance("spin", spin, Distribution, "a distribution")
    if psi == "human":
        degrees, spread = HUMAN_PSI_DEGREES, HUMAN_COT_PSI_RELATIVE_SD
    elif isinstance(psi, str):
        raise ValueError(f"psi must be a cone angle in degrees or 'human', got {psi!r}")
    else:
        degrees, spread = v.number("psi", psi, "degrees"), 0.0
        if not 0.0 < degrees <= 90.0:
            raise ValueError(f"psi must be above 0 and at most 90 degrees, got {degrees:g}")
    from coinflight.studies.edge import cylinder

    i1, i3 = cylinder(ratio).moments
    wx = float(np.asarray(spin.ppf(np.asarray([0.5])))[0])
    wz = 0.0 if degrees == 90.0 else float(precession.axial_spin(wx, math.radians(degrees), i1, i3))
    return Normal(wz, spread * wz) if spread else Fixed(wz)


WOBBLE_PSI: tuple[float | str, ...] = (90.0, "human", 80.0, 70.0, 60.0, 45.0)
"""The cone angles of :func:`wobble_sweep`, degrees (90: planar, no axial spin; "human": the
preset's spread about 82°): a stated sweep, not a fit."""

WOBBLE_CELLS: tuple[Mapping[str, float], ...] = (
    MappingProxyType(
        {"restitution": 0.45, "friction": 0.325, "diameter": 0.024, "drop_height": 0.35}
    ),
    MappingProxyType({"restitution": 0.3, "friction": 0.05, "diameter": 0.02, "drop_height": 0.5}),
    MappingProxyType({"restitution": 0.6, "friction": 0.6, "diameter": 0.05, "drop_height": 0.2}),
)
"""The settings of :func:`wobble_sweep`: the hand-table box's centre (e, μ; a 24 mm cylinder
as :func:`mujoco_check`'s, released 0.35 m up) and two opposite corners: the one of the
planar band's highest P(edge) and the one facing it."""


@dataclass(frozen=True)
class WobbleRow:
    """P(edge) of one experiment's setting with cone angle ``psi`` (degrees or "human") at
    ``parameters``."""

    label: str
    ratio: float
    psi: float | str
    parameters: Mapping[str, float]
    estimate: BinomialEstimate


def wobble_sweep(
    experiments: Sequence[Experiment],
    n: int,
    seed: streams.SeedLike = None,
    *,
    psis: Sequence[float | str] = WOBBLE_PSI,
    cells: Sequence[Mapping[str, float]] = WOBBLE_CELLS,
    g: float = 9.81,
    progress: Callable[[str], None] | None = None,
) -> list[WobbleRow]:
    """P(edge) of each experiment's setting with a wobble: for each cone angle ψ of ``psis``
    (:func:`axial_spin`) and each cell of ``cells`` (restitution, friction, diameter,
    drop_height; and ``resistance``, m, the rolling and pivoting resistance, else the
    surface's default), ``n`` tosses each.

    Experiment i draws from the seed's child i, as in :func:`edge_experiments`: every ψ and
    cell lands the same ωx and v0 (common random numbers; ψ changes ωz only). Work bounded before it
    runs, as :func:`edge_experiments`; ``progress`` is called first once every input is checked,
    before any toss (the run's size), then after each cell.
    """
    items, n, settings = _checked(experiments, n, seed)
    spins = {
        x.label: [axial_spin(x.ratio, settings[x.setting].spin, p) for p in psis] for x in items
    }
    for cell in cells:
        _cell_checked(cell, g)
    runs = len(items) * len(psis) * len(cells)
    what = f"wobble sweep: {runs} cells × {n:,} tosses"
    seconds = len(items) * len(psis) * _landing_seconds(cells, n)
    v.work_bound(what, seconds, v.MAX_RUN_SECONDS, "s", "use fewer tosses per cell (n)")
    if progress is not None:
        progress(f"{what}, about {v.duration(seconds)}")
    root = streams.seed_sequence(seed)
    rows = []
    for i, x in enumerate(items):
        the_setting = settings[x.setting]
        for psi, wz in zip(psis, spins[x.label], strict=True):
            for cell in cells:
                child = streams.child(root, i)
                resistance = cell.get("resistance")
                estimate = _cell_edge(x.ratio, n, child, g, cell, the_setting, wz, resistance)
                rows.append(WobbleRow(x.label, x.ratio, psi, cell, estimate))
                if progress is not None:
                    progress(f"{x.label} ψ {psi} {dict(cell)}: {estimate.p:.4f}")
    return rows


@dataclass(frozen=True)
class EngineCheck:
    """The same ``n`` tosses of one setting at one point of the box in coinflight and in MuJoCo
    (:func:`coinflight.studies.mujoco_compare.run`): edges of each, MuJoCo's tosses still
    moving at its limit and the point (``parameters``)."""

    label: str
    parameters: Mapping[str, float]
    coinflight: BinomialEstimate
    mujoco: BinomialEstimate
    mujoco_moving: int
    mujoco_seconds: float


def mujoco_check(
    experiment: Experiment,
    n: int,
    seed: streams.SeedLike = None,
    *,
    restitution: float = 0.45,
    friction: float = 0.325,
    drop_height: float | None = None,
    resistance: float = 1e-4,
    g: float = 9.81,
    psi: float | Literal["human"] | None = None,
    progress: Callable[[str], None] | None = None,
) -> EngineCheck:
    """``n`` tosses of ``experiment``'s setting (a cylinder of diameter
    :data:`coinflight.studies.edge.SIM_DIAMETER`, so no scaling; spin and launch speed drawn
    from the seed's child 0, release ``drop_height``, default the middle of the setting's
    range) landed on one table (e, μ; the rolling and pivoting resistance, MuJoCo's rolling and
    torsional friction, ``resistance`` m) by coinflight and by MuJoCo (its defaults
    otherwise: condim 6, Euler, damping calibrated to e, each toss carried to rest or 20 s
    past its first contact). ``psi``: a wobble (:func:`axial_spin`; ωz drawn from the third
    row of the same stream, as :func:`~coinflight.studies.edge.simulate_edge` draws it: the
    same ωx and v0 as without it). ImportError without MuJoCo; the whole check's work
    (coinflight at its landing rate, MuJoCo by :func:`coinflight.studies.mujoco_compare.
    seconds_estimate`) bounded before anything runs; ``progress``, if given, is called once
    every input is checked and the work bounded, before any toss (the check's size)."""
    from coinflight.core.outcome import EDGE
    from coinflight.model.surface import Surface
    from coinflight.model.toss import check_gravity
    from coinflight.outcomes.table import TableLanding, land
    from coinflight.studies import mujoco_compare
    from coinflight.studies.edge import SIM_DIAMETER, cylinder

    v.instance("experiment", experiment, Experiment, "an Experiment")
    n = v.count("tosses of the MuJoCo check", n, 1, 100_000)
    the_setting = setting(experiment.setting)
    drop = float(np.mean(the_setting.drop_height)) if drop_height is None else drop_height
    check_gravity(g)
    streams.check_seed(seed)
    wz = None if psi is None else axial_spin(experiment.ratio, the_setting.spin, psi)
    table = Surface(
        "table",
        drop,
        restitution,
        friction,
        rolling_resistance=resistance,
        pivoting_resistance=resistance,
    )
    # Bounded before anything runs: the landings at their rate, and MuJoCo's.
    seconds = n / TableLanding(table).rate
    seconds += mujoco_compare.seconds_estimate(n, mujoco_compare.SETTLE)
    what = f"the MuJoCo check: {n} tosses in coinflight and in MuJoCo"
    v.work_bound(what, seconds, v.MAX_RUN_SECONDS, "s", "use fewer tosses")
    if progress is not None:
        progress(f"{what}, about {v.duration(seconds)}")
    root = streams.seed_sequence(seed)
    k = 2 if wz is None else 3
    u = np.concatenate(list(streams.unit_cube(streams.child(root, 0), n, k)), axis=1)
    omega = np.zeros((n, 3))
    omega[:, 0] = the_setting.spin.ppf(u[0])
    if wz is not None:
        omega[:, 2] = wz.ppf(u[2])
    v0 = np.asarray(the_setting.launch_speed.ppf(u[1]), dtype=float)
    coin = cylinder(experiment.ratio)  # simulate_edge's
    seed_int = streams.reported_seed(root)

    def edges(faces: Any) -> BinomialEstimate:
        return BinomialEstimate(int(np.count_nonzero(faces == EDGE)), n, seed_int)

    ours = edges(land(coin, omega, v0, 1.0, g, table).face)
    engine = mujoco_compare.Engine(torsional=resistance, rolling=resistance)
    run = mujoco_compare.run(coin, omega, v0, drop, restitution, friction, g, engine=engine)
    return EngineCheck(
        experiment.label,
        MappingProxyType(
            {
                "restitution": restitution,
                "friction": friction,
                "diameter": SIM_DIAMETER,
                "drop_height": drop,
                "resistance": resistance,
                **({} if psi is None else {"psi": HUMAN_PSI_DEGREES if psi == "human" else psi}),
            }
        ),
        ours,
        edges(run.rest),
        int(np.count_nonzero(run.moving)),
        float(run.elapsed),
    )


__all__ = [
    "HAND_DIAMETER",
    "HAND_DROP",
    "HUMAN_PSI_DEGREES",
    "RESISTANCE",
    "SETTINGS",
    "SOURCE_SETTINGS",
    "WOBBLE_CELLS",
    "WOBBLE_PSI",
    "Band",
    "BoxCells",
    "Cell",
    "Comparison",
    "EdgeExperiments",
    "EngineCheck",
    "Experiment",
    "Setting",
    "WobbleRow",
    "axial_spin",
    "box_cells",
    "edge_experiments",
    "experiment_box",
    "from_dataset",
    "mujoco_check",
    "setting",
    "wobble_sweep",
]
