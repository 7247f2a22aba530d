"""``coinflight landing-report``: the table landing validated, as figures, numbers and a report.

Every number comes from :mod:`coinflight.studies.landing` at run time (none is written here),
so the report of a later version of the contact physics shows that version's numbers. The
files (``report.md``, ``report.html``, ``numbers.json`` and the figures) appear together at
the end or not at all (:func:`coinflight._files.staged_folder`).
"""

from __future__ import annotations

import json
import math
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any, Literal

import numpy as np

from coinflight import __version__
from coinflight._files import check_all_writable, staged_folder, write_text
from coinflight._provenance import provenance
from coinflight.probability import streams
from coinflight.report.document import (
    Block,
    Bullets,
    Document,
    Heading,
    Image,
    Paragraph,
    Table,
)
from coinflight.studies import landing as study
from coinflight.studies.edge_experiments import EdgeExperiments

DEFAULT_SEED = 20261123
"""The report's documented seed, so that it is the same on every machine (reported)."""
FIGURES = ("dead_landings", "contact_maps", "nickel_band", "mujoco")
REPORTS = ("report.md", "report.html", "numbers.json")
Step = Callable[[str], None]
HNP_NOTE = (
    "Hernández-Navarro & Piñero (2021, arXiv:2103.10927, 'Exact edge landing probability for "
    "the bouncing coin toss and the three-sided die problem'): only the abstract could be read "
    "for this project; their formula and numbers are not reproduced here."
)
"""What the report can say of Hernández-Navarro & Piñero's analytic P(edge) (numbers.json)."""


@dataclass(frozen=True)
class Sizes:
    """How much the report computes (the defaults are the full report, about ten minutes on 2
    cores; :data:`QUICK`). Every landing with e > 0 is carried to rest (about 10² landings a
    second, planar tosses far more); dead landings end at their first impact."""

    dead: int = 100_000
    """Dead landings per ratio h/d (10⁵: P(edge) to about ±0.0015)."""
    bouncing: int = 2_000
    """The same tosses bouncing: tosses per ratio and cell of the box of e, μ and ℓ."""
    bouncing_points: int = 2
    """Values per parameter of that box (2: its 8 corners and its centre)."""
    map_tosses: int = 400
    """Tosses per (e, μ) cell of the maps (P to about ±0.025)."""
    map_restitution: int = 5
    map_friction: int = 6
    """Cells of the maps along e ∈ [0, 0.9] and μ ∈ [0, 1]."""
    band_tosses: int = 100
    """The nickel's band: tosses per cell (the 16 corners and the centre of each preset's box
    of e, μ, the resistances and the corner radius; :func:`coinflight.studies.landing.
    nickel_band`)."""
    band_integrated: int = 400
    """The same: tosses with the four drawn toss by toss, per preset."""
    mujoco: int = 1_000
    """Identical tosses in coinflight and MuJoCo (0: skip; MuJoCo takes about 0.2 s a toss)."""
    experiments: int = 500
    """Thick cylinders against experiments, planar tosses: tosses per cell of each measured
    point's box (0: skip both sections; planar tosses fall flat soon, a millisecond a toss)."""
    experiments_human: int = 100
    """The same with human tosses (the preset's wobble), which roll for long on their rims
    (tens of milliseconds a toss; 100: the least :data:`~coinflight.studies.edge_experiments.
    MIN_TOSSES_TO_JUDGE` judges)."""
    experiments_points: int = 2
    """Values per unmeasured parameter of that box (2: corners and centre)."""

    def to_dict(self) -> dict[str, int]:
        from dataclasses import asdict

        return asdict(self)


QUICK = Sizes(
    dead=2_000,
    bouncing=100,
    bouncing_points=2,
    map_tosses=40,
    map_restitution=3,
    map_friction=3,
    band_tosses=4,
    band_integrated=8,
    mujoco=4,
    experiments=10,
    experiments_human=4,
    experiments_points=2,
)
"""A report in a minute or two (tests, a first look): the same sections, small samples."""


@dataclass(frozen=True)
class LandingReport:
    """What :func:`landing_report` computed and wrote."""

    dead: list[study.DeadLanding]
    maps: study.ContactMaps
    band: study.NickelBand
    mujoco: study.MujocoComparison | None
    mujoco_note: str
    sizes: Sizes
    seed: int
    files: tuple[Path, ...]
    timings: dict[str, float] = field(default_factory=dict)
    bouncing: study.BouncingEdges | None = None
    experiments: EdgeExperiments | None = None
    experiments_left: tuple[str, ...] = ()
    experiments_human: EdgeExperiments | None = None
    """The same measured points beside human tosses as the preset makes them (its wobble)."""

    def numbers(self) -> dict[str, Any]:
        """Every number of the report, JSON-ready (``numbers.json``)."""
        out: dict[str, Any] = {
            "coinflight": __version__,
            "seed": self.seed,
            "sizes": self.sizes.to_dict(),
            "dead_landings": [
                {
                    "ratio": d.ratio,
                    "p_edge_dynamic": d.dynamic,
                    "p_edge_geometric": d.geometric,
                    "p_edge": d.simulated.p,
                    "stderr": d.simulated.stderr,
                    "n": d.simulated.n,
                    "z_dynamic": d.z,
                }
                for d in self.dead
            ],
            "bouncing_edges": None
            if self.bouncing is None
            else {
                "ratios": list(self.bouncing.ratios),
                "cells": [dict(c) for c in self.bouncing.cells],
                "p_edge_cells": self.bouncing.edge.tolist(),
                "low": [self.bouncing.low(k)[0] for k in range(len(self.bouncing.ratios))],
                "high": [self.bouncing.high(k)[0] for k in range(len(self.bouncing.ratios))],
                "n": self.bouncing.n,
                "hernandez_navarro_pinero": HNP_NOTE,
            },
            "contact_maps": {
                "restitution": self.maps.restitution.tolist(),
                "friction": self.maps.friction.tolist(),
                "p_same_side": self.maps.same.tolist(),
                "p_edge": self.maps.edge.tolist(),
                "unsettled": self.maps.unsettled.tolist(),
                "n": self.maps.n,
            },
            "nickel_band": _band_numbers(self.band),
            "mujoco": None if self.mujoco is None else _mujoco_numbers(self.mujoco),
            "mujoco_note": self.mujoco_note,
            "edge_experiments": None
            if self.experiments is None
            else {**self.experiments.to_dict(), "left_out": list(self.experiments_left)},
            "edge_experiments_human": None
            if self.experiments_human is None
            else self.experiments_human.to_dict(),
            "timings": self.timings,
        }
        return out


def _band_numbers(r: study.NickelBand) -> dict[str, Any]:
    """numbers.json's ``nickel_band``: the band per preset, its axes, the edges by how they
    ended, the fully rounded rim."""
    axes = ("corner_radius", "resistance", "friction", "restitution")
    return {
        "paths": list(study.EDGE_PATHS),
        "bands": [
            {
                "preset": b.preset,
                "restitution": list(b.restitution),
                "friction": list(b.friction),
                "resistance": list(b.resistance),
                "corner_radius": list(b.corner),
                "p_edge_cells": b.edge.tolist(),
                "cells_axes": list(axes),
                "edges_by_path_cells": b.paths.tolist(),
                "p_edge_centre": b.centre,
                "low": b.low[0],
                "low_stderr": b.low[1],
                "high": b.high[0],
                "high_stderr": b.high[1],
                "axes": {
                    name: {"low_end": b.axis(k)[0][0], "high_end": b.axis(k)[1][0]}
                    for k, name in enumerate(axes)
                },
                "integrated": b.integrated.p,
                "integrated_stderr": b.integrated.stderr,
                "integrated_n": b.integrated.n,
                "integrated_edges_by_path": dict(
                    zip(study.EDGE_PATHS, b.integrated_paths.tolist(), strict=True)
                ),
                "n": b.n,
                "sources": b.sources,
            }
            for b in r.bands
        ],
        "round_rim": {
            **r.round_rim_parameters,
            "edges": r.round_rim.successes,
            "n": r.round_rim.n,
        },
        "murray_teare": study.MURRAY_TEARE,
        "seconds": r.seconds,
    }


def _settled_fractions(c: study.MujocoComparison) -> list[float] | None:
    """MuJoCo's (tails, heads, edge) among the tosses that settled (None if none did)."""
    settled = c.mujoco_rest[~c.mujoco_moving]
    if not len(settled):
        return None
    return (np.bincount(settled, minlength=3) / len(settled)).tolist()


def _quartiles(t: np.ndarray) -> list[float] | None:
    """(25, 50, 75 %, largest) of the finite values (None if none)."""
    t = t[np.isfinite(t)]
    return None if not len(t) else [*np.percentile(t, (25, 50, 75)).tolist(), float(t.max())]


def _mujoco_numbers(c: study.MujocoComparison) -> dict[str, Any]:
    ours = c.coinflight
    edge = c.mujoco_rest == 2
    return {
        "n": c.n,
        "restitution": c.restitution,
        "friction": c.friction,
        "rolling_resistance": c.rolling_resistance,
        "pivoting_resistance": c.pivoting_resistance,
        "coinflight_first": c.fractions(c.first).tolist(),
        "mujoco_first": c.fractions(c.mujoco_first).tolist(),
        "coinflight_rest": c.fractions(ours.rest).tolist(),
        "coinflight_rest_stderr": c.stderrs(ours.rest).tolist(),
        "mujoco_rest": c.fractions(c.mujoco_rest).tolist(),
        "mujoco_rest_stderr": c.stderrs(c.mujoco_rest).tolist(),
        "first_agreement": c.first_agreement,
        "rest_agreement": c.rest_agreement,
        "coinflight_unsettled": ours.unsettled,
        "coinflight_ended_at_impact": ours.at_impact,
        "mujoco_unsettled": c.mujoco_unsettled,
        "mujoco_unsettled_on_edge": int(np.count_nonzero(c.mujoco_moving & edge)),
        "mujoco_settle_limit": c.mujoco.limit,
        "mujoco_rest_settled_only": _settled_fractions(c),
        "mujoco_time_to_rest_edges": _quartiles(c.mujoco.rest_time[edge & ~c.mujoco_moving]),
        "mujoco_time_to_rest_faces": _quartiles(c.mujoco.rest_time[~edge & ~c.mujoco_moving]),
        "coinflight_seconds": ours.seconds,
        "mujoco_seconds": c.mujoco_seconds,
        "mujoco_steps": c.mujoco.steps,
        "speed_ratio": c.speed_ratio,
        "settings": c.settings,
    }


def report_files(out_dir: str | Path, formats: tuple[str, ...] = ("png",)) -> list[Path]:
    """The files the report writes into ``out_dir``, checked writable before any computing."""
    out = Path(out_dir)
    paths = [out / f"{name}.{fmt}" for name in FIGURES for fmt in formats]
    paths += [out / name for name in REPORTS]
    return check_all_writable(paths)


def landing_report(
    out_dir: str | Path,
    *,
    seed: int = DEFAULT_SEED,
    sizes: Sizes | None = None,
    step: Step | None = None,
) -> LandingReport:
    """Compute every section of the landing report and write it into ``out_dir``.

    Parameters
    ----------
    out_dir : path
        Folder for ``report.md``, ``report.html``, ``numbers.json`` and the figures (PNG).
    seed : int
        The one seed of every random draw (reported; each section draws from its own child).
    sizes : Sizes, optional
        How much to compute; default the full report (:class:`Sizes`), :data:`QUICK` for a
        report in seconds. The MuJoCo section is skipped, and says so, when MuJoCo is not
        installed or ``sizes.mujoco`` is 0.
    step : callable, optional
        Called with a short description after each section (a progress bar).
    """
    from coinflight.plotting.landing import (
        plot_contact_maps,
        plot_dead_and_bouncing,
        plot_mujoco,
        plot_nickel_band,
    )
    from coinflight.plotting.style import save_figure
    from coinflight.studies import mujoco_compare

    streams.check_seed(seed)
    sizes = sizes if sizes is not None else Sizes()
    out = Path(out_dir)
    report_files(out)  # before minutes of computing, not after
    timings: dict[str, float] = {}

    def timed(name: str, fn: Callable[[], Any]) -> Any:
        t0 = time.perf_counter()
        value = fn()
        timings[name] = time.perf_counter() - t0
        if step is not None:
            step(name)
        return value

    dead = timed("dead landings", lambda: study.dead_landings(sizes.dead, seed))
    bouncing = timed(
        "bouncing edges",
        lambda: study.bouncing_edges(sizes.bouncing, seed, points=sizes.bouncing_points),
    )
    maps = timed(
        "maps over (e, μ)",
        lambda: study.contact_maps(
            sizes.map_tosses,
            seed,
            np.linspace(0.0, 0.9, sizes.map_restitution),
            np.linspace(0.0, 1.0, sizes.map_friction),
        ),
    )
    band = timed(
        "nickel band",
        lambda: study.nickel_band(sizes.band_tosses, seed, sizes.band_integrated),
    )
    mujoco: study.MujocoComparison | None = None
    if sizes.mujoco <= 0:
        note = "MuJoCo comparison not asked for (size 0)."
    elif not mujoco_compare.available():
        note = (
            "MuJoCo is not installed (pip install 'coinflight[mujoco]'): the comparison was "
            "skipped."
        )
    else:
        mujoco = timed("MuJoCo", lambda: study.mujoco_comparison(sizes.mujoco, seed))
        note = ""
    experiments: EdgeExperiments | None = None
    human: EdgeExperiments | None = None
    left: tuple[str, ...] = ()
    runs: tuple[tuple[Literal["human"] | None, int], ...] = (
        (None, sizes.experiments),
        ("human", sizes.experiments_human),
    )
    for psi, size in runs if sizes.experiments > 0 else ():
        if size <= 0:
            continue

        def compare(
            psi: Literal["human"] | None = psi, size: int = size
        ) -> tuple[EdgeExperiments, list[str]]:
            return study.thick_experiments(size, seed, sizes.experiments_points, psi)

        name = "thick cylinders against experiments" + (", human tosses" if psi else "")
        x, left_out = timed(name, compare)
        experiments, human = (x, human) if psi is None else (experiments, x)
        left = tuple(left_out)
    files: list[Path] = []
    more = {
        "bouncing": bouncing,
        "experiments": experiments,
        "experiments_human": human,
    }
    report = LandingReport(
        dead, maps, band, mujoco, note, sizes, seed, (), timings, **more, experiments_left=left
    )
    with staged_folder(out) as stage:
        figures = {
            "dead_landings": plot_dead_and_bouncing(dead, bouncing),
            "contact_maps": plot_contact_maps(maps),
            "nickel_band": plot_nickel_band(band),
        }
        if mujoco is not None:
            figures["mujoco"] = plot_mujoco(mujoco)
        for name, fig in figures.items():
            files += save_figure(fig, stage / f"{name}.png")
        doc = build_document(report)
        numbers = {**report.numbers(), **provenance()}  # where numbers.json came from
        for name, text in zip(
            REPORTS,
            (doc.to_markdown(), doc.to_html(), json.dumps(numbers, indent=1) + "\n"),
            strict=True,
        ):
            files.append(write_text(stage / name, text))
        files = [out / f.relative_to(stage) for f in files]
    return replace(report, files=tuple(files))  # the report as computed, and where it went


def _pm(p: float, se: float, digits: int = 4) -> str:
    return f"{p:.{digits}f} ± {se:.{digits}f}"


def _one_in(p: float) -> str:
    return f"1 in {1 / p:,.0f}" if p > 0 else "none seen"


def build_document(r: LandingReport) -> Document:
    """The report's text, tables and figures, from the computed numbers."""
    doc = Document("Table landings validated: dead landings, (e, μ) maps, the nickel, MuJoCo")
    doc.add(
        Paragraph(
            f"coinflight {__version__}, seed {r.seed} (every random draw; each section from its "
            f"own child stream). Sizes: {json.dumps(r.sizes.to_dict())}. Every number below is "
            "computed by the library when the report is made (coinflight.studies.landing); "
            "none is written into the report's code."
        )
    )
    doc.add(*_dead_section(r.dead))
    if r.bouncing is not None:
        doc.add(*_bouncing_section(r.dead, r.bouncing))
    doc.add(*_maps_section(r.maps))
    doc.add(*_band_section(r.band))
    doc.add(*_mujoco_section(r.mujoco, r.mujoco_note))
    if r.experiments is not None:
        doc.add(*_experiments_section(r.experiments, r.experiments_left))
    if r.experiments_human is not None:
        doc.add(*_experiments_section(r.experiments_human, ()))
    doc.add(
        Heading("Timings"),
        Table(("section", "seconds"), tuple((k, f"{v:.1f}") for k, v in r.timings.items())),
    )
    return doc


def _dead_section(dead: list[study.DeadLanding]) -> tuple[Block, ...]:
    from coinflight.studies.edge import SIM_DROP, SIM_FRICTION, SIM_LAUNCH_SPEED, SIM_SPIN

    n = dead[0].simulated.n
    rows = tuple(
        (
            f"{d.ratio:g}",
            f"{d.dynamic:.4f}",
            f"{d.geometric:.4f}",
            _pm(d.simulated.p, d.simulated.stderr),
            f"{d.z:+.2f}",
            "yes" if abs(d.z) <= 3 else "NO",
        )
        for d in dead
    )
    outside = [d for d in dead if abs(d.z) > 3]
    verdict = (
        "Every ratio lies within 3 standard errors of the dynamic model."
        if not outside
        else "Outside 3 standard errors of the dynamic model at h/d = "
        + ", ".join(f"{d.ratio:g} ({d.z:+.1f} s.e.)" for d in outside)
        + ": the landing is not yet the model's dead landing there."
    )
    return (
        Heading("Dead landings against Yong & Mahadevan"),
        Paragraph(
            f"{n:,} tosses per ratio h/d, spinning about a diameter at ωx ~ U{SIM_SPIN} rad/s, "
            f"v0 ~ U{SIM_LAUNCH_SPEED} m/s, landing on a table {SIM_DROP:g} m below with "
            f"restitution 0 and friction {SIM_FRICTION:g} (coinflight.studies.edge.simulate_edge)"
            ": the setting of Yong & Mahadevan's dynamic model (2011, Am. J. Phys. 79:1195), "
            "P(edge) = 2 arctan(h/d)/π. z is the distance in the model's binomial standard "
            f"errors at n = {n:,}. {verdict}"
        ),
        Table(
            ("h/d", "dynamic model", "geometric model", "simulated ± s.e.", "z", "within 3 s.e."),
            rows,
        ),
        Image("dead_landings.png", "Dead landings: simulated P(edge) against both models."),
    )


def _bouncing_verdict(rows: Sequence[tuple[str, ...]]) -> str:
    """The table's last column in words: at which ratios the bouncing band lies below, above or
    across the dynamic model."""
    groups = {
        word: [r[0] for r in rows if r[-1] == word] for word in ("below", "above", "overlaps")
    }
    words = {
        "below": "lowers P(edge) below the dead-landing model at h/d = {}",
        "above": "raises P(edge) above the dead-landing model at h/d = {}",
        "overlaps": "leaves it within reach of the model at h/d = {}",
    }
    parts = [words[w].format(", ".join(r)) for w, r in groups.items() if r]
    return "; ".join(parts) + ", over the whole (e, μ) band (the table's last column)."


def _bouncing_section(dead: list[study.DeadLanding], b: study.BouncingEdges) -> tuple[Block, ...]:
    by_ratio = {d.ratio: d for d in dead}
    rows = []
    for k, ratio in enumerate(b.ratios):
        (lo, lo_se), (hi, hi_se) = b.low(k), b.high(k)
        d = by_ratio.get(ratio)
        below = d is not None and hi + 2 * hi_se < d.dynamic
        above = d is not None and lo - 2 * lo_se > d.dynamic
        rows.append(
            (
                f"{ratio:g}",
                "" if d is None else f"{d.dynamic:.4f}",
                "" if d is None else _pm(d.simulated.p, d.simulated.stderr),
                f"{_pm(lo, lo_se)} – {_pm(hi, hi_se)}",
                "below" if below else "above" if above else "overlaps",
            )
        )
    (e_lo, e_hi), (mu_lo, mu_hi) = b.ranges("restitution"), b.ranges("friction")
    ell_lo, ell_hi = b.ranges("resistance")
    return (
        Heading("Bouncing edges, and Hernández-Navarro & Piñero"),
        Paragraph(
            f"The same tosses as the dead landings ({b.n:,} per ratio and cell, seed {b.seed}, "
            f"one child stream for every cell), now bouncing and carried to rest: restitution "
            f"e ∈ [{e_lo:g}, {e_hi:g}] and friction μ ∈ [{mu_lo:g}, {mu_hi:g}] (the union of "
            f"the surface presets' ranges) and the rolling and pivoting resistance ℓ_r = ℓ_p ∈ "
            f"[{ell_lo:g}, {ell_hi:g}] m, {len(b.cells)} cells (every combination of the "
            "values per parameter and the box's centre). The tosses are planar (spin about a "
            "diameter only). The band runs from the lowest to the highest cell; a band "
            "entirely below or above the dynamic model (each end ±2 s.e.) is marked."
        ),
        Table(
            (
                "h/d",
                "dynamic model (dead)",
                "dead, simulated ± s.e.",
                "bouncing band (± s.e.)",
                "band against the dynamic model",
            ),
            tuple(rows),
        ),
        Paragraph(
            "Hernández-Navarro & Piñero (2021, arXiv:2103.10927, 'Exact edge landing "
            "probability for the bouncing coin toss and the three-sided die problem') combine "
            "the equations of collisions with a statistical-mechanics approach to derive the "
            "outcome probabilities of the partially inelastic (bouncing) coin toss in closed "
            "form. Only their abstract could be read for this project (arXiv v3 and indexing "
            "pages); their formula, its assumptions and their numbers were not, so their curve "
            "is not drawn and no value of theirs is tested here. What the abstract says: the "
            "prediction is validated against earlier simulations and experimental data, with "
            "'moderate discrepancies arising at the highly inelastic regime', and they "
            "'describe the differences with previous, approximate models' (which ones, the "
            "abstract does not say). Our reading, not theirs: a model for the partially "
            "inelastic toss is meant for e > 0, and need not meet Yong & Mahadevan's "
            "dead-landing curve as e → 0. In coinflight, bouncing "
            + _bouncing_verdict(rows)
            + " Whether that agrees with their model can be said only once their formula is "
            "read; the table is the comparison to make then."
        ),
    )


def _maps_section(m: study.ContactMaps) -> tuple[Block, ...]:
    i, j = np.unravel_index(np.argmin(m.same), m.same.shape)
    k, l_ = np.unravel_index(np.argmax(m.same), m.same.shape)
    a, b = np.unravel_index(np.argmax(m.edge), m.edge.shape)
    se = float(m.stderr(np.full(1, 0.5))[0])
    unsettled = int(m.unsettled.sum())
    return (
        Heading("P(same side at rest) and P(edge) over restitution and friction"),
        Paragraph(
            f"The US nickel tossed heads up with ωx ~ U{study.SPIN} rad/s, ωz ~ "
            f"U{study.AXIAL_SPIN} rad/s (it precesses), v0 ~ U{study.LAUNCH_SPEED} m/s, landing "
            f"on a table {study.DROP_HEIGHT:g} m below: {m.n:,} tosses per cell, the same tosses "
            f"in every cell (seed {m.seed}), so that the maps show what e and μ do, not noise. "
            f"P(same side at rest) ranges from {m.same[i, j]:.3f} (e = "
            f"{m.restitution[j]:g}, μ = {m.friction[i]:g}) to {m.same[k, l_]:.3f} (e = "
            f"{m.restitution[l_]:g}, μ = {m.friction[k]:g}), each ± {se:.3f} (s.e.); P(edge) "
            f"reaches {m.edge[a, b]:.4f} at e = {m.restitution[b]:g}, μ = {m.friction[a]:g}. "
            "Neither restitution nor friction of a coin on a table is measured, so a same-side "
            "bias of a table landing is this whole range, not one cell (the rolling and "
            "pivoting resistance and the rim's sharp corners are held at their defaults here; "
            "the nickel's band below varies them too). "
            f"{unsettled:,} of the {m.n * m.same.size:,} landings had not settled when the "
            "simulation stopped (counted by the face they showed)."
        ),
        Image("contact_maps.png", "P(same side at rest) and P(edge) over e and μ."),
    )


def _preset_ranges(b: study.Band) -> tuple[str, str, str]:
    """A nickel band's preset and its ranges of e and μ, as a table row begins."""
    e, mu = b.restitution, b.friction
    return b.preset, f"{e[0]:g}–{e[-1]:g}", f"{mu[0]:g}–{mu[-1]:g}"


def _trend(low: tuple[float, float], high: tuple[float, float]) -> str:
    """ "rises", "falls" or "barely changes" from ``low`` to ``high`` ((P, s.e.) each), beyond
    twice their combined standard error."""
    d = high[0] - low[0]
    if abs(d) <= 2.0 * math.hypot(low[1], high[1]):
        return "barely changes"
    return "rises" if d > 0 else "falls"


def _shift(b: study.Band) -> str:
    """How the edges of ``b``'s cells ended at its least and at its most friction, in words."""
    parts = []
    for end in (0, 1):
        counts = np.take(b.paths, end, axis=2).sum(axis=(0, 1, 2))
        total = int(counts.sum())
        if total:
            parts.append(
                f"at μ {b.friction[end]:g} {counts[1] / total:.0%} of the edges rolled away and "
                f"{counts[2] / total:.0%} stood upright"
            )
    return "".join(f"; {part}" for part in parts)


def _band_section(r: study.NickelBand) -> tuple[Block, ...]:
    from coinflight.model.coin import Coin

    bands = r.bands
    n = bands[0].n
    mt = study.MURRAY_TEARE
    rows = []
    for b in bands:
        (lo, lo_se), (hi, hi_se) = b.low, b.high
        p = b.integrated
        rows.append(
            (
                *_preset_ranges(b),
                f"{lo:.3f} ± {lo_se:.3f} – {hi:.3f} ± {hi_se:.3f}",
                f"{_pm(p.p, p.stderr, 3)} ({_one_in(p.p)}; n = {p.n:,})",
                f"{p.p / mt:,.0f} ×" if p.p > 0 else "–",
            )
        )
    names = ("corner radius a", "resistance ℓ_r = ℓ_p", "friction μ", "restitution e")
    units = (1e3, 1.0, 1.0, 1.0), (" mm", " m", "", "")
    axis_rows = []
    for b in bands:
        ends = (b.corner, b.resistance, b.friction, b.restitution)
        for k, name in enumerate(names):
            low, high = b.axis(k)
            axis_rows.append(
                (
                    b.preset,
                    name,
                    f"{ends[k][0] * units[0][k]:g}{units[1][k]}: {_pm(*low, 3)}",
                    f"{ends[k][1] * units[0][k]:g}{units[1][k]}: {_pm(*high, 3)}",
                    _trend(low, high),
                )
            )
    path_rows = []
    for b in bands:
        edges = int(b.integrated_paths.sum())
        shares = [f"{k} ({k / edges:.0%})" if edges else "0" for k in b.integrated_paths]
        path_rows.append((f"{b.preset}, integrated", str(edges), *shares))
        for end in (0, 1):
            counts = np.take(b.paths, end, axis=2).sum(axis=(0, 1, 2))
            total = int(counts.sum())
            shares = [f"{k} ({k / total:.0%})" if total else "0" for k in counts]
            path_rows.append((f"{b.preset}, cells at μ {b.friction[end]:g}", str(total), *shares))
    pooled = np.sum([b.integrated_paths for b in bands], axis=0)
    edges = int(pooled.sum())
    roll, upright = int(pooled[1]), int(pooled[2])
    first = bands[0]
    mu_low, mu_high = first.axis(2)
    a_low, a_high = first.axis(0)
    par = r.round_rim_parameters
    nickel = Coin.preset(study.COIN)
    if edges:
        why = (
            f"Of the {edges} edges of the integrated tosses "
            f"({' and '.join(b.preset for b in bands)}), "
            f"{roll / edges:.0%} rolled away on their flat band and stopped there, rolling "
            f"straight once the rims' small impacts had taken the rocking out and the "
            f"rolling resistance had slowed the roll, and {upright / edges:.0%} stood upright "
            "on the band, spinning or rocking, until their energy fell below the edge well's "
            f"barrier ({int(pooled[0])} ended at an impact of the bounces, {int(pooled[3])} "
            "had not settled). "
        )
    else:
        why = "None of the integrated tosses ended on edge. "
    friction = _trend(mu_low, mu_high)
    corner = _trend(a_low, a_high)
    why += (
        f"On {first.preset}, P(edge) {friction} with friction (μ {first.friction[0]:g}: "
        f"{mu_low[0]:.3f}, μ {first.friction[1]:g}: {mu_high[0]:.3f}{_shift(first)})"
        + (
            ": friction holds both rims' lowest points, so that a coin on its band rolls "
            "straight rather than slipping off it, and stops its spin about the vertical"
            if friction == "rises"
            else ""
        )
        + ". "
        + f"Rounding the corners to {first.corner[1] * 1e3:g} mm narrows the flat band from "
        f"{nickel.thickness * 1e3:.2f} mm to {(nickel.thickness - 2 * first.corner[1]) * 1e3:.2f}"
        f" mm, and P(edge) {corner} ({a_low[0]:.3f} to {a_high[0]:.3f})"
        + (
            ": a narrow flat band suffices"
            if a_high[0] > 2.0 * a_high[1] and corner != "falls"
            else ""
        )
        + f"; with no band at all (a = h/2) {r.round_rim.successes} of {r.round_rim.n:,} "
        "tosses end on edge. "
    )
    integrated = [b.integrated for b in bands]
    if all(p.p - 2.0 * p.stderr > mt for p in integrated):
        why += (
            f"Murray & Teare's 1 in {1 / mt:,.0f} lies "
            + " and ".join(f"{p.p / mt:,.0f}" for p in integrated)
            + " times below the integrated values: in this rigid-body model the rims' impacts calm "
            "a coin's rocking on its band faster than anything tips it over, and what would (a "
            "real table's roughness and give, the coin's imperfections) is not in the model. "
            "Read these as what rigid bodies do, not as what a nickel on a real table does."
        )
    else:
        why += (
            f"Murray & Teare's 1 in {1 / mt:,.0f} is not below every integrated value by more "
            "than twice its standard error at these sizes."
        )
    return (
        Heading("The US nickel's P(edge): a band over what is not measured, and why"),
        Paragraph(
            "The nickel tossed as for the maps, its landing carried to rest by the rigid, "
            "event-driven 3-D phase once the bounces die out (rolling, sliding and pivoting on "
            "a rim, hops, the other rim's impacts, both rims on the flat band; "
            f"coinflight.core.rigid_ending), {n:,} tosses in each of the 16 corners and at the "
            "centre of a box over each surface preset's e and μ, the rolling and pivoting "
            f"resistance ℓ_r = ℓ_p from {study.RESISTANCES[0]:g} to {study.RESISTANCES[1]:g} m "
            "(the band coinflight.model.surface carries; no source measures it) and the rim's "
            f"corner radius a from 0 to {study.CORNER_RADIUS * 1e3:g} mm (an assumption: no "
            "source gives the nickel's), the same tosses in every cell; and, per preset, "
            "tosses with the four drawn toss by toss (e, μ, a uniform, ℓ log-uniform: "
            "integrated). The band runs from the lowest to the highest cell; Murray & Teare's "
            f"1 in {1 / mt:,.0f} ({mt:.1e}, their extrapolation) beside it is a reference, not "
            f"a target. Computed in {r.seconds:.0f} s."
        ),
        Table(
            (
                "surface preset",
                "e",
                "μ",
                "band of P(edge) (± s.e.)",
                "integrated (± s.e.)",
                "integrated / Murray & Teare's 1 in 6000",
            ),
            tuple(rows),
        ),
        Paragraph(
            "Each axis alone: P(edge) of the cells at its low and at its high end, pooled over "
            "the other three (± binomial s.e. of the pooled landings; the cells share their "
            "tosses, so it is a scale rather than an exact error)."
        ),
        Table(
            ("surface preset", "axis", "low end", "high end", "P(edge) from low to high"),
            tuple(axis_rows),
        ),
        Paragraph(
            "The limit of a fully rounded rim, a = h/2 = "
            f"{par['corner_radius'] * 1e3:.3f} mm (no flat band, no edge well to stand in): the "
            f"cell tosses with e {par['restitution']:g}, μ {par['friction']:g}, ℓ "
            f"{par['resistance']:g} m (those of the first preset's highest cell) end on edge "
            f"{r.round_rim.successes} times in {r.round_rim.n:,}."
        ),
        Paragraph("The edges by how they ended (coinflight.studies.landing.EDGE_PATHS):"),
        Table(("tosses", "edges", *study.EDGE_PATHS), tuple(path_rows)),
        Paragraph("Sources of the ranges of e and μ (coinflight.studies.presets):"),
        Bullets(tuple(f"{b.preset}, {k}: {s}" for b in bands for k, s in b.sources.items())),
        Paragraph(why),
        Image(
            "nickel_band.png",
            "The US nickel's P(edge) over what is not measured, and how the edges ended.",
        ),
    )


def _z_against_mujoco(c: study.MujocoComparison, faces: np.ndarray) -> np.ndarray:
    """(coinflight − MuJoCo) fractions at rest in their combined binomial standard errors
    (as if independent samples; the tosses are the same, so this is a scale, not a test)."""
    se = np.hypot(c.stderrs(faces), c.stderrs(c.mujoco_rest))
    diff = c.fractions(faces) - c.fractions(c.mujoco_rest)
    return np.divide(diff, se, out=np.zeros(3), where=se > 0)


def _times_text(t: np.ndarray) -> str:
    q = _quartiles(t)
    if q is None:
        return "none"
    return f"median {q[1]:.1f} s (quartiles {q[0]:.1f}-{q[2]:.1f}, longest {q[3]:.1f} s)"


def _mujoco_section(c: study.MujocoComparison | None, note: str) -> tuple[Block, ...]:
    head = Heading("The same tosses in MuJoCo")
    if c is None:
        return (head, Paragraph(note))
    s = c.settings
    names = ("tails", "heads", "edge")

    def row(label: str, faces: np.ndarray) -> tuple[str, ...]:
        p = np.bincount(faces, minlength=3) / max(len(faces), 1)
        return (label, *(_pm(float(x), math.sqrt(x * (1 - x) / max(len(faces), 1))) for x in p))

    moving_edges = int(np.count_nonzero(c.mujoco_moving & (c.mujoco_rest == 2)))
    all_edges = int(np.count_nonzero(c.mujoco_rest == 2))
    settled_edge = (c.mujoco_rest == 2) & ~c.mujoco_moving
    settled_face = (c.mujoco_rest != 2) & ~c.mujoco_moving
    rows = [
        row("coinflight, first contact", c.first),
        row("MuJoCo, first contact", c.mujoco_first),
        row("coinflight, at rest", c.coinflight.rest),
        row("MuJoCo, at rest", c.mujoco_rest),
        row(
            f"MuJoCo, at rest, the {c.n - c.mujoco_unsettled:,} settled only",
            c.mujoco_rest[~c.mujoco_moving],
        ),
    ]
    ours = c.coinflight
    agreement = (
        (
            f"{c.rest_agreement:.1%}",
            f"{ours.unsettled:,}",
            ", ".join(f"{z:+.1f}" for z in _z_against_mujoco(c, ours.rest)),
            f"{c.n / ours.seconds:,.0f}",
            f"{c.speed_ratio:,.1f}",
        ),
    )
    theirs_rate = c.n / c.mujoco_seconds
    return (
        head,
        Paragraph(
            f"{c.n:,} identical tosses (seed {c.seed}): the US nickel with ωx ~ U{study.SPIN}, "
            f"ωy ~ U{study.WOBBLE}, ωz = 0 rad/s, v0 ~ U{study.LAUNCH_SPEED} m/s, heads up, "
            f"onto a table {study.DROP_HEIGHT:g} m below, e = {c.restitution:g}, μ = "
            f"{c.friction:g}. coinflight: coinflight.outcomes.table.land, with MuJoCo's rolling "
            f"and torsional friction as its rolling and pivoting resistance (ℓ_r = "
            f"{c.rolling_resistance:g} m, ℓ_p = {c.pivoting_resistance:g} m). MuJoCo "
            f"{s['mujoco']}: a free cylinder over a plane, integrator {s['integrator']}, time step "
            f"{s['timestep']:g} s, contact solref = ({s['solref'][0]:g} s, damping ratio "
            f"{s['solref'][1]:.3f}: calibrated so that a flat drop at the landing speed rebounds "
            f"at {s['flat_drop_restitution']:.3f}), friction (sliding, torsional, rolling) = "
            f"{tuple(s['friction'])} with condim {s.get('condim', 3)} (MuJoCo ignores the "
            f"torsional and rolling coefficients below 4 and 6), {s.get('cone', 'pyramidal')} "
            f"friction cone, {s['threads']} threads; each toss is carried until it can no "
            f"longer change face (at rest, or in a face's well with less energy than the "
            f"corner; checked every {s.get('settle_window', 0.1):g} s), at most "
            f"{s['settle_limit']:g} s past its first contact: {c.mujoco_unsettled:,} tosses "
            f"({moving_edges:,} of them on their edge) were still moving then and are counted "
            "by the well they were in, and shown apart in the settled-only row. No axial spin: "
            "MuJoCo's Euler integrator drifts in the precession phase over a 0.8 m fall (RK4 "
            "does not, at four times the cost)."
        ),
        Table(
            ("engine, moment", *names),
            tuple(rows),
            caption="Fractions of the tosses (± s.e.)",
        ),
        Table(
            (
                "coinflight: same face at rest as MuJoCo",
                "unsettled",
                "at rest − MuJoCo, in s.e. (tails, heads, edge)",
                "tosses/s",
                "speed ratio to MuJoCo",
            ),
            agreement,
            caption=(
                f"Against MuJoCo ({theirs_rate:,.2f} tosses/s, {c.mujoco_unsettled:,} cut at "
                "the settle limit); same tosses, same machine, one run"
            ),
        ),
        Bullets(
            (
                f"Same well at the first contact: {c.first_agreement:.1%} of the tosses "
                "(geometry and free flight only; the rest are within a time step of a "
                "boundary).",
                f"{c.coinflight.at_impact:,} of coinflight's {c.n:,} landings ended at an impact "
                "of the bounces (the energy test: too little energy left to leave the well it was "
                "in, so the outcome is certain), before the rigid 3-D phase; MuJoCo has no such "
                "test and follows every toss until it settles.",
                f"{moving_edges:,} of MuJoCo's {all_edges:,} edges are coins still rolling on "
                f"their edge {s['settle_limit']:g} s after their first contact; the settled-only "
                f"row leaves them out. Time from the first contact to rest in MuJoCo: "
                f"{_times_text(c.mujoco.rest_time[settled_edge])} for the coins at rest on their "
                f"edge, {_times_text(c.mujoco.rest_time[settled_face])} for those on a face.",
                f"These fractions are for one restitution and one friction (e = "
                f"{c.restitution:g}, μ = {c.friction:g}): they compare two engines on identical "
                "tosses and are not a table result to quote; the table's results are the bands "
                "above.",
                "Same face at rest: after several bounces the face at rest depends on every "
                "detail of each impact, so two contact models agree on single tosses little "
                "more than chance; the comparison is of the fractions.",
                "Why the fractions at rest may differ: MuJoCo's contact is soft (a "
                "spring-damper whose rebound depends on the impact speed and that lets the rim "
                "sink fractions of a millimetre, so an impact lasts milliseconds and friction "
                "acts throughout it), its friction creeps, and every contact of a landing is "
                "the same law from the first impact on; coinflight's impacts are instantaneous "
                "with one restitution and one friction, and once the bounces die out its rigid "
                "3-D phase rolls the coin on a point contact, its resistances bounding the "
                "torques as MuJoCo's coefficients do (coinflight.studies.mujoco_compare lists "
                "where the two laws still differ).",
                "Edges: a coin rolling on its rim stays up while its spin lasts (Euler's disk); "
                "both engines give the nickel's rim sharp corners, hence a static edge well "
                "arctan(h/d) = 5.3° wide, which holds a coin that stops rolling upright. Neither "
                "engine's edge rate is a prediction: it moves with the rolling and pivoting "
                "resistance and the corner radius, none measured for a coin.",
            )
        ),
        Image("mujoco.png", "The same tosses in coinflight and MuJoCo."),
    )


_AGAINST = {
    "inside": "within the model's band",
    "above": "above the model's band",
    "below": "below the model's band",
    "too few tosses to judge": "not judged against the model's band (too few tosses per cell)",
}


def _experiments_section(x: EdgeExperiments, left: tuple[str, ...]) -> tuple[Block, ...]:
    from coinflight.studies.edge import SIM_DIAMETER, edge_probability
    from coinflight.studies.edge_experiments import (
        HUMAN_PSI_DEGREES,
        MIN_TOSSES_TO_JUDGE,
        RESISTANCE,
    )

    findings = []
    for c in x.comparisons:
        obs = c.experiment.observed
        lo, hi = obs.ci95
        models = (
            f"no-bounce models: dynamic {float(edge_probability(c.experiment.ratio)):.3f}, "
            f"geometric {float(edge_probability(c.experiment.ratio, 'geometric')):.3f}"
        )
        b = c.band
        word = b.verdict(obs)
        by = "" if word == "inside" else f" by {abs(b.gap(obs)):.3f} (to the band's end)"
        findings.append(
            f"{c.experiment.label}: measured {obs.p:.3f} ± {obs.stderr:.3f} (95 % "
            f"{lo:.3f}–{hi:.3f}) is {_AGAINST[word]}{by}, "
            f"{b.low.p:.3f} ± {b.low.stderr:.3f} to {b.high.p:.3f} ± {b.high.stderr:.3f} "
            f"over {len(b.cells)} cells ({models})."
        )
    verdicts = {c.band.verdict(c.experiment.observed) for c in x.comparisons}
    missed = bool(verdicts & {"above", "below"})
    unjudged = "too few tosses to judge" in verdicts
    settings = sorted({c.setting.description for c in x.comparisons})
    box = x.comparisons[0].box if x.comparisons else {}
    unit = {"diameter": " m", "drop_height": " m (release above the table)", "resistance": " m"}
    ranges = "; ".join(f"{k} {lo:g}–{hi:g}{unit.get(k, '')}" for k, (lo, hi) in box.items())
    wobble = x.psi is not None
    tosses = (
        f"human tosses as the preset makes them, with its wobble (axial spin ωz ~ Normal(μ, "
        f"μ/2), μ putting the normal on a cone of ψ = {HUMAN_PSI_DEGREES:.1f}° at the median "
        "spin: fitted to coins' same-side rate; a cylinder's ψ is not measured)"
        if x.psi == "human"
        else f"tosses with a wobble of ψ = {x.psi}°"
        if wobble
        else "planar tosses (spin about a diameter only, no axial spin)"
    )
    return (
        Heading(
            "Thick cylinders against experiments"
            + (": human tosses with the preset's wobble" if wobble else "")
        ),
        Paragraph(
            "The measured edge fractions shipped with coinflight (coinflight.datasets."
            "edge_experiments; their provenance is weak: fractions read from a secondary table), "
            "each with its binomial standard error, beside the table landing's P(edge) for the "
            f"same kind of throw, {tosses} (coinflight.studies.edge_experiments; its tosses come "
            f"from child {study.EXPERIMENTS_CHILD} of seed {x.seed}: coinflight.studies.landing."
            "thick_experiments with this seed reproduces them). Setting: "
            + "; ".join(settings)
            + f". Unmeasured, carried as a band: {ranges}. {x.n:,} tosses per cell, "
            f"{x.points} values per parameter (every combination and the box's centre), the "
            "same tosses in every cell; cylinders of diameter other than "
            f"{SIM_DIAMETER * 1000:g} mm simulated at their size. "
            "A measured 95 % (Wilson) interval wholly above the highest cell + 2 s.e. is "
            "'above', wholly below the lowest − 2 s.e. 'below', else 'inside'. The band's ends "
            "are its extreme cells, so their noise widens it (the highest of tens of noisy "
            "cells lies a few s.e. above their mean): read it at the full report's sizes, "
            "not --quick's. No parameter was tuned to the data."
        ),
        Table(x.HEADER, tuple(x.table())),
        Bullets(tuple(findings)),
        Paragraph(
            (
                "Where the band misses a measured point, the candidates are: the setting (the "
                "throws' spin, height and release are the human toss preset's and our ranges, "
                "not the experiment's; the cylinders' size, material and the table are not "
                "known; "
                + (
                    "the wobble is the coin preset's, not a cylinder's"
                    if wobble
                    else "planar tosses leave out the axial spin every human toss has (the "
                    "section with the preset's wobble follows)"
                )
                + f"), the unmeasured parameters (e, μ, the resistance {RESISTANCE[0]:g}–"
                f"{RESISTANCE[1]:g} m and a rounded rim, not varied here, may lie outside the "
                "ranges taken), and the model (rigid bodies with Coulomb friction, "
                "instantaneous impacts and point-contact resistances)."
            )
            if missed
            else (
                f"Some bands have fewer than {MIN_TOSSES_TO_JUDGE} tosses per cell (as with "
                "--quick): their ends are noise, so a measured point within them is not "
                "agreement; the full report's sizes judge it."
            )
            if unjudged
            else "Every measured point lies within the model's band; the "
            "band is wide, so this is agreement within what is not measured, not a "
            "confirmation."
        ),
        *((Bullets(tuple(f"left out: {line}" for line in left)),) if left else ()),
    )


__all__ = ["DEFAULT_SEED", "QUICK", "LandingReport", "Sizes", "landing_report", "report_files"]
