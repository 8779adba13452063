"""One very soft direction: a cantilever flexure 10 mm x 10 um (L = 1, 40 elements) is 1e6 times
stiffer in bending about one axis than the other, and its axial eigenvalue is ~1e11 times the
softest one. The soft-plane frequencies (~8 mHz) and the first stiff-plane frequency (~1000x
higher, found among 24 modes by its mode shape) both match reference B3."""
import numpy as np

import sinewtest as st
from modal_util import beam_x, cantilever_hz

L, W, T = 1.0, 0.01, 1e-5
path, out = st.run("modal_soft", beam_x(L, W, T, 40, {1: {"fix": True}}, opt={"nfreq": 24}))
with st.h5(path) as f:
    freq = f["freq"][0]
    st.check(np.all(np.isfinite(freq)) and np.all(freq > 0), "finite, positive frequencies")
    st.close(freq[:5], cantilever_hz(L, W, T), rtol=1e-4, what="soft plane f1..f5 (Hz)")
    plane_y = [np.max(np.abs(f[f"mesh/mode_freq_{i + 1}"][0][:, 1])) > np.max(np.abs(f[f"mesh/mode_freq_{i + 1}"][0][:, 2]))
               for i in range(24)]
    st.check(any(plane_y), "a stiff-plane (y) mode among the first 24")
    if any(plane_y):
        i = plane_y.index(True)
        st.close(freq[i], cantilever_hz(L, T, W, 1), rtol=1e-4, what=f"stiff plane f1 (mode {i + 1})")
        print(f"  stiff / soft first frequency: {freq[i] / freq[0]:.6g}")
st.done()
