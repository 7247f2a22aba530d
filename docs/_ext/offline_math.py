"""Sphinx extension: the equations typeset by the MathJax that ships with the docs.

``sphinx.ext.mathjax`` loads MathJax from a CDN by default; a reader without the network then
sees raw TeX. This extension serves the vendored copy (``docs/_static/mathjax``, see its
``VENDORED.md``) from the site's own ``_static/mathjax/``.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

STATIC = Path(__file__).resolve().parents[1] / "_static"
"""The folder whose ``mathjax/`` is copied into the site's ``_static/``."""
SCRIPT = "mathjax/tex-chtml-full.js"
"""MathJax's combined TeX-to-HTML script, relative to :data:`STATIC`."""


def _offline(_app: Any, config: Any) -> None:
    config.mathjax_path = SCRIPT
    if str(STATIC) not in map(str, config.html_static_path):
        config.html_static_path = [*config.html_static_path, str(STATIC)]


def setup(app: Any) -> dict[str, Any]:
    app.setup_extension("sphinx.ext.mathjax")
    app.connect("config-inited", _offline)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
