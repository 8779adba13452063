# ctest-labels: smoke
"""C4 catenary (../shared/references section C) as an elastic cable analysis: span 10, length 12,
w = 1 per unstretched length, EA = 1e7, gravity ramped by the load steps, 2 ranks.

Start (ffscenes.catenary_scene): the nodes lie on a circular arc with equal chords (not the
solution), prestress N0 in every cable and chord length L = h / (1 - N0/EA), so the stress-free
length of every cable is exactly h = 12/n while the start is taut (a stress-free start has no
transverse stiffness: Newton cannot leave it). The reference is the exact equilibrium of the discrete
(elastic) chain with lumped loads w h, computed below, and the continuous catenary a = 4.695415,
sag 2.923438, T_max = 7.618853 (T_max = support reaction: its vertical part is exactly w S/2)."""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(__file__))
from sinewtest import run, h5, close, check, done, WORK  # noqa: E402
from ffscenes import catenary_scene, to_yaml  # noqa: E402

os.makedirs(WORK, exist_ok=True)
SPAN, S, W, EA, N0 = 10.0, 12.0, 1.0, 1e7, 5.0
A_REF = 4.695415
SAG_REF = A_REF * np.cosh(SPAN / (2 * A_REF)) - A_REF
T_REF = 7.618853


def discrete_chain(n):
    """Equilibrium of n elastic cables (stress-free length h = S/n, N = N0 + EA (l/L - 1),
    L = h/(1 - N0/EA)) with loads w h at the interior nodes: horizontal force H by bisection on the
    span. Returns (sag of the middle node, support reaction)."""
    h = S / n
    v = -W * h * ((n - 1) / 2 - np.arange(n))  # vertical force component of cable i

    def geom(H):
        N = np.hypot(H, v)
        l = h * (1 + (N - N0) / EA) / (1 - N0 / EA)
        return l * H / N, l * v / N

    lo, hi = 1e-3, 1e3
    for _ in range(200):
        H = 0.5 * (lo + hi)
        (lo, hi) = (H, hi) if geom(H)[0].sum() < SPAN else (lo, H)
    dx, dz = geom(H)
    return -dz[: n // 2].sum(), np.hypot(H, W * S / 2)


err = {}
for n, steps in ((20, 1), (40, 5), (40, 1), (80, 1)):
    out, log = run(f"ff_catenary_{n}_{steps}", to_yaml(catenary_scene(n, EA=EA, N0=N0, loadsteps=steps)))
    with h5(out) as f:
        P = f["node/p"][-1]
        sag = P[0, 2] - P[n // 2, 2]
        tmax = np.linalg.norm(f["node/Freac"][-1, 0])
        nsteps = len(f["load_factor"])
    sag_d, t_d = discrete_chain(n)
    print(f"  catenary {n} cables, {steps} load steps: sag {sag:.7f} (analytic error {sag - SAG_REF:+.3e}), "
          f"T_max {tmax:.7f} (analytic error {tmax - T_REF:+.3e})")
    check(nsteps == steps, f"{n} cables: {steps} converged load steps")
    close(sag, sag_d, atol=1e-8, what=f"{n} cables, {steps} steps: sag = discrete chain")
    close(tmax, t_d, atol=1e-8, what=f"{n} cables, {steps} steps: support tension = discrete chain")
    close(P[:, 1], np.zeros(n + 1), atol=1e-12, what=f"{n} cables: stays in its plane")
    err[n] = (sag - SAG_REF, tmax - T_REF)
# 40 cables: discretization error (lumped weight), measured sag +9.5e-4, T_max -5.4e-4
close(err[40][0], 0.0, atol=1.0e-3, what="40 cables: sag vs the analytic catenary")
close(err[40][1], 0.0, atol=6.0e-4, what="40 cables: T_max vs the analytic catenary")
for k in (0, 1):
    r1, r2 = err[20][k] / err[40][k], err[40][k] / err[80][k]
    print(f"  {('sag', 'T_max')[k]} error ratios 20/40: {r1:.3f}, 40/80: {r2:.3f} (h^2: 4)")
    check(3.8 < r1 < 4.2 and 3.8 < r2 < 4.2, f"{('sag', 'T_max')[k]} error decreases like h^2")
done()
