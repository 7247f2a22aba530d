"""Reports: the founding paper reproduced (figures, report.md, report.html)."""
