"""-target_error on an Euler column's buckling multipliers (docs/accuracy.md), from nbeams 2, 2 ranks,
the target as the flag -target_error: for 1e-3 and 1e-5 the true error (reference B2) is within the
target and the estimate within a factor 3 of it; the statics quantities the scene asks for too (the
tip's position, the support's reaction, the max stress) are watched and, exact on every mesh
(axial bar), reported as resolved. -accuracy_quantities buck watches the multipliers alone."""
import accuracy_cases as ac
import sinewtest as st

for target in (1e-3, 1e-5):
    name = f"accuracy_buck_{target:g}"
    path, out = st.run(name, ac.column(2), args=["-target_error", str(target)])
    ac.check_answer("column", path, "buck", ac.BUCK_REF, target)
    with st.h5(path) as f:
        g = f["accuracy"]
        names = [n for n in g.attrs["quantities"].split("\n") if n]
        st.check(names[:3] == ["node 2 p", "node 1 Freac", "stressmax"], f"watched quantities {names}")
        st.check(all(s == 1 for s in g["status"][-1][:3]), "tip position, reaction and stress resolved (status 1)")

path, out = st.run("accuracy_buck_named", ac.column(2), args=["-target_error", "1e-3", "-accuracy_quantities", "buck"])
with st.h5(path) as f:
    names = [n for n in f["accuracy"].attrs["quantities"].split("\n") if n]
    st.check(names == ["buck 1", "buck 2"], f"-accuracy_quantities buck: watched {names}")
st.done()
