"""Read coinflight's docstrings as they are written: plain text with Unicode maths.

The package's docstrings write |M| for a norm, v*T for a product and (a, b, *rest) for Python's
star, as a reader of the source expects; reStructuredText would take ``|M|`` for a substitution
and ``*`` for emphasis. This hook escapes those characters outside literal text, roles, tables,
directives and doctests before numpydoc and autodoc parse the docstring, so the API pages show
the same symbols as the source. Real *emphasis* (a pair of stars, possibly across two lines)
is kept.
"""

from __future__ import annotations

import re
from typing import Any

_LITERAL = re.compile(r"(``.*?``|`[^`]*`_?|:[a-z:]+:`[^`]*`)")
_TABLE_RULE = re.compile(r"^\s*(=+\s+)+=+\s*$|^\s*\+[-=+]+\+\s*$")
_SINGLE_STAR = re.compile(r"(?<![\\*])\*(?!\*)")


_BULLET = re.compile(r"^(\s*[*\-+] )")


def _outside(line: str) -> list[str]:
    """The line split into alternating plain text (even) and literals/roles (odd); a bullet
    (``* item``) counts as a literal, so its star stays a bullet."""
    bullet = _BULLET.match(line)
    if bullet is None:
        return _LITERAL.split(line)
    return ["", bullet.group(1), *_LITERAL.split(line[bullet.end() :])]


def _stars(line: str) -> int:
    return sum(len(_SINGLE_STAR.findall(p)) for p in _outside(line)[::2])


def _escape(line: str, unpaired_star: bool) -> str:
    parts = _outside(line)
    for i in range(0, len(parts), 2):
        parts[i] = re.sub(r"(?<!\\)\|", r"\\|", parts[i])
        # a * between operands (v*T, 2*pi) is multiplication, not emphasis
        parts[i] = re.sub(r"(?<=[\w)\]])\*(?=[\w(\[])", r"\\*", parts[i])
    if unpaired_star:  # Python's star (``*tallies``): escape the last single star
        for i in reversed(range(0, len(parts), 2)):
            found = list(_SINGLE_STAR.finditer(parts[i]))
            if found:
                k = found[-1].start()
                parts[i] = parts[i][:k] + "\\" + parts[i][k:]
                break
    return "".join(parts)


def escape(lines: list[str]) -> None:
    """Escape ``|`` and stray ``*`` in place, leaving code blocks and doctests alone."""
    plain = [False] * len(lines)
    in_block, block_indent = False, 0
    for i, line in enumerate(lines):
        stripped = line.lstrip()
        indent = len(line) - len(stripped)
        if in_block and (not stripped or indent > block_indent):
            continue
        in_block = False
        if stripped.startswith((">>>", "...", ".. ")) or _TABLE_RULE.match(line):
            in_block = stripped.startswith(".. ")
            block_indent = indent
            continue
        if line.rstrip().endswith("::"):
            in_block, block_indent = True, indent
        plain[i] = True
    for i, line in enumerate(lines):
        if not plain[i]:
            continue
        # multiplication stars are escaped first; the ones left pair up as emphasis, possibly
        # with a neighbouring line (emphasis wrapped across a line break)
        left = _stars(_escape(line, unpaired_star=False))
        odd = left % 2 == 1
        if odd:
            for j in (i - 1, i + 1):
                if 0 <= j < len(lines) and plain[j] and _stars(_escape(lines[j], False)) % 2:
                    odd = False
        lines[i] = _escape(line, unpaired_star=odd)


def process_docstring(
    app: Any, what: str, name: str, obj: Any, options: Any, lines: list[str]
) -> None:
    if name.startswith("coinflight"):
        escape(lines)


def skip_alias(app: Any, what: str, name: str, obj: Any, skip: bool, options: Any) -> bool | None:
    """Type aliases such as ``Counts = NDArray[np.int64]`` are not documentable objects; their
    meaning is in the docstrings of the functions that return them."""
    return True if type(obj).__name__ == "_GenericAlias" or name == "Counts" else None


def setup(app: Any) -> dict[str, Any]:
    app.connect("autodoc-skip-member", skip_alias)
    # before numpydoc (priority 500) reformats the sections: escape the text as written
    app.connect("autodoc-process-docstring", process_docstring, priority=100)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
