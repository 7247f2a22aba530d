"""The ``coinflight`` command line: a thin typed layer over the library.

Each command lives in a module of its own and only parses, calls the library and formats.
Heavy imports (SciPy, numba, matplotlib) happen inside the commands, so that
``coinflight --help`` answers at once.
"""

from __future__ import annotations

from coinflight.cli.app import app, main

__all__ = ["app", "main"]
