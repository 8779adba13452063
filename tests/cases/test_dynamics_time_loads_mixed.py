# ctest-labels: smoke
"""Time-dependent nodal loads on every node kind (docs/dynamics.md, "Loads and motions as functions
of time"; 2 ranks): beam (Frame6 force and moment), cable (Point3) and ancf_cable2d (force and the
torque on the slope) nodes, in a mixed 3D scene (a beam cantilever and a prestressed two-element
cable with a mass in the middle) and a 2D ANCF cantilever. Check by time invariance: every load is
switched on by Exudyn's SmoothStep (smoothstep(t, t0, t0 + 0.02, 0, 1)); the run with t0 = 0.01
stays exactly at rest (zero load, zero accelerations) until t0 and then must repeat the run with
t0 = 0 shifted by 0.01 s (dt = 1e-3 divides the shift), up to the round-off of t - t0. Ignoring the
functions leaves both runs at rest (the loads vanish at t = 0), and evaluating them at a wrong time
breaks the shift. Measured: max difference / max motion 6.5e-15 (mixed), 1.8e-14 (ANCF); the motion
is 11 mm (mixed) and 24 mm (ANCF). The ANCF cable at rest under zero load needed the round-off
acceptance of a stalled Newton solve in DynamicAnalysis::convergenceTest (its residual starts at
the round-off floor, 9e-8 N, and cannot drop by 1e-3)."""
import numpy as np

import beamtools as bt
import sinewtest as st
from ancf_scenes import cantilever, text

dt, shift = 1e-3, 10


def ramp(t0, value):
    return f"{value}*smoothstep(t, {t0}, {t0 + 0.02}, 0, 1)"


def mixed(t0, tend):
    return bt.yaml_text({
        "title": "mixed time loads",
        "nodes": [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0.5, 1, 0], [1, 1, 0]],
        "elements": [[1, 2], [3, 4], [4, 5]],
        "nprops": {1: {"fix": True}, 3: {"fix": True}, 5: {"fix": True},
                   2: {"force": [0, ramp(t0, 50.0), 0], "moment": [ramp(t0, 5.0), 0, 0]},
                   4: {"mass": 1.0, "force": [0, 0, ramp(t0, -2.0)]}},
        "eprops": [dict(bt.beam_set([1], 0.02, 0.02, nbeams=4), dens=7800),
                   {"elems": [2, 3], "type": "cable", "area": 1e-4, "emod": 1e9, "dens": 1000, "prestress": 100.0}],
        "opt": {"calcfreq": False, "calccompl": False, "dynamics": {"tend": tend, "dt": dt, "spectral_radius": 0.9}}})


def ancf(t0, tend):
    sc = cantilever(4, dynamics={"tend": tend, "dt": dt, "spectral_radius": 0.6})
    sc["nprops"][2] = {"force": [0, ramp(t0, -1e4)], "moment": ramp(t0, 2e3)}
    return text(sc)


for name, build in (("mixed", mixed), ("ancf", ancf)):
    ref, _ = st.run(f"tload_{name}_ref", build(0.0, 0.05))
    late, _ = st.run(f"tload_{name}_late", build(shift * dt, 0.05 + shift * dt))
    with st.h5(ref) as f, st.h5(late) as g:
        p, q = f["node/p"][:], g["node/p"][:]
        motion = np.abs(p - p[0]).max()
        rest = np.abs(q[:shift + 1] - q[0]).max()
        d = np.abs(q[shift:] - p).max() / motion
        print(f"  {name}: motion {motion:.3e} m, at rest before t0 to {rest:.1e} m, shifted runs differ by {d:.2e} of the motion")
        st.check(motion > 1e-4, f"{name}: the time-dependent loads move the model")
        st.check(rest < 1e-12, f"{name}: at rest (to round-off) while the loads are zero")
        st.check(d < 1e-9, f"{name}: a load switched on at t0 = 0.01 repeats the run with t0 = 0 (to 1e-9)")
        if name == "mixed":
            r, s = f["node/r_quat"][:], g["node/r_quat"][:]
            st.check(np.abs(r - r[0]).max() > 1e-4 and np.abs(s[shift:] - r).max() < 1e-9, "mixed: rotations shifted too")
st.done()
