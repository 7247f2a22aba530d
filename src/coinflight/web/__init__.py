"""The web application of ``coinflight serve``: the classroom page and a JSON API that mirrors
the command line.

:func:`create_app` makes the ASGI application (FastAPI): ``/`` is the page
(``coinflight/web/static/index.html``), ``/static/...`` its scripts and styles (package data:
nothing is fetched from the internet), ``/api/...`` the answers of the commands as the same JSON
objects their ``--json`` prints (one implementation, :mod:`coinflight.queries`), and
``/openapi.json`` the schema. FastAPI and uvicorn are imported here, never by
``import coinflight`` or ``coinflight --help``.
"""

from __future__ import annotations

from coinflight.web.app import create_app

__all__ = ["create_app"]
