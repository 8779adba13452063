"""The direct solver of ANCF chains (issue 12 item 2). In dynamics on several processes each rank
factors its part of the chain with PETSc's LU in reverse Cuthill-McKee order and the unknowns
coupling the ranks are corrected exactly (useCutCorrectedLU, -dynamics_chain_lu, default auto = cut
here); -dynamics_chain_lu redundant and statics: every process factors the whole matrix
(PCREDUNDANT, useChainLU in src/solvers/solver_defaults.hpp). Both instead of MUMPS, whose factorization of a chain is 5-10x slower
(A1g, 16384 elements, 2 ranks: 100 ms against 12 ms per factorization, 30 ms against 2 ms per solve;
docs/performance.md, Dynamics). In dynamics (the time-step matrix) and in statics (the fine LU of the
two-level preconditioner, options prefix fine_).

A1g (the A1 cantilever swinging down under gravity, h = 1e-3) on 1024 elements, 2 ranks, 10 steps:
- the default's -ksp_view names the cut-corrected LU and its local LU in RCM order (the test fails
  when the default is dropped: PCREDUNDANT or MUMPS shows up instead);
- -dynamics_chain_lu redundant shows PCREDUNDANT (fails when the option is ignored);
- the cut-corrected LU is a registered PC type (cutlu): -pc_type cutlu selects it, and its option
  -pc_cutlu_max_coupling reaches it (a bound of 1 coupling unknown stops the run, exit 4), also as
  -rotated_pc_cutlu_max_coupling inside the node-rotated kept matrix (PC type noderotated);
- the tips agree: default, PCREDUNDANT, MUMPS (-pc_type lu -pc_factor_mat_solver_type mumps) and
  one process (PETSc's LU in RCM order).
Measured (2026-11-26): tip (-7.37e-14, -4.905000e-04) m in all four runs, 20 Newton iterations on
3 Jacobians each; differences to PCREDUNDANT (0, 1.7e-18) m, to MUMPS (0, 3.4e-18) m, to one process
(0, 5.2e-18) m. Statics: 4.5e-13 m to MUMPS, 4.7e-13 m to one process. Runtime 4 s.
"""
import re

import numpy as np

import sinewtest as st
from ancf_scenes import cantilever, text, tip_displacement

N, STEPS, H = 1024, 10, 1e-3
SCENE = text(cantilever(N, EA=1e6, EI=833.3333333333333, gravity=[0, -9.81],
                        dynamics={"tend": STEPS * H, "dt": H, "spectral_radius": 0.6, "output_every": STEPS}))


def run(name, np_=2, args=()):
    h5, out = st.run(name, SCENE, np_=np_, args=list(args))
    m = re.search(r"(\d+) Newton iterations on (\d+) Jacobians", out)
    with st.h5(h5) as f:
        st.close(f["time"][-1], STEPS * H, rtol=1e-12, what=f"{name}: end time reached")
        tip = np.array(tip_displacement(f))
    print(f"  {name}: {m.group(1)} Newton iterations on {m.group(2)} Jacobians, tip {tip}")
    return tip, out


tip, out = run("chain_default", args=["-ksp_view"])
view = out.split("time step 0/")[-1]
st.check("cut-corrected LU" in view, "the default time-step solver of a 2-rank ANCF chain is not the cut-corrected LU")
st.check("mumps" not in view.lower(), "MUMPS appears in the default time-step solver of an ANCF chain")
st.check(re.search(r"ordering:\s*rcm", view) is not None, "the chain's LU is not in RCM order (-ksp_view)")
st.check("type: cutlu" in view, "the cut-corrected LU is not the registered PC type cutlu (-ksp_view)")
# a registered PC type (issue 23): PETSc's options name it and reach its SetFromOptions
_, out_c = run("chain_user_cutlu", args=["-dynamics_chain_lu", "redundant", "-pc_type", "cutlu", "-ksp_view"])
st.check("type: cutlu" in out_c.split("time step 0/")[-1], "-pc_type cutlu from the command line is not used")
# its options carry the prefix of the KSP it sits in: the time-step KSP's, or rotated_ inside the
# node-rotated kept matrix (PC type noderotated, the default here)
for name, args in (("chain_cutlu_bound", ["-dynamics_node_rotation", "false", "-pc_cutlu_max_coupling", "1"]),
                   ("chain_cutlu_bound_rotated", ["-rotated_pc_cutlu_max_coupling", "1"])):
    _, out_x = st.run(name, SCENE, np_=2, args=args, expect_exit=4)
    st.check("-pc_cutlu_max_coupling" in out_x and "at most 1" in out_x,
             f"{name}: {' '.join(args)} does not reach the cut-corrected LU: {out_x[-600:]}")
# -dynamics_chain_lu redundant: every rank factors the whole chain (PCREDUNDANT), the former default
tip_r, out_r = run("chain_redundant", args=["-dynamics_chain_lu", "redundant", "-ksp_view"])
view_r = out_r.split("time step 0/")[-1]
st.check("type: redundant" in view_r and "cut-corrected LU" not in view_r,
         "-dynamics_chain_lu redundant: the time-step solver is not PCREDUNDANT (-ksp_view)")
dr = np.abs(tip - tip_r)
print(f"  tip difference to PCREDUNDANT {dr} m")
st.check(dr.max() < 1e-12, f"tip differs from PCREDUNDANT's by {dr} m: 1e-12 m expected")
tip_m, _ = run("chain_mumps", args=["-pc_type", "lu", "-pc_factor_mat_solver_type", "mumps"])
tip_1, _ = run("chain_one", np_=1)
dm, d1 = np.abs(tip - tip_m), np.abs(tip - tip_1)
print(f"  tip difference to MUMPS {dm} m, to one process {d1} m (deflection {np.linalg.norm(tip):.3g} m)")
st.check(dm.max() < 1e-12, f"tip differs from MUMPS's by {dm} m: 1e-12 m expected")
st.check(d1.max() < 1e-12, f"tip differs from one process by {d1} m: 1e-12 m expected")

# statics: A1 under its weight, one load step, 2 ranks; the fine LU of the two-level preconditioner
# (1024 elements: the coarse space is built) is the redundant PETSc LU; tip vs MUMPS and one process.
# Measured (2026-11-26): tip (-0.50130585, -1.2325101) m; MUMPS (1.5e-12, 1.2e-12) m and one process
# (1.2e-12, 1.0e-12) m from it (the Newton update tolerance; 1e-9 m allowed).
STATIC = text(cantilever(N, EA=1e6, EI=833.3333333333333, gravity=[0, -9.81]))


def static(name, np_=2, args=()):
    h5, out = st.run(name, STATIC, np_=np_, args=list(args))
    with st.h5(h5) as f:
        tip = np.array(tip_displacement(f))
    print(f"  {name}: tip {tip}")
    return tip, out


stip, out = static("chain_static", args=["-fine_ksp_view", "-ksp_view"])
st.check("type: cablecoarse" in out, "the two-level preconditioner is the registered PC type cablecoarse (-ksp_view)")
st.check("type: redundant" in out and re.search(r"ordering:\s*rcm", out) is not None and "mumps" not in out.lower(),
         "the fine LU of a 2-rank ANCF chain in statics is not the redundant PETSc LU in RCM order (-fine_ksp_view)")
stip_m, _ = static("chain_static_mumps", args=["-fine_pc_type", "lu", "-fine_pc_factor_mat_solver_type", "mumps"])
stip_1, _ = static("chain_static_one", np_=1)
for other, what in ((stip_m, "MUMPS"), (stip_1, "one process")):
    d = np.abs(stip - other)
    print(f"  statics: tip difference to {what} {d} m")
    st.check(d.max() < 1e-9, f"statics: tip differs from {what} by {d} m: 1e-9 m expected")
st.done()
