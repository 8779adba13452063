"""Checkpoint and restart with the energy-momentum scheme (-dynamics_scheme energy_momentum; docs/dynamics.md,
"Energy-momentum scheme"; issue 27): the free steel beam of test_dynamics_energy_momentum.py (4 elements,
lumped mass, a 0.1 s pulse, dt = 0.01 to t = 0.5, every 5th step written). The scheme's state is the
positions, rotations and the translational and spatial angular velocities at the step's start; a run
stopped after 4 rows (t = 0.2, in free flight) and continued on the other rank count equals the
uninterrupted run: every dataset to 1e-12 (norm-wise relative), derived ones within twice the
rank-count round-off floor. Both directions: plain, stopped on 2 ranks and continued on 1; with the
energy decay 0.1 and the torsion rigid (index-3 multipliers in the state), stopped on 1 and continued
on 2. The continued run must also keep the scheme's invariants: T + S and the angular momentum of the
free flight to 1e-11 (plain)."""
import numpy as np

import sinewtest as st
from energy_momentum_scenes import args, em, scene
from restartutil import compare, restarted, stopped

decay = ["-dynamics_energy_decay", "0.1"]
for name, text, extra, first, second in (
        ("rs_em", scene(4, 0.5, 5), em, 2, 1),
        ("rs_em_decay", scene(4, 0.5, 5, flex=(1, 3, 4, 5, 6)), em + decay, 1, 2)):
    flags = args + extra
    ref, _ = st.run(f"{name}_ref{second}", text, np_=second, args=flags)
    other, _ = st.run(f"{name}_ref{first}", text, np_=first, args=flags)
    part = stopped(f"{name}_part{first}", text, first, 4, args=flags)
    rest, out = restarted(f"{name}_rest{second}", text, second, part, args=flags)
    st.check("50 of 50 steps" in out, f"{name}: the restart runs to step 50 of 50")
    compare(ref, rest, f"{name}: stopped after 4 rows on {first} rank(s), continued on {second}", other_ranks=other)
    with st.h5(rest) as f:
        t = f["time"][:]
        E = (f["energy/kinetic"][:] + f["energy/strain"][:])[t >= 0.1 - 1e-12]
        H = f["momentum/angular"][:][t >= 0.1 - 1e-12]
    dE = np.abs(E - E[0]).max() / E[0]
    dH = np.abs(H - H[0]).max() / np.linalg.norm(H[0])
    print(f"  {name}: continued run, free flight T + S drift {dE:.2e}, H drift {dH:.2e}")
    if not extra[2:]:
        st.check(dE < 1e-11 and dH < 1e-11, f"{name}: the continued run conserves T + S ({dE:.2e}) and H ({dH:.2e})")
    else:
        st.check(np.all(np.diff(E) < 0), f"{name}: with the energy decay T + S decreases at every written row")
st.done()
