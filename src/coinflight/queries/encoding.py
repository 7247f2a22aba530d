"""The one JSON text of an answer: what ``--json`` prints and what the web application sends."""

from __future__ import annotations

import json
from typing import Any

from coinflight._provenance import provenance


def json_text(payload: dict[str, Any] | list[Any]) -> str:
    """``payload`` as one line of JSON: NumPy scalars and arrays become numbers and lists; a
    NaN or an infinity is an error (the text is whole and valid JSON, or not made).

    Each object (``payload``, or each object of a list) ends with where it came from
    (:func:`coinflight._provenance.provenance`): ``coinflight_version``, and ``command``, the
    command line (``coinflight toss --omega 80 0 0 --json``) or the web request
    (``GET /api/toss?omega=80,0,0``) that asked.
    """
    return json.dumps(_with_provenance(payload), default=_jsonable, allow_nan=False)


def _with_provenance(payload: dict[str, Any] | list[Any]) -> dict[str, Any] | list[Any]:
    made = provenance()
    if isinstance(payload, dict):
        return {**payload, **made}
    return [{**item, **made} if isinstance(item, dict) else item for item in payload]


def _jsonable(obj: Any) -> Any:
    import numpy as np

    if isinstance(obj, np.ndarray):
        return obj.tolist()
    if isinstance(obj, np.generic):
        return obj.item()
    raise TypeError(f"cannot write {type(obj).__name__} as JSON")


__all__ = ["json_text"]
