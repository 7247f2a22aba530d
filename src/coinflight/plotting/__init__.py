"""Figures. Imports matplotlib, so it is imported only when a figure is asked for.

Every public function returns a ``matplotlib.figure.Figure`` (for notebooks); the CLI saves it
with :func:`coinflight.plotting.style.save_figure`.
"""
