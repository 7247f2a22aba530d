"""How a toss ends: outcome models that turn initial conditions into faces.

``base`` holds the one protocol every estimator and map asks (:class:`OutcomeModel`) and the
hand catch of the founding paper; ``table`` the landings on a table (bounces, edge) and the catch
through air. Kernels live in :mod:`coinflight.core`; estimators in :mod:`coinflight.probability`.
"""
