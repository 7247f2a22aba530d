"""``coinflight paper``: the founding paper's figures and a reproduction report, in one folder."""

from __future__ import annotations

import math
import time
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from coinflight import __version__
from coinflight._files import check_all_writable, check_writable, staged_folder, write_text
from coinflight.model.coin import Coin
from coinflight.report.document import (
    Block,
    Bullets,
    Document,
    Heading,
    Image,
    Paragraph,
    Table,
)
from coinflight.report.paper import (
    DEFAULT_SEED,
    METHOD_A_INTERVALS,
    METHOD_B_EVENTS,
    METHOD_B_INTERVALS,
    PaperNumbers,
    ProbabilityRow,
    RotationRow,
    paper_numbers,
)

Step = Callable[[str], None]

FIGURES = (
    "fig2a",
    "fig2a-error",
    "fig2b",
    "fig2b-error",
    "fig2c",
    "fig2d",
    "fig3a",
    "fig3a-error",
    "fig3b",
    "fig3b-error",
    "fig3c-f",
)
"""The figures' file stems: each probability figure in the paper's form (P(heads)) and, beside
it, the error form (``-error``: |P(heads) − exact|, log–log)."""
"""File stems of the reproduced figures (each written as .png and .svg)."""
STEPS = 1 + 4 + len(FIGURES) + 1
"""Progress steps of :func:`reproduce_paper`: numbers (5), figures (11), report (1)."""


REPORTS = ("report.md", "report.html")
"""The report's files, beside the figures."""


def paper_files(out_dir: str | Path, formats: tuple[str, ...] = ("png", "svg")) -> list[Path]:
    """The files :func:`reproduce_paper` writes into ``out_dir``, checked writable first.

    ValueError (``cannot write PATH: reason``) for a folder that cannot be written or a file
    that cannot be replaced (a folder of that name), before anything is computed.
    """
    out = Path(out_dir)
    check_writable(out, folder=True)
    files = [out / f"{stem}.{fmt}" for stem in FIGURES for fmt in formats]
    return check_all_writable([*files, *(out / name for name in REPORTS)])


@dataclass(frozen=True)
class PaperReport:
    """What :func:`reproduce_paper` wrote and computed."""

    numbers: PaperNumbers
    files: tuple[Path, ...]
    elapsed: float


def reproduce_paper(
    out_dir: str | Path,
    *,
    coin: Coin | None = None,
    seed: int = DEFAULT_SEED,
    events: int = METHOD_B_EVENTS,
    formats: tuple[str, ...] = ("png", "svg"),
    step: Step | None = None,
    progress: Callable[[int], None] | None = None,
) -> PaperReport:
    """Regenerate every figure of Stefan & Cheche and write ``report.md`` and ``report.html``.

    Parameters
    ----------
    out_dir : path
        Folder for the figures (``fig2a.png`` … ``fig3c-f.svg``) and the report.
    coin : Coin, optional
        Default the US quarter (the paper names no coin; a spin about a diameter does not
        depend on it).
    seed : int
        Seed of method B's random events (reported).
    events : int
        Method B events per probability figure.
    formats : tuple of str
        Image formats of each figure.
    step : callable, optional
        Called with a description after each of :data:`STEPS` steps (a progress bar).
    progress : callable, optional
        Called with the work units done by the probabilities' estimates, most of the run
        (:func:`coinflight.report.paper.paper_work` counts them: a progress bar's total).
    """
    from coinflight.model.toss import Toss
    from coinflight.plotting.convergence import plot_convergence, plot_estimates
    from coinflight.plotting.style import save_figure
    from coinflight.plotting.toss import plot_toss

    t_start = time.perf_counter()
    out = Path(out_dir)
    paper_files(out, formats)  # before minutes of computing, not after
    coin = coin if coin is not None else Coin.preset("us-quarter")
    numbers = paper_numbers(coin, seed=seed, events=events, step=step, progress=progress)
    files: list[Path] = []

    def done(message: str) -> None:
        if step:
            step(message)

    with staged_folder(out) as stage:  # every file appears at the end, or none does
        for row in numbers.probabilities:
            c = row.case
            title = (
                f"Fig {c.figure}: ωx0 ∈ [{c.omega_x[0]:g}, {c.omega_x[1]:g}] rad/s, "
                f"ωy0 = {c.omega_y:g} rad/s, ωz0 = 0, T ∈ [{c.flight_time[0]:g}, "
                f"{c.flight_time[1]:g}] s\n{coin.name} tossed heads up and caught"
            )
            files += save_figure(
                plot_estimates(row.convergence, title), stage / f"fig{c.figure}", formats
            )
            done(f"Fig {c.figure}")
            files += save_figure(
                plot_convergence(row.convergence, title), stage / f"fig{c.figure}-error", formats
            )
            done(f"Fig {c.figure}, error form")
        by_fig = {r.case.figure: r for r in numbers.rotations}
        for fig_id in ("2c", "2d"):
            case = by_fig[fig_id].case
            toss = Toss(omega=(case.omega_x, case.omega_y, 0.0), flight_time=case.flight_time)  # type: ignore[arg-type]
            fig = plot_toss(coin, toss)
            fig.suptitle(
                f"Fig {fig_id}: ωx0 = {case.omega_x:g} rad/s, T = {case.flight_time:g} s — "
                f"{coin.name} {_launch_catch()}",
                fontsize=11,
            )
            files += save_figure(fig, stage / f"fig{fig_id}", formats)
            done(f"Fig {fig_id}")
        cases_3 = [by_fig[f].case for f in ("3c", "3d", "3e", "3f")]
        toss3 = Toss(
            omega=(90.0, 30.0, 0.0),  # type: ignore[arg-type]
            flight_time=np.array([c.flight_time for c in cases_3]),
        )
        fig = plot_toss(coin, toss3)
        fig.suptitle(
            "Figs 3c-f: ωx0 = 90 rad/s, ωy0 = 30 rad/s, T = 0.6, 0.65, 0.7, 0.75 s — "
            f"{coin.name} {_launch_catch()}",
            fontsize=11,
        )
        files += save_figure(fig, stage / "fig3c-f", formats)
        done("Figs 3c-f")

        elapsed = time.perf_counter() - t_start
        doc = build_document(numbers, image_suffix=formats[0])
        doc.add(*timings_footer(numbers, elapsed))
        for name, text in zip(REPORTS, (doc.to_markdown(), doc.to_html()), strict=True):
            files.append(write_text(stage / name, text))
        files = [out / f.relative_to(stage) for f in files]
    done("report.md and report.html")
    return PaperReport(numbers=numbers, files=tuple(files), elapsed=time.perf_counter() - t_start)


def _colour(color: str) -> str:
    from coinflight.plotting.style import color_name

    return color_name(color)


def _method_colours() -> tuple[str, str]:
    from coinflight.plotting.style import method_color

    return _colour(method_color("grid")), _colour(method_color("monte-carlo"))


def _launch_catch() -> str:
    from coinflight.plotting.style import CATCH_COLOR, LAUNCH_COLOR

    return f"at launch ({_colour(LAUNCH_COLOR)}) and at catch ({_colour(CATCH_COLOR)})"


def _toss_colours() -> str:
    from coinflight.plotting.style import HEADS_COLOR, TAILS_COLOR

    return (
        f"{_launch_catch()}, the caught coin's heads face {_colour(HEADS_COLOR)} and tails "
        f"face {_colour(TAILS_COLOR)}"
    )


def _captions(numbers: PaperNumbers) -> dict[str, str]:
    rot = {r.case.figure: r for r in numbers.rotations}
    prob = {r.case.figure: r for r in numbers.probabilities}

    colour_a, colour_b = _method_colours()

    def plotted(fig: str, form: str, what: str, b_note: str, scale: str) -> str:
        """The opening both forms of a probability figure's caption share: what is plotted
        against what, for which tosses."""
        c = prob[fig].case
        return (
            f"Fig {fig}, the {form} form: {what} method A ({colour_a}) and method B "
            f"({colour_b}{b_note}) against the number of configurations or events{scale} for "
            f"ωx0 ∈ [{c.omega_x[0]:g}, {c.omega_x[1]:g}] rad/s, ωy0 = {c.omega_y:g} rad/s, T ∈ "
            f"[{c.flight_time[0]:g}, {c.flight_time[1]:g}] s; "
        )

    def paper_caption(fig: str) -> str:
        return plotted(fig, "paper's", "P(heads) by", ", with 95 % intervals", " (log scale)") + (
            f"the exact value {prob[fig].exact.p_heads:.6f} as a black line, method B's limit "
            f"(its {METHOD_B_INTERVALS}-cell grid's exact count) dashed."
        )

    def p_caption(fig: str) -> str:
        return plotted(fig, "error", "|P(heads) − exact| of", "", ", log–log,") + (
            f"exact value {prob[fig].exact.p_heads:.6f}. Shaded: method B's 95 % interval "
            f"half-width (1.96 s.e.), with its expected slope −1/2 dotted; method A's observed "
            f"slope dashed; method B's floor, its {METHOD_B_INTERVALS}-cell grid's distance "
            "from exact, dashed across."
        )

    def t_caption(fig: str) -> str:
        r = rot[fig]
        c = r.case
        said = (
            f" (the paper's text says {c.paper_face} up; its eq 14 gives {r.face} up)"
            if r.face_agrees is False
            else ""
        )
        return (
            f"Fig {fig}: the coin {_toss_colours()}, ωx0 = {c.omega_x:g} "
            f"rad/s, T = {c.flight_time:g} s: {r.rotations:.3f} turns, {r.face} up{said}."
        )

    turns = ", ".join(f"{rot[f].rotations:.3f}" for f in ("3c", "3d", "3e", "3f"))
    faces = ", ".join(rot[f].face for f in ("3c", "3d", "3e", "3f"))
    return {
        **{f"fig{f}": paper_caption(f) for f in prob},
        **{f"fig{f}-error": p_caption(f) for f in prob},
        "fig2c": t_caption("2c"),
        "fig2d": t_caption("2d"),
        "fig3c-f": "Figs 3c-f: ωx0 = 90, ωy0 = 30 rad/s, T = 0.6, 0.65, 0.7, 0.75 s: "
        f"{turns} turns, {faces} up; the coin {_toss_colours()}; n and S (S ⟂ n) and the "
        "path of n on the unit sphere.",
    }


def _other_checks() -> tuple[str, ...]:
    from coinflight.core import ballistics

    g = 9.81
    t_lo, t_hi = (float(x) for x in ballistics.flight_time(np.array([3.0, 5.0]), g))
    apex = float(ballistics.height(ballistics.launch_speed(0.9, g), g, 0.45))
    v_lo, v_hi = (float(x) for x in ballistics.launch_speed(np.array([0.6, 0.9]), g))
    return (
        f'"3 m/s to 5 m/s (which approximately corresponds to duration of motion in the '
        f'interval 0.6 s to 1 s)": T = 2 v0/g = {t_lo:.3f} to {t_hi:.3f} s (g = {g} m/s²). '
        "Agrees, with the flight time of eq 11.",
        f'"height of motion in gravitational field is less than 1 m": the highest flight of '
        f"the ranges, T = 0.9 s (v0 = {v_hi:.2f} m/s), rises g T²/8 = {apex:.3f} m. Agrees, "
        "barely.",
        f"Launch speeds of the ranges T ∈ [0.6, 0.9] s: v0 = g T/2 = {v_lo:.2f} to "
        f"{v_hi:.2f} m/s, inside the paper's 3 to 5 m/s only from T = {2 * 3 / g:.3f} s on.",
    )


def _face_word(face: str | None) -> str:
    return "—" if face is None else face


def _yes(flag: bool | None) -> str:
    return "—" if flag is None else ("yes" if flag else "NO")


def build_document(numbers: PaperNumbers, image_suffix: str = "png") -> Document:
    """The reproduction report's body as a :class:`~coinflight.report.document.Document`.

    The body holds only what the numbers determine, so that two runs with the same seed write
    the same body; the run's timings go in a footer after it (:func:`timings_footer`).
    """
    doc = Document('Reproduction of Stefan & Cheche, "Coin toss modeling"')
    doc.add(*_summary(numbers))
    doc.add(*_rotations_section(numbers.rotations))
    doc.add(*_disagreements_section(numbers.rotations))
    doc.add(*_probabilities_section(numbers))
    doc.add(Heading("Other statements checked"), Bullets(_other_checks()))
    doc.add(Heading("4. Figures"))
    captions = _captions(numbers)
    for stem in FIGURES:
        doc.add(Image(f"{stem}.{image_suffix}", captions[stem]))
    return doc


TIMINGS_HEADING = "Timings of this run"
"""The footer's heading: what follows it changes from run to run, what precedes it does not."""


def timings_footer(numbers: PaperNumbers, elapsed: float) -> tuple[Block, ...]:
    """The run's timings, appended after the report's body (they change every run)."""
    return (
        Heading(TIMINGS_HEADING),
        Paragraph(
            f"Generated by coinflight {__version__} in {elapsed:.1f} s. These timings are the "
            "only part of the report that changes between runs with the same seed."
        ),
        Table(
            ("step", "seconds"),
            (
                *((k, f"{v:.2f}") for k, v in numbers.timings.items()),
                ("whole reproduction before writing the report", f"{elapsed:.2f}"),
            ),
        ),
    )


def _summary(numbers: PaperNumbers) -> tuple[Block, ...]:
    rot = numbers.rotations
    prob = numbers.probabilities
    n_agree = sum(r.rotations_agree for r in rot)
    disagreements = [r for r in rot if r.face_agrees is False]
    worst_a = max(abs(r.method_a.p_heads - r.exact.p_heads) for r in prob)
    events = numbers.method_b_events
    a_faster = sum(
        r.error_at("grid", events)[1] < r.error_at("monte-carlo", events)[1] for r in prob
    )
    faces = (
        "the paper's text and its own eq 14 disagree for "
        + ", ".join(f"Fig {r.case.figure}" for r in disagreements)
        + " (section 2 below)."
        if disagreements
        else "every face the paper states agrees with its eq 14."
    )
    return (
        Paragraph(
            f"Generated by coinflight {__version__}. Coin: "
            f"{numbers.coin.describe()} (the paper names no coin; for a spin about a diameter "
            "the face does not depend on it). Every toss starts heads up and is caught at "
            f"launch height. Method B seed: {numbers.seed}."
        ),
        Heading("Summary"),
        Bullets(
            (
                f"Rotations: {n_agree} of {len(rot)} counts the paper prints agree with "
                "coinflight to the digits printed.",
                "Faces: " + faces,
                "Probabilities: the paper gives no number, only that methods A and B tend to "
                "50 %. coinflight's exact values for its four ranges lie within "
                f"{max(abs(r.exact.p_heads - 0.5) for r in prob):.4f} of 1/2; method A with "
                f"{METHOD_A_INTERVALS}² configurations is within {worst_a:.1e} of exact.",
                "Method A converges faster than method B, as the paper says, in "
                f"{a_faster} of {len(prob)} figures at equal numbers of tosses (section 3).",
                "The ranges the paper writes as T = v0/g ∈ [0.6, 0.9] s are flight times "
                "T = 2 v0/g (section 2 below).",
            )
        ),
    )


def _rotations_section(rot: tuple[RotationRow, ...]) -> tuple[Block, ...]:
    return (
        Heading("1. Rotations and faces (Figs 2c-d, 3c-f)"),
        Paragraph(
            "θ(T) = T·sqrt(ωx0² + ωy0²) (eqs 11, 15); rotations = θ(T)/2π. The face follows "
            "the paper's rule (eq 14, §2.1): heads up iff cos θ(T) > 0. cos θ is computed three "
            "ways: cos(θ(T)) from eq 14, the paper's Euler-matrix construction (eqs 12-13), and "
            "coinflight's general closed form n(T)·n(0)."
        ),
        rotation_table(rot),
        Table(
            (
                "Fig",
                "cos θ, eq 14",
                "cos θ, Euler matrix (eqs 12-13)",
                "n(T)·n(0), closed form",
                "Ŝ·n at catch",
            ),
            tuple(
                (
                    r.case.figure,
                    f"{r.cos_theta:+.12f}",
                    f"{r.cos_theta_construction:+.12f}",
                    f"{r.cos_theta_closed_form:+.12f}",
                    f"{r.s_dot_n:+.1e}",
                )
                for r in rot
            ),
            caption="Checks the paper states: the three cos θ agree, and S ⟂ n (\"Diaconis' "
            'theorem", S·n = 0 in case b).',
        ),
    )


def _disagreements_section(rot: tuple[RotationRow, ...]) -> tuple[Block, ...]:
    blocks: list[Block] = [Heading("2. Where the paper's text and its own formulas disagree")]
    for r in (r for r in rot if r.face_agrees is False):
        c = r.case
        frac = c.paper_rotations - math.floor(c.paper_rotations)
        blocks += (
            Heading(f'Fig {c.figure}: the text says "{c.quote}"', 3),
            Paragraph(
                f"With ωx0 = {c.omega_x:g} rad/s and T = {c.flight_time:g} s the paper counts "
                f"{c.paper_rotations} rotations, so θ(T) = {c.paper_rotations} × 360° = "
                f"{c.paper_rotations * 360:.1f}°, and θ(T) mod 360° = {frac * 360:.1f}° "
                f"(coinflight: {r.theta_mod_deg:.1f}°). That angle lies in "
                f"{_quadrant_words(r.theta_mod_deg)}, so cos θ(T) = {r.cos_theta:+.4f}. By the "
                "paper's own rule (§2.1 i: θ ∈ (0, π/2) ∪ (3π/2, 2π) ⇔ cos θ > 0 ⇒ head up), "
                f"the coin ends {r.face.upper()} up, not {c.paper_face} up as the text says. "
                "A head-down ending would need the fractional part of the rotation count to lie "
                f"between 0.25 and 0.75; it is {frac:.3f}."
            ),
        )
    blocks += (
        Heading('The ranges written "T = v0/g"', 3),
        Paragraph(
            "Section 3 gives the ranges as T = v0/g ∈ [0.6, 0.9] s, but eq 11 defines the "
            "flight time as T = 2 v0/g. The paper's own numbers use T as the flight time: "
            "80 rad/s × 0.7 s / 2π = 8.913 rotations (Fig 2c) is θ(T) = ωx0·T with T = 0.7 s, "
            "whereas a flight of 2 v0/g with v0/g = 0.7 s would last 1.4 s and give 17.83 "
            "rotations. Its speeds agree too: 3 to 5 m/s corresponds to 2 v0/g = 0.61 to "
            '1.02 s ("approximately 0.6 s to 1 s"). coinflight therefore reads the ranges as '
            "flight times (launch speeds 2.94 to 4.41 m/s for T ∈ [0.6, 0.9] s)."
        ),
    )
    return tuple(blocks)


def _probabilities_section(numbers: PaperNumbers) -> tuple[Block, ...]:
    return (
        Heading("3. Probabilities (Figs 2a-b, 3a-b)"),
        Paragraph(
            f"Method A: the ranges of ωx0 and T cut into {METHOD_A_INTERVALS} intervals each, "
            f"heads counted over the {METHOD_A_INTERVALS}² cell midpoints (an exact count). "
            f"Method B: {numbers.method_b_events:,} random events drawn among the midpoints of "
            f"{METHOD_B_INTERVALS} intervals per parameter (seed {numbers.seed}); it converges "
            f"to the {METHOD_B_INTERVALS} × {METHOD_B_INTERVALS} grid value, shown beside it. "
            "Exact: the measure of the heads bands integrated in closed form (Keller 1986). "
            "The paper states no probability beyond 'tends to the unbiased value of 50%'."
        ),
        probability_table(numbers.probabilities, numbers.method_b_events),
        speed_table(numbers.probabilities, numbers.method_b_events),
    )


def rotation_table(rows: tuple[RotationRow, ...]) -> Table:
    """Rotations and faces: the paper's numbers beside coinflight's."""
    return Table(
        (
            "Fig",
            "ωx0 (rad/s)",
            "ωy0 (rad/s)",
            "T (s)",
            "rotations, paper",
            "rotations, coinflight",
            "agree",
            "θ(T) mod 360°",
            "cos θ(T)",
            "face by eq 14",
            "face in the paper's text",
            "agree",
        ),
        tuple(
            (
                r.case.figure,
                f"{r.case.omega_x:g}",
                f"{r.case.omega_y:g}",
                f"{r.case.flight_time:g}",
                f"{r.case.paper_rotations:.{r.case.decimals}f}",
                f"{r.rotations:.6f}",
                _yes(r.rotations_agree),
                f"{r.theta_mod_deg:.1f}°",
                f"{r.cos_theta:+.4f}",
                r.face,
                _face_word(r.case.paper_face),
                _yes(r.face_agrees),
            )
            for r in rows
        ),
    )


def probability_table(rows: tuple[ProbabilityRow, ...], events: int) -> Table:
    """Probabilities by methods A and B beside the exact value."""
    out = []
    for r in rows:
        c = r.case
        limit_b = r.method_b_limit.p_heads
        ci = r.method_b.ci95
        out.append(
            (
                c.figure,
                f"{c.omega_x[0]:g}–{c.omega_x[1]:g}",
                f"{c.omega_y:g}",
                f"{c.flight_time[0]:g}–{c.flight_time[1]:g}",
                "→ 50 %",
                f"{r.method_a.p_heads:.6f}",
                f"{r.method_b.p_heads:.4f} [{ci[0]:.4f}, {ci[1]:.4f}]" if ci else "",
                f"{limit_b:.4f}",
                f"{r.exact.p_heads:.6f}",
                f"{r.method_a.p_heads - r.exact.p_heads:+.1e}",
            )
        )
    return Table(
        (
            "Fig",
            "ωx0 (rad/s)",
            "ωy0 (rad/s)",
            "T (s)",
            "paper",
            f"method A ({METHOD_A_INTERVALS}²)",
            f"method B ({events:,} events, 95 % CI)",
            f"{METHOD_B_INTERVALS}² grid (B's limit)",
            "exact",
            "A − exact",
        ),
        tuple(out),
    )


def speed_table(rows: tuple[ProbabilityRow, ...], events: int) -> Table:
    """The paper's "Method A ... is faster convergent": errors at equal numbers of tosses."""
    out = []
    for r in rows:
        n_a, err_a = r.error_at("grid", events)
        n_b, err_b = r.error_at("monte-carlo", events)
        out.append(
            (
                r.case.figure,
                f"{err_a:.1e} ({n_a:,} configurations)",
                f"{err_b:.1e} ({n_b:,} events)",
                "yes" if err_a < err_b else "NO",
            )
        )
    return Table(
        ("Fig", "|A − exact|", "|B − exact|", "A closer"),
        tuple(out),
        caption='The paper: "Method A, as expected from the mathematical principles, is faster '
        'convergent." Errors against the exact value at about the same number of tosses.',
    )


def _quadrant_words(deg: float) -> str:
    if deg < 90:
        return "(0°, 90°)"
    if deg < 180:
        return "(90°, 180°)"
    if deg < 270:
        return "(180°, 270°)"
    return "(270°, 360°)"


__all__ = [
    "FIGURES",
    "STEPS",
    "PaperReport",
    "build_document",
    "probability_table",
    "reproduce_paper",
    "rotation_table",
    "speed_table",
    "timings_footer",
]
