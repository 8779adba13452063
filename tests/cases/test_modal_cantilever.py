# ctest-labels: smoke
"""Cantilever bending frequencies against reference B3 (Euler-Bernoulli, beta_n L), first five in
the compliant plane of a rect section 10 mm x 0.1 mm (the stiff plane is 100x higher, torsion and
axial far above). Also: rigid axial/torsion modes (multipliers, zero-mass rows) change nothing and
never show up as eigenvalues; asking for more eigenpairs than the model has finite ones computes
those with a warning."""
import numpy as np

import sinewtest as st
from modal_util import beam_x, cantilever_hz

L, W, T = 1.0, 0.01, 1e-4
ref = cantilever_hz(L, W, T)

# 1. all modes flexible, 40 elements
path, out = st.run("modal_cantilever", beam_x(L, W, T, 40, {1: {"fix": True}}, opt={"nfreq": 6}))
with st.h5(path) as f:
    freq = f["freq"][:]
    st.check(freq.shape == (1, 6), f"/freq shape {freq.shape}, expected (1, 6)")
    st.close(freq[0, :5], ref, rtol=1e-4, what="f1..f5 (Hz) vs B3, 40 elements")
    print("  relative errors:", np.array2string(freq[0, :5] / ref - 1, precision=3))
    st.check(np.all(np.diff(freq[0]) > 0), "frequencies ascending")
    # mode 1: tip deflection in z, normalized to max |u| = 1 at the tip (FE node 2 = scene node 2)
    m1 = f["mesh/mode_freq_1"][0]
    st.close(m1[1], [0, 0, 1], atol=1e-9, what="mode 1 at the tip (normalized, z up)")
    st.check(np.max(np.abs(m1)) <= 1 + 1e-12, "mode 1 scaled to max |u| = 1")
    st.check(f.attrs["converged"] in (1, True), "converged attribute")
st.check("natural frequencies (Hz, last step): 0.083819" in out, "summary line with the frequencies")

# 2. axial and torsion rigid (2 multipliers per element, zero mass rows): same bending frequencies
path, out = st.run("modal_cantilever_rigid", beam_x(L, W, T, 40, {1: {"fix": True}}, flex=(3, 4, 5, 6), opt={"nfreq": 6}))
with st.h5(path) as f:
    fr = f["freq"][0]
    st.close(fr[:5], ref, rtol=1e-4, what="f1..f5 with rigid axial/torsion")
    st.check(np.all(fr > 0.05), "no zero frequency from the multipliers")

# 3. 10 elements with rigid axial/torsion: 60 node DOFs - 20 constraints = 40 finite eigenvalues.
# Asking for 44 computes the 40 finite ones with a warning (never a spurious 0, infinity or NaN padding).
path, out = st.run("modal_cantilever_nev44", beam_x(L, W, T, 10, {1: {"fix": True}}, flex=(3, 4, 5, 6)),
                   args=["-eps_nev", "44"], expect_exit=0)
with st.h5(path) as f:
    fr = f["freq"][0]
    print(f"  -eps_nev 44: {fr.size} frequencies, min {fr.min():.6g} Hz, max {fr.max():.6g} Hz")
    st.check(fr.size == 40 and np.all(np.isfinite(fr)), f"{fr.size} frequencies written, expected the 40 finite ones")
    st.check(np.all(fr > 0.05), "no zero frequency from the infinite eigenvalues")
st.check("the model has 40 finite ones" in out and "computing 40" in out, "warning names the 40 finite modes")
st.done()
