"""Sphinx configuration of the coinflight documentation.

The build is offline, and so are its pages: no intersphinx, no remote images; the equations
are typeset in the reader's browser by the MathJax vendored in ``_static/mathjax``
(``_ext/offline_math.py``), nothing loaded from another host. Every tutorial and gallery
script is executed at build time (sphinx-gallery), so a figure on a page is the figure the code
beside it makes today.
"""

from __future__ import annotations

import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE / "_ext"))

from coinflight_cli import write_cli_page  # noqa: E402
from figure_scraper import ReturnedFigures  # noqa: E402

import coinflight  # noqa: E402

write_cli_page(HERE / "cli.md")

project = "coinflight"
author = "coinflight developers"
copyright = "coinflight developers, MIT licence"
version = release = coinflight.__version__

extensions = [
    "sphinx.ext.autodoc",
    "sphinx.ext.autosummary",
    "offline_math",  # sphinx.ext.mathjax with the vendored MathJax
    "sphinx.ext.viewcode",
    "numpydoc",
    "myst_parser",
    "plain_docstrings",
    "sphinx_gallery.gen_gallery",
]

source_suffix = {".rst": "restructuredtext", ".md": "markdown"}
exclude_patterns = [
    "_build",
    "_static",  # vendored files (MathJax and its VENDORED.md), copied as they are
    "**.ipynb_checkpoints",
    "tutorials/README.rst",
    "gallery/README.rst",
]
templates_path: list[str] = []
nitpicky = False

# -- API reference ------------------------------------------------------------------------
autosummary_generate = True
autosummary_imported_members = False
autodoc_default_options = {"members": True}
autodoc_typehints = "none"  # numpydoc's Parameters sections carry the types and units
numpydoc_show_class_members = False
numpydoc_class_members_toctree = False
numpydoc_validation_checks: set[str] = set()

# -- Gallery: every script executed at build time ----------------------------------------
sphinx_gallery_conf = {
    "examples_dirs": ["tutorials", "gallery"],
    "gallery_dirs": ["auto_tutorials", "auto_gallery"],
    "filename_pattern": r".*\.py$",  # execute every script, not only plot_*.py
    "ignore_pattern": r"__init__\.py",
    "within_subsection_order": "FileNameSortKey",
    "download_all_examples": False,
    "remove_config_comments": True,
    "matplotlib_animations": False,
    # the Figure objects coinflight's functions return, then pyplot's (in this order)
    "image_scrapers": (ReturnedFigures(), "matplotlib"),
    "abort_on_example_error": True,
    "only_warn_on_example_error": False,
    "show_memory": False,
    "plot_gallery": "True",
    # its computation-times pages load jQuery and DataTables from CDNs: not written, so that
    # no page of the site asks another host for anything
    "write_computation_times": False,
}

# -- HTML ----------------------------------------------------------------------------------
html_theme = "pydata_sphinx_theme"
html_title = f"coinflight {release}"
html_theme_options = {
    "navigation_with_keys": False,
    "show_toc_level": 2,
    "secondary_sidebar_items": ["page-toc"],
    "footer_start": ["copyright"],
    "footer_end": ["sphinx-version"],
}
html_show_sourcelink = False
html_context = {"default_mode": "light"}
