"""--scheduler and --workers: where a command's tasks run (threads here, or a Dask cluster).

One option group (see :mod:`coinflight.cli.command`) shared by ``probability``,
``convergence``, ``edge``, ``plot basin`` and ``sweep``; the library does the work
(:mod:`coinflight.probability.distributed`).
"""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import ExitStack, contextmanager
from typing import Annotated, Any, NamedTuple

import typer

from coinflight.cli.command import Group
from coinflight.cli.options import PARALLEL_PANEL, Threads

CLUSTER_PANEL = PARALLEL_PANEL


class ClusterArgs(NamedTuple):
    """--scheduler and --workers as typed (checked when the command runs), and --threads where
    the command takes it (:data:`ParallelOptions`; None otherwise)."""

    scheduler: str | None
    workers: int | None
    threads: int | None = None

    @contextmanager
    def executor(self) -> Iterator[Any]:
        """None (the library's thread pool, of --threads threads) without --scheduler; else the
        Dask executor, its cluster started or joined here and closed at the end."""
        if self.scheduler is None:
            if self.workers is not None:
                raise ValueError(
                    "--workers applies to --scheduler local only (for threads: --threads)"
                )
            yield None
            return
        if self.threads is not None:
            raise ValueError(
                "--threads applies without --scheduler; on a Dask cluster each worker is "
                "one process with one thread (--workers with --scheduler local)"
            )
        from coinflight.probability.distributed import check_scheduler, dask_client

        try:
            check_scheduler(self.scheduler, self.workers)
        except ValueError as exc:
            raise ValueError(f"--{exc}") from None
        with ExitStack() as stack:
            try:
                executor = stack.enter_context(dask_client(self.scheduler, self.workers))
            except ModuleNotFoundError as exc:
                raise ValueError(f"--scheduler: {exc}") from None
            yield executor


CLUSTER = Group(
    {
        "scheduler": (
            Annotated[
                str | None,
                typer.Option(
                    "--scheduler",
                    metavar="local|tcp://HOST:PORT",
                    rich_help_panel=CLUSTER_PANEL,
                    help='Run the tasks on a Dask cluster (pip install "coinflight[dask]"): '
                    "local starts a LocalCluster of --workers processes on this machine; "
                    "tcp://HOST:PORT joins a running one (`dask scheduler`, `dask worker "
                    "tcp://HOST:PORT`; waits 5 s for it). Same seed, same result as on threads.",
                ),
            ],
            None,
        ),
        "workers": (
            Annotated[
                int | None,
                typer.Option(
                    "--workers",
                    metavar="N",
                    min=1,
                    rich_help_panel=CLUSTER_PANEL,
                    help="Worker processes of --scheduler local (default: one per CPU).",
                ),
            ],
            None,
        ),
    },
    ClusterArgs,
)
ClusterOptions = Annotated[ClusterArgs, CLUSTER]
"""--scheduler and --workers, as typed."""
PARALLEL = Group({"threads": (Threads, None), **CLUSTER.params}, ClusterArgs)
ParallelOptions = Annotated[ClusterArgs, PARALLEL]
"""--threads, --scheduler and --workers, as typed: the commands whose estimators take a
number of threads on this machine."""
