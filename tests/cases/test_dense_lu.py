"""The dense LU of small one-process tangents (-dense_max_unknowns, PC type denselu, src/solvers/dense_lu.*)
gives MUMPS's results, and it is the path that runs: each scene runs on 1 rank with the default bound
(dense LU) and with -dense_max_unknowns 0 (MUMPS), both with -log_view. The dense run must log
SinewDenseLU factorizations (statics Newton, compliance, constraint check) and no MUMPS factorization
(MatLUFactorNum), the MUMPS run the reverse; its summary names the dense LU of the compliance, so an
ignored option fails the test. Every dataset of the two files is compared (relative 2-norm):
1e-12 for the state (measured 2e-16 on the crosshinge) and the load factors; 5e-12 for reactions and
stresses, sums of internal forces that cancel (measured 1.3e-12; MUMPS's own 1- and 2-rank results
differ by 8.4e-13 there); 1e-10 for the eigenvalues (measured 4e-12 buckling, 5e-13 frequencies);
5e-10 for the compliance matrices (measured 7.1e-11, 2.6e-10 before the dense solve's refinement
step; MUMPS's 1- and 2-rank results differ by 5.2e-11: the tangent's condition); 2e-6 for mode shapes
of isolated eigenvalues as test_eigen_dense (measured 1.1e-9 frequency modes); the error datasets
are accuracy figures at round-off, each path its own, below 1e-8."""
# ctest-processors: 1
import os
import re


import sinewtest as st
from modal_util import beam_x
from path_compare import compare_files

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
with open(os.path.join(ROOT, "runs", "crosshinge.yaml")) as f:
    crosshinge = f.read().replace("loadsteps: 10", "loadsteps: 3")
cantilever = beam_x(0.2, 0.02, 1e-3, 8, {1: {"fix": True}, 2: {"force": [-10, 0, 0]}},
                    opt={"loadsteps": 2, "calcbuck": True, "calccompl": True, "nfreq": 4})


def event_count(log, event):
    m = re.search(r"^" + event + r"\s+(\d+)", log, re.M)
    return int(m.group(1)) if m else 0


def tolerance(n):
    """The measured bounds of the docstring, by dataset."""
    if n in ("freq", "buck"):
        return 1e-10
    if n in ("node/CMglob", "node/CMloc"):
        return 5e-10
    if n in ("node/Freac", "node/Mreac", "stressmax", "element/stressmax", "cell/lines/stress"):
        return 5e-12
    return 1e-12


for name, scene in (("crosshinge", crosshinge), ("cantilever", cantilever)):
    dense, log_d = st.run(f"denselu_{name}", scene, np_=1, args=["-log_view"])
    mumps, log_m = st.run(f"mumps_{name}", scene, np_=1, args=["-log_view", "-dense_max_unknowns", "0"])
    nd, nm = event_count(log_d, "SinewDenseLU"), event_count(log_m, "SinewDenseLU")
    st.check(nd > 0 and event_count(log_d, "MatLUFactorNum") == 0,
             f"{name}: the dense run factors by the dense LU only ({nd} SinewDenseLU, "
             f"{event_count(log_d, 'MatLUFactorNum')} MatLUFactorNum)")
    st.check(nm == 0 and event_count(log_m, "MatLUFactorNum") > 0, f"{name}: -dense_max_unknowns 0 factors with MUMPS")
    st.check("dense LU, up to -dense_max_unknowns" in log_d and "dense LU" not in log_m,
             f"{name}: the compliance summary names the solver that ran")
    with st.h5(dense) as a, st.h5(mumps) as b:
        worst = compare_files(name, a, b, tolerance)
        print(f"  {name}: {nd} dense LU factorizations; " + ", ".join(f"{g} {w:.1e}" for g, w in sorted(worst.items())))
st.done()
