"""Energy and momentum output of dynamics (-dynamics_energy: /energy/kinetic, /energy/strain,
/energy/external_work, /energy/total = T + S - W, /momentum/linear, /momentum/angular about the
origin; docs/dynamics.md "Energy and momentum") on 2 ranks.
1. The leaf cantilever of test_beam_dynamics.py (8 beams, tip force applied at t = 0, linear
   range), dt = T1/50, 2 T1. Reference: energy balance T + S = W. W of a constant force is
   F (x - x0) exactly, T + S - W stays constant up to the scheme's drift with rho = 1 and decays
   with rho = 0.8 (numerical dissipation) and with modal damping (zeta = 0.05).
2. The free rigid body of test_beam_dynamics_spin.py (constant moment M0, no forces): the written
   angular momentum about the origin follows H = M0 t (balance of angular momentum), the linear
   momentum stays 0. Arnold-Brüls generalized alpha is not momentum conserving: the error of H
   is measured at dt = 0.02 and 0.01 and its order printed.
MEASURED (2 ranks, this test's run): leaf rho = 1: |W - F u| / max W = 1.2e-11, |T + S - W| change /
max W = 3.2e-10 (tolerance 1e-4), max T = 0.250 max W, max S = 0.991 max W; rho = 0.8 loses 1.9e-3
of max W over 2 T1 (largest rise between written steps 5.6e-5), modal zeta = 0.05 loses 0.185.
Spin: max |H - M0 t| / |M0 tend| = 3.41e-4 at dt = 0.02, 8.39e-5 at dt = 0.01: order 2.02 (the
scheme's, not round-off), linear momentum <= 1.4e-15 kg m/s."""
import numpy as np

import beamtools as bt
import sinewtest as st

L, w, t, nel = 1.0, 0.02, 0.002, 8
sec = bt.rect_section(w, t)
F = 1e-5 * 3 * sec["EIy"] / L ** 3
nodes, elems = bt.chain([0, 0, 0], [L, 0, 0], nel)
f1 = 1.676  # about the first frequency of this leaf (test_beam_dynamics.py); only sets the time scale
T1 = 1 / f1


def leaf(dyn):
    return {"title": "leaf", "nodes": nodes, "elements": elems,
            "nprops": {1: {"fix": True}, nel + 1: {"force": [0, F, 0]}},
            "eprops": [bt.beam_set(range(1, nel + 1), w, t, dens=7800)],
            "opt": {"calccompl": False, "calcfreq": False,
                    "dynamics": {"tend": 2 * T1, "dt": T1 / 50, "output_every": 2, **dyn}}}


res = {}
for name, dyn in (("rho1", {"spectral_radius": 1.0}), ("rho08", {"spectral_radius": 0.8}),
                  ("modal", {"spectral_radius": 1.0, "modal_damping": 0.05})):
    h, _ = st.run(f"energy_leaf_{name}", bt.yaml_text(leaf(dyn)), args=["-dynamics_energy"])
    with st.h5(h) as f:
        res[name] = {k: f[f"energy/{k}"][:] for k in ("kinetic", "strain", "external_work", "total")}
        res[name]["u"] = (f["node/p"][:, nel, :] - f["node/p0"][nel, :])[:, 1]
        res[name]["p"] = f["momentum/linear"][:]
r = res["rho1"]
Wmax = np.max(r["external_work"])
ew = np.max(np.abs(r["external_work"] - F * r["u"])) / Wmax
drift = np.max(np.abs(r["total"] - r["total"][0])) / Wmax
print(f"  leaf rho = 1: max W = {Wmax:.4e} J, |W - F u| / max W = {ew:.1e}, |T + S - W| change / max W = {drift:.1e}, "
      f"max T / max W = {np.max(r['kinetic']) / Wmax:.3f}, max S / max W = {np.max(r['strain']) / Wmax:.3f}")
st.check(ew < 1e-6, "leaf: external work of the constant tip force = F u_tip")
st.check(drift < 1e-4, "leaf, rho = 1: T + S - W constant within the scheme's drift")
st.check(np.max(r["kinetic"]) > 0.2 * Wmax and np.max(r["strain"]) > 0.9 * Wmax, "leaf: energy moves between T and S")
for name in ("rho08", "modal"):
    e = res[name]["total"]
    loss = -(e[-1] - e[0]) / Wmax
    rise = np.max(np.diff(e)) / Wmax
    # generalized alpha dissipates its own (algorithmic) energy: the physical T + S - W may rise a
    # little between steps while it decays overall
    print(f"  leaf {name}: T + S - W lost over 2 T1: {loss:.3e} of max W, largest rise between written steps {rise:.1e}")
    st.check(loss > 100 * drift and rise < 0.1 * loss, f"leaf {name}: T + S - W decays")

# 2. free rigid body under a constant moment
M0 = np.array([0.05, 0.03, 0.02])
err = {}
for dt in (0.02, 0.01):
    scene = {"title": "spin", "nodes": [[0, 0, 0], [0.2, 0, 0]], "elements": [[1, 2]],
             "nprops": {1: {"mass": 1.0, "mominertia": [0.01, 0, 0, 0.02, 0, 0.03], "moment": list(M0)},
                        2: {"mass": 1.0, "mominertia": [0.01, 0, 0, 0.02, 0, 0.03]}},
             "eprops": [bt.beam_set([1], 0.02, 0.02)],
             "opt": {"calcfreq": False, "calccompl": False,
                     "dynamics": {"tend": 2.0, "dt": dt, "spectral_radius": 1.0}}}
    h, _ = st.run(f"energy_spin_{dt}", bt.yaml_text(scene), args=["-dynamics_energy"])
    with st.h5(h) as f:
        tt, H, p = f["time"][:], f["momentum/angular"][:], f["momentum/linear"][:]
        T, W = f["energy/kinetic"][:], f["energy/external_work"][:]
    err[dt] = np.max(np.linalg.norm(H - np.outer(tt, M0), axis=1)) / np.linalg.norm(M0 * tt[-1])
    pe = np.max(np.abs(p))
    ee = np.max(np.abs(T - W)) / np.max(W)
    print(f"  spin dt = {dt}: max |H - M0 t| / |M0 tend| = {err[dt]:.2e}, max |p| = {pe:.1e} kg m/s, "
          f"|T - W| / max W = {ee:.1e}")
    st.check(pe < 1e-12, f"spin dt = {dt}: linear momentum 0")
order = np.log2(err[0.02] / err[0.01])
print(f"  angular momentum error order {order:.2f}")
st.check(err[0.02] < 2e-3, "spin: angular momentum output = M0 t (to 2e-3 at dt = 0.02)")
st.check(1.5 < order < 2.5, "spin: the angular momentum error is second order in dt (not conserved to round-off)")
st.done()
