"""The landing speed targets, all in one run: measured rate, target, ratio, met or not.

    python benchmarks/bench_targets.py                 # default sizes, 5 rounds
    python benchmarks/bench_targets.py --quick         # a tenth of the tosses, 3 rounds
    python benchmarks/bench_targets.py --json          # the record as JSON (numbers as numbers)
    python benchmarks/bench_targets.py --mujoco 100    # + MuJoCo on 100 of the same tosses
    python benchmarks/bench_targets.py --rounds 7 --seed 11 --n 2000   # every case on 2,000
    python benchmarks/bench_targets.py --cpu           # + each case in one thread, per CPU s

The targets, on 2 cores: ≥ 20,000 human or vigorous tosses a second carried to rest (the
bounces, then the rigid 3-D ending), first contact ≥ 2 M a second, the hand catch and the
table's first contact through air ≥ 100,000 a second, and the speed ratio against MuJoCo on
the same tosses (no target). Every case runs in one process on 2 of numba's threads (fewer when
numba has fewer; said in the output), the rounds interleaved (one of each case in turn, so the
machine's other load falls on all alike), the rate of each case the median of its rounds. The
cases (default tosses; ``--quick`` a tenth):

- first contact with the table 0.8 m below launch, e 0.5, μ 0.3 (1,000,000 tosses);
- carried to rest at e 0.5, μ 0.3, vigorous and human tosses, and vigorous ones with each toss
  its own e ~ U(0.2, 0.8), μ ~ U(0.1, 0.6) (1,000 tosses each);
- through air (C_d 1.17, no spin damping): the hand catch and the table's first contact
  (100,000 tosses each), and, as a reference without a target (marked "(ref)"), the table
  carried to rest (1,000);
- with ``--mujoco N`` (the optional extra; one line and skipped when not installed): MuJoCo
  (:func:`coinflight.studies.mujoco_compare.run`, its settings, ``threads`` 2, its wall time
  including its calibration) on the first N of the vigorous rows' tosses, and coinflight on
  the same N with MuJoCo's rolling and torsional lengths as resistances (medians of the
  rounds): the speed ratio coinflight / MuJoCo. The ratio depends on the tosses.

With ``--cpu`` each case also runs in one thread (``parallel=False``) right after its timing
in each round, timed by the thread's CPU clock: a second table gives the one-thread rate per CPU
second and twice that over the target (what 2 cores would give if they scaled perfectly and
nothing else ran: an upper estimate beside the measured rate, not the target's measure).

The tosses are ``bench_bounce.py``'s (a US nickel, heads up, seed ``--seed``, default 2026):
vigorous (:func:`bench_bounce.tosses`: ωx ~ U(150, 300), ωy, ωz ~ U(−30, 30) rad/s, v0 ~
U(1.5, 3) m/s) and human (:func:`bench_bounce.human_tosses`), each toss's own e, μ
:func:`bench_bounce.own_rates` (seed ``bench_bounce.OWN_RATES_SEED``, 7); the air cases are
``bench_air.py``'s (:func:`bench_air.cases_in_air`). Every case is compiled (or loaded from
numba's cache) on 20 tosses before the timing. The work is bounded before anything runs
(:func:`seconds_estimate`). The record (``--json``) holds the rows, the seeds, the threads,
MuJoCo's part and the provenance (command, date, versions, machine, load).
"""

from __future__ import annotations

import argparse
import math
import os
import statistics
import sys
import time
from collections.abc import Callable, Mapping, Sequence
from typing import Any, NamedTuple, NoReturn

import numpy as np

import bench_air  # the script's own folder is on the path
import bench_bounce
from _record import Recorder, dumps
from coinflight import _validation as v
from coinflight.model.surface import Drag, Surface
from coinflight.outcomes.table import land

THREADS = 2
"""The targets are "on 2 cores": numba's threads for every case (fewer if numba has
fewer)."""

TO_REST = bench_bounce.TO_REST_TARGET
FIRST_CONTACT = bench_bounce.FIRST_CONTACT_TARGET
IN_AIR = 100_000.0
"""The targets, tosses a second on 2 cores."""

DRAG = Drag(coefficient=1.17)
"""The air of the air cases: a flat disc broadside on, no spin damping (``bench_air.py``'s
default)."""


class Case(NamedTuple):
    """One timed case: its key (JSON), what it is, its target (None for a reference row, which
    times something no target asks for), its default tosses and its rate on a quiet 2-core
    machine (for the work bound only)."""

    key: str
    label: str
    target: float | None
    size: int
    quiet_rate: float


REF = "(ref)"
REF_NOTE = "(ref): a reference, no target (20,000/s is for landings in vacuum)"
"""A reference row times something no target asks for: marked :data:`REF` in its label and
explained by :data:`REF_NOTE` under the table."""

CASES = (
    Case("first_contact", "first contact (table, 0.8 m drop, e 0.5 μ 0.3)", FIRST_CONTACT,
         1_000_000, 2.0e6),
    Case("rest", "to rest, vigorous, e 0.5 μ 0.3", TO_REST, 1_000, 300.0),
    Case("rest_human", "to rest, human, e 0.5 μ 0.3", TO_REST, 1_000, 300.0),
    Case("rest_own", "to rest, vigorous, own e, μ", TO_REST, 1_000, 300.0),
    Case("air_hand", "air: hand catch", IN_AIR, 100_000, 2.5e5),
    Case("air_first_contact", "air: table first contact", IN_AIR, 100_000, 1.7e5),
    Case("air_rest", f"air: table to rest {REF}", None, 1_000, 200.0),
)  # fmt: skip
"""Every timed case, in the order of the table."""

ROW_KEYS = (
    "key", "target_name", "n", "measured", "target", "ratio", "met", "rounds", "one_thread",
    "one_thread_ratio",
)  # fmt: skip
"""The keys of a row of :func:`rows`, in this order."""

MAX_TOSSES = 10**7
MAX_ROUNDS = 100
MAX_MUJOCO = 10**4


def sizes(quick: bool, n: int | None = None) -> dict[str, int]:
    """Tosses of each case: ``n`` for all when given, else the defaults (a tenth with
    ``quick``)."""
    if n is not None:
        return {c.key: n for c in CASES}
    return {c.key: max(1, c.size // 10) if quick else c.size for c in CASES}


def seconds_estimate(size: Mapping[str, int], rounds: int) -> float:
    """Wall seconds of the timed rounds at the quiet rates of :data:`CASES` (an estimate for
    the work bound, not a worst case: a loaded machine takes longer)."""
    return rounds * sum(size[c.key] / c.quiet_rate for c in CASES)


def calls(
    size: Mapping[str, int], seed: int, parallel: bool = True
) -> dict[str, Callable[[], Any]]:
    """Each case of :data:`CASES` as a call of no arguments on its tosses (``bench_bounce``'s,
    seed ``seed``; cases of one size and kind of toss share them), on numba's threads (one
    without ``parallel``)."""
    B = bench_bounce
    drawn: dict[tuple[str, int], tuple[np.ndarray, np.ndarray]] = {}

    def toss(key: str, kind: str = "vigorous") -> tuple[np.ndarray, np.ndarray]:
        n = size[key]
        if (kind, n) not in drawn:
            drawn[kind, n] = B.SETS[kind](n, seed)
        return drawn[kind, n]

    def case(key: str, kind: str = "vigorous", **kw: Any) -> Callable[[], Any]:
        omega, v0 = toss(key, kind)
        return lambda: land(B.COIN, omega, v0, 1.0, B.G, B.SURFACE, parallel=parallel, **kw)

    def air(key: str, name: str) -> Callable[[], Any]:
        return bench_air.cases_in_air(*toss(key), DRAG, parallel)[name]

    out = {
        "first_contact": case("first_contact", max_bounces=0),
        "rest": case("rest"),
        "rest_human": case("rest_human", "human"),
        "rest_own": case("rest_own", contact=B.own_rates(size["rest_own"])),
        "air_hand": air("air_hand", "hand"),
        "air_first_contact": air("air_first_contact", "table first contact"),
        "air_rest": air("air_rest", "table to rest"),
    }
    assert list(out) == [c.key for c in CASES]
    return out


def interleaved(
    cases: Mapping[str, Callable[[], Any]],
    size: Mapping[str, int],
    rounds: int,
    serial: Mapping[str, Callable[[], Any]] | None = None,
) -> tuple[dict[str, list[float]], dict[str, list[float]]]:
    """Tosses a second of each case in each of ``rounds`` rounds, one of each case in turn,
    and with ``serial`` (the same cases in one thread) right after each its tosses per second
    of that thread's CPU time (:func:`time.thread_time`: the machine's other load excluded as
    far as CPU time does): ({key: [rate of round 1, …]}, {key: [CPU rate of round 1, …]} or {})."""
    rates: dict[str, list[float]] = {key: [] for key in cases}
    cpu: dict[str, list[float]] = {key: [] for key in serial} if serial else {}
    for _ in range(rounds):
        for key, fn in cases.items():
            t0 = time.perf_counter()
            fn()
            rates[key].append(size[key] / (time.perf_counter() - t0))
            if serial:
                t0 = time.thread_time()
                serial[key]()
                cpu[key].append(size[key] / (time.thread_time() - t0))
    return rates, cpu


def _median(key: str, given: Mapping[str, Sequence[float]]) -> tuple[float, list[float]]:
    """The median of a case's rates and the rates; ValueError when there is none, or one that
    is not a finite positive number."""
    got = [float(r) for r in given.get(key, ())]
    if not got:
        raise ValueError(f"no rate measured for {key}")
    bad = [r for r in got if not (math.isfinite(r) and r > 0.0)]
    if bad:
        raise ValueError(f"rates must be finite and positive, got {bad[0]!r} for {key}")
    return statistics.median(got), got


def rows(
    rates: Mapping[str, Sequence[float]],
    size: Mapping[str, int],
    cpu: Mapping[str, Sequence[float]] | None = None,
) -> list[dict[str, Any]]:
    """The table: one row a case of :data:`CASES` (keys :data:`ROW_KEYS`), ``measured`` the
    median of its rounds' rates, ``ratio`` measured / target, ``met`` ratio ≥ 1; with ``cpu``
    (tosses per CPU second of one thread, by round) ``one_thread`` its median and
    ``one_thread_ratio`` :data:`THREADS` × that / target (what 2 cores would give if they
    scaled perfectly and nothing else ran: an upper estimate, not the target's measure), else
    None. ValueError when a case has no rates or one that is not a finite positive number."""
    out = []
    for c in CASES:
        measured, got = _median(c.key, rates)
        one, one_ratio = None, None
        if cpu is not None:
            one = _median(c.key, cpu)[0]
            one_ratio = None if c.target is None else THREADS * one / c.target
        ratio = None if c.target is None else measured / c.target
        row = {
            "key": c.key,
            "target_name": c.label,
            "n": int(size[c.key]),
            "measured": measured,
            "target": c.target,
            "ratio": ratio,
            "met": None if ratio is None else bool(ratio >= 1.0),
            "rounds": got,
            "one_thread": one,
            "one_thread_ratio": one_ratio,
        }
        out.append(row)
    return out


def table(found: Sequence[Mapping[str, Any]]) -> str:
    """:func:`rows` as a text table, the first column as wide as the longest label; a reference
    row's target, ratio and met "ref", "-", "-" and :data:`REF_NOTE` under the table; when
    the one-thread rates were measured, a second table of them."""
    w = max(len("target"), *(len(r["target_name"]) for r in found))

    def ratio(x: float | None) -> str:
        return "-" if x is None else f"{x:.3f}"

    head = ("target", "tosses", "measured /s", "target /s", "ratio", "met")
    lines = [f"{head[0]:<{w}} {head[1]:>9} {head[2]:>13} {head[3]:>11} {head[4]:>7}  {head[5]}"]
    for r in found:
        target = "ref" if r["target"] is None else f"{r['target']:,.0f}"
        met = "-" if r["met"] is None else "yes" if r["met"] else "no"
        lines.append(
            f"{r['target_name']:<{w}} {r['n']:>9,} {r['measured']:>13,.0f} {target:>11} "
            f"{ratio(r['ratio']):>7}  {met}"
        )
    if any(r["target"] is None for r in found):
        lines.append(REF_NOTE)
    if any(r["one_thread"] is not None for r in found):
        lines.append(
            f"{'one thread (parallel=False)':<{w}} {'per CPU s':>13} {'2 × that / target':>19}"
        )
        for r in found:
            lines.append(
                f"{r['target_name']:<{w}} {r['one_thread']:>13,.0f} "
                f"{ratio(r['one_thread_ratio']):>19}"
            )
    return "\n".join(lines)


def mujoco_version() -> dict[str, str | None]:
    """MuJoCo's version for the record's versions (None when not installed)."""
    from coinflight.studies import mujoco_compare

    if not mujoco_compare.available():
        return {"mujoco": None}
    import mujoco as mj

    return {"mujoco": str(mj.__version__)}


def against_mujoco(m: int, size: Mapping[str, int], seed: int, rounds: int) -> dict[str, Any]:
    """MuJoCo on the first ``m`` of the vigorous rows' tosses (one run, its settings, 2
    threads) and coinflight on the same with MuJoCo's rolling and torsional lengths as
    resistances (median of ``rounds``): rates and the ratio coinflight / MuJoCo. The tosses are
    the first ``m`` of the ``rest`` row's when ``m`` ≤ ``size["rest"]``; a larger ``m`` draws
    ``m`` tosses of the same seed (:func:`bench_bounce.tosses` draws its columns in turn, so
    their first ones differ). {"skipped": reason} when MuJoCo is not installed."""
    from coinflight.studies import mujoco_compare as mc

    if not mc.available():
        return {"skipped": "MuJoCo not installed (pip install 'coinflight[mujoco]')"}
    B = bench_bounce
    omega, v0 = B.tosses(max(m, size["rest"]), seed)
    omega, v0 = omega[:m], v0[:m]
    e, mu = B.SURFACE.restitution, B.SURFACE.friction
    resisted = Surface(
        "table", B.DROP, e, mu, rolling_resistance=mc.ROLLING, pivoting_resistance=mc.TORSIONAL
    )
    land(B.COIN, omega[:20], v0[:20], 1.0, B.G, resisted)  # compile or load the cache
    ours = interleaved(
        {"rest": lambda: land(B.COIN, omega, v0, 1.0, B.G, resisted)}, {"rest": m}, rounds
    )[0]["rest"]
    run = mc.run(B.COIN, omega, v0, B.DROP, e, mu, B.G, threads=THREADS)
    theirs = m / float(run.elapsed)
    rate = statistics.median(ours)
    return {
        "n": m,
        "mujoco": run.version,
        "mujoco_rate": theirs,
        "mujoco_moving": int(np.count_nonzero(run.moving)),
        "limit": float(run.limit),
        "coinflight_rate": rate,
        "coinflight_rounds": ours,
        "ratio": rate / theirs,
        "rolling_resistance": mc.ROLLING,
        "pivoting_resistance": mc.TORSIONAL,
    }


def measure(
    size: Mapping[str, int],
    rounds: int,
    seed: int,
    mujoco: int = 0,
    threads: int = THREADS,
    cpu: bool = False,
) -> dict[str, Any]:
    """Everything the report holds but the command: threads, load before and after, the rows
    (with ``cpu`` each case also in one thread per CPU second), MuJoCo's part (None without
    ``mujoco``)."""
    import numba

    numba.set_num_threads(min(threads, numba.config.NUMBA_NUM_THREADS))  # type: ignore[attr-defined]
    threads = numba.get_num_threads()  # what the cases run on, as numba reports it
    for parallel in (True, False) if cpu else (True,):  # compile or load the cache
        for fn in calls({c.key: 20 for c in CASES}, seed, parallel).values():
            fn()
    timed = calls(size, seed)
    serial = calls(size, seed, parallel=False) if cpu else None
    load_before = os.getloadavg()
    rates, one = interleaved(timed, size, rounds, serial)
    extra = against_mujoco(mujoco, size, seed, rounds) if mujoco else None
    load_after = os.getloadavg()
    return {
        "threads": threads,
        "load": {"before": list(load_before), "after": list(load_after)},
        "rows": rows(rates, size, one if cpu else None),
        "mujoco": extra,
    }


def report(
    measured: Mapping[str, Any], recorder: Recorder, seed: int, rounds: int
) -> dict[str, Any]:
    """The record (:class:`_record.Recorder`): its figures the seeds, rounds, threads, the rows
    (``targets``) and MuJoCo's part; the load average the timing's own (before and after)."""
    figures = {
        "seed": seed,
        "own_rates_seed": bench_bounce.OWN_RATES_SEED,
        "rounds": rounds,
        "threads": measured["threads"],
        "targets": measured["rows"],
        "mujoco": measured["mujoco"],
    }
    return recorder.record(figures, load=measured["load"], more_versions=mujoco_version())


def text(rep: Mapping[str, Any]) -> str:
    """The record as the printed text."""
    m, ver, fig = rep["machine"], rep["versions"], rep["figures"]
    before, after = rep["load"]["before"], rep["load"]["after"]
    lines = [
        f"{rep['command']}  ({rep['date']})",
        f"{m['processor']}, {m['cpus']} CPUs, {m['system']}; Python {ver['python']}, NumPy "
        f"{ver['numpy']}, numba {ver['numba']}, coinflight {ver['coinflight']}",
        f"{fig['threads']} threads, seed {fig['seed']} (own e, μ seed {fig['own_rates_seed']}), "
        f"medians of {fig['rounds']} interleaved rounds; load {before[0]:.2f} before",
    ]
    if fig["threads"] < THREADS:
        lines.append(f"  (numba has {fig['threads']} threads: the targets are for {THREADS})")
    lines.append(table(fig["targets"]))
    mj = fig["mujoco"]
    if mj is not None and "skipped" in mj:
        lines.append(f"MuJoCo: skipped, {mj['skipped']}")
    elif mj is not None:
        lines.append(
            f"MuJoCo {mj['mujoco']}, {mj['n']:,} of the same tosses: {mj['mujoco_rate']:,.1f} "
            f"tosses/s ({mj['mujoco_moving']} still moving at {mj['limit']:g} s); coinflight "
            f"(ℓ_r {mj['rolling_resistance']:g} m, ℓ_p "
            f"{mj['pivoting_resistance']:g} m) {mj['coinflight_rate']:,.0f} tosses/s: ratio "
            f"{mj['ratio']:,.0f}"
        )
    lines.append(f"load average {before[0]:.2f} before, {after[0]:.2f} after")
    return "\n".join(lines)


class _Parser(argparse.ArgumentParser):
    def error(self, message: str) -> NoReturn:  # one line, exit code 2
        self.exit(2, f"bench_targets.py: {message}\n")


def parse(argv: Sequence[str]) -> argparse.Namespace:
    """The options, checked (one line and exit code 2 on bad input, the work bounded)."""
    parser = _Parser(description=__doc__.split("\n")[0] if __doc__ else None)
    parser.add_argument("--quick", action="store_true", help="a tenth of the tosses, 3 rounds")
    parser.add_argument("--json", action="store_true", help="print the report as JSON")
    parser.add_argument("--rounds", type=int, default=None, help="rounds (default 5; quick 3)")
    parser.add_argument("--seed", type=int, default=2026, help="seed of the tosses")
    parser.add_argument("--n", type=int, default=None, help="tosses of every case")
    parser.add_argument("--mujoco", type=int, default=0, metavar="N", help="MuJoCo on N tosses")
    parser.add_argument(
        "--cpu", action="store_true", help="also each case in one thread, per CPU second"
    )
    args = parser.parse_args(argv)
    if args.rounds is None:
        args.rounds = 3 if args.quick else 5
    try:
        v.count("--rounds", args.rounds, 1, MAX_ROUNDS)
        v.count("--seed", args.seed, 0)
        if args.n is not None:
            v.count("--n", args.n, 1, MAX_TOSSES)
        v.count("--mujoco", args.mujoco, 0, MAX_MUJOCO)
        args.sizes = sizes(args.quick, args.n)
        v.work_bound(
            f"{args.rounds} rounds of the cases",
            seconds_estimate(args.sizes, args.rounds) * (3 if args.cpu else 1),
            v.MAX_RUN_SECONDS,
            "s",
            "use fewer tosses (--n, --quick) or fewer --rounds",
        )
        if args.mujoco:
            from coinflight.studies import mujoco_compare as mc

            mc.bound([args.mujoco], mc.SETTLE)
    except ValueError as err:
        parser.error(str(err))
    return args


def main(argv: Sequence[str] | None = None) -> int:
    argv = list(sys.argv[1:] if argv is None else argv)
    args = parse(argv)
    recorder = Recorder("bench_targets", argv)
    measured = measure(args.sizes, args.rounds, args.seed, args.mujoco, cpu=args.cpu)
    rep = report(measured, recorder, args.seed, args.rounds)
    print(dumps(rep) if args.json else text(rep))
    return 0


if __name__ == "__main__":
    sys.exit(main())
