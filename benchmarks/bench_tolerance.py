"""How far the contact ending's outcomes are set by its step tolerance (issue 11).

    python benchmarks/bench_tolerance.py [N] [--seed S] [--tolerances 1e-5,1e-6,1e-7,1e-8,1e-9]
        [--extra 1e-10 --subset M] [--nudges 1e-9,1e-6] [--settings 0,1,2]
    python benchmarks/bench_tolerance.py --recorded

The same seeded vigorous tosses of a US nickel as ``bench_bounce.py`` (``bench_bounce.tosses``: ωx ~
U(150, 300), ωy, ωz ~ U(−30, 30) rad/s, v0 ~ U(1.5, 3) m/s, 0.8 m drop, heads up) land on three
surfaces with the contact ending (``bench_bounce.UPRIGHT_SURFACES``): e 0.5 μ 0.3, e 0.5 μ 0.6, and
each toss its own e ~ U(0.2, 0.8), μ ~ U(0.1, 0.6) (``bench_bounce.own_rates``, seed 7, as
``bench_bounce.contact_rates`` draws them, and applied with
:func:`coinflight.core.bounce.with_surface`, as ``land`` does). Each toss's bounces run once
(:func:`bench_contact.handoff`; they do not depend on the contact phase's tolerance); a toss handed
to the contact phase is then carried to its end by :func:`coinflight.core.contact_phase.advance`
(``settle_check``, ``decide`` as :data:`~coinflight.core.contact_phase.UPRIGHT_DECISION`: what
``settle`` does) at each step tolerance ``rtol``, one thread, timed per toss in CPU time. At the
default :data:`~coinflight.core.contact_phase.RTOL` the faces and statuses are checked equal to
``land``'s on the same tosses (the script stops if not).

Per tolerance: the faces (heads, tails, edge) and statuses (settled at an impact, settled in
contact, decided upright, unsettled) of all N tosses, each fraction with its binomial standard
error; against the tightest tolerance of the list: the tosses whose face differs (count, share
of the handed tosses with a 95 % Wilson interval), the statuses that differ, and each face
fraction's difference in units of its standard error (the two runs' errors added in quadrature,
as for independent samples) with the two-proportion test's p (SciPy's ``chi2_contingency``,
no continuity correction) and, since the runs are paired, McNemar's exact p on the discordant
pairs (``binomtest``); steps, CPU time and simulated time per handed toss (medians).

The chaos baseline: each handed state, every component multiplied by 1 + 1e-12 N(0, 1) (seed
``S + 1``), is carried on at the tightest and at the default tolerance; its faces are compared
with the unperturbed run's at that tolerance. When the default disagrees with the tightest
about as often as a 1e-12 nudge does, per-toss faces are not numerically determined at any
practical tolerance, and only the ensemble's fractions mean anything. ``--nudges`` adds larger
nudges at the tightest tolerance; the run ends with the share of handed tosses each nudge size
changes, summed over the settings, and the exponent a of share ~ size^a fitted to them
(:func:`uncertainty_exponent`; ``--recorded`` prints it for the counts below, :data:`RECORDED`).
``--extra 1e-10 --subset M`` also runs the first M tosses at 1e-10 and compares the tightest of
the list with it there.

Measured 2026-11-24 (05:00-05:14 UTC, load 6-8; the project machine, 2 shared cores):
``python benchmarks/bench_tolerance.py 5000 --extra 1e-10 --subset 5000 --nudges
1e-9,1e-8,1e-7,1e-6`` (848 s wall). Handed to the contact phase: 3,533 (e 0.5 μ 0.3), 3,513
(e 0.5 μ 0.6), 3,482 (own e, μ) of 5,000; faces equal to ``land()``'s at 1e-7 in each.

====================  ======  ======  ======  ======  =======  ========================
faces differing from  1e-5    1e-6    1e-7    1e-8    1e-10    1e-12 nudge at 1e-9, 1e-7
rtol 1e-9 (handed)
====================  ======  ======  ======  ======  =======  ========================
e 0.5, μ 0.3          137     75      27      5       3        1, 2
e 0.5, μ 0.6          114     60      34      6       2        0, 0
own e, μ              95      38      21      10      3        0, 1
====================  ======  ======  ======  ======  =======  ========================

Relative nudges of the handed states at rtol 1e-9 change 0, 1, 2 faces (1e-9), 4, 0, 4 (1e-8),
6, 5, 12 (1e-7), 23, 16, 24 (1e-6); on 1,000 tosses (``1000 --tolerances 1e-7,1e-9 --nudges
1e-5,1e-4``, 05:01-05:04 UTC) 21, 15, 10 of 723, 717, 683 (1e-5) and 43, 34, 21 (1e-4), where
rtol 1e-5 differs on 31, 17, 20. What this supports: at the default 1e-7 the faces are
reproducible to 0.6-1.0 % of the handed tosses (against 1e-9), the error of a ~1e-6 relative
nudge of the handed state (1e-5 errs as a ~1e-5 one), and a 1e-12 nudge changes about 1e-4 of
them (1 of 10,528 at 1e-9, 3 at 1e-7). It does not show the faces free of chaos at finer
scales: summed over the settings, the share of faces a nudge δ changes grows as δ^0.45 ± 0.01
(δ from 1e-9 to 1e-4; least squares on log-log, ``--recorded``; 0.36 ± 0.04 with the 1e-12
point), not as δ^1, which a smooth boundary between the faces' basins would give; an exponent
below 1 is the signature of final-state sensitivity, a fractal basin boundary (the uncertainty
exponent of Grebogi, McDonald, Ott & Yorke, Phys. Lett. A 99 (1983) 415). Part of the 1e-12
count may be the adaptive step control's (a nudge moves the accepted steps). A 300-toss check of
the printed fit (``300 --tolerances 1e-7,1e-9 --nudges 1e-8,1e-7,1e-6,1e-5,1e-4``, 05:46 UTC,
load 4-5, 58 s): 0, 0, 1, 4, 10, 29 of 622 changed by 1e-12, 1e-8 ... 1e-4; a = 0.48 ± 0.03 over
the four sizes that changed a face.

Ensemble fractions: no face fraction at any tolerance differs from 1e-9's by more than 0.4 of
its standard error (two-proportion p ≥ 0.72). McNemar's paired test gives p < 0.05 in 2 of its
36 applications, both heads at 1e-6 and of the same sign (+0.0036, first setting; +0.0026,
third), none at 1e-5. The 36 tests are correlated, not independent: the three settings launch
the same tosses, each tolerance is compared with the same 1e-9 run, and a setting's three face
shares sum to 1; so 2 of 36 cannot be set against the 1.8 that independent tests would give by
chance (a single paired test of the three faces per tolerance and setting, Stuart-Maxwell on the
3×3 table, was not run). Statuses: no toss unsettled at any tolerance;
decided upright 411-414, 1,461-1,465, 650-653. CPU per handed toss (median, ms):
0.55, 0.74, 1.07, 1.55, 2.33 (e 0.5 μ 0.3); 0.99, 1.25, 1.70, 2.49, 3.71 (μ 0.6); 0.59, 0.78,
1.12, 1.68, 2.55 (own) at 1e-5 ... 1e-9; 3.55, 5.66, 3.93 at 1e-10; median steps 348, 626,
1,425, 2,232 at 1e-5, 1e-7, 1e-9, 1e-10 (e 0.5 μ 0.3); settle times unchanged (median
0.271-0.272 s, 0.331 s, 0.273 s at every tolerance). RTOL is kept at 1e-7: a looser default
leaves the ensembles alone (1.7-1.95x faster a handed toss at 1e-5) but changes 1-4 % of
per-toss faces, where a 1e-12 nudge changes about 1 in 10,000.
"""

from __future__ import annotations

import os

os.environ.setdefault("NUMBA_NUM_THREADS", "1")  # before numba is imported

import argparse
import math
import time
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

import bench_bounce  # the script's own folder is on the path

SETTINGS = bench_bounce.UPRIGHT_SURFACES
"""The surfaces (e, μ); None: each toss its own e, μ (:func:`bench_bounce.own_rates`)."""
TOLERANCES = (1e-5, 1e-6, 1e-7, 1e-8, 1e-9)
NUDGE = 1e-12
"""Relative size of the chaos baseline's perturbation of each handed state's components."""

RECORDED = {
    1e-12: (1, 10_528),
    1e-9: (3, 10_528),
    1e-8: (8, 10_528),
    1e-7: (23, 10_528),
    1e-6: (63, 10_528),
    1e-5: (46, 2_123),
    1e-4: (98, 2_123),
}
"""Faces changed by a relative nudge of each handed state at rtol 1e-9, summed over the three
settings: (changed, handed). 1e-12 to 1e-6: the 5,000-toss run of 2026-11-24 (05:00-05:14 UTC);
1e-5, 1e-4: the 1,000-toss run (05:01-05:04 UTC); the commands are in the module's notes.
``--recorded`` prints their fit (:func:`uncertainty_exponent`)."""

FACES = ("tails", "heads", "edge")  # the codes TAILS 0, HEADS 1, EDGE 2
# Status codes of coinflight.core.outcome.Status grouped for the tables.
STATUSES = {"impact": (0, 1, 2), "contact": (5,), "decided": (6,), "unsettled": (3,)}


@dataclass
class Run:
    """Outcomes of N tosses at one tolerance (non-handed tosses: their bounces' outcome)."""

    face: np.ndarray
    status: np.ndarray
    steps: np.ndarray
    cpu: np.ndarray
    time: np.ndarray


def disagreements(a: np.ndarray, b: np.ndarray, among: np.ndarray | None = None) -> int:
    """How many entries of ``a`` and ``b`` (paired) differ, among ``among`` (a mask) if given."""
    differ = np.asarray(a) != np.asarray(b)
    if among is not None:
        differ &= np.asarray(among, dtype=bool)
    return int(np.count_nonzero(differ))


def discordant(a: np.ndarray, b: np.ndarray) -> tuple[int, int]:
    """McNemar's discordant pairs of two paired boolean arrays: (a and not b, b and not a)."""
    a = np.asarray(a, dtype=bool)
    b = np.asarray(b, dtype=bool)
    return int(np.count_nonzero(a & ~b)), int(np.count_nonzero(b & ~a))


def mcnemar_p(a: np.ndarray, b: np.ndarray) -> float:
    """McNemar's exact two-sided p for equal marginal shares of two paired boolean arrays (the
    discordant pairs as Binomial(b + c, 1/2), McNemar 1947; SciPy's ``binomtest``); 1 when no
    pair is discordant."""
    from scipy.stats import binomtest

    k, j = discordant(a, b)
    return 1.0 if k + j == 0 else float(binomtest(k, k + j, 0.5).pvalue)


def two_proportions(k1: int, k2: int, n: int) -> tuple[float, float, float]:
    """Two shares k1/n and k2/n as independent samples: (difference, its standard error
    sqrt(p1 q1/n + p2 q2/n), two-sided p of the two-proportion test). The p is SciPy's
    ``chi2_contingency`` without continuity correction on the 2×2 table (the pooled
    two-proportion z test squared); 1 when k1 = k2 (also when both are 0 or n, where the
    table has an empty margin)."""
    from scipy.stats import chi2_contingency

    p1, p2 = k1 / n, k2 / n
    se = math.sqrt(p1 * (1 - p1) / n + p2 * (1 - p2) / n)
    if k1 == k2:
        return 0.0, se, 1.0
    table = np.array([[k1, n - k1], [k2, n - k2]])
    p = float(chi2_contingency(table, correction=False).pvalue)
    return p1 - p2, se, p


def nudged(y: np.ndarray, rng: np.random.Generator, size: float = NUDGE) -> np.ndarray:
    """``y`` with each component multiplied by 1 + size N(0, 1) (a relative perturbation; the
    unit normal n = y[4:7] renormalised)."""
    out = np.asarray(y, dtype=float) * (1.0 + size * rng.standard_normal(len(y)))
    out[4:7] /= np.linalg.norm(out[4:7])
    return out


def uncertainty_exponent(counts: dict[float, tuple[int, int]]) -> tuple[float, float, int]:
    """The exponent α of f ∝ δ^α, f the share of handed tosses whose face a relative nudge δ
    changes, ``counts`` {δ: (changed, handed)}: the least-squares slope of log f on log δ
    (SciPy's ``linregress``, unweighted), its standard error and the number of nudge sizes
    fitted (sizes that changed no face are left out: log 0). A smooth boundary between the
    outcomes' basins gives α = 1; α < 1 is final-state sensitivity, the boundary fractal
    (the uncertainty exponent of Grebogi, McDonald, Ott & Yorke, Phys. Lett. A 99 (1983) 415).
    NaN when fewer than three sizes changed a face."""
    from scipy.stats import linregress

    sizes = sorted(d for d, (k, m) in counts.items() if k > 0 and m > 0)
    if len(sizes) < 3:
        return math.nan, math.nan, len(sizes)
    f = [counts[d][0] / counts[d][1] for d in sizes]
    fit = linregress(np.log(sizes), np.log(f))
    return float(fit.slope), float(fit.stderr), len(sizes)


def print_exponent(counts: dict[float, tuple[int, int]], what: str) -> None:
    """The fit of :func:`uncertainty_exponent` over all the nudges of ``counts`` and over those
    larger than the 1e-12 baseline (its count is a face or two, and may be the step control's)."""
    rows = ", ".join(f"{d:g}: {k} of {m:,}" for d, (k, m) in sorted(counts.items()))
    print(f"faces changed by a relative nudge at the tightest rtol ({what}): {rows}")
    for label, part in (
        ("all nudges", counts),
        (f"nudges above {NUDGE:g}", {d: c for d, c in counts.items() if d > NUDGE}),
    ):
        alpha, se, k = uncertainty_exponent(part)
        if k >= 3:
            print(f"  share changed ~ nudge^a over {label} ({k} sizes): a = {alpha:.2f} ± {se:.2f}")
        else:
            print(f"  share changed ~ nudge^a over {label}: fewer than 3 sizes changed a face")


def share(k: int, n: int) -> str:
    """'k/n = p ± s.e.'."""
    p = k / n
    return f"{p:.4f} ± {math.sqrt(p * (1 - p) / n):.4f}"


def records(n: int, setting: tuple[float, float] | None) -> list[Any]:
    """The contact record of each of ``n`` tosses on ``setting`` (as ``bench_bounce`` lands
    them: one surface, or its e 0.5 μ 0.3 surface with each toss's own e, μ)."""
    import bench_contact
    from coinflight.core import bounce

    if setting is not None:
        c = bench_contact.contact(*setting)
        return [c] * n
    base = bench_contact.contact(bench_bounce.CONTACT.restitution, bench_bounce.CONTACT.friction)
    own = bench_bounce.own_rates(n)
    e, mu = own["restitution"], own["friction"]
    rolling, pivoting = base.rolling_resistance, base.pivoting_resistance
    return [bounce.with_surface(base, e[k], mu[k], rolling, pivoting) for k in range(n)]


def handoffs(
    cs: list[Any], omega: np.ndarray, v0: np.ndarray
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Each toss's bounces run once (``bench_contact.handoff``, contact records ``cs``, launch
    ω (n, 3) and speeds v0): the states handed to the contact phase (n, 10), whether each is
    handed, and for the tosses not handed their face and status (:func:`carry`'s base; −1 for
    the handed ones)."""
    import bench_contact
    from coinflight.core import bounce

    n = len(cs)
    states = np.zeros((n, 10))
    handed = np.zeros(n, dtype=bool)
    base_face = np.full(n, -1)
    base_status = np.full(n, -1)
    for k in range(n):
        w = (omega[k, 0], omega[k, 1], omega[k, 2])
        states[k], handed[k] = bench_contact.handoff(w, 1.0, v0[k], cs[k])
        if not handed[k]:
            out = bounce.bounce_loop(w, 1.0, v0[k], cs[k], bounce.MAX_IMPACTS)
            base_face[k], base_status[k] = out[0], out[4]
    return states, handed, base_face, base_status


def carry(
    states: np.ndarray,
    cs: list[Any],
    handed: np.ndarray,
    base_face: np.ndarray,
    base_status: np.ndarray,
    rtol: float,
    durations: np.ndarray | None = None,
) -> Run:
    """Every handed state carried to its end at ``rtol`` (what ``contact_phase.settle`` does),
    or for at most ``durations[k]`` s of simulated time (None: no limit; a toss stopped by it is
    UNSETTLED, with the well it is in then)."""
    from coinflight.core import contact_phase as cp
    from coinflight.core.impact import resting_face
    from coinflight.core.outcome import Status

    n = len(cs)
    run = Run(base_face.copy(), base_status.copy(), np.zeros(n), np.zeros(n), np.zeros(n))
    status_of = {
        cp.Ending.SETTLED: Status.SETTLED_CONTACT,
        cp.Ending.DECIDED: Status.DECIDED_UPRIGHT,
        cp.Ending.RUNNING: Status.UNSETTLED,
    }
    for k in np.flatnonzero(handed):
        y = states[k].copy()
        c = cs[k]
        limit = math.inf if durations is None else float(durations[k])
        t0 = time.process_time()
        t, steps, ended = cp.advance(
            y, limit, c, settle_check=True, decide=cp.UPRIGHT_DECISION, rtol=rtol
        )
        run.cpu[k] = time.process_time() - t0
        run.face[k] = resting_face(y[6], c.edge_sine)
        run.status[k] = status_of[ended]
        run.steps[k], run.time[k] = steps, t
    return run


def report_run(name: str, run: Run, handed: np.ndarray, ref: Run | None) -> None:
    """One tolerance's line: faces, statuses, cost and, against ``ref``, the disagreements."""
    n, h = len(run.face), handed
    faces = ", ".join(f"{f} {share(int(np.sum(run.face == j)), n)}" for j, f in enumerate(FACES))
    counts = {s: int(np.isin(run.status, codes).sum()) for s, codes in STATUSES.items()}
    print(
        f"  {name}: {faces}; statuses {counts}; per handed toss median "
        f"{np.median(run.steps[h]):,.0f} steps (mean {run.steps[h].mean():,.0f}), "
        f"{np.median(run.cpu[h]) * 1e3:.2f} ms CPU "
        f"(total {run.cpu[h].sum():.1f} s), settles after {np.median(run.time[h]):.3f} s "
        f"(90 % {np.percentile(run.time[h], 90):.3f} s)"
    )
    if ref is None:
        return
    from coinflight.probability.result import wilson_interval

    k, m = disagreements(run.face, ref.face, h), int(h.sum())
    lo, hi = wilson_interval(k, m)
    st = disagreements(run.status, ref.status, h)
    tests = []
    for j, f in enumerate(FACES):
        a, b = run.face == j, ref.face == j
        diff, se, p = two_proportions(int(a.sum()), int(b.sum()), n)
        z = diff / se if se > 0 else 0.0
        tests.append(f"{f} {diff:+.4f} ({z:+.1f} s.e., p {p:.2f}, McNemar {mcnemar_p(a, b):.2f})")
    print(
        f"    against the tightest: faces differ on {k} of {m} handed ({k / m:.1%}, 95 % "
        f"{lo:.1%}-{hi:.1%}), statuses on {st}; fractions " + "; ".join(tests)
    )


def study(
    n: int,
    seed: int,
    name: str,
    setting: tuple[float, float] | None,
    tolerances: Sequence[float],
    extra: float | None,
    subset: int,
    nudges: Sequence[float] = (),
) -> dict[str, float]:
    """The tolerance study of ``n`` tosses on one setting; returns the headline counts (faces
    differing from the tightest, changed by each nudge; the handed tosses) and each
    tolerance's median steps per handed toss."""
    from coinflight.core import contact_phase as cp
    from coinflight.outcomes.table import land
    from coinflight.probability.result import wilson_interval

    omega, v0 = bench_bounce.tosses(n, seed)
    cs = records(n, setting)
    states, handed, base_face, base_status = handoffs(cs, omega, v0)
    m = int(handed.sum())
    if m == 0:
        print(
            f"{name}: {n} tosses (seed {seed}), 0 handed to the contact phase: nothing to compare"
        )
        return {"handed": 0}
    tight = min(tolerances)
    first = int(np.flatnonzero(handed)[0])
    cp.advance(states[first].copy(), 1e-3, cs[first], settle_check=True)  # compile or load
    runs = {r: carry(states, cs, handed, base_face, base_status, r) for r in tolerances}
    # The default tolerance must give land()'s outcomes on the same tosses.
    if cp.RTOL in runs:
        e, mu = (0.5, 0.3) if setting is None else setting
        surface = bench_bounce.Surface("table", bench_bounce.DROP, e, mu, ending="contact")
        own = None if setting is not None else bench_bounce.own_rates(n)
        out = land(bench_bounce.COIN, omega, v0, 1.0, bench_bounce.G, surface, contact=own)
        same = np.array_equal(out.face, runs[cp.RTOL].face) and np.array_equal(
            out.status, runs[cp.RTOL].status
        )
        if not same:
            raise SystemExit(f"{name}: the study's default run differs from land()'s outcomes")
    print(
        f"{name}: {n} tosses (seed {seed}), {m} handed to the contact phase; load "
        f"{os.getloadavg()[0]:.2f}; faces checked equal to land()'s at RTOL {cp.RTOL:g}"
    )
    for r in tolerances:
        report_run(f"rtol {r:g}", runs[r], handed, None if r == tight else runs[tight])
    result: dict[str, float] = {
        f"differ {r:g}": disagreements(runs[r].face, runs[tight].face, handed) for r in tolerances
    }
    for r in tolerances:
        result[f"steps {r:g}"] = float(np.median(runs[r].steps[handed]))
    cases = [(NUDGE, r) for r in sorted({tight, cp.RTOL}) if r in runs]
    cases += [(size, tight) for size in nudges if size != NUDGE]
    for size, r in cases:
        rng = np.random.default_rng(seed + 1)
        pert = np.array([nudged(y, rng, size) for y in states])
        other = carry(pert, cs, handed, base_face, base_status, r)
        k = disagreements(other.face, runs[r].face, handed)
        lo, hi = wilson_interval(k, m)
        print(
            f"  chaos baseline at rtol {r:g}: a {size:g} relative nudge of each handed state "
            f"changes the face of {k} of {m} ({k / m:.1%}, 95 % {lo:.1%}-{hi:.1%}), statuses "
            f"{disagreements(other.status, runs[r].status, handed)}"
        )
        result[f"nudge {size:g} at {r:g}"] = k
    if extra is not None and subset > 0:
        sub = handed.copy()
        sub[subset:] = False
        if not sub.any():
            print(f"  rtol {extra:g} on the first {subset} tosses: 0 handed")
            result["handed"] = m
            return result
        finer = carry(states, cs, sub, base_face, base_status, extra)
        k = disagreements(finer.face, runs[tight].face, sub)
        print(
            f"  rtol {extra:g} on the first {subset} tosses ({int(sub.sum())} handed): faces "
            f"differ from rtol {tight:g} on {k}; median {np.median(finer.steps[sub]):,.0f} steps, "
            f"{np.median(finer.cpu[sub]) * 1e3:.2f} ms CPU"
        )
        result[f"extra {extra:g}"] = k
    result["handed"] = m
    return result


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("n", type=int, nargs="?", default=100, help="tosses per setting")
    parser.add_argument("--seed", type=int, default=2026)
    parser.add_argument(
        "--tolerances", default=",".join(f"{r:g}" for r in TOLERANCES), help="rtol list"
    )
    parser.add_argument("--extra", type=float, default=None, help="a finer rtol on a subset")
    parser.add_argument("--subset", type=int, default=0, help="tosses run at --extra")
    parser.add_argument(
        "--nudges", default="", help="further relative nudges, at the tightest rtol (1e-9,1e-6)"
    )
    parser.add_argument("--settings", default=",".join(range_names()), help="settings to run")
    parser.add_argument(
        "--recorded", action="store_true", help="print the fit of the recorded nudge counts only"
    )
    args = parser.parse_args()
    if args.recorded:
        print_exponent(RECORDED, "recorded, RECORDED")
        return
    tolerances = numbers(parser, "--tolerances", args.tolerances)
    nudges = numbers(parser, "--nudges", args.nudges) if args.nudges else []
    if args.n < 1:
        parser.error(f"N {args.n}: must be at least 1")
    if args.extra is not None and not 0.0 < args.extra < 1.0:
        parser.error(f"--extra {args.extra:g}: must be in (0, 1)")
    if args.subset < 0 or (args.subset > 0 and args.extra is None):
        parser.error(
            f"--subset {args.subset}: must be at least 0, and more than 0 only with --extra"
        )
    keys = args.settings.split(",")
    if not keys or any(key not in range_names() for key in keys):
        parser.error(
            f"--settings {args.settings!r}: must be indices among {','.join(range_names())}"
        )
    t0 = time.perf_counter()
    tight = min(tolerances)
    counts: dict[float, tuple[int, int]] = {}
    for key in keys:
        name = list(SETTINGS)[int(key)]
        result = study(
            args.n, args.seed, name, SETTINGS[name], tolerances, args.extra, args.subset, nudges
        )
        m = int(result["handed"])
        for size in {NUDGE, *nudges}:
            k, total = counts.get(size, (0, 0))
            counts[size] = (k + int(result.get(f"nudge {size:g} at {tight:g}", 0)), total + m)
    print_exponent(counts, f"this run, summed over the settings, rtol {tight:g}")
    print(f"{time.perf_counter() - t0:.0f} s wall, load {os.getloadavg()}")


def numbers(parser: argparse.ArgumentParser, option: str, text: str) -> list[float]:
    """The comma-separated numbers of ``option``, each in (0, 1) (a tolerance or a relative
    nudge); a bad one ends the script through ``parser.error`` (one line, exit code 2)."""
    try:
        values = [float(x) for x in text.split(",")]
    except ValueError:
        values = []
    if not values or not all(0.0 < x < 1.0 for x in values):
        parser.error(f"{option} {text!r}: must be comma-separated numbers, each in (0, 1)")
    return values


def range_names() -> list[str]:
    """The indices of :data:`SETTINGS` as strings (``--settings 0,2``)."""
    return [str(i) for i in range(len(SETTINGS))]


if __name__ == "__main__":
    main()
