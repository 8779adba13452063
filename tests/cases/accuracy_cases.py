"""Scenes and checks shared by the -target_error system tests (docs/accuracy.md): a cantilever's
bending frequencies (reference B3, Euler-Bernoulli) and an Euler column's buckling multipliers
(reference B2), both slender enough (thickness / length 1e-4) that shear and rotary inertia stay
below 1e-7 of the answers, so the true error is the discretization error."""
import numpy as np

import sinewtest as st
from modal_util import E, beam_x

L, W, T = 1.0, 0.01, 1e-4
# beta_n L of the clamped-free beam to 16 digits (cos b cosh b = -1): the 9 digits of modal_util's
# table leave 1.4e-9 in f1, above the smallest errors compared here
BETA_L = np.array([1.875104068711961, 4.694091132974175, 7.854757438237613])
A, I = W * T, W * T**3 / 12
FREQ_REF = BETA_L**2 * np.sqrt(E * I / (7800.0 * A * L**4)) / (2 * np.pi)
# fixed-free column under P0 = P_cr / 2: mu_n = (2n - 1)^2 * 2
P_CR = np.pi**2 * E * I / (2 * L) ** 2
BUCK_REF = np.array([2.0, 18.0])


def cantilever(nbeams, opt=None):
    o = {"nfreq": 3}
    o.update(opt or {})
    return beam_x(L, W, T, nbeams, {1: {"fix": True}}, opt=o)


def column(nbeams, opt=None):
    o = {"loadsteps": 1, "calcbuck": True, "nbuck": 2}
    o.update(opt or {})
    return beam_x(L, W, T, nbeams, {1: {"fix": True}, 2: {"force": [-0.5 * P_CR, 0, 0]}}, dens=0, opt=o)


def check_answer(name, path, dataset, ref, target):
    """The reported level's values against the reference: the true error at most the target; the
    estimate within a factor 3 of the true error for the quantity that limits and for every quantity
    whose true error is above target / 100 (below it, the reference's own digits and the model's
    shear terms are of the same size). Returns the /accuracy group's figures."""
    with st.h5(path) as f:
        g = f["accuracy"]
        names = [n for n in g.attrs["quantities"].split("\n") if n]
        values = f[dataset][-1][: len(ref)]
        est_all = g["error"][-1]
        cols = [names.index(f"{dataset} {k + 1}") for k in range(len(ref))]
        est = est_all[cols]
        true = np.abs(values / ref - 1)
        info = dict(levels=len(g["level"]), unknowns=int(g["unknowns"][-1]), time=float(np.sum(g["wall_time"][:])),
                    true=float(true.max()), estimate=float(g["worst_error"][-1]), met=int(g.attrs["met"]))
        print(f"  {name}: target {target:g}: {info['levels']} levels, {info['unknowns']} unknowns, "
              f"{info['time']:.2f} s; true errors {np.array2string(true, precision=2)}, "
              f"estimates {np.array2string(est, precision=2)}, worst estimate {info['estimate']:.2e}")
        st.check(info["met"] == 1, f"{name}: /accuracy met = 1")
        st.check(true.max() <= target, f"{name}: true error {true.max():.2e} above the target {target:g}")
        for k in range(len(ref)):
            if true[k] > target / 100 or k == int(np.argmax(true)):
                r = est[k] / true[k]
                st.check(1 / 3 <= r <= 3, f"{name}: {dataset} {k + 1}: estimate {est[k]:.2e} vs true error "
                                          f"{true[k]:.2e} (ratio {r:.2f}, outside 1/3..3)")
        st.check(np.all(est_all[np.isfinite(est_all)] <= target), f"{name}: every estimate within the target")
    return info
