"""How the contact ending's edges depend on its numerical parameters, from fixed hand-off states.

    python benchmarks/bench_edge_sensitivity.py [N] [--seed S] [--slip-factor F]
        [--contact-time T] [--damping-factor D] [--friction MU] [--resistance L] [--stride K]

The N vigorous tosses of ``bench_mujoco_edges.py --handoff-only`` (seed 2026, a US nickel, e 0.5,
μ 0.3, rolling and pivoting resistance 1e-4 m) are landed with the contact ending; the states in
which the bounces hand them to :mod:`coinflight.core.contact_phase` are then carried to rest
again by that phase alone with one parameter changed: ``SLIP_SPEED`` times F (the
regularisation of Coulomb's friction; F → 0 is the Coulomb limit), the contact time t_c, the
damping ratio ζ times D, μ, the resistances. Prints P(edge) among the handed tosses.
SLIP_SPEED is a constant compiled into the numba kernels: a factor other than 1 compiles them
afresh into a temporary cache, removed at the end (the package's own cache is not touched).
"""

from __future__ import annotations

import argparse
import atexit
import os
import shutil
import tempfile
import time


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("n", type=int, nargs="?", default=600)
    parser.add_argument("--seed", type=int, default=2026)
    parser.add_argument("--slip-factor", type=float, default=1.0)
    parser.add_argument("--contact-time", type=float, default=1e-3)
    parser.add_argument("--damping-factor", type=float, default=1.0)
    parser.add_argument("--friction", type=float, default=0.3, help="μ of the contact phase")
    parser.add_argument("--resistance", type=float, default=1e-4, help="ℓ_r = ℓ_p, m")
    parser.add_argument("--stride", type=int, default=1, help="every K-th handed toss")
    args = parser.parse_args()
    if args.slip_factor != 1.0:
        cache = tempfile.mkdtemp(prefix="coinflight-slip-")
        atexit.register(shutil.rmtree, cache, True)
        os.environ["NUMBA_CACHE_DIR"] = cache
    import numpy as np

    from coinflight.core import contact_phase as cp

    cp.SLIP_SPEED *= args.slip_factor  # before any kernel is compiled
    import bench_contact
    from coinflight.core.outcome import EDGE, HEADS, Status
    from coinflight.outcomes.table import land
    from coinflight.studies import landing as study

    e, mu = 0.5, 0.3
    dist, omega, v0 = study.edge_draw(args.n, args.seed)
    surface = study.edge_surface(e, mu)
    out = land(dist.coin, omega, v0, 1.0, dist.g, surface)
    handed = out.status != Status.SETTLED_ENERGY
    c = bench_contact.contact(e, mu)
    states = []
    for k in np.flatnonzero(handed):
        y, h = bench_contact.handoff(tuple(omega[k]), 1.0, v0[k], c)
        if h:
            states.append(y.copy())
    zeta = cp.damping_of(c) * args.damping_factor
    c = c._replace(
        friction=args.friction,
        rolling_resistance=args.resistance,
        pivoting_resistance=args.resistance,
        contact_time=args.contact_time,
        damping_ratio=zeta,
        damping_restitution=c.restitution,
    )
    t0 = time.perf_counter()
    faces, unsettled = [], 0
    for y in states[:: args.stride]:
        face, status, _ = cp.settle(y[0], tuple(y[1:4]), tuple(y[4:7]), tuple(y[7:10]), c)
        faces.append(face)
        unsettled += int(status != Status.SETTLED_CONTACT)
    f = np.array(faces)
    k = len(f)
    p = float(np.mean(f == EDGE))
    print(
        f"{args.n} tosses (seed {args.seed}), {len(states)} handed, {k} carried: SLIP_SPEED "
        f"{cp.SLIP_SPEED:g} m/s, t_c {args.contact_time:g} s, ζ {zeta:.4g}, μ {args.friction:g}, "
        f"resistances {args.resistance:g} m: edges {np.count_nonzero(f == EDGE)}/{k} = {p:.3f} "
        f"± {np.sqrt(p * (1 - p) / k):.3f}, heads {np.mean(f == HEADS):.3f}, unsettled "
        f"{unsettled} (counted by their well); {time.perf_counter() - t0:.0f} s, load "
        f"{os.getloadavg()[0]:.1f}"
    )


if __name__ == "__main__":
    main()
