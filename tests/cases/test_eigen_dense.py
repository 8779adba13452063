"""The dense eigensolver path (-eigen_dense_max_unknowns, src/step/dense_eigen.*) gives SLEPc's results:
each scene runs on 2 ranks with the dense path (default bound) and with -eigen_dense_max_unknowns 0
(SLEPc), and every dataset of the two files is compared. Scenes: the crosshinge (frequencies with the
element-wise operator and rigid-body multipliers, buckling with the assembled operator), a loaded
cantilever (buckling with the element-wise operator, nfreq: all) and a free-free beam (rigid-body
modes at omega = 0). Mode shapes are compared where they are defined: the first 12, of isolated
nonzero eigenvalues. Eigenvalues agree to 1e-10 relative (measured: 1e-13 frequencies, 4e-12
buckling); mode shapes to 2e-6 after the sign (measured: crosshinge 4.1e-9 on the fifth mode's
rotations, where SLEPc itself differs by 9.4e-9 between 1 and 2 ranks, 2.7e-10 buckling modes;
free-free beam 7.6e-7 on its third elastic mode); the
error datasets hold accuracy figures below -eps_tol on both paths; every other dataset is equal.
The summary names the dense solver only when it ran, so an ignored option fails the test."""
import os


import sinewtest as st
from modal_util import beam_x
from path_compare import compare_files

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
with open(os.path.join(ROOT, "runs", "crosshinge.yaml")) as f:
    crosshinge = f.read().replace("loadsteps: 10", "loadsteps: 3")
cantilever = beam_x(0.2, 0.02, 1e-3, 8, {1: {"fix": True}, 2: {"force": [-10, 0, 0]}},
                    opt={"loadsteps": 2, "calcbuck": True, "nfreq": "all"})
freefree = beam_x(0.2, 0.02, 1e-3, 6, {}, opt={"nfreq": 9})
MARK = "eigensolver: dense LAPACK"


def tolerance(n):
    """Eigenvalues and the state-space matrices (built from them) 1e-10; everything else 1e-12."""
    return 1e-10 if n in ("freq", "buck") or n.startswith("statespace") else 1e-12


for name, scene in (("crosshinge", crosshinge), ("cantilever", cantilever), ("freefree", freefree)):
    dense, log_d = st.run(f"dense_{name}", scene)
    slepc, log_s = st.run(f"slepc_{name}", scene, args=["-eigen_dense_max_unknowns", "0"])
    st.check(MARK in log_d, f"{name}: the dense run names the dense eigensolver in its summary")
    st.check(MARK not in log_s, f"{name}: -eigen_dense_max_unknowns 0 runs SLEPc")
    st.check("warning" not in log_d, f"{name}: no warning on the dense path")
    with st.h5(dense) as a, st.h5(slepc) as b:
        worst = compare_files(name, a, b, tolerance, first=12)
        print(f"  {name}: " + ", ".join(f"{g} {w:.1e}" for g, w in sorted(worst.items()) if w > 0 or g in ("freq", "buck")))
st.done()
