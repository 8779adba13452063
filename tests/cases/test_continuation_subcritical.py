"""Issue 11: -branch_switch at a subcritical (unstable-symmetric) bifurcation (beams, 2 ranks).
A clamped cosine arch, stress-free shape w0 = h/2 (1 - cos 2 pi x/L), L = 0.1 m, rise h = 3 mm, section
5 x 0.5 mm, E = 210 GPa, 40 beam elements, in-plane, a mid-span point load (the load factor is the force
in N); ds = 0.008. With this rise (h/t = 6) the symmetric path reaches the antisymmetric buckling of the
arch before its limit point: a symmetric bifurcation, whose branch is unstable (subcritical; the load
falls along it), unlike the Euler column's (test_continuation_euler).
Reference: shallow-arch theory (tests/cases/shallow_beam.py, the reference of test_continuation_flexures;
exact to the order of the squared slopes, (pi h/L)^2 = 0.9%): on the symmetric path the uniform axial
compression reaches the antisymmetric buckling load of the clamped beam, 80.763 EI/L^2, at
F_b = 12.786 N (800 intervals).
Checks:
  (1) the first critical point is a bifurcation (kind 2, not a limit point), located by the zero of the
      lowest eigenvalue at F_b within 1.5% (measured 12.681 N, -0.82%);
  (2) -branch_switch at this subcritical bifurcation fails as documented (docs/continuation.md): no
      branch exists at loads above F_b, so Newton from the perturbed states returns to the primary path;
      the run says so, ends normally (exit 0) and the path stays symmetric (the mid-span node does not
      move sideways: |dx| < 1e-12 m);
  (3) the bifurcation is subcritical indeed: the same arch with a 1% antisymmetric imperfection
      (w0 + 0.01 h sin(2 pi x/L)(1 - cos 2 pi x/L)) has a limit point below F_b (measured 11.395 N, 0.89 F_b)
      and no bifurcation, with one negative eigenvalue after it."""
import numpy as np

import path_scenes as ps
import sinewtest as st
from shallow_beam import Shallow

L, t, wd, E, h = 0.1, 0.5e-3, 5e-3, 210e9, 3e-3
EI, EA = E * wd * t ** 3 / 12, E * wd * t
ref = Shallow(L, EI, EA, lambda x: h / 2 * (1 - np.cos(2 * np.pi * x / L)), 0.0, N=800)
Fb = ref.roots(ref.P2 * (1 - 1e-9))[0][0]
print(f"  shallow-arch theory: antisymmetric bifurcation at F = {Fb:.4f} N")

text, c = ps.clamped_arch(h, max_steps=10)
h5, out = st.run("continuation_subcritical", text, args=["-branch_switch"])
with st.h5(h5) as f:
    lam, neg, crit = f["load_factor"][:], f["path/negative_eigenvalues"][:], f["path/critical_points"][:]
    dx = f["node/p"][:, c - 1, 0] - f["node/p"][0, c - 1, 0]
    conv = int(f.attrs["converged"])
print("  load factors", np.array2string(lam, precision=4))
print("  negative eigenvalues", neg.astype(int))
st.check(conv == 1, "perfect arch: path converged")
if st.check(len(crit) >= 1 and crit[0, 0] == 2, f"perfect arch: the first critical point is a bifurcation ({crit})"):
    st.close(crit[0, 2], Fb, rtol=1.5e-2, what="perfect arch: bifurcation load [N] vs shallow-arch theory")
st.check(any("branch switch at path point" in line and "failed" in line for line in out.splitlines())
         and "branch switched" not in out, "perfect arch: the switch is reported as failed, no switched point")
st.close(np.abs(dx).max(), 0.0, atol=1e-12, what="perfect arch: sideways motion of the mid-span node [m]")

text, c = ps.clamped_arch(h, imperfection=0.01, max_steps=22)
h5, out = st.run("continuation_subcritical_imperfect", text)
with st.h5(h5) as f:
    lam_i, neg_i, crit_i = f["load_factor"][:], f["path/negative_eigenvalues"][:], f["path/critical_points"][:]
print("  imperfect: load factors", np.array2string(lam_i, precision=4))
if st.check(len(crit_i) == 1 and crit_i[0, 0] == 1, f"imperfect arch: one limit point, no bifurcation ({crit_i})"):
    print(f"  imperfect arch: limit load {crit_i[0, 2]:.4f} N = {crit_i[0, 2] / Fb:.4f} F_b")
    st.check(crit_i[0, 2] < 0.95 * Fb, "imperfect arch: limit load below the perfect arch's bifurcation load (subcritical)")
    st.check(neg_i[-1] == 1, "imperfect arch: one negative eigenvalue past the limit point")
st.done()
