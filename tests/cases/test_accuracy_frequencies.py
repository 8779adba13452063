# ctest-labels: smoke
"""-target_error on a cantilever's bending frequencies (docs/accuracy.md), from nbeams 1, 2 ranks,
the target as the scene key opt.target_error: for 1e-3 and 1e-5 the reported level's true error
(against Euler-Bernoulli, reference B3) is within the target and the estimate within a factor 3 of
it; the result file holds the reported level's mesh (more elements than the scene's one) and
/accuracy; the summary's table names the level that met the target."""
import numpy as np

import accuracy_cases as ac
import sinewtest as st

for target in (1e-3, 1e-5):
    name = f"accuracy_freq_{target:g}"
    path, out = st.run(name, ac.cantilever(1, {"target_error": target}))
    info = ac.check_answer("cantilever", path, "freq", ac.FREQ_REF, target)
    with st.h5(path) as f:
        g = f["accuracy"]
        st.check(f["mesh/p"].shape[1] == int(g["nbeams_factor"][-1]) + 1,
                 f"/mesh/p has {f['mesh/p'].shape[1]} nodes: the reported level's mesh")
        st.check(int(g["nbeams_factor"][-1]) >= 4, "refined beyond the scene's nbeams 1 (target_error not ignored)")
        st.check(np.all(np.diff(g["unknowns"][:]) > 0), "unknowns grow level by level")
        st.check(f.attrs["converged"] in (1, True), "converged attribute")
    st.check(f"met at level {info['levels'] - 1}" in out, "the summary's accuracy table says where the target was met")
st.done()
