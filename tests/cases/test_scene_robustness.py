# ctest-labels: smoke
"""Issue 13 reproducers (scene side): absurd numbers, duplicated elements, several YAML documents,
deep nesting and bad scene/mesh paths. Every case runs build/sinew on 1 and 2 ranks under a
timeout and must exit 2 with one "error:" line (rank 0 only) that names the field and the fault,
never hang, crash or leave a result file. Before the fix: dens 1e308/1e-308 hung 2 ranks in SLEPc,
physicsAxialStiffness 1e308 hung in MatLUFactorNumeric, a node at x = 1e308 "coincided", E = 1e308
was "a mechanism", a duplicated element and a second YAML document were accepted silently,
100k-deep nesting said "bad file" and a directory said "nodes: missing"."""
import os
import shutil
import subprocess

import sinewtest as st

BEAM = """nodes:
  - [0, 0, 0]
  - [{x2}, 0, 0]
  - [2, 0, 0]
elements:
  - [1, 2]
  - [2, 3]{extra}
eprops:
  - elems: [{elems}]
    flex: [1, 2, 3, 4, 5, 6]
    emod: {emod}
    smod: 80e9
    dens: {dens}
    cshape: rect
    dim: [0.02, 0.01]
    orien: [0, 0, 1]
nprops:
  1: {{fix: true}}
  3: {{force: [0, 0, -10]}}
opt:
  loadsteps: 2
  calccompl: false
  calcfreq: true
"""


def beam(x2="1", emod="210e9", dens="7800", extra="", elems="1, 2"):
    return BEAM.format(x2=x2, emod=emod, dens=dens, extra=extra, elems=elems)


with open(os.path.join(st.SOURCE, "runs", "ancf_cantilever.yaml")) as f:
    ANCF = f.read()
with open(os.path.join(st.SOURCE, "meshes", "square_tri.msh")) as f:
    MESH = f.read()

os.makedirs(st.WORK, exist_ok=True)
a_dir = os.path.join(st.WORK, "robust_scene_dir.yaml")
mesh_dir = os.path.join(st.WORK, "robust_mesh_dir.msh")
truncated = os.path.join(st.WORK, "robust_truncated.msh")
for d in (a_dir, mesh_dir):
    os.makedirs(d, exist_ok=True)
with open(truncated, "w") as f:
    f.write(MESH[: len(MESH) // 2])
MESH_SCENE = """nodes: []
elements: []
mesh: {path}
eprops:
  - {{elems: [1], type: membrane, thickness: 0.001, emod: 1e9, nu: 0.3}}
"""

assert "physicsAxialStiffness:" in ANCF
ancf_axial = "\n".join("    physicsAxialStiffness: 1e308" if ln.strip().startswith("physicsAxialStiffness:") else ln
                       for ln in ANCF.splitlines()) + "\n"

# (name, scene text, or a path to run as is; fragments the error line must hold; fragments it must not)
CASES = [
    ("dens_huge", beam(dens="1e308"), ["eprops(1).dens", "1e+308", "[1e-20, 1e+20]"], []),
    ("dens_tiny", beam(dens="1e-308"), ["eprops(1).dens", "1e-308", "[1e-20, 1e+20]"], []),
    ("emod_huge", beam(emod="1e308"), ["eprops(1).emod", "1e+308"], ["mechanism"]),
    ("node_far", beam(x2="1e308"), ["nodes(2,1)", "coordinate", "1e+308"], ["coincide"]),
    ("ancf_axial_huge", ancf_axial, ["physicsAxialStiffness", "1e+308"], []),
    ("duplicated_element", beam(extra="\n  - [2, 1]", elems="1, 2, 3"), ["elements(3)", "element 3 duplicates element 1"], []),
    ("two_documents", beam() + "---\ntitle: second\n", ["the file holds 2 YAML documents", "Sinew reads one"], []),
    ("deep_nesting", "nodes: " + "[" * 100000 + "]" * 100000 + "\n", ["the nesting is too deep", "line 1"], ["bad file"]),
    ("empty_file", "", ["is empty"], ["nodes: missing"]),
    ("binary_file", "\x00\x01\x02\x03binary\xff" * 50, ["not a text file", "control byte 0x00"], []),
    ("directory", a_dir, ["is a directory, not a scene file"], ["nodes: missing"]),
    ("mesh_directory", MESH_SCENE.format(path=mesh_dir), ["mesh:", "is a directory, not a Gmsh mesh file"], []),
    ("mesh_truncated", MESH_SCENE.format(path=truncated), ["mesh:", "robust_truncated.msh:"], []),
]

for name, text, want, avoid in CASES:
    if isinstance(text, str) and os.path.isdir(text):
        path = text
    else:
        path = os.path.join(st.WORK, "robust_" + name + ".yaml")
        with open(path, "w", encoding="latin-1") as f:
            f.write(text)
    for np_ in (1, 2):
        out = os.path.join(st.WORK, f"robust_{name}_{np_}.h5")
        for stale in (out, out + ".part"):
            if os.path.exists(stale):
                os.remove(stale)
        cmd = st.launcher(np_) + [path, "-o", out]
        try:
            p = subprocess.run(cmd, env=st.ENV, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=120)
            log, code = p.stdout.decode("utf-8", "replace"), p.returncode
        except subprocess.TimeoutExpired:
            st.fail(f"{name} on {np_} rank(s): no answer within 120 s (hang)")
            continue
        lines = [ln for ln in log.splitlines() if ln.startswith("error:")]
        msg = lines[0] if lines else ""
        print(f"{name} ({np_} rank{'s' if np_ > 1 else ''}): exit {code}: {msg[:200]}")
        st.check(code == 2, f"{name} on {np_} rank(s): exit code {code}, expected 2")
        st.check(len(lines) == 1, f"{name} on {np_} rank(s): {len(lines)} error lines, expected 1")
        for frag in want:
            st.check(frag in msg, f"{name} on {np_} rank(s): message lacks '{frag}'")
        for frag in avoid:
            st.check(frag not in msg, f"{name} on {np_} rank(s): misleading message with '{frag}'")
        st.check(not os.path.exists(out) and not os.path.exists(out + ".part"), f"{name}: result file left behind")
        st.check("MPI_ABORT" not in log and "Segmentation" not in log and "signal" not in log.lower(),
                 f"{name} on {np_} rank(s): crash output")
for d in (a_dir, mesh_dir):
    shutil.rmtree(d, ignore_errors=True)
st.done()
