"""The docs' docstring hook (docs/_ext/plain_docstrings.py): plain-text maths survives RST.

coinflight's docstrings write |M| for a norm, v*T for a product and (a, *rest) for Python's
star; the API reference must show them as written, while real *emphasis*, literals, bullets,
tables and doctests are left alone.
"""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "docs" / "_ext"))
docutils_core = pytest.importorskip("docutils.core")
plain_docstrings = pytest.importorskip("plain_docstrings")


def _escaped(*lines: str) -> list[str]:
    out = list(lines)
    plain_docstrings.escape(out)
    return out


@pytest.mark.parametrize(
    ("line", "expected"),
    [
        ("ωp = |M| / I1", r"ωp = \|M\| / I1"),
        ("the speed v*T and 2*pi", r"the speed v\*T and 2\*pi"),
        ("(tails, heads, edge, *tallies)", r"(tails, heads, edge, \*tallies)"),
        ("see *Impact Mechanics*, ch. 2", "see *Impact Mechanics*, ch. 2"),
        ("``|x|`` and :math:`|x|`", "``|x|`` and :math:`|x|`"),
        ("* a bullet with |v|", r"* a bullet with \|v\|"),
    ],
)
def test_escape_one_line(line: str, expected: str) -> None:
    assert _escaped(line) == [expected]


def test_emphasis_across_two_lines_is_kept() -> None:
    lines = ["Catto, *Iterative", "dynamics with temporal coherence*, GDC 2005"]
    assert _escaped(*lines) == lines


def test_doctests_code_blocks_and_table_rules_are_untouched() -> None:
    lines = [">>> abs(-2)*3 | 1", "Example::", "", "    a*b |c|", "", "=====  =====", "x"]
    assert _escaped(*lines) == lines


def test_escaped_docstring_renders_without_warnings() -> None:
    text = "\n".join(
        _escaped(
            "The norm |M| of M, the product v*T and the star in (a, *rest).",
            "",
            "* |L| is fixed; see *Fluid-Dynamic Drag*, 1965.",
        )
    )
    html = docutils_core.publish_string(
        text, writer="html", settings_overrides={"report_level": 2, "halt_level": 2}
    ).decode()
    assert "|M|" in html and "v*T" in html and "*rest" in html
    assert "<em>Fluid-Dynamic Drag</em>" in html
