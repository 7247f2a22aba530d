"""The docs render with no network: the equations typeset by the MathJax shipped with them
(docs/_static/mathjax, wired in by docs/_ext/offline_math.py), and no script, style or font of
a built page loaded from another host.

A small site is built with the docs' theme and math extension and the real ``physics.rst`` (the
full build, gallery and API reference, takes minutes: ``make docs``; ``make test`` builds it
before the tests, and every page of it is then read too). Its HTML and CSS are read
for outside addresses; Debian's Chromium, driven by Playwright (``tests/_chromium.py``),
opens the page with every request to another host refused and checks that MathJax typeset the
equations. The screenshot of the rendered equations is the run's artefact, in the test's own
temporary folder ``docs-math0/`` (``pytest --basetemp=test-artefacts`` keeps it).
"""

from __future__ import annotations

import re
import shutil
import subprocess
import sys
from html.parser import HTMLParser
from pathlib import Path
from urllib.parse import urlparse

import pytest

from _chromium import IN_CI, browser_or_skip, chromium
from _images import assert_nontrivial

DOCS = Path(__file__).resolve().parents[1] / "docs"
CONF = f"""
import sys
sys.path.insert(0, {str(DOCS / "_ext")!r})
project = "coinflight"
extensions = ["offline_math"]
html_theme = "pydata_sphinx_theme"
html_theme_options = {{"navigation_with_keys": False}}
"""


@pytest.fixture(scope="module")
def site(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The small site, built: its output folder."""
    pytest.importorskip("sphinx")
    pytest.importorskip("pydata_sphinx_theme")
    src = tmp_path_factory.mktemp("docs-src")
    (src / "conf.py").write_text(CONF, encoding="utf-8")
    (src / "index.rst").write_text(
        "coinflight\n==========\n\n.. toctree::\n\n   physics\n", encoding="utf-8"
    )
    shutil.copy(DOCS / "physics.rst", src / "physics.rst")
    out = tmp_path_factory.mktemp("docs-html")
    build = subprocess.run(
        [sys.executable, "-m", "sphinx", "-b", "html", "-q", str(src), str(out)],
        capture_output=True,
        text=True,
        timeout=600,
    )
    assert build.returncode == 0, build.stderr
    return out


class _Loads(HTMLParser):
    """The addresses a page loads: scripts, stylesheets, fonts and other preloads, images."""

    def __init__(self) -> None:
        super().__init__()
        self.urls: list[str] = []

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        a = dict(attrs)
        if tag in ("script", "img", "iframe") and a.get("src"):
            self.urls.append(a["src"] or "")
        if tag == "link" and a.get("href") and a.get("rel") not in ("canonical",):
            rel = a.get("rel") or ""
            if any(r in rel for r in ("stylesheet", "preload", "icon", "modulepreload")):
                self.urls.append(a["href"] or "")


def _outside(url: str) -> bool:
    parsed = urlparse(url)
    return bool(parsed.scheme in ("http", "https") or parsed.netloc or url.startswith("//"))


def test_the_built_page_loads_nothing_from_another_host(site: Path) -> None:
    loads = _Loads()
    loads.feed((site / "physics.html").read_text(encoding="utf-8"))
    assert any("_static/mathjax/tex-chtml-full.js" in u for u in loads.urls), loads.urls
    # no page of the small site, nor a style it loads, asks another host for anything
    assert _outside_loads(site) == {}


def _outside_loads(site: Path) -> dict[str, list[str]]:
    """Every page's and style sheet's addresses of another host, by file."""
    found: dict[str, list[str]] = {}
    for page in site.rglob("*.html"):
        loads = _Loads()
        loads.feed(page.read_text(encoding="utf-8", errors="replace"))
        if outside := [u for u in loads.urls if _outside(u)]:
            found[str(page.relative_to(site))] = outside
    for css in site.rglob("*.css"):
        text = css.read_text(encoding="utf-8", errors="replace")
        if urls := re.findall(r"(?:url\(|@import\s+)['\"]?((?:https?:)?//[^'\")\s]+)", text):
            found[str(css.relative_to(site))] = urls
    return found


def test_the_full_site_loads_nothing_from_another_host() -> None:
    """The full build (``make docs``, which ``make test`` runs first): no page, gallery and
    API reference included, loads a script, style or font of another host."""
    site = DOCS / "_build" / "html"
    if not (site / "index.html").is_file():
        if IN_CI:
            pytest.fail("the documentation was not built before the tests: make docs")
        pytest.skip("the documentation is not built here: make docs")
    assert len(list(site.rglob("*.html"))) > 50  # the whole site, not a stub
    assert _outside_loads(site) == {}


def test_mathjax_ships_with_its_fonts_and_licence(site: Path) -> None:
    mathjax = site / "_static" / "mathjax"
    assert (mathjax / "tex-chtml-full.js").stat().st_size > 1_000_000
    assert (mathjax / "LICENSE").read_text(encoding="utf-8").lstrip().startswith("Apache")
    fonts = sorted(p.name for p in (mathjax / "output/chtml/fonts/woff-v2").glob("*.woff"))
    assert "MathJax_Main-Regular.woff" in fonts and len(fonts) == 23


def test_the_equations_render_with_no_network(
    site: Path, tmp_path_factory: pytest.TempPathFactory
) -> None:
    """Chromium, every request to another host refused: MathJax typesets every equation of
    physics.html (no raw ``\\frac`` left on the page) and nothing was asked of another host."""
    browser_or_skip()
    shots = tmp_path_factory.mktemp("docs-math")
    refused: list[str] = []
    problems: list[str] = []
    with chromium(viewport={"width": 1200, "height": 900}) as context:

        def route(r):  # type: ignore[no-untyped-def]
            if r.request.url.startswith("file://"):
                return r.continue_()
            refused.append(r.request.url)
            return r.abort()

        context.route("**/*", route)
        page = context.new_page()
        page.on("pageerror", lambda e: problems.append(f"uncaught: {e}"))
        page.goto((site / "physics.html").as_uri())
        page.wait_for_function("() => window.MathJax && MathJax.startup && MathJax.startup.promise")
        page.evaluate("() => MathJax.startup.promise")
        count = page.locator("mjx-container").count()
        errors = page.locator("mjx-merror").all_inner_texts()  # TeX MathJax refused
        display = page.locator("mjx-container[display=true]").first
        display.scroll_into_view_if_needed()
        shot = shots / "physics-equation.png"
        display.screenshot(path=str(shot))
        page.screenshot(path=str(shots / "physics-page.png"))
        text = page.locator("article").inner_text()
    assert refused == [] and problems == []
    assert errors == []
    assert count >= 20  # physics.rst's display and inline equations, each typeset
    assert "\\frac" not in text and "\\left(" not in text  # no raw TeX left
    assert_nontrivial(shot, min_side=20)  # an equation: a line of text, ink on white
