"""The estimators of P(heads), each declared once.

An :class:`Estimator` says what a method is: its name, the function that runs it, its default
size, whether it takes a seed and which options, a label and description for help texts and
legends, its work bound and its convergence series. :func:`coinflight.probability.estimate`
dispatches through :func:`get`; ``convergence`` and the command line's method choices and help
read the same entries. How a method looks is decided where it is shown: its colour and marker
in :func:`coinflight.plotting.style.method_style`, the one line saying how a run was made in
:meth:`coinflight.probability.result.ProbabilityResult.describe_run`.

Adding an estimator (two files): write its module, ending with
``ESTIMATOR = Estimator(name=..., run=estimate, ...)``, and add the module's name to
:data:`BUILTIN`. Code outside the package may instead call :func:`register` with an
:class:`Estimator` at run time (tests/test_walkthrough_estimator.py does).
"""

from __future__ import annotations

import importlib
from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from coinflight import _validation as v

if TYPE_CHECKING:
    from coinflight.model.ensemble import TossDistribution
    from coinflight.outcomes.base import OutcomeModel
    from coinflight.probability.result import ProbabilityResult

BUILTIN = (
    "coinflight.probability.exact",
    "coinflight.probability.grid",
    "coinflight.probability.monte_carlo",
    "coinflight.probability.qmc",
)
"""Modules whose ``ESTIMATOR`` is registered on first use, in this order."""

RUNNER_OPTIONS = ("executor", "threads", "progress")

VARIANCE_REDUCTIONS = {
    "conditional-on-spin": (
        "draw the spins only and take P(same side | spins) in closed form over the flight time "
        "(conditional Monte Carlo; hand catch only)"
    ),
}
"""The variance reductions an estimator may declare in ``modes`` (its ``variance_reduction``
option), each with one sentence for help texts. Results report the one used in
``details["variance_reduction"]``."""


def _tosses(k: int, n: int) -> int:
    return n


@dataclass(frozen=True)
class Estimator:
    """One method of estimating P(heads).

    Attributes
    ----------
    name : str
        What users type (``estimate(dist, name)``, ``--method name``).
    run : callable
        ``run(dist, [n], *, model, [seed], [executor, threads, progress], **options)``: n when
        ``default_n`` is given, seed when ``seeded``, the runner arguments when ``parallel``.
    label, description : str
        A few words (legends) and one sentence (help texts).
    default_n : callable or None
        The default size as a function of the number k of ranged parameters; None: no size.
    size : str
        What n counts, for help texts ("tosses").
    seeded : bool
        Whether it draws random numbers (takes ``seed``, reports it).
    options : tuple of str
        Extra keyword options it accepts.
    parallel : bool
        Whether it takes ``executor``, ``threads`` and ``progress``.
    work : callable or None
        ``work(dist, n, model)``: seconds of work at size n, a ValueError beyond what a single
        run accepts; None when the method bounds its own work inside ``run``.
    work_units : callable
        ``work_units(k, n)``: the amount ``progress`` reports over a run of size n.
    series : tuple of int
        Default sizes of a :func:`~coinflight.probability.convergence.convergence` series;
        empty: the method has no series (exact).
    sizes_keyword : str
        The keyword of its convergence sizes when not ``NAME_sizes``.
    modes : tuple of str
        The variance reductions (keys of :data:`VARIANCE_REDUCTIONS`) its
        ``variance_reduction`` option takes.
    """

    name: str
    run: Callable[..., ProbabilityResult]
    label: str
    description: str
    default_n: Callable[[int], int] | None = None
    size: str = ""
    seeded: bool = False
    options: tuple[str, ...] = ()
    parallel: bool = True
    work: Callable[[TossDistribution, int, OutcomeModel], float] | None = None
    work_units: Callable[[int, int], int] = _tosses
    series: tuple[int, ...] = ()
    sizes_keyword: str = ""
    modes: tuple[str, ...] = ()

    @property
    def series_option(self) -> str:
        """The keyword of :func:`~coinflight.probability.convergence.convergence` for its
        sizes: ``sizes_keyword`` if given (monte-carlo: ``event_sizes``, the paper's
        "events"), else ``NAME_sizes``."""
        return self.sizes_keyword or f"{self.name.replace('-', '_')}_sizes"

    def size_for(self, k: int, n: int | None) -> int | None:
        """``n``, or the default size for k ranged parameters (None for a method without n)."""
        if self.default_n is None:
            return None
        return self.default_n(k) if n is None else n

    def __call__(
        self,
        dist: TossDistribution,
        n: int | None = None,
        seed: Any = None,
        *,
        model: OutcomeModel,
        executor: Any = None,
        threads: int | None = None,
        progress: Any = None,
        **options: Any,
    ) -> ProbabilityResult:
        """Check the arguments against this declaration, then run."""
        from coinflight.probability._runner import check_count, check_runner

        if n is not None:
            check_count("n", n)
        if not self.seeded and seed is not None:
            raise TypeError(
                f"method {self.name!r} takes no seed (it is deterministic); got seed={seed}"
            )
        if self.default_n is None and n is not None:
            raise ValueError(f"the {self.name} method takes no n")
        runner = {"executor": executor, "threads": threads, "progress": progress}
        allowed = self.options + (RUNNER_OPTIONS if self.parallel else ())
        given = {**{k: x for k, x in runner.items() if x is not None}, **options}
        extra = [k for k in given if k not in allowed]
        if extra:
            raise TypeError(f"method {self.name!r} takes no option {', '.join(extra)}")
        mode = options.get("variance_reduction")
        if mode is not None and mode not in self.modes:
            allowed_modes = ", ".join(self.modes) or "none"
            raise ValueError(
                f"method {self.name!r} has no variance reduction {mode!r}; it takes: "
                f"{allowed_modes}"
            )
        kwargs: dict[str, Any] = {"model": model, **options}
        if self.parallel:
            check_runner(executor, threads, progress)
            kwargs.update(runner)
        if self.seeded:
            kwargs["seed"] = seed
        from coinflight.outcomes.base import check_contact

        check_contact(dist, model)
        size = self.size_for(len(dist.ranged), n)
        return self.run(dist, **kwargs) if size is None else self.run(dist, size, **kwargs)


_REGISTRY: dict[str, Estimator] = {}
_loaded = False


def register(estimator: Estimator) -> Estimator:
    """Add ``estimator``; ValueError if its name is taken (by a different estimator)."""
    v.instance("estimator", estimator, Estimator, "an Estimator")
    old = _REGISTRY.get(estimator.name)
    if old is not None and old is not estimator:
        raise ValueError(f"an estimator named {estimator.name!r} is already registered")
    _REGISTRY[estimator.name] = estimator
    return estimator


def unregister(name: str) -> None:
    """Remove the estimator ``name`` (for tests and plug-ins that replace one)."""
    _REGISTRY.pop(name, None)


def _load() -> None:
    global _loaded
    if not _loaded:
        _loaded = True
        for module in BUILTIN:
            register(importlib.import_module(module).ESTIMATOR)


def estimators() -> tuple[Estimator, ...]:
    """Every registered estimator, built-ins first."""
    _load()
    return tuple(_REGISTRY.values())


def names(*, seeded: bool | None = None, series: bool | None = None) -> tuple[str, ...]:
    """The registered names, optionally only those (not) ``seeded`` / with(out) a ``series``."""
    return tuple(
        e.name
        for e in estimators()
        if (seeded is None or e.seeded == seeded) and (series is None or bool(e.series) == series)
    )


def get(name: object, among: tuple[str, ...] | None = None, what: str = "") -> Estimator:
    """The estimator ``name``: TypeError if not a string, ValueError naming the choices if
    unknown (or not in ``among``; ``what`` says for what, e.g. " for convergence")."""
    choices = names() if among is None else among
    v.instance("method", name, str, f"a string, one of {', '.join(choices)}")
    if name not in choices:
        raise ValueError(f"unknown method {name!r}{what}; choose one of {', '.join(choices)}")
    return _REGISTRY[str(name)]


__all__ = [
    "BUILTIN",
    "VARIANCE_REDUCTIONS",
    "Estimator",
    "estimators",
    "get",
    "names",
    "register",
    "unregister",
]
