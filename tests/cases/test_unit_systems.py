"""Tolerances and warnings do not depend on the unit system (issue 24 item 13): runs/crosshinge.yaml
in m, N, Pa, kg and its twin tests/scenes/units/crosshinge_mm.yaml in mm, N, MPa, t give the same
positions (x 1000), frequencies and buckling multipliers, and the same eigenpair backward errors
(rotations scaled by the model size, src/step/backward_error.hpp). The backward error
||K x - lambda M x|| / ((||K|| + |lambda| ||M||) ||x||) mixed N/m with N m/rad: 6e-11 in SI but
1.2e-8 .. 2.1e-8 in mm at steps 6-10, above -eps_tol 1e-8, so only the mm scene warned."""
import os

import numpy as np

import sinewtest as st

si_scene = os.path.join(st.SOURCE, "runs", "crosshinge.yaml")
mm_scene = os.path.join(st.SOURCE, "tests", "scenes", "units", "crosshinge_mm.yaml")
si, si_log = st.run("units_si", si_scene, np_=2)
mm, mm_log = st.run("units_mm", mm_scene, np_=2)
for name, log in (("SI", si_log), ("mm", mm_log)):
    warnings = [line for line in log.splitlines() if "warning" in line]
    print(f"{name}: {len(warnings)} warnings {warnings}")
    st.check(not any("eigenpair exceeds" in w for w in warnings), f"{name}: no eigenpair warning")
with st.h5(si) as a, st.h5(mm) as b:
    p_si, p_mm = a["node/p"][:] * 1000.0, b["node/p"][:]
    dp = np.abs(p_si - p_mm).max() / np.abs(p_mm).max()
    print(f"positions: max |p_SI x 1000 - p_mm| / max |p| = {dp:.2e}")
    st.check(dp < 1e-10, f"positions equal in both unit systems ({dp:.2e})")
    for key in ("freq", "buck"):
        d = np.abs(a[key][:] - b[key][:]).max() / np.abs(a[key][:]).max()
        print(f"{key}: max relative difference {d:.2e}")
        st.check(d < 1e-6, f"{key} equal in both unit systems ({d:.2e})")
    for key in ("freq_backward_error", "buck_backward_error"):
        x, y = a[key][:], b[key][:]
        print(f"{key}: SI max {x.max():.2e}, mm max {y.max():.2e}")
        st.check(max(x.max(), y.max()) < 1e-8, f"{key}: below -eps_tol 1e-8 in both ({x.max():.2e}, {y.max():.2e})")
    # above round-off the two unit systems give the same backward error (rotations scaled by the model size)
    x, y = a["freq_backward_error"][:], b["freq_backward_error"][:]
    big = x > 1e-12
    d = np.abs(x[big] - y[big]).max() / x[big].max()
    print(f"freq_backward_error above 1e-12: max relative difference {d:.2e}")
    st.check(d < 1e-3, f"freq_backward_error the same in m and mm ({d:.2e})")
st.done()
