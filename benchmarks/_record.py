"""The record a speed benchmark writes: its figures and where they came from.

A script makes one :class:`Recorder` when it starts (the command line, the UTC date and time,
the load average before) and, with ``--json``, prints :meth:`Recorder.record` at the end: the
benchmark's name, its figures (numbers, the unit in each key's name: ``_per_s``, ``_s``,
``_ms``, ``_mb``), the command, the versions of coinflight, Python, NumPy, numba and SciPy,
the processor's model and core count, the system, and the load average before and after.
While a script runs with ``--json`` its text goes to stderr (:meth:`Recorder.text_to_stderr`),
so that stdout holds the record alone.

Not a ``bench_*`` script: ``python -m benchmarks`` does not run it.
"""

from __future__ import annotations

import json
import os
import platform
import re
import shlex
import sys
from collections.abc import Iterator, Mapping, Sequence
from contextlib import contextmanager, redirect_stdout
from datetime import UTC, datetime
from pathlib import Path
from typing import Any

PROVENANCE_KEYS = ("benchmark", "command", "date", "versions", "machine", "load")
"""The keys every record holds beside ``figures``."""


def machine() -> dict[str, Any]:
    """The processor's model (from /proc/cpuinfo where there is one), its logical CPUs and the
    system."""
    model = platform.processor() or platform.machine()
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                model = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    return {
        "processor": model,
        "cpus": os.cpu_count(),
        "system": f"{platform.system()} {platform.release()} {platform.machine()}",
    }


def versions() -> dict[str, str]:
    """The versions of coinflight (as its own outputs give it), Python, NumPy, numba, SciPy."""
    import numba
    import numpy
    import scipy

    from coinflight._provenance import provenance

    return {
        "coinflight": provenance()["coinflight_version"],
        "python": platform.python_version(),
        "numpy": numpy.__version__,
        "numba": numba.__version__,
        "scipy": scipy.__version__,
    }


def summary() -> str:
    """One line: processor, CPUs, system, versions and the load average now."""
    m, v = machine(), versions()
    return (
        f"{m['processor']}, {m['cpus']} CPUs, {m['system']}; Python {v['python']}, NumPy "
        f"{v['numpy']}, numba {v['numba']}, SciPy {v['scipy']}, coinflight {v['coinflight']}; "
        f"load average {os.getloadavg()[0]:.2f}"
    )


def key(name: str) -> str:
    """A printed label as a record's key: ``"table first contact"`` → ``"table_first_contact"``,
    μ as ``mu``."""
    return re.sub(r"[^0-9a-z]+", "_", name.lower().replace("μ", "mu")).strip("_")


def dumps(record: Mapping[str, Any]) -> str:
    """A record as JSON text (numbers as numbers, non-ASCII kept)."""
    return json.dumps(record, indent=1, ensure_ascii=False)


def _load() -> list[float]:
    return [round(x, 2) for x in os.getloadavg()]


class Recorder:
    """The provenance of one run of the benchmark ``name`` (``bench_air``): made when the run
    starts, with the script's arguments ``argv`` (``sys.argv[1:]`` when None)."""

    def __init__(self, name: str, argv: Sequence[str] | None = None) -> None:
        args = list(sys.argv[1:] if argv is None else argv)
        self.benchmark = name
        self.command = shlex.join(["python", f"benchmarks/{name}.py", *args])
        self.date = datetime.now(UTC).isoformat(timespec="seconds")
        self.load_before = _load()

    def record(
        self,
        figures: Mapping[str, Any],
        load: Mapping[str, Sequence[float]] | None = None,
        more_versions: Mapping[str, str | None] | None = None,
    ) -> dict[str, Any]:
        """The record: ``figures`` and the provenance (:data:`PROVENANCE_KEYS`). ``load``: the
        load average before and after the timing when the script took it itself, else from
        the start of the run to now; ``more_versions``: other packages' versions (None: not
        installed)."""
        if load is None:
            load = {"before": self.load_before, "after": _load()}
        return {
            "benchmark": self.benchmark,
            "figures": dict(figures),
            "command": self.command,
            "date": self.date,
            "versions": {**versions(), **(more_versions or {})},
            "machine": machine(),
            "load": {"before": list(load["before"]), "after": list(load["after"])},
        }

    def json(self, figures: Mapping[str, Any]) -> str:
        """:meth:`record` of ``figures`` as JSON text (numbers as numbers, non-ASCII kept)."""
        return dumps(self.record(figures))

    @contextmanager
    def text_to_stderr(self, active: bool) -> Iterator[None]:
        """Within the block, with ``active`` (``--json``), what the script prints goes to
        stderr, so that stdout holds the record alone."""
        if not active:
            yield
            return
        with redirect_stdout(sys.stderr):
            yield
