"""Figures. Imports matplotlib, so it is imported only when a figure is asked for.

Every public function returns a ``matplotlib.figure.Figure`` (for notebooks); the CLI saves it
with :func:`coinflight.plotting.style.save_figure`.
"""

from __future__ import annotations

import os


def _check_backend() -> None:
    """matplotlib reads ``MPLBACKEND`` when it is first imported and refuses a name it does not
    know in words that do not name the variable; say which variable it is, and the way on.
    (The figures use matplotlib's object API, no backend of pyplot's.)"""
    name = os.environ.get("MPLBACKEND")
    if name is None:
        return
    try:
        import matplotlib  # noqa: F401
    except ValueError:
        from coinflight._validation import shortened

        raise ValueError(
            f"the environment variable MPLBACKEND={shortened(name, 80)!r} is not a backend "
            "matplotlib knows (e.g. agg); correct it, or unset it"
        ) from None


_check_backend()
