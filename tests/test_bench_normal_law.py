"""benchmarks/normal_law.py, the benchmark-only knob on the contact phase's rim law: the patched
kernel reaches the derivative (not only ``rim_contact``), its copy of ``contact_phase._rim``
keeps the default's geometry, and it refuses to patch kernels it cannot reach. Each check runs
in a subprocess whose numba cache and temporary files are in tmp_path (the package's own cache
is never written with a patched kernel)."""

from __future__ import annotations

import math
import os
import subprocess
import sys
import textwrap
from pathlib import Path

from _bench import BENCH

PRELUDE = """
import math, sys
import numpy as np
import normal_law
{fresh}
import bench_contact
from coinflight.core import contact_phase as cp
"""


def _run(code: str, tmp_path: Path, fresh: bool = True) -> str:
    env = dict(os.environ, TMPDIR=str(tmp_path))
    env["PYTHONPATH"] = os.pathsep.join([str(BENCH), env.get("PYTHONPATH", "")])
    env.pop("NUMBA_CACHE_DIR", None)
    run = subprocess.run(
        [
            sys.executable,
            "-c",
            PRELUDE.format(fresh="normal_law.fresh_cache()" if fresh else "")
            + textwrap.dedent(code),
        ],
        capture_output=True,
        text=True,
        timeout=600,
        cwd=tmp_path,
        env=env,
    )
    assert run.returncode == 0, run.stderr
    return run.stdout


UPRIGHT = """
normal_law.use_exponent({p})
c = bench_contact.contact(0.5, 0.3)
kappa = cp.stiffness_of(c)
d0 = 1e-6  # both rims' lowest points this deep, the coin at rest upright
y = np.array([c.radius - d0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0])
out = np.zeros(10)
cp._derivative(y, out, c, kappa, cp.damping_of(c))
force = c.mass * (out[3] + c.g)  # both rims' normal force
print(force, kappa, d0, c.radius)
"""


def test_the_linear_law_reaches_the_derivative_and_the_default_is_left(tmp_path):
    force, kappa, d0, radius = map(float, _run(UPRIGHT.format(p=1.0), tmp_path).split())
    # p = 1: an upright rim's K_1 = 2πκ (module notes), two rims touching.
    assert abs(force / (2 * 2 * math.pi * kappa * d0) - 1) < 1e-3
    force, kappa, d0, radius = map(float, _run(UPRIGHT.format(p=1.5), tmp_path).split())
    # p = 3/2, the default: F = (4√2/3) κ d0^(3/2) / sqrt(r) per rim (contact_phase's notes).
    hertz = 4 * math.sqrt(2) / 3 * kappa * d0**1.5 / math.sqrt(radius)
    assert abs(force / (2 * hertz) - 1) < 1e-3
    assert force < 0.1 * 2 * 2 * math.pi * kappa * d0  # the two laws differ at 1 μm


def test_the_copy_keeps_the_rims_geometry(tmp_path):
    # With p = 3/2 the copy's law is the default's times a constant C (β = 1, λ = C; C from the
    # module notes' K_p d0^p normalisation): the same centre of pressure and pivot radius, force
    # and energy C times, when its damping ratio is ζ sqrt(C). So a drift of the copy from
    # contact_phase._rim (its arc, its sums, its damper, its centre of pressure) fails here.
    out = _run(
        """
        c = bench_contact.contact(0.5, 0.3, corner=2e-4)
        kappa, zeta = cp.stiffness_of(c), cp.damping_of(c)
        r = c.radius - c.corner_radius
        big_c = 2 * math.pi * kappa / (2.5 * 8 * math.sqrt(2) * kappa / (15 * math.sqrt(r)))
        copy = normal_law.rim_law(1.5)
        rng = np.random.default_rng(7)
        pressed, worst = 0, 0.0
        for _ in range(400):
            n = rng.normal(size=3)
            n /= np.linalg.norm(n)
            s, w = cp._tangent_basis(tuple(n))
            lowest = r * math.sqrt(1 - n[2] ** 2) + c.half_thickness * abs(n[2])
            z = lowest * rng.uniform(0.9, 1.01)
            args = (float(rng.choice([-1.0, 1.0])), z, tuple(rng.normal(size=3) * 0.3), tuple(n),
                    tuple(rng.normal(size=3) * 50), s, w, c.radius, c.half_thickness, c.mass,
                    c.i1, c.i3, kappa)
            f0, q0, r0, e0 = cp._rim(*args, zeta, c.corner_radius)
            f1, q1, r1, e1 = copy(*args, zeta * math.sqrt(big_c), c.corner_radius)
            pressed += f0 > 0
            worst = max(worst, abs(f1 - big_c * f0) / max(big_c * f0, 1e-30) if f0 > 0 else f1,
                        abs(e1 - big_c * e0) / max(big_c * e0, 1e-30),
                        float(np.max(np.abs(np.subtract(q1, q0)))) / c.radius,
                        abs(r1 - r0) / c.radius)
        print(pressed, worst)
        """,
        tmp_path,
    )
    pressed, worst = out.split()
    assert int(pressed) > 100  # the draws press a rim most of the time (and not always)
    assert float(worst) < 1e-9


REFUSE = """
{setup}
try:
    normal_law.use_exponent(1.0)
except RuntimeError as refused:
    print(refused)
print(cp._rim.py_func.__module__)
"""


def test_the_knob_refuses_without_a_fresh_cache_or_after_a_compile(tmp_path):
    words = (
        "use_exponent needs fresh_cache() first, before any kernel of contact_phase is imported "
        "or compiled"
    )
    for setup, fresh in (
        ("", False),  # no fresh cache
        ("normal_law.fresh_cache()", False),  # contact_phase imported before it
        ("cp.static_depth(bench_contact.contact(0.5, 0.3), 1.0)", True),  # a kernel compiled
    ):
        out = _run(REFUSE.format(setup=setup), tmp_path, fresh).splitlines()
        assert out == [words, "coinflight.core.contact_phase"]  # refused, not patched
