"""Von Mises stress: clamped beam with a tip force -> max at the root = F L (t/2) / I_y; pure
torsion -> sqrt(3) tau with tau = T * torsionStressFactor (rect: T t / I_t, B6); rigid elements
only with rigidstress (stress from their multipliers). Run on 2 ranks."""
import numpy as np

import sinewtest as st

E, G, w, t, L, L2 = 210e9, 80e9, 0.02, 0.005, 0.5, 0.1
Iy = w * t**3 / 12


def rect_torsion_constant(s1, s2):  # B6
    a, b = min(s1, s2) / 2, max(s1, s2) / 2
    n = np.arange(1, 2001, 2)
    return (1 / 3) * (2 * a)**3 * (2 * b) * (1 - 192 / np.pi**5 * (a / b) * np.sum(np.tanh(n * np.pi * b / (2 * a)) / n**5))


It = rect_torsion_constant(w, t)
SEC = f"cshape: rect, dim: [{w}, {t}], orien: [0, 1, 0]"


def scene(load, opt="", rigid_set=True):
    sets = f"[{{elems: [1], flex: [1, 2, 3, 4, 5, 6], emod: {E}, smod: {G}, {SEC}, nbeams: 3}}"
    sets += f", {{elems: [2], {SEC}}}]" if rigid_set else "]"
    return f"""
title: beam with a rigid end piece
nodes: [[0, 0, 0], [{L}, 0, 0], [{L + L2}, 0, 0]]
elements: [[1, 2], [2, 3]]
nprops: {{1: {{fix: true}}, 3: {{{load}}}}}
eprops: {sets}
opt: {{loadsteps: 1, calccompl: false, stressperelement: true{opt}}}
"""


F = 1.0  # tip deflection ~ 1e-4 L: geometric nonlinearity far below the tolerance
out, log = st.run("stress_bending", scene(f"force: [0, 0, {F}]"), np_=2)
with st.h5(out) as f:
    smax, per = f["stressmax"][-1], f["element/stressmax"][-1]
st.close(smax, F * (L + L2) * (t / 2) / Iy, rtol=1e-3, what="max stress = F L_tot (t/2) / Iy at the root")
st.close(per[0], smax, rtol=1e-12, what="the max is in element 1 (the root)")
st.close(per[1], 0.0, atol=0.0, what="rigid element 2 skipped without rigidstress")

out, log = st.run("stress_rigid", scene(f"force: [0, 0, {F}]", ", rigidstress: true"), np_=2)
with st.h5(out) as f:
    per = f["element/stressmax"][-1]
st.close(per[1], F * L2 * (t / 2) / Iy, rtol=1e-3, what="rigidstress: rigid element 2 root stress from its multipliers")

Tq = 0.5
out, log = st.run("stress_torsion", scene(f"moment: [{Tq}, 0, 0]"), np_=2)
with st.h5(out) as f:
    smax = f["stressmax"][-1]
tau = Tq * min(w, t) / It
st.close(smax, np.sqrt(3) * tau, rtol=1e-3, what="pure torsion: sqrt(3) T t / I_t")
st.done()
