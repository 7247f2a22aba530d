"""The one import of numba: the kernels' compiler, after its environment is checked.

numba reads its settings from ``NUMBA_*`` environment variables when it is first imported. A
value it cannot parse (``NUMBA_NUM_THREADS=abc``) is only a warning there, with numba's
traceback in it, and the default is used instead of what was asked; ``NUMBA_NUM_THREADS=0``
fails at the first parallel kernel with words that name no variable. Both are refused here,
as a ValueError naming the variable and its value, before numba starts; every kernel module
imports numba from this module (``from coinflight.core._jit import njit, prange``).
"""

from __future__ import annotations

import os
import re
import warnings
from collections.abc import Mapping
from types import ModuleType

MAX_THREADS = 1024
"""Most threads ``NUMBA_NUM_THREADS`` may ask for (numba starts all of them at once), or the
machine's CPU count when that is larger."""

_UNPARSED = re.compile(
    r"Environment variable '(?P<name>\w+)' is defined but its associated value "
    r"'(?P<value>.*?)' could not be parsed",
    re.DOTALL,
)


def _shown(value: str) -> str:
    from coinflight._validation import shortened

    return repr(shortened(value, 80))


def check_environment(environ: Mapping[str, str] = os.environ) -> None:
    """ValueError unless ``NUMBA_NUM_THREADS`` (when set) is a whole number of threads from 1
    to :data:`MAX_THREADS` (or the CPU count). Cheap: imports nothing."""
    text = environ.get("NUMBA_NUM_THREADS")
    if text is None:
        return
    most = max(MAX_THREADS, os.cpu_count() or 1)
    try:
        threads = int(text.strip())
    except ValueError:
        threads = 0
    if not 1 <= threads <= most:
        raise ValueError(
            f"the environment variable NUMBA_NUM_THREADS={_shown(text)} is not a whole "
            f"number of threads from 1 to {most}; set one, or unset it to use every CPU"
        )


def _import_numba() -> ModuleType:
    """numba, imported after :func:`check_environment`; a ``NUMBA_*`` variable numba cannot
    parse is a ValueError naming it (numba would warn and use its default), at this import
    and at every later one in the process (numba reads its environment once)."""
    import coinflight.core as package  # keeps the refusal once numba is imported

    check_environment()
    refused = getattr(package, "_numba_refused", None)
    if refused is not None:
        raise ValueError(refused)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        import numba
    for warning in caught:
        found = _UNPARSED.search(str(warning.message))
        if found is not None:
            package._numba_refused = (  # type: ignore[attr-defined]
                f"the environment variable {found['name']}={_shown(found['value'])} cannot be "
                "read by numba; correct it, or unset it"
            )
            raise ValueError(package._numba_refused)  # type: ignore[attr-defined]
    for warning in caught:  # others as they were
        warnings.warn_explicit(warning.message, warning.category, warning.filename, warning.lineno)
    from coinflight._compiling import listen

    listen()  # the first compilation of a kernel says so on stderr
    return numba


numba = _import_numba()
njit = numba.njit
prange = numba.prange

__all__ = ["MAX_THREADS", "check_environment", "njit", "numba", "prange"]
