"""Reports: the founding paper reproduced (figures, report.md, report.html).

>>> from coinflight.report import reproduce_paper
>>> report = reproduce_paper("paper/")  # doctest: +SKIP
"""

from coinflight.report.paper import PaperNumbers, paper_numbers
from coinflight.report.reproduce import PaperReport, reproduce_paper

__all__ = ["PaperNumbers", "PaperReport", "paper_numbers", "reproduce_paper"]
