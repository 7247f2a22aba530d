"""The benchmark scripts for the tests: one loader of ``benchmarks/<name>.py`` as a module
(the scripts are not a package), so their testable pieces are called in-process."""

from __future__ import annotations

import importlib.util
from pathlib import Path
from types import ModuleType

BENCH = Path(__file__).resolve().parents[1] / "benchmarks"


def bench_script(name: str) -> Path:
    """The path of ``benchmarks/<name>.py``."""
    return BENCH / f"{name}.py"


def load_bench(name: str) -> ModuleType:
    """``benchmarks/<name>.py`` loaded afresh as the module ``name``."""
    spec = importlib.util.spec_from_file_location(name, bench_script(name))
    assert spec is not None and spec.loader is not None
    bench = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(bench)
    return bench
