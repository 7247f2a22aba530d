# Everything a fresh machine with Python 3.11 and pip needs: `make demo`, `make test`.
PYTHON ?= python3
VENV := .venv
BIN := $(VENV)/bin
STAMP := $(VENV)/.installed
DOCS_STAMP := $(VENV)/.installed-docs

.PHONY: demo test lint docs bench clean chromium

$(STAMP): pyproject.toml
	$(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip
	$(BIN)/python -m pip install --quiet -e ".[dev]"
	touch $(STAMP)

$(DOCS_STAMP): $(STAMP)
	$(BIN)/python -m pip install --quiet -e ".[dev,docs]"
	touch $(DOCS_STAMP)

# The second toss lands on a table: its kernels compile once here (about 20 s of computing, it
# says so) and are cached, so a user's first table landing answers in seconds.
demo: $(STAMP)
	$(BIN)/coinflight toss --omega 80 0 0 --flight-time 0.7
	$(BIN)/coinflight toss --omega 80 0 0 --flight-time 0.7 --surface table --drop-height 0.8

lint: $(STAMP)
	$(BIN)/ruff check .
	$(BIN)/ruff format --check .
	$(BIN)/mypy
	$(BIN)/lint-imports

# The site, offline, warnings as errors, every tutorial and gallery script executed.
docs: $(DOCS_STAMP)
	MPLBACKEND=Agg $(BIN)/sphinx-build -W --keep-going -b html docs docs/_build/html
	@echo "open docs/_build/html/index.html"

# The browser tests (tests/test_web_browser.py) drive Debian's Chromium through Playwright; they
# never use Playwright's own browser download (`playwright install` needs the internet). Install
# the system package when it is missing: as root, or through sudo. Where it cannot be installed
# the tests skip on a workstation and fail under CI=true.
CHROMIUM ?= /usr/bin/chromium
SUDO := $(shell [ "$$(id -u)" = 0 ] || echo sudo)

chromium:
	@if [ -x "$(CHROMIUM)" ]; then \
		echo "chromium: $(CHROMIUM)"; \
	elif ! command -v apt-get >/dev/null; then \
		echo "chromium: $(CHROMIUM) missing and no apt-get here; the browser tests cannot run"; \
	else \
		apt-cache policy chromium 2>/dev/null | grep -q 'Candidate: [0-9]' \
			|| $(SUDO) apt-get update -q || true; \
		$(SUDO) env DEBIAN_FRONTEND=noninteractive apt-get install -y -q chromium \
			|| echo "chromium: could not install Debian's chromium; the browser tests cannot run"; \
	fi

# CI runs `make test` only: it builds the documentation too.
test: lint docs chromium
	$(BIN)/python -m pytest

bench: $(STAMP)
	$(BIN)/python -m benchmarks

clean:
	rm -rf $(VENV) build dist docs/_build docs/api/generated docs/auto_tutorials docs/auto_gallery docs/cli.md docs/sg_execution_times.rst src/*.egg-info .pytest_cache .mypy_cache .ruff_cache .hypothesis
