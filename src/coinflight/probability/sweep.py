"""Sweeps: P(heads), P(same side) and P(edge) for many distributions of tosses in one call.

:func:`estimate_many` runs one method over a list of distributions, one after the other, with
one seed for all (common random numbers). :func:`sweep` runs one row per :class:`Case` (a
distribution and the way its tosses end) as an independent task on an executor (threads, or a
Dask cluster: :mod:`coinflight.probability.distributed`), each row with its own random stream
derived from the one seed and the row's inputs, and can resume from a checkpoint of finished
rows; :func:`write_table` writes the results as one Parquet or CSV table, whole or not at all.

>>> from coinflight.model.distributions import Uniform
>>> from coinflight.model.ensemble import TossDistribution
>>> fig2a = TossDistribution(omega_x=Uniform(60, 90), flight_time=Uniform(0.6, 0.9))
>>> fig3a = TossDistribution(omega_x=Uniform(60, 90), omega_y=10, flight_time=Uniform(0.6, 0.9))
>>> results = estimate_many([fig2a, fig3a], "exact")  # Stefan & Cheche Figs 2a and 3a
>>> [round(r.p_heads, 5) for r in results]
[0.49747, 0.49721]
"""

from __future__ import annotations

import hashlib
import itertools
import json
import math
import os
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from coinflight import _validation as v
from coinflight.model.distributions import Distribution
from coinflight.model.ensemble import PARAMETERS, UNITS, TossDistribution
from coinflight.model.toss import STANDARD_GRAVITY
from coinflight.outcomes.base import OutcomeModel
from coinflight.outcomes.hand import HAND_CATCH
from coinflight.probability import registry
from coinflight.probability.checkpoint import MAX_ROWS
from coinflight.probability.result import ProbabilityResult, require_pandas
from coinflight.probability.streams import SeedLike, reported_seed, seed_sequence

if TYPE_CHECKING:
    import pandas as pd

    from coinflight.model.coin import Coin


class ProbabilityResults(list[ProbabilityResult]):
    """The results of :func:`estimate_many`, in the order of its distributions.

    A list of :class:`~coinflight.probability.result.ProbabilityResult` that also keeps the
    distributions (:attr:`distributions`) and turns into a table (:meth:`to_dicts`,
    :meth:`to_frame`).
    """

    def __init__(
        self, distributions: Iterable[TossDistribution], results: Iterable[ProbabilityResult]
    ) -> None:
        super().__init__(results)
        self.distributions: tuple[TossDistribution, ...] = tuple(distributions)
        if len(self.distributions) != len(self):
            raise ValueError(
                f"{len(self.distributions)} distributions for {len(self)} results; "
                "they must pair up"
            )

    def to_dicts(self) -> list[dict[str, Any]]:
        """One flat dictionary per result: the tosses (each parameter as text, e.g.
        ``"60–90 rad/s"``, and as numbers to plot: ``omega_x.low``, ``omega_x.high`` (the
        smallest and largest value, ±inf for a normal), ``omega_x.mean``, ``omega_x.sd`` (the
        standard deviation, 0 for a single value), SI units; ``launch_speed`` when given, all
        None when not), coin, start face, g, then :meth:`ProbabilityResult.to_row`."""
        rows = []
        for dist, result in zip(self.distributions, self, strict=True):
            row: dict[str, Any] = {}
            for name in PARAMETERS:
                row.update(_described(name, getattr(dist, name), UNITS[name]))
            row.update(_described("launch_speed", dist.launch_speed, "m/s"))
            row.update(coin=dist.coin.name, start=dist.start, g=dist.g)
            row.update(result.to_row())
            rows.append(row)
        return rows

    def to_frame(self) -> pd.DataFrame:
        """A pandas DataFrame of :meth:`to_dicts`, one row per distribution (needs
        ``pip install pandas``)."""
        return require_pandas().DataFrame(self.to_dicts())


def _described(name: str, dist: Distribution | None, unit: str) -> dict[str, Any]:
    """A parameter's columns: its text, then ``.low``, ``.high``, ``.mean``, ``.sd``."""
    if dist is None:
        return {name: None} | {f"{name}.{stat}": None for stat in ("low", "high", "mean", "sd")}
    low, high = dist.bounds
    return {
        name: dist.describe(unit),
        f"{name}.low": low,
        f"{name}.high": high,
        f"{name}.mean": float(dist.mean),
        f"{name}.sd": dist.std,
    }


def estimate_many(
    dists: Iterable[TossDistribution], method: str = "exact", **kwargs: Any
) -> ProbabilityResults:
    """P(heads) for each distribution of ``dists`` by ``method``: one result each.

    Parameters
    ----------
    dists : iterable of TossDistribution
        The distributions to compare, e.g. one per coin or per spin range.
    method : str
        A registered method (:func:`coinflight.probability.registry.names`).
    **kwargs
        Passed to :func:`~coinflight.probability.estimate` for every distribution (``n``,
        ``seed``, ``model``, ``threads``, …). One ``seed`` serves every distribution: the
        random methods then draw the same points of the unit cube for each (common random
        numbers), so differences between the distributions are not blurred by independent
        sampling noise.

    Returns
    -------
    ProbabilityResults
        A list of results in the order of ``dists``; ``.to_frame()`` gives a DataFrame.

    Raises
    ------
    TypeError
        Before any work, naming the position of an entry that is not a TossDistribution.
    """
    from coinflight.probability import estimate

    if isinstance(dists, TossDistribution):
        raise TypeError("dists must be a list of TossDistribution; for one, use estimate()")
    items = list(dists)
    for i, dist in enumerate(items):
        if not isinstance(dist, TossDistribution):
            raise TypeError(f"dists[{i}] must be a TossDistribution, got {dist!r}")
    return ProbabilityResults(items, [estimate(dist, method, **kwargs) for dist in items])


# --- sweeps: rows as tasks, streams per row, a checkpoint, one table -----------------------

ROW_SECONDS = 0.05
"""Seconds of work counted for a row whose method bounds its own work and makes no estimate
of it (exact's adaptive quadrature; exact otherwise estimates its row,
:func:`coinflight.probability.exact.estimated_seconds`): the sweep's work bound
(:func:`check_sweep_work`) adds this per row; a single row's own bound still holds."""
CHECKPOINT_SUFFIX = ".partial.jsonl"
"""A sweep writing FILE keeps its finished rows in FILE + this suffix until FILE is written."""


@dataclass(frozen=True)
class Case:
    """One row of a sweep: a distribution of tosses and how the tosses end.

    Parameters
    ----------
    dist : TossDistribution
    model : OutcomeModel
        Default: caught in the hand.
    """

    dist: TossDistribution
    model: OutcomeModel = HAND_CATCH

    def __post_init__(self) -> None:
        v.instance("dist", self.dist, TossDistribution, "a TossDistribution")
        v.instance("model", self.model, OutcomeModel, "an OutcomeModel (HandCatch, TableLanding)")

    def inputs(self) -> dict[str, Any]:
        """Everything that defines the row, JSON-ready: each parameter's distribution, the
        launch speed when given, the coin's name and dimensions, start face, g, the outcome
        model (:meth:`~coinflight.outcomes.base.OutcomeModel.to_dict`)."""
        dist = self.dist
        coin = dist.coin
        speed = dist.launch_speed
        return {
            **{name: getattr(dist, name).to_dict() for name in PARAMETERS},
            "launch_speed": None if speed is None else speed.to_dict(),
            "coin": coin.to_dict(),  # name, r, h, m and a rounded rim's corner radius
            "start": dist.start,
            "g": dist.g,
            "model": self.model.to_dict(),
        }

    def stream(self) -> int:
        """The row's random stream: a 60-bit number from its :meth:`inputs` (not from its
        position, the method, n or the seed). Row i of a seeded sweep draws from
        ``SeedSequence(seed, spawn_key=(stream,))``: the same tosses whatever the order of the
        rows, the workers, the other rows, and a run of n tosses is the first n of a longer
        one."""
        return _stream(self.inputs())


def product_cases(
    *,
    omega_x: Sequence[Distribution | float],
    omega_y: Sequence[Distribution | float] = (0.0,),
    omega_z: Sequence[Distribution | float] = (0.0,),
    flight_time: Sequence[Distribution | float] | None = None,
    launch_speed: Sequence[Distribution | float] | None = None,
    coins: Sequence[Coin] | None = None,
    starts: Sequence[str] = ("heads",),
    models: Sequence[OutcomeModel] = (HAND_CATCH,),
    g: float = STANDARD_GRAVITY,
) -> list[Case]:
    """The Cartesian product of the given values, one :class:`Case` each.

    Each argument is a list of the values to sweep (distributions or numbers for the toss
    parameters, as :class:`~coinflight.model.ensemble.TossDistribution` takes them); give
    exactly one of ``flight_time`` and ``launch_speed``. Rows come in the order coin, start
    face, outcome model, ωx, ωy, ωz, flight time (or launch speed), the last varying fastest.
    The number of rows is checked against :data:`MAX_ROWS` before any is built.
    """
    from coinflight.model.coin import DEFAULT_COIN, Coin

    if (flight_time is None) == (launch_speed is None):
        raise TypeError("give one of flight_time (s) and launch_speed (m/s)")
    the_coins = [Coin.preset(DEFAULT_COIN)] if coins is None else list(coins)
    time_key = "flight_time" if launch_speed is None else "launch_speed"
    times = flight_time if launch_speed is None else launch_speed
    assert times is not None
    lists: dict[str, Sequence[Any]] = {
        "coin": the_coins,
        "start": starts,
        "model": models,
        "omega_x": omega_x,
        "omega_y": omega_y,
        "omega_z": omega_z,
        time_key: times,
    }
    for name, values in lists.items():
        if len(values) == 0:
            raise ValueError(f"no values given for {name}")
    rows = math.prod(len(values) for values in lists.values())
    if rows > MAX_ROWS:
        sizes = " × ".join(f"{len(x)} {name}" for name, x in lists.items() if len(x) > 1)
        shown, most = v.over_limit(rows, MAX_ROWS)
        raise ValueError(f"a sweep of {sizes} is {shown} rows, more than {most}; use fewer")
    cases = []
    for combo in itertools.product(*lists.values()):
        row = dict(zip(lists, combo, strict=True))
        model = row.pop("model")
        cases.append(Case(TossDistribution(**row, g=g), model))
    return cases


def _digest(obj: object) -> str:
    text = json.dumps(obj, sort_keys=True, separators=(",", ":"), allow_nan=False)
    return hashlib.sha256(text.encode()).hexdigest()


def row_key(case: Case, method: str, n: int | None, seed: int | None) -> str:
    """The key of a finished row in a checkpoint: a digest of its inputs, method, n and seed
    (a row is reused only when all four are the same)."""
    return _key(case.inputs(), method, n, seed)


def _key(inputs: Mapping[str, Any], method: str, n: int | None, seed: int | None) -> str:
    return _digest({"inputs": inputs, "method": method, "n": n, "seed": seed})[:32]


def _stream(inputs: Mapping[str, Any]) -> int:
    return int(_digest(inputs)[:15], 16)


class SweepResults(ProbabilityResults):
    """The results of :func:`sweep`, in the order of its cases.

    A :class:`ProbabilityResults` that also keeps the cases, the method, size and seed, the row
    keys and streams, and how many rows came from the checkpoint (:attr:`reused`).
    """

    def __init__(
        self,
        cases: Sequence[Case],
        results: Iterable[ProbabilityResult],
        *,
        method: str,
        n: int | None,
        seed: int | None,
        keys: Sequence[str],
        reused: int = 0,
    ) -> None:
        super().__init__([c.dist for c in cases], results)
        self.cases = tuple(cases)
        self.method = method
        self.n = n
        self.seed = seed
        self.keys = tuple(keys)
        self.reused = reused

    def to_dicts(self) -> list[dict[str, Any]]:
        """One flat row per case: :meth:`ProbabilityResults.to_dicts` (parameters as text,
        and the parameters' numbers ``omega_x.low``, … ``omega_x.sd``, coin, start, g, the
        result's fields), each parameter's kind and, for a single value, that value
        (``omega_x.kind``, ``omega_x.value``), the coin's
        dimensions, the outcome model's fields (``surface``, ``restitution``, …), the row's
        ``stream`` (seeded methods) and ``key``. ``p_edge`` is empty where the surface cannot
        leave a coin on its edge (the hand). Of the method's details only the outcome model's
        tallies are kept (:attr:`coinflight.outcomes.base.OutcomeModel.tallies`: ``unsettled``
        with its ``_fraction``), as columns
        of their own, empty in the table for rows whose model has none."""
        rows = []
        seeded = registry.get(self.method).seeded
        for row, case, key in zip(super().to_dicts(), self.cases, self.keys, strict=True):
            out = {k: x for k, x in row.items() if not k.startswith("details.")}
            for name in case.model.tallies:  # the tallies, as columns of their own
                for column in (name, f"{name}_fraction"):
                    if f"details.{column}" in row:
                        out[column] = row[f"details.{column}"]
            inputs = case.inputs()
            for name in (*PARAMETERS, "launch_speed"):
                dist = inputs[name]
                if dist is None:
                    continue
                for field in ("kind", "value"):
                    out[f"{name}.{field}"] = dist.get(field)
            out.update({f"coin.{k}": x for k, x in inputs["coin"].items() if k != "name"})
            for k, x in inputs["model"].items():
                out[k] = json.dumps(x) if isinstance(x, dict) else x
            if not case.model.can_end_on_edge:
                out["p_edge"] = None
            out["stream"] = case.stream() if seeded else None
            out["key"] = key
            rows.append(out)
        return rows


def check_sweep_work(cases: Sequence[Case], method: str, n: int | None) -> float:
    """Seconds of work of the sweep on the reference machine (each row's estimate, exact's
    from the integral it will do, or :data:`ROW_SECONDS` for a method without one); ValueError
    beyond
    :data:`coinflight._validation.MAX_RUN_SECONDS`, before anything runs."""
    from coinflight.probability import exact

    estimator = registry.get(method)
    total = 0.0
    for case in cases:
        size = estimator.size_for(len(case.dist.ranged), n)
        if estimator.name == exact.NAME:
            seconds = exact.estimated_seconds(case.dist, case.model)
            total += ROW_SECONDS if seconds is None else seconds
        elif estimator.work is None or size is None:
            total += ROW_SECONDS
        else:
            total += estimator.work(case.dist, size, case.model)
    v.work_bound(
        f"a sweep of {len(cases)} rows by {method}" + ("" if n is None else f" with n = {n}"),
        total,
        v.MAX_RUN_SECONDS,
        "s of work",
        "use fewer values per option or a smaller n",
    )
    return total


def _row_task(args: tuple[Any, ...]) -> ProbabilityResult:
    """One row, computed serially (the rows are the parallel tasks)."""
    from coinflight.probability import estimate

    dist, model, method, n, seed, stream = args
    estimator = registry.get(method)
    kwargs: dict[str, Any] = {"model": model}
    if estimator.seeded:
        kwargs["seed"] = np.random.SeedSequence(seed, spawn_key=(stream,))
    if estimator.parallel:
        kwargs["threads"] = 1
    return estimate(dist, method, n=n, **kwargs)


def result_from_dict(data: Mapping[str, Any]) -> ProbabilityResult:
    """The :class:`ProbabilityResult` of its :meth:`~ProbabilityResult.to_dict` (floats come
    back bit for bit through JSON)."""
    d = dict(data)
    ci = d.get("ci95")
    counts = d.get("counts")
    d["ci95"] = None if ci is None else (float(ci[0]), float(ci[1]))
    d["counts"] = None if counts is None else (counts["tails"], counts["heads"], counts["edge"])
    return ProbabilityResult(**d)


def read_checkpoint(
    path: str | os.PathLike[str], method: str, n: int | None = None, seed: int | None = None
) -> dict[str, ProbabilityResult]:
    """The finished rows, by key, of the checkpoint of a sweep by ``method`` with ``n`` and
    ``seed`` ({} when there is none). A file that such a run did not write (not a checkpoint,
    another run's, edited, damaged, a symbolic link) is refused with a ValueError naming it
    (:class:`coinflight.probability.checkpoint.Checkpoint`); a last line cut short by a killed
    run is skipped and that row computed again."""
    from coinflight.probability.checkpoint import Checkpoint

    return Checkpoint(path, method, n, seed).read()


def sweep(
    cases: Iterable[Case],
    method: str = "exact",
    n: int | None = None,
    seed: SeedLike = None,
    *,
    executor: Any = None,
    threads: int | None = None,
    progress: Callable[[int], None] | None = None,
    checkpoint: str | os.PathLike[str] | None = None,
    fresh: bool = False,
) -> SweepResults:
    """P(heads), P(same side), P(edge) for each case, each row an independent task.

    Parameters
    ----------
    cases : iterable of Case
        The rows: a distribution of tosses and its outcome model each.
    method : str
        A registered method (:func:`coinflight.probability.registry.names`), for every row.
    n : int, optional
        The method's size for every row (default: the method's default per row).
    seed : int, optional
        For the seeded methods: one seed for the whole sweep (None: a fresh one, reported).
        Row i draws from ``SeedSequence(seed, spawn_key=(cases[i].stream(),))``
        (:meth:`Case.stream`), so each row is reproducible on its own, whatever the order of the
        rows and the workers; ``estimate(case.dist, method, n, seed=that SeedSequence,
        model=case.model)`` gives the same row.
    executor : object with ``map``, or a distributed.Client, optional
        Runs the rows (default: a thread pool of ``threads`` workers); each row runs serially
        inside its task.
    progress : callable, optional
        Called with 1 as each row finishes (in any order), reused rows included.
    checkpoint : path, optional
        A file of finished rows (JSON lines, one per row, keyed by :func:`row_key`): rows found
        in it are not recomputed, and every row computed is appended as it finishes, so a sweep
        that is stopped (Ctrl-C, a failure, a killed process) resumes where it stopped. Its
        first line names the run (method, n, seed) and each row carries a checksum: a file
        that is not the checkpoint of this run, or was edited, or is a symbolic link, is
        refused before any work (ValueError naming it), never read, followed or appended to.
    fresh : bool
        Start over: replace the file at ``checkpoint`` (a regular file or a link, never what
        a link points to) instead of resuming from it.

    Returns
    -------
    SweepResults
        One result per case, in order; ``.to_dicts()``/``.to_frame()`` give the table.

    Raises
    ------
    ValueError
        Before any work: too many rows, or more work than
        :data:`coinflight._validation.MAX_RUN_SECONDS` in all (:func:`check_sweep_work`).
    """
    from coinflight.probability._runner import check_runner, completed, executor_or_threads

    items = list(cases)
    if len(items) > MAX_ROWS:
        shown, most = v.over_limit(len(items), MAX_ROWS)
        raise ValueError(f"a sweep of {shown} rows is more than {most}; use fewer")
    for i, case in enumerate(items):
        if not isinstance(case, Case):
            raise TypeError(f"cases[{i}] must be a Case, got {case!r}")
    if not items:
        raise ValueError("a sweep needs at least one case")
    estimator = registry.get(method)
    if n is not None:
        n = v.count("n", n)
        if estimator.default_n is None:
            raise ValueError(f"the {method} method takes no n")
    check_runner(executor, threads, progress)
    the_seed: int | None = None
    if estimator.seeded:
        the_seed = reported_seed(seed_sequence(seed))
    elif seed is not None:
        raise TypeError(f"method {method!r} takes no seed (it is deterministic); got seed={seed}")
    check_sweep_work(items, method, n)
    inputs = [case.inputs() for case in items]  # once a row: its key and its stream
    keys = [_key(x, method, n, the_seed) for x in inputs]
    from coinflight.probability.checkpoint import Checkpoint

    log = None if checkpoint is None else Checkpoint(checkpoint, method, n, the_seed)
    done = {} if log is None else log.read(fresh=fresh)
    results: list[ProbabilityResult | None] = [done.get(k) for k in keys]
    reused = sum(r is not None for r in results)
    if progress is not None and reused:
        progress(reused)
    todo = [i for i, r in enumerate(results) if r is None]
    tasks = [(items[i].dist, items[i].model, method, n, the_seed, _stream(inputs[i])) for i in todo]
    try:
        with executor_or_threads(executor, threads) as ex:
            for j, result in completed(ex, _row_task, tasks, [1] * len(tasks)):
                i = todo[j]
                results[i] = result
                if log is not None:
                    log.append(keys[i], result)
                if progress is not None:
                    progress(1)
    finally:
        if log is not None:
            log.close()
    return SweepResults(
        items,
        [r for r in results if r is not None],
        method=method,
        n=n,
        seed=the_seed,
        keys=keys,
        reused=reused,
    )


def table_metadata(results: SweepResults, inputs: Mapping[str, Any] | None = None) -> dict:
    """What a sweep's table records about itself: the package version, the method, n, seed,
    rows, the inputs as given (e.g. the command line's options), the columns of the standard
    errors; the command line when run by one (:mod:`coinflight._provenance`)."""
    from coinflight._provenance import provenance

    return {
        **provenance(),
        "method": results.method,
        "n": results.n,
        "seed": results.seed,
        "rows": len(results),
        "inputs": dict(inputs or {}),
        "stderr": "column stderr: standard error of p_heads per row (random methods); "
        "error_estimate: the numerical error bound of exact",
    }


TABLE_FORMATS = (".parquet", ".csv")
"""Suffixes :func:`write_table` writes."""


def table_files(path: str | os.PathLike[str]) -> list[Path]:
    """The files :func:`write_table` writes for ``path``: FILE.parquet alone (its metadata
    inside), or FILE.csv with FILE.csv.json (the metadata beside it)."""
    target = Path(path)
    suffix = target.suffix.lower()
    if suffix not in TABLE_FORMATS:
        raise ValueError(
            f"cannot write {os.fspath(path)}: the table's format follows the suffix, "
            f"{' or '.join(TABLE_FORMATS)}"
        )
    return [target] if suffix == ".parquet" else [target, target.with_name(target.name + ".json")]


def write_table(
    results: SweepResults,
    path: str | os.PathLike[str],
    inputs: Mapping[str, Any] | None = None,
) -> list[Path]:
    """Write the sweep as one table, whole or not at all (:func:`coinflight._files.replacing_all`).

    ``.parquet`` (needs ``pip install "coinflight[parquet]"``): one file, the metadata of
    :func:`table_metadata` as JSON under the key ``coinflight`` of the schema's metadata.
    ``.csv``: the table, and its metadata as FILE.csv.json. Returns the files written.
    """
    from coinflight._files import cannot_write, replacing_all

    files = table_files(path)
    rows = results.to_dicts()
    columns: dict[str, None] = {}
    for row in rows:
        columns.update(dict.fromkeys(row))
    meta = table_metadata(results, inputs)
    if files[0].suffix.lower() == ".parquet":
        pa, pq = _require_pyarrow()
        table = pa.Table.from_pylist(
            [{c: row.get(c) for c in columns} for row in rows],
            metadata={"coinflight": json.dumps(meta)},
        )
    try:
        with replacing_all(files) as temps:
            if files[0].suffix.lower() == ".parquet":
                pq.write_table(table, temps[0])
            else:
                import csv

                with open(temps[0], "w", newline="", encoding="utf-8") as f:
                    writer = csv.DictWriter(f, fieldnames=list(columns), restval="")
                    writer.writeheader()
                    writer.writerows(rows)
                temps[1].write_text(json.dumps(meta, indent=2) + "\n", encoding="utf-8")
    except OSError as exc:
        raise cannot_write(path, exc) from None
    return files


def read_table(path: str | os.PathLike[str]) -> tuple[list[dict[str, Any]], dict[str, Any]]:
    """The rows and metadata of a table written by :func:`write_table` (CSV values as text)."""
    files = table_files(path)
    if files[0].suffix.lower() == ".parquet":
        _, pq = _require_pyarrow()
        table = pq.read_table(files[0])
        meta = json.loads((table.schema.metadata or {})[b"coinflight"])
        return table.to_pylist(), meta
    import csv

    with open(files[0], newline="", encoding="utf-8") as f:
        rows = list(csv.DictReader(f))
    return rows, json.loads(files[1].read_text(encoding="utf-8"))


def _require_pyarrow() -> tuple[Any, Any]:
    try:
        import pyarrow as pa
        import pyarrow.parquet as pq
    except ModuleNotFoundError:
        raise ValueError(
            'writing Parquet needs pyarrow: pip install "coinflight[parquet]" (or write a .csv)'
        ) from None
    return pa, pq


def run_sweep(
    cases: Iterable[Case],
    out: str | os.PathLike[str],
    method: str = "exact",
    n: int | None = None,
    seed: SeedLike = None,
    *,
    inputs: Mapping[str, Any] | None = None,
    fresh: bool = False,
    **runner: Any,
) -> tuple[SweepResults, list[Path]]:
    """:func:`sweep` into the table ``out`` (:func:`write_table`), resumable.

    The finished rows are kept in ``out`` + :data:`CHECKPOINT_SUFFIX` while the sweep runs; a
    rerun with the same cases, method, n and seed computes only the rows missing from it. The
    table is written whole at the end, then the checkpoint removed; if anything fails, no table
    is written and the checkpoint stays for the next run. A file in the checkpoint's place
    that this run did not write is refused (see :func:`sweep`); ``fresh=True`` replaces it
    and starts over. ``runner``: ``executor``, ``threads``, ``progress``.
    """
    from coinflight._files import check_all_writable
    from coinflight.probability.checkpoint import Checkpoint

    files = table_files(out)
    if files[0].suffix.lower() == ".parquet":
        _require_pyarrow()
    check_all_writable(files)
    checkpoint = Path(os.fspath(out) + CHECKPOINT_SUFFIX)
    results = sweep(cases, method, n, seed, checkpoint=checkpoint, fresh=fresh, **runner)
    written = write_table(results, out, inputs)
    Checkpoint(checkpoint, results.method, results.n, results.seed).remove()
    return results, written


__all__ = [
    "CHECKPOINT_SUFFIX",
    "MAX_ROWS",
    "Case",
    "ProbabilityResults",
    "SweepResults",
    "check_sweep_work",
    "estimate_many",
    "product_cases",
    "read_checkpoint",
    "read_table",
    "result_from_dict",
    "row_key",
    "run_sweep",
    "sweep",
    "table_files",
    "table_metadata",
    "write_table",
]
