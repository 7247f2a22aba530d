"""Data shipped with coinflight, with provenance and citation (see ``README.md`` beside it).

The registry :data:`DATASETS` names each dataset; :func:`coinflight.studies.data.load_dataset`
reads one into a :class:`coinflight.studies.data.CountsTable`, and
``coinflight data --dataset NAME`` analyses it.

bartos2023
    Per-person same-side counts of Bartoš et al., "Fair coins tend to land on the same side they
    started: Evidence from 350,757 flips" (arXiv:2310.04153; JASA 2025,
    doi:10.1080/01621459.2025.2516210): 48 people, 350,757 flips, 178,078 on the side they
    started. The table as distributed with the ``metadat`` R package (``dat.bartos2023``),
    copied unchanged.

thick_coin_edges
    Published edge landings of thick coins (cylinders), one record per reported point, each
    with its source, setting and how it was read: :func:`edge_experiments` (in
    :mod:`coinflight.datasets.edges`) returns them as frozen :class:`EdgeExperiment` records.
    Not a :data:`DATASETS` entry: it is not a table of same-side counts.
"""

from __future__ import annotations

from dataclasses import dataclass
from importlib.resources import files

from coinflight.datasets.edges import EDGE_SOURCES, EdgeExperiment, edge_experiments


@dataclass(frozen=True)
class Dataset:
    """A named dataset shipped as package data.

    Attributes
    ----------
    name : str
        The name ``--dataset`` and :func:`coinflight.studies.data.load_dataset` take.
    filename : str
        The file inside this package.
    title : str
        One line saying what it is.
    short : str
        The citation in a few words, for a line of output ("Bartoš et al. 2023").
    citation : str
        The publication to cite.
    doi : str
        The publication's DOI.
    provenance : str
        Where this copy of the numbers comes from.
    """

    name: str
    filename: str
    title: str
    short: str
    citation: str
    doi: str
    provenance: str

    def read_text(self) -> str:
        """The file's text (UTF-8), read from the installed package."""
        return files(__name__).joinpath(self.filename).read_text(encoding="utf-8")


DATASETS: dict[str, Dataset] = {
    "bartos2023": Dataset(
        name="bartos2023",
        filename="bartos2023.txt",
        title="350,757 coin flips by 48 people, per person, by starting and landing face",
        short="Bartoš et al. 2023",
        citation=(
            "Bartoš, F. et al. (2025). Fair coins tend to land on the same side they started: "
            "Evidence from 350,757 flips. Journal of the American Statistical Association. "
            "arXiv:2310.04153"
        ),
        doi="10.1080/01621459.2025.2516210",
        provenance="the table of the metadat R package (dat.bartos2023), copied unchanged",
    ),
}
"""The datasets shipped with coinflight, by name."""

DEFAULT_DATASET = "bartos2023"
"""The dataset ``coinflight data`` analyses when given neither ``--dataset`` nor ``--counts``."""

__all__ = [
    "DATASETS",
    "DEFAULT_DATASET",
    "EDGE_SOURCES",
    "Dataset",
    "EdgeExperiment",
    "edge_experiments",
]
