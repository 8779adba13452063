# ctest-labels: smoke
"""Modal state-space model (opt.transfer: [true, zeta]) of a cantilever (L = 1, rect 10 x 0.1 mm,
40 elements, 6 modes: all in the compliant plane x-z): input force_z at the tip, outputs displ_z
and veloc_z at the tip. Checks: the poles (eigenvalues of A) are -zeta w +- i w sqrt(1 - zeta^2)
of the computed frequencies; the static gain -C A^-1 B of displ_z / force_z is the tip compliance
L^3 / (3 EI) up to the modes left out (1.9e-4 measured with 6 modes); D = 0; the veloc row has no static gain.
SPACAR Light's refusals: a force ramp together with transfer, and transfer without outputs, are
scene errors (exit 2) naming the fields. scripts/bode.py draws the Bode plot beside the result file
(<result>_bode.png, nothing in the working directory)."""
import os
import subprocess

import numpy as np

import sinewtest as st
from modal_util import E, beam_x

L, W, T, zeta = 1.0, 0.01, 1e-4, 0.02
nprops = {1: {"fix": True}, 2: {"transfer_in": ["force_z"], "transfer_out": ["displ_z", "veloc_z"]}}
path, out = st.run("statespace", beam_x(L, W, T, 40, nprops, opt={"transfer": [True, zeta], "nfreq": 6}))
with st.h5(path) as f:
    A, B, C, D = (f["statespace/" + k][:] for k in "ABCD")
    hz = f["freq"][-1]
    st.check(A.shape == (12, 12) and B.shape == (12, 1) and C.shape == (2, 12) and D.shape == (2, 1),
             f"shapes A {A.shape} B {B.shape} C {C.shape} D {D.shape}")
    w = 2 * np.pi * hz
    poles = np.linalg.eigvals(A)
    expected = np.concatenate([-zeta * w + 1j * w * np.sqrt(1 - zeta**2), -zeta * w - 1j * w * np.sqrt(1 - zeta**2)])
    ps = poles[np.lexsort((poles.imag, np.abs(poles)))]
    es = expected[np.lexsort((expected.imag, np.abs(expected)))]
    err = np.max(np.abs(ps - es) / np.abs(es))
    print(f"  poles: max relative deviation {err:.3e}; first pair {ps[0]:.6g}, {ps[1]:.6g}")
    st.check(err < 1e-10, f"poles = -zeta w +- i w sqrt(1 - zeta^2) (max rel. deviation {err:.3e})")
    gain = (-C @ np.linalg.solve(A, B))[:, 0]
    compliance = L**3 / (3 * E * W * T**3 / 12)
    st.close(gain[0], compliance, rtol=5e-4, what="static gain displ_z/force_z vs L^3/(3EI)")
    st.check(abs(gain[1]) < 1e-12 * compliance, "veloc_z has no static gain")
    st.check(np.all(D == 0), "D = 0")
    st.close(f["statespace/inputs"][:], [[2, 3]], what="inputs (node, force_z)")
    st.close(f["statespace/outputs"][:], [[2, 3], [2, 6]], what="outputs (node, displ_z / veloc_z)")
# bode.py writes <result>_bode.png beside the result file, not bode.png in the working directory
png = os.path.splitext(path)[0] + "_bode.png"
elsewhere = os.path.join(st.WORK, "statespace_cwd")
os.makedirs(elsewhere, exist_ok=True)
for stale in (png, os.path.join(elsewhere, "bode.png")):
    if os.path.exists(stale):
        os.remove(stale)
p = subprocess.run(["/usr/bin/python3", os.path.join(st.SOURCE, "scripts", "bode.py"), path],
                   stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, cwd=elsewhere)
st.check(p.returncode == 0 and os.path.exists(png) and os.path.getsize(png) > 10000
         and not os.listdir(elsewhere), "scripts/bode.py writes <result>_bode.png beside the result: " + p.stdout.strip())

bad = {1: {"fix": True}, 2: {"force": [0, 0, 1e-3], "transfer_in": ["force_z"], "transfer_out": ["displ_z"]}}
_, out = st.run("statespace_with_load", beam_x(L, W, T, 4, bad, opt={"transfer": True}), expect_exit=2)
st.check("nprops(2).force" in out and "opt.transfer" in out, "refusal names nprops(2).force and opt.transfer: " + out.strip()[-300:])
noout = {1: {"fix": True}, 2: {"transfer_in": ["force_z"]}}
_, out = st.run("statespace_no_output", beam_x(L, W, T, 4, noout, opt={"transfer": True}), expect_exit=2)
st.check("transfer_out" in out, "refusal names transfer_out")
st.done()
