"""Issue 11: path following of two flexures (beams, 2 ranks), against shallow-beam theory.
Both are clamped-clamped steel leaf springs, L = 0.1 m, section 5 x 0.5 mm (in-plane thickness
t = 0.5 mm), E = 210 GPa, 40 beam elements, in-plane (every node fix_z), pushed down at mid-span by
the reference load F = 1 N (the load factor is F in N):
  (A) a shallow clamped arch: stress-free cosine shape w0 = h/2 (1 - cos 2 pi x/L), h = 0.75 mm
      (h/t = 1.5: the snap-through is a symmetric limit point, reached before the antisymmetric
      bifurcation); checked: the limit load and the mid-span deflection there, the negative-eigenvalue
      count 0 before and 1 after it, SLEPc's lowest eigenvalue of the tangent of the same sign.
  (B) a bistable buckled leaf spring: nearly straight (imperfection w0 = e/2 (1 - cos 2 pi x/L) +
      a sin(2 pi x/L)(1 - cos 2 pi x/L), e = 0.1 h, a = 0.02 h), its right end pushed in by the end
      shortening Delta = pi^2 h^2 / (4 L) (h = 1.5 mm) as an initial prescribed motion (displ_initial_x:
      the path starts from its buckled equilibrium), then pushed through: the snap force (first limit
      point), the second limit point (pulling force), and the second stable state (F = 0 on the far
      side, no negative eigenvalue) with its mid-span position.
Reference: shallow-beam (Marguerre) theory with a uniform axial force P, exact for small slopes:
EI (w - w0)'''' + P w'' = -F delta(x - L/2), clamped ends, P L / EA = Delta + 1/2 int (w0'^2 - w'^2) dx
(e.g. Vangbo 1998, Sens. Actuators A 69, 212, for the buckled beam; Qiu, Lang & Slocum 2004, JMEMS 13,
137, for the curved beam). For each P the deflection is linear in F (w = a + F b, a fourth-order finite
difference solve on 400 intervals here), the compatibility is a quadratic for F: the path F(P) is
maximized/minimized over P. Its error against the exact kinematics of the beam elements is of the
order of the squared slopes (max slope 2 pi h / L = 0.09): tolerances 0.5% on the limit loads (arch 0.6%), 1% on
the deflections."""
import numpy as np
from scipy.optimize import brentq

import beamtools as bt
import sinewtest as st
from shallow_beam import Shallow

L, t, wd, E, n = 0.1, 0.5e-3, 5e-3, 210e9, 40
EI, EA = E * wd * t ** 3 / 12, E * wd * t


def scene(title, y, nprops_end, ds, ds_max, steps):
    x = np.linspace(0, L, n + 1)
    nodes = [[float(a), float(b), 0.0] for a, b in zip(x, y(x))]
    c = n // 2 + 1
    nprops = {i + 1: {"fix_z": True} for i in range(n + 1)}
    nprops[1] = {"fix": True}
    nprops[n + 1] = nprops_end
    nprops[c] = {"fix_z": True, "force": [0, -1, 0]}
    return bt.yaml_text({"title": title, "nodes": nodes, "elements": [[i + 1, i + 2] for i in range(n)], "nprops": nprops,
                         "eprops": [{"elems": list(range(1, n + 1)), "flex": [1, 2, 3, 4, 5, 6], "emod": E, "smod": E / 2.6,
                                     "cshape": "rect", "dim": [wd, t], "orien": [0, 0, 1]}],
                         "opt": {"calccompl": False,
                                 "continuation": {"method": "arclength", "ds": ds, "ds_max": ds_max, "node": c,
                                                  "direction": "y", "max_steps": steps}}}), c


def run(name, text, c, args=()):
    h5, out = st.run(name, text, args=list(args))
    with st.h5(h5) as f:
        return dict(lam=f["load_factor"][:], w=f["node/p"][:, c - 1, 1], neg=f["path/negative_eigenvalues"][:],
                    crit=f["path/critical_points"][:], y0=f["node/p"][0, c - 1, 1] - f["path/control_displacement"][0],
                    low=f["path/lowest_eigenvalue"][:] if "path/lowest_eigenvalue" in f else None,
                    conv=int(f.attrs["converged"]))


# (A) shallow clamped arch
h = 0.75e-3
w0 = lambda x: h / 2 * (1 - np.cos(2 * np.pi * x / L))
ref = Shallow(L, EI, EA, w0, 0.0)
Flim, wlim = ref.extreme(0.0, 0.999 * ref.P2, 1, 1)  # at P = 0 the second root is F = 0, w = w0
print(f"  arch: shallow theory limit load {Flim:.6f} N at mid-span w = {wlim * 1e3:.6f} mm")
text, c = scene("shallow clamped arch", w0, {"fix": True}, 0.002, 0.004, 30)
r = run("continuation_arch", text, c, ["-continuation_lowest_eigenvalue"])
print("  load factors", np.array2string(r["lam"], precision=4))
print("  negative eigenvalues", r["neg"].astype(int))
st.check(r["conv"] == 1, "arch: path converged")
crit = r["crit"]
if st.check(len(crit) >= 1 and crit[0, 0] == 1, f"arch: a limit point located first ({crit})"):
    st.close(crit[0, 2], Flim, rtol=6e-3, what="arch: limit load [N] vs shallow-arch theory (measured 0.43% at 40 elements, 0.14% at 80)")
    st.close(r["y0"] + crit[0, 3], wlim, rtol=1e-2, what="arch: mid-span position at the limit point [m]")
    k = int(crit[0, 1])  # path points k (before) and k + 1 (after), 1-based
    st.check(np.all(r["neg"][:k] == 0) and r["neg"][k] == 1, "arch: 0 negative eigenvalues before the limit point, 1 after")
if st.check(r["low"] is not None, "arch: /path/lowest_eigenvalue written"):
    st.check(np.array_equal(r["low"] < 0, r["neg"] > 0), "arch: SLEPc's lowest eigenvalue < 0 exactly where the inertia counts one")

# (B) bistable buckled leaf spring
h = 1.5e-3
Delta = np.pi ** 2 * h ** 2 / (4 * L)
w0 = lambda x: 0.1 * h / 2 * (1 - np.cos(2 * np.pi * x / L)) + 0.02 * h * np.sin(2 * np.pi * x / L) * (1 - np.cos(2 * np.pi * x / L))
ref = Shallow(L, EI, EA, w0, Delta)
Fsnap, wsnap = ref.extreme(1.001 * ref.P1, 0.99999 * ref.P2, 0, 1)
Fback, wback = ref.extreme(1.001 * ref.P1, 0.99999 * ref.P2, 1, -1)
g0 = lambda P: 0.5 * ref.g(*(2 * [ref.ab(P)[0]])) - (ref.C0 - P * L / EA)
P0 = brentq(g0, 1.0001 * ref.P1, 1.5 * ref.P1)  # the second stable state: F = 0 on the far side
w2 = ref.ab(P0)[0][ref.c]
print(f"  leaf spring: shallow theory snap force {Fsnap:.6f} N at w = {wsnap * 1e3:.5f} mm, second limit {Fback:.6f} N "
      f"at w = {wback * 1e3:.5f} mm, second stable state w = {w2 * 1e3:.5f} mm")
text, c = scene("bistable buckled leaf spring", w0, {"fix_y": True, "fix_z": True, "fix_orien": True, "displ_initial_x": -Delta},
                0.003, 0.008, 100)
r = run("continuation_leafspring", text, c, ["-continuation_initial_steps", "20"])
lam, w, neg, crit = r["lam"], r["w"], r["neg"], r["crit"]
print("  load factors", np.array2string(lam, precision=4))
print("  negative eigenvalues", neg.astype(int))
st.check(r["conv"] == 1, "leaf spring: path converged")
st.check(w[0] > 0.9 * h, f"leaf spring: the path starts from the buckled state (w = {w[0] * 1e3:.4f} mm at F = {lam[0]:.3f} N)")
if st.check(crit.shape[0] == 2 and np.all(crit[:, 0] == 1), f"leaf spring: two limit points ({crit})"):
    st.close(crit[0, 2], Fsnap, rtol=5e-3, what="leaf spring: snap force [N] vs shallow-beam theory")
    st.close(r["y0"] + crit[0, 3], wsnap, rtol=1e-2, what="leaf spring: mid-span position at snap [m]")
    st.close(crit[1, 2], Fback, rtol=5e-3, what="leaf spring: second limit load [N]")
    st.close(r["y0"] + crit[1, 3], wback, rtol=1e-2, what="leaf spring: mid-span position at the second limit [m]")
    k1, k2 = int(crit[0, 1]), int(crit[1, 1])
    st.check(np.all(neg[:k1] == 0) and np.all(neg[k1:k2] == 1) and np.all(neg[k2:] == 0),
             "leaf spring: stable (0), unstable (1) between the limit points, stable (0) after")
# second stable state: the load factor crosses 0 on the far side, stable; its mid-span position
k = np.nonzero((lam[:-1] < 0) & (lam[1:] >= 0) & (w[1:] < 0))[0]
if st.check(len(k) >= 1 and neg[k[0] + 1] == 0, "leaf spring: F = 0 reached again on the far side, stable"):
    i = k[0]
    wz = w[i] + (w[i + 1] - w[i]) * (0 - lam[i]) / (lam[i + 1] - lam[i])
    st.close(wz, w2, rtol=1e-2, what="leaf spring: second stable state, mid-span position [m]")
st.done()
