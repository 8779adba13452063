"""-target_error's reuse for the load analysis after form finding (docs/accuracy.md, "Reuse between
levels"), 2 ranks: a finer level starts each load step's Newton from its own found shape plus the coarser
level's displacement from its found shape at that load step, interpolated onto its nodes (a split cable's
midpoint the mean of its ends). The hypar cable net of runs/hypar_net.yaml (force density form finding,
then a snow load in 5 load steps) at target 1e-3 with -accuracy_reuse 1 (default) and 0: the same levels
and level values to Newton's tolerance, the estimates at round-off (the net is exact between its loaded
nodes) with reuse too, and far fewer Newton
iterations (/accuracy newton_iterations) on the finer levels, whose load steps started from the coarser
level's states (/accuracy reused_starts). A loaded catenoid (split membranes) at 3e-2: the same answer, and
every finer level starts load steps from the coarser level's displacements."""
import os

import numpy as np

import ffscenes as ff
import sinewtest as st

SCENE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "runs", "hypar_net.yaml")


def study(path):
    with st.h5(path) as f:
        g = f["accuracy"]
        return {k: g[k][:] for k in ("level", "worst_error", "error", "value", "newton_iterations", "reused_starts")}


def with_and_without_reuse(tag, scene, target):
    """The study of the scene with -accuracy_reuse 1 and 0: (with, without)."""
    runs = {}
    for reuse in (1, 0):
        path, _ = st.run(f"{tag}_{reuse}", scene, args=["-target_error", target, "-accuracy_reuse", str(reuse)])
        runs[reuse] = study(path)
    return runs[1], runs[0]


on, off = with_and_without_reuse("accuracy_ff_reuse", os.path.abspath(SCENE), "1e-3")
print(f"  hypar net: levels {list(on['level'])}, Newton iterations per level {list(on['newton_iterations'])} "
      f"with reuse, {list(off['newton_iterations'])} without; reused starts {list(on['reused_starts'])}")
st.check(np.array_equal(on["level"], off["level"]), "the same levels")
v_on, v_off = np.nan_to_num(on["value"]), np.nan_to_num(off["value"])
size = np.maximum(np.linalg.norm(v_off, axis=2), 1e-300)
change = np.max(np.linalg.norm(v_on - v_off, axis=2) / size)
print(f"  largest relative change of a level's value {change:.1e}")
st.check(change < 1e-9, f"the level values do not depend on the Newton start ({change:.1e})")
# the net is exact between its loaded nodes: every estimate of the finest level is round-off (1e-13, which
# quantity is the worst may change), with reuse too
e_on, e_off = on["error"][-1], off["error"][-1]
st.check(np.array_equal(np.isfinite(e_on), np.isfinite(e_off)), "the same quantities estimated")
worst = max(np.nanmax(e_on), np.nanmax(e_off))
st.check(worst < 1e-9, f"the estimates stay at round-off ({worst:.1e})")
st.check(np.all(off["reused_starts"] == 0), "-accuracy_reuse 0 starts no load step from a coarser level")
st.check(np.all(on["reused_starts"][1:] > 0), "with reuse every level after the first starts from the coarser one")
# form finding is one Newton iteration on every level; the load steps started from the coarser level's
# displacements (exact on the straight cable segments between the loaded nodes) need few
fine_on, fine_off = int(on["newton_iterations"][1:].sum()), int(off["newton_iterations"][1:].sum())
st.check(fine_on < 0.5 * fine_off, f"reuse saves Newton iterations on the finer levels ({fine_on} against {fine_off})")

# split membranes: a catenoid (64 triangles) under a pressure of a tenth of its prestress in 4 load steps,
# target 3e-2 (levels x1 .. x4): the new edge midpoints start from the mean of their edge's displacements;
# the first loaded step of every finer level starts from the coarser level's state, the answer is the same
cat = ff.catenoid_scene(R=1.0, halfh=0.5, nt=8, nz=4, steps=40, tol=1e-6)
cat["eprops"][0]["pressure"] = 0.1
cat["formfinding"]["elastic_restart_method"] = "FORCE"
cat["opt"].update({"loadsteps": 4, "accuracy_quantities": ["node 17 p"]})
on, off = with_and_without_reuse("accuracy_ff_reuse_catenoid", ff.to_yaml(cat), "3e-2")
print(f"  catenoid: levels {list(on['level'])}, Newton iterations per level {list(on['newton_iterations'])} "
      f"with reuse, {list(off['newton_iterations'])} without; reused starts {list(on['reused_starts'])}")
st.check(np.array_equal(on["level"], off["level"]), "catenoid: the same levels")
change = np.max(np.linalg.norm(on["value"] - off["value"], axis=2) / np.linalg.norm(off["value"], axis=2))
st.check(change < 1e-9, f"catenoid: the level values do not depend on the Newton start ({change:.1e})")
st.check(np.allclose(on["worst_error"][2:], off["worst_error"][2:], rtol=1e-6, atol=0), "catenoid: the same estimates")
st.check(np.all(on["reused_starts"][1:] > 0), "catenoid: every finer level starts load steps from the coarser one")
st.check(np.all(on["newton_iterations"] <= off["newton_iterations"]), "catenoid: no level needs more Newton iterations")
st.done()
