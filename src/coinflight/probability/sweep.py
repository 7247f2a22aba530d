"""A sweep: P(heads) for each of several distributions of tosses in one call.

>>> from coinflight.model.distributions import Uniform
>>> from coinflight.model.ensemble import TossDistribution
>>> fig2a = TossDistribution(omega_x=Uniform(60, 90), flight_time=Uniform(0.6, 0.9))
>>> fig3a = TossDistribution(omega_x=Uniform(60, 90), omega_y=10, flight_time=Uniform(0.6, 0.9))
>>> results = estimate_many([fig2a, fig3a], "exact")  # Stefan & Cheche Figs 2a and 3a
>>> [round(r.p_heads, 5) for r in results]
[0.49747, 0.49721]
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import TYPE_CHECKING, Any

from coinflight.model.ensemble import PARAMETERS, UNITS, TossDistribution
from coinflight.probability.result import ProbabilityResult, require_pandas

if TYPE_CHECKING:
    import pandas as pd


class ProbabilityResults(list[ProbabilityResult]):
    """The results of :func:`estimate_many`, in the order of its distributions.

    A list of :class:`~coinflight.probability.result.ProbabilityResult` that also keeps the
    distributions (:attr:`distributions`) and turns into a table (:meth:`to_dicts`,
    :meth:`to_frame`).
    """

    def __init__(
        self, distributions: Iterable[TossDistribution], results: Iterable[ProbabilityResult]
    ) -> None:
        super().__init__(results)
        self.distributions: tuple[TossDistribution, ...] = tuple(distributions)
        if len(self.distributions) != len(self):
            raise ValueError(
                f"{len(self.distributions)} distributions for {len(self)} results; "
                "they must pair up"
            )

    def to_dicts(self) -> list[dict[str, Any]]:
        """One flat dictionary per result: the tosses (each parameter as text, e.g.
        ``"60–90 rad/s"``, ``launch_speed`` when given, coin, start face, g) then
        :meth:`ProbabilityResult.to_row`."""
        rows = []
        for dist, result in zip(self.distributions, self, strict=True):
            row: dict[str, Any] = {
                name: getattr(dist, name).describe(UNITS[name]) for name in PARAMETERS
            }
            speed = dist.launch_speed
            row["launch_speed"] = None if speed is None else speed.describe("m/s")
            row.update(coin=dist.coin.name, start=dist.start, g=dist.g)
            row.update(result.to_row())
            rows.append(row)
        return rows

    def to_frame(self) -> pd.DataFrame:
        """A pandas DataFrame of :meth:`to_dicts`, one row per distribution (needs
        ``pip install pandas``)."""
        return require_pandas().DataFrame(self.to_dicts())


def estimate_many(
    dists: Iterable[TossDistribution], method: str = "exact", **kwargs: Any
) -> ProbabilityResults:
    """P(heads) for each distribution of ``dists`` by ``method``: one result each.

    Parameters
    ----------
    dists : iterable of TossDistribution
        The distributions to compare, e.g. one per coin or per spin range.
    method : str
        A registered method (:func:`coinflight.probability.registry.names`).
    **kwargs
        Passed to :func:`~coinflight.probability.estimate` for every distribution (``n``,
        ``seed``, ``model``, ``threads``, …). One ``seed`` serves every distribution: the
        random methods then draw the same points of the unit cube for each (common random
        numbers), so differences between the distributions are not blurred by independent
        sampling noise.

    Returns
    -------
    ProbabilityResults
        A list of results in the order of ``dists``; ``.to_frame()`` gives a DataFrame.

    Raises
    ------
    TypeError
        Before any work, naming the position of an entry that is not a TossDistribution.
    """
    from coinflight.probability import estimate

    if isinstance(dists, TossDistribution):
        raise TypeError("dists must be a list of TossDistribution; for one, use estimate()")
    items = list(dists)
    for i, dist in enumerate(items):
        if not isinstance(dist, TossDistribution):
            raise TypeError(f"dists[{i}] must be a TossDistribution, got {dist!r}")
    return ProbabilityResults(items, [estimate(dist, method, **kwargs) for dist in items])


__all__ = ["ProbabilityResults", "estimate_many"]
