"""A notice on standard error when numba compiles coinflight's kernels, so that the first
table landing (about 20 s of computing, a minute on a busy machine) is not a silent minute.

The kernels in :mod:`coinflight.core` are compiled by numba on their first call and cached on
disk (``cache=True``: ``__pycache__`` beside the sources, or ``NUMBA_CACHE_DIR``); later runs
load them in about a second. When one is compiled rather than loaded, numba announces it
(its ``numba:compile`` event), and the first such compilation of each kind of coinflight
kernel (:data:`KERNEL_MODULES`) in a process prints, at once::

    coinflight: compiling the table landing's kernels for their first use (about 20 s of
    computing, longer on a busy machine); numba caches them, so this happens once

:mod:`coinflight.core._jit`, the one module that imports numba (after checking the ``NUMBA_*``
environment), registers the listener (:func:`listen`) right after that import, so ``import
coinflight`` alone imports no numba.
``make demo`` leaves the table landing's kernels compiled.
"""

from __future__ import annotations

import sys
import threading
from typing import Any

KERNEL_MODULES = {
    "coinflight.core.band_contact": ("the table landing's", 20),
    "coinflight.core.bounce": ("the table landing's", 20),
    "coinflight.core.impact": ("the table landing's", 20),
    "coinflight.core.rigid_contact": ("the table landing's", 20),
    "coinflight.core.rigid_ending": ("the table landing's", 20),
    "coinflight.core.dormand_prince": ("the table landing's", 20),
    "coinflight.core.drag": ("the flight through air's", 6),
    "coinflight.core.flight": ("the table landing's", 20),
    "coinflight.core.sampling": ("the sampling's", 2),
}
"""The modules of numba kernels: what to call their kernels in the notice, and about how many
seconds of computing compiling them takes (measured with an empty cache: one table landing
compiles about 70 kernels in about 20 s of CPU time, a toss through air 15 in about 6 s, the
sampling kernel 1 in 1-2 s)."""

_lock = threading.Lock()
_state: dict[str, Any] = {"listening": False, "told": set()}


def notice(module: str) -> str:
    """The line printed when a kernel of ``module`` is first compiled."""
    what, seconds = KERNEL_MODULES.get(module, ("coinflight's", 20))
    return (
        f"coinflight: compiling {what} kernels for their first use (about {seconds} s of "
        "computing, longer on a busy machine); numba caches them, so this happens once"
    )


def _tell(module: str) -> None:
    line = notice(module)
    with _lock:
        if line in _state["told"]:
            return
        _state["told"].add(line)
    try:
        sys.stderr.write(line + "\n")
        sys.stderr.flush()
    except (OSError, ValueError):  # standard error closed: the notice is not worth a failure
        pass


def listen() -> None:
    """Register the ``numba:compile`` listener (once; imports numba)."""
    with _lock:
        if _state["listening"]:
            return
        _state["listening"] = True
    from numba.core import event

    class _Compiling(event.Listener):
        def on_start(self, ev: Any) -> None:
            dispatcher = ev.data.get("dispatcher") if isinstance(ev.data, dict) else None
            module = getattr(getattr(dispatcher, "py_func", None), "__module__", "") or ""
            if module.startswith("coinflight."):
                _tell(module)

        def on_end(self, ev: Any) -> None:
            pass

    event.register("numba:compile", _Compiling())


NUMBA_GATE = "coinflight.core._jit"
"""The module through which every kernel module imports numba."""
