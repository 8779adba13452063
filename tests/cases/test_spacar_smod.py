#!/usr/bin/python3
"""flex [3, 4] without smod (issue 10, item 13): bending is Timoshenko (shear deformation from smod),
so the scene check asks for smod as the element does (unit test SpacarScene.ModulusRequirementsAgree
covers every flex set); the error (exit 2, once, on 2 ranks) names the set's field and its line. An
elongation-only set (flex [1]) needs no smod and runs."""
import sinewtest as st

SCENE = """title: bending without smod
nodes: [[0, 0, 0], [1, 0, 0]]
elements: [[1, 2]]
nprops: {1: {fix: true}, 2: {force: [1, 0, 0]}}
eprops:
  - elems: [1]
    flex: [3, 4]
    emod: 210e9
    cshape: rect
    dim: [0.01, 0.001]
    orien: [0, 0, 1]
opt: {loadsteps: 1, calccompl: false}
"""
_, log = st.run("smod_missing", SCENE, expect_exit=2)
err = [ln for ln in log.splitlines() if ln.startswith("error:")]
print("  message:", err)
st.check(len(err) == 1, f"one error line, got {len(err)}")
st.check(err and "eprops(1).smod" in err[0] and "line 6" in err[0], "the error names eprops(1).smod and line 6 (the set)")
st.check(err and "modes 3 and 4 (bending, with shear deformation) need smod" in err[0], "the error says why smod is needed")
# elongation only: no smod needed
out, log = st.run("smod_axial", SCENE.replace("flex: [3, 4]", "flex: [1]"))
with st.h5(out) as f:
    st.close(f["node/p"][-1, 1, 0] - 1, 1 / (210e9 * 0.01 * 0.001), rtol=1e-6, what="flex [1] without smod: elongation F L / (E A)")
st.done()
