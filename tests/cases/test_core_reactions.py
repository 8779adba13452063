"""Reactions balance the applied loads: at every converged step, the support reactions plus the
applied nodal forces sum to zero, and so do their moments (x cross F at the deformed positions,
plus nodal moments) about the origin, to 1e-10 of the load scale, or to the residual norm Newton
stopped at when that is larger (the crosshinge's step 1, the 20 N initial load alone: 20 -> 8.7e-5 ->
3.4e-9 N, accepted by the round-off-floor rule (3) of the convergence test; force balance 1.4e-10 of
the load, the other steps <= 1.1e-12; measured). Scenes: the cross-flexure hinge
(runs/crosshinge.yaml: force_initial + ramped moment, rigid top body) and a braced 3D tower with
fixed, pinned (fix_pos) and rigid members under large loads."""
import os
import re

import numpy as np
import yaml

import beamtools as bt
import frames
import sinewtest as st


def applied(scene_nprops, lam, n):
    F, M = np.zeros((n, 3)), np.zeros((n, 3))
    for k, pr in scene_nprops.items():
        i = int(k) - 1
        F[i] = np.array(pr.get("force_initial", [0, 0, 0])) + lam * np.array(pr.get("force", [0, 0, 0]))
        M[i] = np.array(pr.get("moment_initial", [0, 0, 0])) + lam * np.array(pr.get("moment", [0, 0, 0]))
    return F, M


def residuals(log):
    """|residual| per load step from the summary table (step, load factor, Newton its, increments, residual)."""
    rows = re.findall(r"^\s+(\d+)\s+\S+\s+\d+\s+\d+\s+(\S+)\s*$", log, re.M)
    return {int(k): float(r) for k, r in rows}


def balance(name, path, nprops, args=()):
    out, log = st.run(name, path, args=args)
    res = residuals(log)
    with st.h5(out) as f:
        lam, p, Fr, Mr = f["load_factor"][:], f["node/p"][:], f["node/Freac"][:], f["node/Mreac"][:]
    st.check(sorted(res) == list(range(1, len(lam) + 1)), f"{name}: residual of every step in the summary, got {sorted(res)}")
    worstF = worstM = rawF = 0.0
    for k in range(len(lam)):
        F, M = applied(nprops, lam[k], p.shape[1])
        scaleF = np.abs(F).sum()
        arm = np.abs(p[k]).max()
        resF = (Fr[k] + F).sum(axis=0)
        resM = (np.cross(p[k], Fr[k] + F) + Mr[k] + M).sum(axis=0)
        # relative to 1e-10, or to the residual Newton accepted when that is larger
        allowF = max(1.0, res.get(k + 1, 0.0) / scaleF / 1e-10)
        worstF = max(worstF, np.abs(resF).max() / scaleF / allowF)
        rawF = max(rawF, np.abs(resF).max() / scaleF)
        worstM = max(worstM, np.abs(resM).max() / (scaleF * arm + np.abs(M).sum()))
    print(f"{name}: {len(lam)} steps, max |sum F| / sum|F_applied| = {rawF:.3e} "
          f"(/ max(1, |residual| / (1e-10 sum|F_applied|)): {worstF:.3e}), "
          f"max |sum M| / moment scale = {worstM:.3e}; reactions {np.abs(Fr[-1]).max():.4g} N max")
    st.check(len(lam) > 0, f"{name}: no converged step")
    st.close(worstF, 0, atol=1e-10, what=f"{name}: force balance")
    st.close(worstM, 0, atol=1e-10, what=f"{name}: moment balance")


# SNES rtol 1e-14: the default 1e-10 of an increment's first residual (dominated by the stiff leaves
# jumping) leaves a crosshinge force balance of 1.2e-8 (measured); 1e-14 gives 5e-11.
ARGS = ["-snes_rtol", "1e-14"]
hinge = os.path.join(st.SOURCE, "runs", "crosshinge.yaml")
with open(hinge) as f:
    hn = yaml.safe_load(f)["nprops"]
balance("reactions_crosshinge", hinge, {str(k): v for k, v in hn.items()}, args=ARGS)
scene, _ = frames.tower()
path = st.scene_file("reactions_tower", bt.yaml_text(scene))
balance("reactions_tower", path, scene["nprops"], args=ARGS)
st.done()
