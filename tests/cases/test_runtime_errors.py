"""Issue 13 reproducers (run-time side), each on 1 and 2 ranks under a timeout, checking the exit code
and the one "error:" line (rank 0 only); never a hang, signal, MPI_ABORT or raw PETSc trace:
  1. orien parallel to the element axis with nbeams 1 (the kernel fails on one rank only): exit 2 with
     the orien message and the element (2 ranks: SEGV exit 59, later a hang);
  2. PETSc/SLEPc errors at run time, forced by solver flags (dens/stiffness 1e308 are scene errors
     now, test_scene_robustness): a KSP that must converge and cannot in the statics Newton solve and
     in the eigensolver's shift-and-invert, an unknown -eps_type: exit 4 "internal solver error in
     <phase>" with PETSc's reason (exit 91 / 86 with a trace on 1 rank, a hang on 2 before);
  4./6. non-finite ANCF user functions: 1/0*curvature in dynamics ("the mass matrix is singular"
     before), sqrt(-1), log(0), exp(1000) in statics, 1/0 in an axial law: exit 3 naming the user
     function, its set, the element and the time, the same exit code on 1 and 2 ranks;
  5. nfreq above the number of unknowns (24 unknowns, nfreq 25 and 100000): exit 0, the 24 finite
     frequencies, a warning naming the unknowns, a small file, quickly (NaN frequencies and exit 3,
     or 48 s and a 373 MB file before)."""
import os
import re
import subprocess
import time

import numpy as np

import sinewtest as st

TIMEOUT = 120

BEAM = """nodes:
  - [0, 0, 0]
  - [1, 0, 0]
  - [2, 0, 0]
elements:
  - [1, 2]
  - [2, 3]
eprops:
  - elems: [1]
    flex: [1, 2, 3, 4, 5, 6]
    emod: 210e9
    smod: 80e9
    dens: 7800
    cshape: rect
    dim: [0.02, 0.01]
    orien: [0, 0, 1]
    nbeams: {nbeams}
  - elems: [2]
    flex: [1, 2, 3, 4, 5, 6]
    emod: 210e9
    smod: 80e9
    dens: 7800
    cshape: rect
    dim: [0.02, 0.01]
    orien: {orien2}
    nbeams: {nbeams}
nprops:
  1: {{fix: true}}
{load}opt:
  loadsteps: 2
  calcfreq: true
  calccompl: false
{extra}"""


def beam(orien2="[0, 0, 1]", nbeams=1, load="  3: {force: [0, 0, -10]}\n", extra=""):
    return BEAM.format(orien2=orien2, nbeams=nbeams, load=load, extra=extra)


with open(os.path.join(st.SOURCE, "runs", "ancf_cantilever.yaml")) as f:
    ANCF_STATICS = f.read()
with open(os.path.join(st.SOURCE, "runs", "ancf_userfunction.yaml")) as f:
    ANCF_DYNAMICS = f.read()


def with_law(text, law, expr):
    anchor = "    useReducedOrderIntegration: 0\n"
    assert anchor in text
    return text.replace(anchor, anchor + f"    {law}: \"{expr}\"\n")


assert "atan(10*curvature)" in ANCF_DYNAMICS
dyn_div0 = ANCF_DYNAMICS.replace("atan(10*curvature)", "atan(10*curvature) + 1/0*curvature")


def run(name, text, np_, args=()):
    path = st.scene_file("rt_" + name, text)
    out = os.path.join(st.WORK, f"rt_{name}_{np_}.h5")
    for stale in (out, out + ".part"):
        if os.path.exists(stale):
            os.remove(stale)
    cmd = st.launcher(np_) + [path, "-o", out] + list(args)
    t0 = time.time()
    try:
        p = subprocess.run(cmd, env=st.ENV, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=TIMEOUT)
    except subprocess.TimeoutExpired:
        st.fail(f"{name} on {np_} rank(s): no exit within {TIMEOUT} s (hang)")
        return None, "", out, TIMEOUT
    return p.returncode, p.stdout, out, time.time() - t0


def expect(name, text, code, want, avoid=(), args=()):
    """Runs on 1 and 2 ranks: exit `code`, one error line holding every fragment of `want`."""
    codes = {}
    for np_ in (1, 2):
        rc, log, out, secs = run(name, text, np_, args)
        codes[np_] = rc
        lines = [ln for ln in log.splitlines() if ln.startswith("error:")]
        msg = lines[0] if lines else ""
        print(f"{name} ({np_} rank{'s' if np_ > 1 else ''}): exit {rc} in {secs:.1f} s: {msg[:400]}")
        if rc is None:
            continue
        st.check(rc == code, f"{name} on {np_} rank(s): exit {rc}, expected {code}")
        st.check(len(lines) == 1, f"{name} on {np_} rank(s): {len(lines)} error lines, expected 1")
        for frag in want:
            st.check(frag in msg, f"{name} on {np_} rank(s): message lacks {frag!r}")
        for frag in avoid:
            st.check(frag not in msg, f"{name} on {np_} rank(s): misleading {frag!r}")
        st.check(not re.search(r"Signal|Segmentation|MPI_ABORT|terminate called|PETSC ERROR", log),
                 f"{name} on {np_} rank(s): no signal, abort or raw PETSc trace")
    st.check(codes[1] == codes[2], f"{name}: the same exit code on 1 and 2 ranks ({codes})")


# 1. orien parallel to the axis of element 2 (one rank builds it, the other does not)
expect("orien_parallel", beam(orien2="[1, 0, 0]"), 2,
       ["eprops.orien", "orien is parallel to the beam axis", "(element 2)"])

# 2. PETSc/SLEPc errors at run time
expect("ksp_statics", beam(nbeams=2), 4,
       ["internal solver error in statics", "KSPSolve has not converged", "DIVERGED_ITS", "PETSc error"],
       args=["-ksp_error_if_not_converged", "-ksp_type", "gmres", "-pc_type", "none", "-ksp_max_it", "1"])
expect("ksp_eigen", beam(nbeams=2), 4,
       ["internal solver error in natural frequencies", "KSPSolve has not converged", "PETSc error"],
       args=["-eigen_dense_max_unknowns", "0", "-eigen_operator", "assembled", "-st_ksp_type", "cg", "-st_pc_type", "none", "-st_ksp_max_it", "2",
             "-st_ksp_error_if_not_converged"])  # SLEPc (not the dense path of small models) with the assembled operator: its ST KSP is forced to fail
expect("eps_type", beam(nbeams=2), 4, ["internal solver error", "Unknown EPS type given: bogus"], args=["-eps_type", "bogus"])

# 4. and 6. non-finite user functions: which one, which set, element and time
expect("uf_dynamics_div0", dyn_div0, 3,
       ['bendingMomentUserFunction "', "1/0*curvature", "of eprops(1) returned nan", "not finite", "at element 1",
        "time t = 0"], avoid=["mass matrix", "singular"])
for tag, expr, value in (("sqrt", "sqrt(-1)", "nan"), ("log", "log(0)", "-inf"), ("exp", "exp(1000)", "inf")):
    expect("uf_statics_" + tag, with_law(ANCF_STATICS, "bendingMomentUserFunction", expr), 3,
           [f'bendingMomentUserFunction "{expr}" of eprops(1) returned {value}', "at element 1 (part 1 of 32)", "time t = "],
           avoid=["mechanism", "singular"])
expect("uf_statics_axial_div0", with_law(ANCF_STATICS, "axialForceUserFunction", "1/0"), 3,
       ['axialForceUserFunction "1/0" of eprops(1) returned inf', "at element 1", "time t = "], avoid=["mechanism"])

# 5. nfreq above the number of unknowns: 2 beams x 2 parts, node 1 clamped: 4 free nodes = 24 unknowns
for nfreq in (25, 100000):
    text = beam(nbeams=2, load="", extra=f"  nfreq: {nfreq}\n")
    for np_ in (1, 2):
        rc, log, out, secs = run(f"nfreq_{nfreq}", text, np_)
        warn = [ln for ln in log.splitlines() if ln.startswith("warning:") and "natural frequencies" in ln]
        print(f"nfreq {nfreq} ({np_} rank(s)): exit {rc} in {secs:.1f} s: {warn[0] if warn else '(no warning)'}")
        st.check(rc == 0, f"nfreq {nfreq} on {np_} rank(s): exit {rc}, expected 0")
        st.check("24 unknowns" in log, f"nfreq {nfreq}: 24 unknowns")
        st.check(len(warn) == 1 and f"{nfreq} natural frequencies asked for" in warn[0] and "computing at most 24" in warn[0],
                 f"nfreq {nfreq} on {np_} rank(s): the warning names nfreq and the 24 unknowns")
        st.check(secs < 60, f"nfreq {nfreq} on {np_} rank(s): {secs:.1f} s")
        if rc == 0:
            size = os.path.getsize(out) + os.path.getsize(out[:-3] + ".xdmf")
            st.check(size < 2_000_000, f"nfreq {nfreq}: result files {size} bytes")
            with st.h5(out) as f:
                fr = f["freq"][-1]
                print(f"  {fr.size} frequencies, {fr.min():.6g} .. {fr.max():.6g} Hz, files {size} bytes")
                st.check(fr.size == 24 and np.all(np.isfinite(fr)) and np.all(fr > 0),
                         f"nfreq {nfreq} on {np_} rank(s): 24 finite positive frequencies ({fr.size})")
st.done()
