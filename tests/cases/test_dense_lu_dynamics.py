"""The dense LU of small models' time steps (-dense_max_unknowns; DynamicAnalysis::useDynamicsSolver):
a model with multipliers on one rank, and any small model on several ranks (PCREDUNDANT: every rank
factors the whole matrix with PCDENSELU), instead of MUMPS. The cross-flexure hinge of
runs/crosshinge.yaml in motion (rigid top body: Lagrange multipliers; moment 0.5 N m from t = 0,
rho = 0.9, dt = 5e-4 to 0.025 s) on 1 and 2 ranks, with the default bound and with
-dense_max_unknowns 0 (MUMPS), with -log_view: the default runs must log SinewDenseLU factorizations
and at most one MUMPS factorization (MatLUFactorNum: the initial accelerations), the MUMPS runs no dense
LU, so an ignored option fails the test; the positions and rotations agree to 1e-12 of the motion
(measured: positions 1.1e-14 on 1 rank, 9.3e-15 on 2; rotations 1.3e-15; 150 dense factorizations
against 151 MUMPS ones)."""
import os
import re

import numpy as np

import sinewtest as st

with open(os.path.join(os.environ["SINEW_SOURCE_DIR"], "runs", "crosshinge.yaml")) as f:
    hinge = f.read().split("\nopt:")[0] + """
opt:
  calcfreq: false
  calccompl: false
  dynamics: {tend: 0.025, dt: 0.0005, spectral_radius: 0.9, output_every: 10}
"""


def event_count(log, event):
    m = re.search(r"^" + event + r"\s+(\d+)", log, re.M)
    return int(m.group(1)) if m else 0


for np_ in (1, 2):
    dense, log_d = st.run(f"dldyn_dense{np_}", hinge, np_=np_, args=["-log_view"])
    mumps, log_m = st.run(f"dldyn_mumps{np_}", hinge, np_=np_, args=["-log_view", "-dense_max_unknowns", "0"])
    nd, fd = event_count(log_d, "SinewDenseLU"), event_count(log_d, "MatLUFactorNum")
    nm, fm = event_count(log_m, "SinewDenseLU"), event_count(log_m, "MatLUFactorNum")
    print(f"  {np_} rank(s): default {nd} dense LU, {fd} MUMPS factorizations; -dense_max_unknowns 0: {nm} dense, {fm} MUMPS")
    st.check(nd >= 10 and fd <= 1, f"{np_} rank(s): the time steps factor by the dense LU ({nd} SinewDenseLU, {fd} MatLUFactorNum)")
    st.check(nm == 0 and fm >= 10, f"{np_} rank(s): -dense_max_unknowns 0 factors with MUMPS ({nm} dense, {fm} MUMPS)")
    with st.h5(dense) as a, st.h5(mumps) as b:
        p0 = a["node/p0"][:]
        motion = np.abs(b["node/p"][:] - p0).max()
        dp = np.abs(a["node/p"][:] - b["node/p"][:]).max() / motion
        dr = np.abs(a["node/r_axang"][:] - b["node/r_axang"][:]).max() / np.abs(b["node/r_axang"][:]).max()
    print(f"  {np_} rank(s): dense vs MUMPS positions {dp:.2e}, rotations {dr:.2e} of the motion")
    st.check(dp < 1e-12 and dr < 1e-12, f"{np_} rank(s): dense and MUMPS steps agree to 1e-12 ({dp:.2e}, {dr:.2e})")
st.done()
