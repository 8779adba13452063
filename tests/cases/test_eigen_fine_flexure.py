"""Frequencies of a flexure with rigid bodies (constraint multipliers) on fine meshes (issue 12
item 1; docs/modal.md, "Eigenvalues on fine meshes"): runs/crosshinge.yaml, leaves split into
nbeams elements, on 2 ranks.

Figures measured on the scene before `cw: true` was added to it (the test compares runs of the
current scene with each other).
- Unloaded, the three lowest frequencies at 1024 elements per leaf agree with those at 256 to the
  discretization error (measured: f1 4e-12, f2 and f3 6.7e-10; 64 vs 256: f1 2e-12, f2 3e-8). The
  assembled stiffness and its LU alone (-eigen_operator assembled, the default for such models
  before) drifted with the mesh: f1 1.1e-7 off at 256, 1.8e-6 at 1024, 4.6e-6 at 4096 elements.
- Loaded (the scene's support load and moment, one load step): the element-wise operator made
  symmetric as the assembled tangent gives the assembled method's frequencies (measured 6.6e-10 at
  64 elements, the assembled method's own rank-to-rank spread is 4e-10; before the skew part was added f2 differed by 2.1e-5 at every mesh size), and
  1 and 2 ranks agree (measured 0 difference with the element-wise operator)."""
import os
import re

import numpy as np

import sinewtest as st

BASE = open(os.path.join(st.SOURCE, "runs", "crosshinge.yaml")).read()


def scene(nbeams, loaded):
    s = BASE.replace("nbeams: 4", f"nbeams: {nbeams}").replace("loadsteps: 10", "loadsteps: 1")
    s = s.replace("calcbuck: true", "calcfreq: true\n  nfreq: 3").replace("stressperelement: true", "stressperelement: false")
    if not loaded:
        s = re.sub(r"force_initial: \[[^]]*\], moment: \[[^]]*\], ", "", s)
    return s


def freqs(name, nbeams, loaded, np_=2, args=()):
    path, out = st.run(name, scene(nbeams, loaded), np_=np_, args=list(args))
    with st.h5(path) as h:
        return np.array(h["freq"][-1][:3])


ref = freqs("flexure_u256", 256, False)
fine = freqs("flexure_u1024", 1024, False)
print(f"  unloaded: 256 elements {np.array2string(ref, precision=12)} Hz; 1024: relative "
      f"{np.array2string(fine / ref - 1, precision=2)}")
st.close(fine / ref, 1.0, atol=2e-9, what="unloaded crosshinge, 1024 vs 256 elements per leaf")

auto = freqs("flexure_l64", 64, True)
assembled = freqs("flexure_l64_assembled", 64, True, args=["-eigen_operator", "assembled"])
one = freqs("flexure_l64_1rank", 64, True, np_=1)
st.close(auto / assembled, 1.0, atol=2e-9, what="loaded crosshinge: element-wise (auto) vs assembled operator")
st.close(auto / one, 1.0, atol=1e-10, what="loaded crosshinge: 2 vs 1 ranks")
st.done()
