"""Constrained warping (cw, references B5 x B6): a short wide clamped leaf twisted by a torque
turns by T L / (G I_t f_cw); without cw the L/w < 3 warning is printed and the twist is
T L / (G I_t). Run on 2 ranks."""
import numpy as np

import sinewtest as st

E, G, w, t, L, T = 210e9, 80e9, 0.02, 0.0005, 0.02, 1e-3
nu = E / (2 * G) - 1


def rect_torsion_constant(s1, s2):  # B6
    a, b = min(s1, s2) / 2, max(s1, s2) / 2
    n = np.arange(1, 2001, 2)
    return (1 / 3) * (2 * a)**3 * (2 * b) * (1 - 192 / np.pi**5 * (a / b) * np.sum(np.tanh(n * np.pi * b / (2 * a)) / n**5))


It = rect_torsion_constant(w, t)
a, c = L / w, np.sqrt(24 / (1 + nu))
f_cw = a * c / (a * c - 2 * np.tanh(a * c / 2))  # B5


def scene(cw):
    return f"""
title: short wide leaf in torsion
nodes: [[0, 0, 0], [{L}, 0, 0]]
elements: [[1, 2]]
nprops: {{1: {{fix: true}}, 2: {{moment: [{T}, 0, 0]}}}}
eprops: [{{elems: [1], flex: [1, 2, 3, 4, 5, 6], emod: {E}, smod: {G}, cshape: rect, dim: [{w}, {t}],
          orien: [0, 1, 0], cw: {str(cw).lower()}}}]
opt: {{loadsteps: 1, calccompl: false}}
"""


def twist(out):
    with st.h5(out) as f:
        return f["node/r_axang"][-1, 1, 0] * np.sign(f["node/r_axang"][-1, 1, 1])  # [angle, axis]


print(f"  L/w = {L / w}, nu = {nu:.4f}, f_cw = {f_cw:.6f}, I_t = {It:.6e}")
out, log = st.run("cw_on", scene(True), np_=2)
st.close(twist(out), T * L / (G * It * f_cw), rtol=1e-6, what="twist with cw vs T L / (G I_t f_cw)")
st.check("warning" not in log, "cw: true -> no warping warning")
out, log = st.run("cw_off", scene(False), np_=2)
st.close(twist(out), T * L / (G * It), rtol=1e-6, what="twist without cw vs T L / (G I_t)")
st.check("warning: eprops(1) element 1: L/w = 1 < 3 without cw" in log, "L/w < 3 without cw: warning printed")
st.check(f_cw > 1.5, f"the warping factor matters here (f_cw = {f_cw:.3f})")
# a long leaf (L/w = 5) gets no warning
out, log = st.run("cw_long", scene(False).replace(f"[{L}, 0, 0]", f"[{5 * w}, 0, 0]"), np_=2)
st.check("warning" not in log, "L/w = 5: no warning")
st.done()
