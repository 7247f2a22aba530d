"""The questions the command line and the web application ask, answered once.

Each module takes the options as typed (texts and numbers, named as the command line names
them), checks them in the order the command line does, calls the library and returns the
JSON-ready object that ``coinflight COMMAND --json`` prints and ``GET /api/COMMAND`` returns.
:mod:`coinflight.cli` formats the text output or prints the object; :mod:`coinflight.web`
returns it. Errors are the library's ``ValueError``/``TypeError`` with the command line's words.

Nothing here imports typer, rich or the web stack, and the heavy modules (SciPy, numba) load
inside the functions, so ``import coinflight.cli`` stays light.
"""
