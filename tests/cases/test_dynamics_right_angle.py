"""Issue 14: the right-angle cantilever of Simo & Vu-Quoc 1988 under an out-of-plane pulse (2 ranks).
Simo, J. C. & Vu-Quoc, L. (1988), "On the dynamics in space of rods undergoing large motions - a
geometrically exact approach", CMAME 66, 125-161; re-analysed by Le, Battini & Hjiaj (2012), "Dynamics
of 3D beam elements in a corotational context", FEAD 61, 97-111 (their Example 1). Two legs of length
10, the first along y clamped at the origin, the second along x from the elbow (0, 10, 0) to the tip
(10, 10, 0); EA = GA = 1e6, GJ = EI = 1e3, A_rho = 1, J_rho = diag(20, 10, 10) (axial, bending,
bending); a force F_z(t) at the elbow rising linearly from 0 to 50 at t = 1 and back to 0 at t = 2,
then free motion in combined bending and torsion with amplitudes of the order of the legs.
Model: 10 beam elements per leg, circular section d = sqrt(16e-3) with E = 1e3 / I and G = E/2
(EA = 1e6, EI = GJ = 1e3; the shear stiffness is Cowper's kappa G A = 6/7 G A = 4.3e5 against the
paper's GA = 1e6, negligible for these slender legs: 12 EI / (kGA h^2) = 0.028); the
inertia is lumped at the nodes (dens 0): mass A_rho h and mominertia J_rho h (half at the ends, the
elbow half of each leg's J_rho in its own axes), so the rotary inertia J_rho, which the beam kernel's
consistent mass cannot represent (it takes rho A and rho I of the section, here rho I = I / A = 1e-3),
and its gyroscopic moments are exact. Generalized alpha with rho_inf = 1, dt = 0.1, t = 0..30 (results
every 0.2), the span of the published curves (the digitized Simo & Vu-Quoc curve below covers
t = 0..30, and the verification code runs Le's example to t = 30).
References (the literature gives curves only):
  Le et al. 2012, Fig. 3, as read in a public verification code (YQY, PaperBeamDynamicsVerification:
  "read from the published plot axes"): tip maximum 8.2, tip minimum -9.7, elbow minimum -4.0, elbow
  maximum 6.2 (that code compares them with the extrema of its own run over 0..30 s);
  Simo & Vu-Quoc 1988's tip curve as digitized in FinEtoolsFlexStructures.jl
  (examples/beams/nonlin_transient/simo_vuquoc_examples.jl, 45 points): maximum 8.32.
Tolerance 0.3 = the reading accuracy: the two readings of the tip maximum differ by 0.12; the
digitized curve's trough (two points at -9.21, 0.5 above Le's reading) is too coarse to use, and its
time axis runs about 0.8 ahead of this computation (its tip is at 0.93 at t = 1.54, while the pulse has
barely reached the tip here: 0.05), so only extrema are compared, not times.
Measured (2 ranks, this model, results every 0.2): tip maximum 8.215 at t = 7.4, tip minimum -9.698
at t = 16.0, elbow minimum -4.056 at t = 11.0, elbow maximum 6.145 at t = 25.4 (every step: 8.227,
-9.698, -4.062, 6.145; dt = 0.05: 8.232 at 7.5, -9.716 at 15.95, -4.075 at 10.9, 6.126 at 25.3; 20
elements per leg: 8.236, -9.697, -4.036, 6.131 at 25.2). The elbow maximum is that of the second swing:
the elbow's first peak, during the pulse, is 5.50 at t = 3.2 (5.51 with dt = 0.05, 5.50 with 20
elements per leg). Earlier versions of this test stopped at t = 17 and compared that first peak with
the reading 6.2, which it misses by 0.7 under every refinement; over the figure's 0..30 s the maximum
matches the reading to 0.06, so 6.2 is the second-swing maximum, not the pulse peak.
Switched off (run once): with the rotary inertia reduced to the section's own (mominertia times 1e-4,
J_rho = diag(2e-3, 1e-3, 1e-3)) the tip maximum is 9.43 at t = 4.8 (outside the tolerance) and Newton
fails at t = 12.25. The test took 8 s to t = 30 (2026-11-27, shared 2-core machine at a quiet moment;
the former run to t = 17 took about 45 s under load)."""
import numpy as np

import right_angle_scene as ras
import sinewtest as st

n, tend = 10, 30.0
scene = ras.scene(n=n, dt=0.1, tend=tend)
h5, out = st.run("dynamics_right_angle", scene)
with st.h5(h5) as f:
    t, p, conv = f["time"][:], f["node/p"][:], int(f.attrs["converged"])
tip, elbow = p[:, 2 * n, 2], p[:, n, 2]
st.check(conv == 1 and abs(t[-1] - tend) < 1e-9, f"converged to t = {tend} ({t[-1]})")
for name, v, fn in [("tip maximum", tip, np.argmax), ("tip minimum", tip, np.argmin),
                    ("elbow minimum", elbow, np.argmin), ("elbow maximum", elbow, np.argmax)]:
    i = fn(v)
    print(f"  {name} {v[i]:+.4f} at t = {t[i]:.2f}")
le = ras.LE_EXTREMA
st.close(tip.max(), le["tip maximum"], atol=0.3, what="tip maximum vs Le et al. 2012 Fig. 3 (reading 8.2)")
st.close(tip.max(), ras.SIMO_VUQUOC_TIP[:, 1].max(), atol=0.3, what="tip maximum vs Simo & Vu-Quoc 1988 as digitized (8.32)")
st.close(tip.min(), le["tip minimum"], atol=0.3, what="tip minimum vs Le et al. 2012 Fig. 3 (reading -9.7)")
st.close(elbow.min(), le["elbow minimum"], atol=0.3, what="elbow minimum vs Le et al. 2012 Fig. 3 (reading -4.0)")
st.close(elbow.max(), le["elbow maximum"], atol=0.3, what="elbow maximum (second swing) vs Le et al. 2012 Fig. 3 (6.2)")
# the whole digitized tip curve: its time axis leads this computation (best shift measured 0.8 s);
# after the best shift in 0 .. 2 s the RMS difference over its 45 points (measured 0.45)
rms0, shift, rms = ras.digitized_fit(t, tip, 0.1)
print(f"  tip vs Simo & Vu-Quoc's digitized curve: RMS {rms0:.3f} unshifted, {rms:.3f} shifted by {shift:.1f} s")
st.check(rms < 0.6 and 0.5 <= shift <= 1.1, f"tip history vs the digitized curve: RMS {rms:.3f} at shift {shift:.1f} s")
st.check(t[np.argmax(tip)] < t[np.argmin(elbow)] < t[np.argmin(tip)] < t[np.argmax(elbow)],
         "the order of the extrema: tip maximum, elbow minimum, tip minimum (as in the published curves), "
         "then the elbow maximum")
early = t < 5.0
st.check(elbow[early].max() < elbow.max() - 0.3, "the elbow's first peak (in the pulse) is not its maximum")
st.done()
