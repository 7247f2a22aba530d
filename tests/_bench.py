"""The benchmark scripts for the tests: one loader of ``benchmarks/<name>.py`` as a module
(the scripts are not imported as a package), so their testable pieces are called in-process.

The scripts import each other as top-level modules (``import bench_contact``), at load time and
inside functions, as they do when run as ``python benchmarks/<name>.py``: the loader puts
``benchmarks/`` on ``sys.path`` (once, for the rest of the session; its modules' names are all
``bench_*`` or named apart from the standard library's, the tests' and the installed packages',
as test_bench_tolerance checks). A script timed on one thread sets ``NUMBA_NUM_THREADS`` to 1
unless it is set, before numba is imported; in the tests numba is already running, and it
refuses a change of that variable once its threads are launched, so the loader keeps it at
numba's value while the script loads and restores it after."""

from __future__ import annotations

import importlib.util
import os
import sys
from pathlib import Path
from types import ModuleType

BENCH = Path(__file__).resolve().parents[1] / "benchmarks"


def bench_script(name: str) -> Path:
    """The path of ``benchmarks/<name>.py``."""
    return BENCH / f"{name}.py"


def bench_on_path() -> None:
    """Put ``benchmarks/`` first on ``sys.path`` (once), as running a script there does."""
    if str(BENCH) not in sys.path:
        sys.path.insert(0, str(BENCH))


def load_bench(name: str) -> ModuleType:
    """``benchmarks/<name>.py`` loaded afresh as the module ``name``, with ``benchmarks/`` on
    ``sys.path`` and ``NUMBA_NUM_THREADS`` as it was before. A fresh module each call, not put
    in ``sys.modules``: a script's own ``import bench_contact`` reuses the copy cached there, so
    ``load_bench("bench_contact")`` and the ``bench_contact`` another script imports are two
    module objects (patch the one the code under test reads)."""
    import numba

    bench_on_path()
    before = os.environ.get("NUMBA_NUM_THREADS")
    os.environ["NUMBA_NUM_THREADS"] = str(numba.config.NUMBA_NUM_THREADS)  # type: ignore[attr-defined]
    try:
        spec = importlib.util.spec_from_file_location(name, bench_script(name))
        assert spec is not None and spec.loader is not None
        bench = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(bench)
    finally:
        if before is None:
            os.environ.pop("NUMBA_NUM_THREADS", None)
        else:
            os.environ["NUMBA_NUM_THREADS"] = before
    return bench
