"""Thick cylinders against experiments: the measured edge fractions beside the model's band.

    python benchmarks/bench_edge_experiments.py [N] [--contact M] [--points P] [--seed S]
        [--json FILE] [--mujoco K] [--psi PSI] [--wobble]

The measured points of :func:`coinflight.datasets.edge_experiments` (those a setting of
:mod:`coinflight.studies.edge_experiments` simulates) each simulated with N tosses per cell of
the rocking ending (P values per unmeasured parameter, default 3: corners, mid-points and the
centre) and M per cell of the 3-D contact ending (corners and centre); prints the table (band
against the measured 95 % interval), the time, and the records left out and why. With
``--mujoco K``: K tosses of each point at the box's centre (24 mm cylinder) in coinflight's two
endings and in MuJoCo (:func:`coinflight.studies.edge_experiments.mujoco_check`). With
``--psi PSI`` (degrees, or "human") every toss wobbles on a precession cone of angle PSI
(:func:`coinflight.studies.edge_experiments.axial_spin`). With ``--wobble``: instead of the
band, the sweep of :func:`coinflight.studies.edge_experiments.wobble_sweep` (N rocking and M
contact tosses per ψ and cell) as a table of P(edge) ± s.e.
"""

from __future__ import annotations

import argparse
import contextlib
import importlib.util
import json
import os
import time
from collections.abc import Callable, Iterator


def _write_json(path: str, obj: object) -> None:
    """``obj`` as JSON at ``path``, whole or not at all (the project's one way to write)."""
    from coinflight._files import replacing_all

    with replacing_all([path]) as (temp,):
        temp.write_text(json.dumps(obj, indent=1), encoding="utf-8")


def _psi(text: str) -> float | str:
    """--psi as a number of degrees, or the word as typed (the study refuses any but "human",
    in its words)."""
    try:
        return float(text)
    except ValueError:
        return text


def _mujoco_count(text: str) -> int:
    """--mujoco K: a whole number ≥ 0 (0: no check), refused here rather than after the run."""
    try:
        k = int(text)
    except ValueError:
        k = -1
    if k < 0:
        raise argparse.ArgumentTypeError(f"must be a whole number ≥ 0 (0: no check), got {text!r}")
    return k


@contextlib.contextmanager
def _one_line(parser: argparse.ArgumentParser) -> Iterator[Callable[[str], None]]:
    """The library's refusal of a bad input (ValueError or TypeError) as one line and exit 2,
    as the command line gives it, instead of a traceback; gives the study's ``progress``
    (printing). The studies call it first once every input is checked and the work bounded,
    before any toss: a ValueError or TypeError after that is a fault of the run, not a refusal
    of the input, and keeps its traceback."""
    started = False

    def progress(text: str) -> None:
        nonlocal started
        started = True
        print(text, flush=True)

    try:
        yield progress
    except (ValueError, TypeError) as exc:
        if started:
            raise
        parser.exit(2, f"{parser.prog}: error: {exc}\n")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("n", type=int, nargs="?", default=2_000, help="rocking tosses per cell")
    parser.add_argument("--contact", type=int, default=200, help="contact tosses per cell")
    parser.add_argument("--points", type=int, default=3, help="values per parameter (rocking)")
    parser.add_argument("--seed", type=int, default=2018)
    parser.add_argument("--json", metavar="FILE", help="write every cell as JSON")
    parser.add_argument(
        "--mujoco", type=_mujoco_count, default=0, metavar="K", help="MuJoCo check size"
    )
    parser.add_argument("--psi", type=_psi, default=None, help="cone angle, degrees, or 'human'")
    parser.add_argument("--wobble", action="store_true", help="the ψ sweep instead of the band")
    args = parser.parse_args()
    psi = args.psi
    if args.wobble:
        if psi is not None:
            parser.error("--psi is one cone angle for the band; --wobble sweeps its own")
        wobble(args, parser)
        return
    if args.mujoco and importlib.util.find_spec("mujoco") is None:
        parser.error("--mujoco needs MuJoCo (pip install 'coinflight[mujoco]')")

    from coinflight.datasets import edge_experiments as dataset
    from coinflight.studies.edge_experiments import edge_experiments, from_dataset, mujoco_check

    records, left = from_dataset(dataset())
    load = os.getloadavg()[0]
    t0 = time.perf_counter()
    with _one_line(parser) as progress:  # every input is checked before the first toss
        result = edge_experiments(
            records,
            args.n,
            args.seed,
            contact=args.contact,
            points=args.points,
            psi=psi,  # type: ignore[arg-type]  # a word but "human": refused in the study's words
            progress=progress,
        )
    wall = time.perf_counter() - t0
    print(
        f"\n{len(records)} experiments; {args.n:,} rocking tosses per cell ({args.points} points "
        f"per parameter), {args.contact:,} contact-ending tosses per cell (corners and centre); "
        f"seed {result.seed}; {wall:.0f} s wall; load {load:.1f} → {os.getloadavg()[0]:.1f}"
    )
    widths = [
        max(len(str(r[i])) for r in [result.HEADER, *result.table()])
        for i in range(len(result.HEADER))
    ]
    for row in [result.HEADER, *result.table()]:
        print(" | ".join(str(x).ljust(w) for x, w in zip(row, widths, strict=True)))
    for c in result.comparisons:
        print(f"\n{c.experiment.label}: {c.setting.description}")
        for band in c.bands:
            for name, cell in (("low", band.low), ("high", band.high)):
                where = ", ".join(f"{k} {x:.3g}" for k, x in cell.parameters.items())
                print(f"  {band.ending} {name}: {cell.p:.4f} ± {cell.stderr:.4f} at {where}")
    for line in left:
        print(f"left out: {line}")
    for x in records if args.mujoco else ():
        with _one_line(parser) as progress:  # checked (and its work bounded) before a toss
            check = mujoco_check(
                x,
                args.mujoco,
                args.seed,
                psi=psi,  # type: ignore[arg-type]
                progress=progress,
            )
        where = ", ".join(f"{k} {val:.3g}" for k, val in check.parameters.items())
        print(f"\nMuJoCo check, {x.label}, {args.mujoco} tosses at {where}:")
        for name, est in (
            ("coinflight rocking", check.rocking),
            ("coinflight contact", check.contact),
            ("MuJoCo", check.mujoco),
        ):
            print(f"  {name}: P(edge) {est.p:.3f} ± {est.stderr:.3f}")
        print(
            f"  coinflight contact: {check.contact_decided_upright} of its "
            f"{check.contact.successes} edges decided upright (ended still rolling by the "
            "upright decision, a measured predictor, not carried to rest)"
        )
        print(
            f"  MuJoCo still moving at its limit: {check.mujoco_moving}; "
            f"{check.mujoco_seconds:.0f} s"
        )
    if args.json:
        _write_json(args.json, result.to_dict())


def wobble(args: argparse.Namespace, parser: argparse.ArgumentParser) -> None:
    """The ψ sweep: one line per experiment, ψ, ending and cell."""
    from coinflight.datasets import edge_experiments as dataset
    from coinflight.studies.edge_experiments import from_dataset, wobble_sweep

    records, _ = from_dataset(dataset())
    load = os.getloadavg()[0]
    t0 = time.perf_counter()
    with _one_line(parser) as progress:  # every input is checked before the first toss
        rows = wobble_sweep(records, args.n, args.seed, contact=args.contact, progress=progress)
    wall = time.perf_counter() - t0
    print(
        f"wobble sweep; {args.n:,} rocking and {args.contact:,} contact-ending tosses per cell; "
        f"seed {args.seed}; {wall:.0f} s wall; load {load:.1f} → {os.getloadavg()[0]:.1f}"
    )
    for x in records:
        print(f"\n{x.label}: measured {x.observed.p:.3f}")
        for r in rows:
            if r.label == x.label:
                cell = ", ".join(f"{k} {val:g}" for k, val in r.parameters.items())
                decided = getattr(r.estimate, "decided_upright", 0)
                print(
                    f"  ψ {r.psi!s:>6} {r.ending:8} {cell}: "
                    f"{r.estimate.p:.4f} ± {r.estimate.stderr:.4f} (n {r.estimate.n:,})"
                    + (f", {decided:,} decided upright" if r.ending == "contact" else "")
                )
    if args.json:
        out = [
            {
                "label": r.label,
                "ratio": r.ratio,
                "psi": r.psi,
                "ending": r.ending,
                **dict(r.parameters),
                "p_edge": r.estimate.p,
                "stderr": r.estimate.stderr,
                "n": r.estimate.n,
                "seed": r.estimate.seed,
                "decided_upright": getattr(r.estimate, "decided_upright", 0)
                if r.ending == "contact"
                else None,
            }
            for r in rows
        ]
        _write_json(args.json, out)


if __name__ == "__main__":
    main()
