"""-restart of a damped dynamics run (docs/dynamics.md "Damping"), 2 ranks: the continued run uses the
damping of the uninterrupted run, built at the state the time loop started from (stored at time
step 0 in /checkpoint_dynamics_start: U0, the start rotations, element states), on any rank count.

Model: the steel leaf of test_dynamics_adaptive.py (1 m, rect 20 mm x 2 mm, 4 elements) struck by
the tip pulse 40 sin^2(pi t / 0.005) N (t < 5 ms), then free; dt = 1e-3 to t = 0.3 s, spectral
radius 0.6, rows every 20 steps. Peak tip deflection 0.029 m (beta) .. 0.13 m (alpha, modal): the
leaf rotates by a few 1e-2 rad. Three damping kinds: stiffness-proportional beta = 1e-3 s,
mass-proportional alpha = 0.5 1/s, modal zeta = 0.02 (10 modes). Each run is stopped after 6 rows
(t = 0.1) on 2 ranks and continued on 1 rank; every dataset equals the uninterrupted 2-rank run
(restartutil.compare, 1e-12 norm-wise; derived datasets within twice the 1 vs 2 rank floor).
A beta run stopped again after 11 rows of its continuation (the restarted file carries the start
state) and continued on 2 ranks: equal too.
Reference: the uninterrupted run itself. MEASURED (this test): see the printed "largest relative
difference" lines; before the fix (C rebuilt from the resumed state) the tip history of the
continued run differed by 0.43 (beta), 8.2e-6 (alpha), 8.7e-4 (modal) of its peak; with it by
2.0e-14, 6.2e-14, 1.1e-13 (max over the rows of |tip y difference| / peak).
A checkpoint without /checkpoint_dynamics_start (older files; made here by deleting the group):
the run continues with a warning and the damping of the resumed state; for beta its tip history
differs by more than 0.1 of the peak (this is the former behaviour: the test's exact comparisons
fail without the stored start state).
Start rotations other than the identity: the leaf bent first by 1 N at the tip in 4 load steps
(start: static, tip rotation 0.18 rad), beta damping, stopped after 10 rows on 1 rank, continued
on 2: measured 5.8e-14 of the peak (modal damping, tried by hand: 9.4e-13, not in the test).
Rigid elements (multipliers in U): the crosshinge of test_restart_beam_dynamics with beta = 1e-3 s,
2 -> 1 ranks: state datasets 7.0e-15 (with the multipliers of U after the initial accelerations
instead of those the damping saw, 2.3e-6: the start state must be the damping's own).
45 s on the shared machine (load ~8).
Stiffness-proportional damping: the cases above are beta K0 of the start state, which the stored start
state is for: they run with -stiffness_damping initial (PETSC_OPTIONS). The default (corotated: the beams
damp their own strain rates, no matrix of a start state) is checked at the end: the beta leaf stopped
on 2 ranks and continued on 1 equals the uninterrupted run (and writes no start state: nothing to rebuild)."""
import os
import shutil

import h5py
import numpy as np

import beamtools as bt
import sinewtest as st
from restartutil import compare, restarted, stopped


st.ENV["PETSC_OPTIONS"] = "-stiffness_damping initial"  # beta K0 of the start state (see the docstring)


def scene(damp):
    return bt.leaf_pulse_scene(f"tend: 0.3, dt: 1e-3, spectral_radius: 0.6, output_every: 20, {damp}",
                               title="leaf, tip force pulse then free vibration, damped")


def tip_diff(a_path, b_path):
    with st.h5(a_path) as a, st.h5(b_path) as b:
        ua, ub = a["node/p"][:, -1, 1], b["node/p"][:, -1, 1]
        return np.max(np.abs(ua - ub)) / np.max(np.abs(ua))


cases = {"beta": "stiffness_proportional_damping: 1e-3", "alpha": "mass_proportional_damping: 0.5",
         "modal": "modal_damping: 0.02"}
for c, damp in cases.items():
    s = scene(damp)
    ref2, _ = st.run(f"rsdamp_{c}_ref2", s, np_=2)
    ref1, _ = st.run(f"rsdamp_{c}_ref1", s, np_=1)
    with st.h5(ref2) as f:
        st.check("checkpoint_dynamics_start/scalars" in f, f"{c}: /checkpoint_dynamics_start missing")
    part = stopped(f"rsdamp_{c}_part2", s, 2, 6)
    rest, out = restarted(f"rsdamp_{c}_rest1", s, 1, part)
    st.check("warning" not in out, f"{c}: unexpected warning on restart")
    d = tip_diff(ref2, rest)
    print(f"  {c}: continued 2 -> 1 ranks, tip history difference {d:.2e} of the peak")
    st.check(d < 1e-12, f"{c}: continued run's tip differs by {d:.2e} of the peak")
    compare(ref2, rest, f"{c} damping 2 -> 1 (stopped at t = 0.1)", other_ranks=ref1)
    if c == "beta":
        # the continued file is continued again (it holds the start state of the first run)
        part2, _ = restarted("rsdamp_beta_rest1_part", s, 1, part, args=["-stop_after_step", "11"], expect_exit=5)
        with st.h5(part2) as f:
            st.check("checkpoint_dynamics_start/scalars" in f, "beta: restarted file lacks /checkpoint_dynamics_start")
        rest2, _ = restarted("rsdamp_beta_rest2", s, 2, part2)
        compare(ref2, rest2, "beta damping 2 -> 1 -> 2 (stopped at t = 0.1, then at t = 0.2)", other_ranks=ref1)
        # an older checkpoint without the start state: warning, damping of the resumed state
        old = part.replace(".h5", "_old.h5")
        shutil.copyfile(part, old)
        with h5py.File(old, "r+") as f:
            del f["checkpoint_dynamics_start"]
        rold, out = restarted("rsdamp_beta_old1", s, 1, old)
        st.check("warning" in out and "checkpoint_dynamics_start" in out, "beta, old checkpoint: warning missing")
        d = tip_diff(ref2, rold)
        print(f"  beta, checkpoint without the start state (former behaviour): tip difference {d:.2e} of the peak")
        st.check(d > 0.1, f"beta, old checkpoint: difference {d:.2e}, expected the former > 0.1")

# start rotations that are not the identity: the leaf bent by a static tip force of 1 N in 4 load
# steps (opt.dynamics start: static; tip rotation 0.18 rad), then the pulse on top; stopped after
# 4 load-step + 6 time rows on 1 rank, continued on 2
bent = scene(cases["beta"] + ", start: static").replace('"40*', '"1 + 40*').replace(
    "  calcfreq: false\n", "  calcfreq: false\n  loadsteps: 4\n")
bref2, _ = st.run("rsdamp_bent_ref2", bent, np_=2)
bref1, _ = st.run("rsdamp_bent_ref1", bent, np_=1)
with st.h5(bref2) as f:
    st.check(f["load_factor"].shape[0] == 20 and f["node/r_axang"][4, -1, 0] > 0.1,
             "bent leaf: 4 load steps and a start rotation > 0.1 rad expected")
bpart = stopped("rsdamp_bent_part1", bent, 1, 10)
brest, _ = restarted("rsdamp_bent_rest2", bent, 2, bpart)
d = tip_diff(bref2, brest)
print(f"  bent leaf, beta: continued 1 -> 2 ranks, tip history difference {d:.2e} of the peak")
st.check(d < 1e-12, f"bent leaf: continued run's tip differs by {d:.2e} of the peak")
compare(bref2, brest, "bent leaf, beta damping 1 -> 2 (stopped at t = 0.1)", other_ranks=bref1)

# rigid elements (Lagrange multipliers in U): the cross-flexure hinge of runs/crosshinge.yaml in
# motion (as test_restart_beam_dynamics) with beta = 1e-3 s; the stored start state holds the
# multipliers the damping was built with (before the initial accelerations set lambda0: K0 has
# lambda terms); stopped after 6 rows on 2 ranks, continued on 1
with open(os.path.join(os.environ["SINEW_SOURCE_DIR"], "runs", "crosshinge.yaml")) as f:
    hinge = f.read().split("\nopt:")[0] + """
opt:
  calcfreq: false
  calccompl: false
  dynamics: {tend: 0.05, dt: 0.0005, spectral_radius: 0.9, output_every: 10, stiffness_proportional_damping: 1e-3}
"""
href2, _ = st.run("rsdamp_hinge_ref2", hinge, np_=2)
href1, _ = st.run("rsdamp_hinge_ref1", hinge, np_=1)
hpart = stopped("rsdamp_hinge_part2", hinge, 2, 6)
hrest, _ = restarted("rsdamp_hinge_rest1", hinge, 1, hpart)
compare(href2, hrest, "crosshinge, beta damping 2 -> 1 (stopped at t = 0.025)", other_ranks=href1)

# the default -stiffness_damping corotated: strain-rate damping of the beams needs no start state
del st.ENV["PETSC_OPTIONS"]
s = scene(cases["beta"])
cref2, _ = st.run("rsdamp_corot_ref2", s, np_=2)
cref1, _ = st.run("rsdamp_corot_ref1", s, np_=1)
with st.h5(cref2) as f:
    st.check("checkpoint_dynamics_start/scalars" not in f, "corotated beta: no start state expected")
cpart = stopped("rsdamp_corot_part2", s, 2, 6)
crest, out = restarted("rsdamp_corot_rest1", s, 1, cpart)
st.check("warning" not in out, "corotated beta: unexpected warning on restart")
d = tip_diff(cref2, crest)
print(f"  corotated beta: continued 2 -> 1 ranks, tip history difference {d:.2e} of the peak")
st.check(d < 1e-12, f"corotated beta: continued run's tip differs by {d:.2e} of the peak")
compare(cref2, crest, "corotated beta damping 2 -> 1 (stopped at t = 0.1)", other_ranks=cref1)
st.done()
