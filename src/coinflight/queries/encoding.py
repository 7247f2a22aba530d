"""The one JSON text of an answer: what ``--json`` prints and what the web application sends."""

from __future__ import annotations

import json
from typing import Any


def json_text(payload: dict[str, Any] | list[Any]) -> str:
    """``payload`` as one line of JSON: NumPy scalars and arrays become numbers and lists; a
    NaN or an infinity is an error (the text is whole and valid JSON, or not made)."""
    return json.dumps(payload, default=_jsonable, allow_nan=False)


def _jsonable(obj: Any) -> Any:
    import numpy as np

    if isinstance(obj, np.ndarray):
        return obj.tolist()
    if isinstance(obj, np.generic):
        return obj.item()
    raise TypeError(f"cannot write {type(obj).__name__} as JSON")


__all__ = ["json_text"]
