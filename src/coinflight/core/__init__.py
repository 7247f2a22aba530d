"""Pure numerical kernels of coinflight.

Everything here works on floats and NumPy arrays in SI units (m, s, kg, rad), broadcasts over
leading dimensions, and does no I/O, plotting or validation of user input: that happens in the
value objects above (:mod:`coinflight.model.coin`, :mod:`coinflight.model.toss`).
"""
