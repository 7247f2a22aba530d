"""The first compilation of coinflight's numba kernels says so on stderr (coinflight._compiling):
once a process, at once, naming the kernels and about how long; a warm cache says nothing."""

from __future__ import annotations

import os
import re
import subprocess
import sys
from pathlib import Path

from coinflight._compiling import KERNEL_MODULES, NUMBA_GATE, notice

CORE = Path(__file__).resolve().parents[1] / "src" / "coinflight" / "core"


def test_every_module_of_numba_kernels_is_named_and_numba_has_one_gate():
    """The listener is registered by numba's one gate (core._jit) after its import; every module
    that compiles kernels through it is named in KERNEL_MODULES (its words in the notice)."""
    sources = {p.stem: p.read_text(encoding="utf-8") for p in CORE.glob("*.py")}
    imports_numba = {
        name
        for name, text in sources.items()
        if re.search(r"^\s*(from|import) numba\b", text, re.M)
    }
    assert f"coinflight.core.{imports_numba.pop()}" == NUMBA_GATE and not imports_numba
    kernels = {
        f"coinflight.core.{name}"
        for name, text in sources.items()
        if re.search(r"^from coinflight\.core\._jit import", text, re.M)
    }
    assert kernels == set(KERNEL_MODULES)


def _python(code: str, **env: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-c", code],
        capture_output=True,
        text=True,
        timeout=300,
        env={**os.environ, **env},
        check=False,
    )


def test_a_kernel_compiled_says_so_once_and_other_code_does_not():
    """Two kernels of one kind compiled (uncached): one notice; another kind: its own; a
    function of another package compiled first: none for it."""
    code = """
import types, numba
import coinflight
from coinflight import _compiling
_compiling.listen()
other = numba.njit(lambda x: x + 1)
other(1)
import sys; sys.stderr.write("other compiled\\n")
fake = types.ModuleType("coinflight.core.drag")
exec("def f(x):\\n    return x * 2\\ndef g(x):\\n    return x * 3\\n", fake.__dict__)
numba.njit(fake.f)(1.0)
numba.njit(fake.g)(1.0)
table = types.ModuleType("coinflight.core.impact")
exec("def h(x):\\n    return x * 4\\n", table.__dict__)
numba.njit(table.h)(1.0)
"""
    run = _python(code)
    assert run.returncode == 0, run.stderr
    assert run.stderr.splitlines() == [
        "other compiled",
        notice("coinflight.core.drag"),
        notice("coinflight.core.impact"),
    ]
    assert "the flight through air's kernels" in notice("coinflight.core.drag")


def test_a_command_on_an_empty_cache_tells_first_and_a_warm_one_is_silent(tmp_path):
    """`coinflight probability` by Monte Carlo compiles the sampling kernel: with an empty
    numba cache its notice is the first line on stderr; run again, the cache is warm and
    nothing is said."""
    argv = ["-m", "coinflight", "probability", "--omega-x", "60:90", "--flight-time",
            "0.6:0.9", "--method", "monte-carlo", "--n", "1000", "--seed", "1", "-q"]  # fmt: skip
    env = {**os.environ, "NUMBA_CACHE_DIR": str(tmp_path / "numba")}
    runs = [
        subprocess.run(
            [sys.executable, *argv], capture_output=True, text=True, timeout=300, env=env
        )
        for _ in range(2)
    ]
    for run in runs:
        assert run.returncode == 0, run.stderr
        assert "P(heads)" in run.stdout
    assert runs[0].stderr.splitlines() == [notice("coinflight.core.sampling")]
    assert runs[1].stderr == ""
