"""
Forest plot of 350,757 real flips
=================================

Each of Bartoš et al.'s 48 flippers' same-side rate with its 95 % Clopper-Pearson interval,
the pooled rate as a diamond and Diaconis, Holmes & Montgomery's natural toss (0.508) as a
line. The counts ship with coinflight. (``coinflight data --plot forest.png``)
"""

from coinflight import plot_forest
from coinflight.studies.data import load_dataset, summarize

fig = plot_forest(summarize(load_dataset("bartos2023")), p_model=0.508)
