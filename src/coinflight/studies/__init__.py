"""Questions asked of the model, each a module: the same-side bias (``bias``), real flips
(``data``), thick coins and edges (``edge``) and toss presets (``presets``).

Studies use the model, the outcome models and the estimators; plotting, reports and the command
line use the studies.
"""
