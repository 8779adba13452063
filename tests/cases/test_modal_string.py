"""A tensioned string with a small bending stiffness: pinned-pinned beam (L = 1, rect 10 x 0.1 mm,
40 elements; torsion held by a rigid arm at node 1) under an axial tension T ramped over 3 load
steps. Euler-Bernoulli beam-string: omega_n^2 = (n pi / L)^4 EI / rhoA + (n pi / L)^2 T / rhoA,
i.e. f_n = n/(2L) sqrt(T / rhoA) sqrt(1 + (n pi)^2 EI / (T L^2)); with T = 1000 pi^2 EI / L^2 the
string term dominates. The frequencies come from the tangent at each tensioned state (geometric
stiffness), so they rise with tension as the formula says. The static steps run with -force_rtol 1e-6: the
equilibrium residual of the stretched beam stalls at the round-off of its axial force."""
import numpy as np

import sinewtest as st
from modal_util import E, RHO, beam_x

L, W, T = 1.0, 0.01, 1e-4
EI, rhoA = E * W * T**3 / 12, RHO * W * T
tension = 1000 * np.pi**2 * EI / L**2
nprops = {1: {"fix_pos": True}, 2: {"fix_y": True, "fix_z": True, "force": [tension, 0, 0]}, 3: {"fix_z": True}}
path, out = st.run("modal_string", beam_x(L, W, T, 40, nprops, opt={"loadsteps": 3, "nfreq": 6},
                                        extra_nodes=[[0, 0.1, 0]], extra_elements=[[1, 3]]),
                   args=["-force_rtol", "1e-6"])
n = np.arange(1, 4)
with st.h5(path) as f:
    lam = f["load_factor"][:]
    # the x-z plane modes (torsion modes have no translation, y-plane modes are 100x stiffer)
    freq = []
    for k in range(len(lam)):
        z = [i for i in range(6) if np.max(np.abs(f[f"mesh/mode_freq_{i + 1}"][k][:, 2])) > 0.5]
        st.check(len(z) >= 3, f"step {k + 1}: {len(z)} x-z plane modes among the first 6")
        freq.append(f["freq"][k][z[:3]])
    freq = np.array(freq)
    for k in range(len(lam)):
        Tk = lam[k] * tension
        ref = np.sqrt((n * np.pi / L) ** 4 * EI / rhoA + (n * np.pi / L) ** 2 * Tk / rhoA) / (2 * np.pi)
        st.close(freq[k], ref, rtol=1e-4, what=f"f1..f3 at T = {Tk:.4g} N")
        print("    relative errors:", np.array2string(freq[k] / ref - 1, precision=3))
    st.check(np.all(np.diff(freq[:, 0]) > 0), "f1 rises with tension")
    string = n / (2 * L) * np.sqrt(tension / rhoA)
    print("  pure string n/(2L) sqrt(T/rhoA):", string, " measured at full tension:", freq[-1])
    st.close(freq[-1], string, rtol=0.02, what="close to the pure string (bending adds (n pi)^2 / 2000)")
st.done()
