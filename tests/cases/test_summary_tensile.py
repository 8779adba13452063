"""Issue 24 point 10, what the run prints for tensile structures: the summary of a cable net
(runs/hypar_net.yaml: 144 cables, 81 loaded nodes, 32 supports) and of a sail (runs/sail.yaml:
membrane + edge cables, 4 supports) gives what a designer reads, checked against the result file
of the same run:
  - the extreme cable axial forces with their (1-based) scene element and the slack count
    (/cell/lines/axial_force, /mesh/lines_element, last row);
  - the extreme principal membrane stress resultants n1 max, n2 min with their element and the
    wrinkled count (n2 <= 0), from /cell/triangles/membrane_n11, _n22, _n12;
  - the free node that moves most (largest |p - p_found| among the nodes without reactions);
  - the reactions: listed for the sail's 4 supports, summed for the net's 32 (sum = /node/Freac);
  - no table of every loaded node (hypar_net printed 145 lines of them) and no rotation columns;
  - the developer counters (assemblies, commits) only with -verbose."""
import os
import re

import numpy as np

import sinewtest as st

RUNS = os.path.join(os.environ.get("SINEW_SOURCE_DIR", st.SOURCE), "runs")


def num(pattern, text):
    m = re.search(pattern, text)
    return m.groups() if m else None


def last_found(f):
    """Row of the found shape (the last form-finding row) and the last row."""
    ff = f["formfinding/step"][:]
    return int(np.max(np.nonzero(~np.isnan(ff))[0])), f["node/p"].shape[0] - 1


def moving_node(f):
    r0, r1 = last_found(f)
    u = f["node/p"][r1] - f["node/p"][r0]
    free = np.all(f["node/Freac"][r1] == 0, axis=1)
    mag = np.where(free, np.linalg.norm(u, axis=1), -1)
    return int(np.argmax(mag)) + 1, float(np.max(mag))


# ---- cable net
h5, out = st.run("summary_hypar", os.path.join(RUNS, "hypar_net.yaml"), np_=2)
print("\n".join("  | " + l for l in out.splitlines() if l.startswith((" cables", " node that", " reactions"))))
with st.h5(h5) as f:
    N = f["cell/lines/axial_force"][-1]
    el = f["mesh/lines_element"][:]
    node, umax = moving_node(f)
    Fz = np.sum(f["node/Freac"][-1][:, 2])
    nsup = int(np.sum(np.any(f["node/Freac"][-1] != 0, axis=1)))
g = num(r"cables \(last step\): axial force max (\S+) N \(element (\d+)\), min (\S+) N \(element (\d+)\); (\d+) of (\d+) slack", out)
st.check(g is not None, "net: the cable line is printed")
if g:
    st.close(float(g[0]), np.max(N), rtol=1e-4, what="net: max cable force [N]")
    emax, emin = el[N == np.max(N)].min(), el[N == np.min(N)].min()  # ties: the lowest element
    st.check(int(g[1]) == emax, f"net: element of the max force {g[1]} (file: {emax})")
    st.close(float(g[2]), np.min(N), rtol=1e-4, what="net: min cable force [N]")
    st.check(int(g[3]) == emin, f"net: element of the min force {g[3]} (file: {emin})")
    st.check(int(g[4]) == int(np.sum(N <= 0)) and int(g[5]) == len(N), f"net: slack count {g[4]} of {g[5]}")
g = num(r"node that moves most \(last step\): node (\d+), \|u\| = (\S+) m", out)
st.check(g is not None and int(g[0]) == node, f"net: the node that moves most {g} (file: node {node}, {umax:.4e} m)")
if g:
    st.close(float(g[1]), umax, rtol=1e-4, what="net: its displacement [m]")
g = num(r"reactions \(last step\): (\d+) supported nodes, sum \((\S+), (\S+), (\S+)\) N", out)
st.check(g is not None and int(g[0]) == nsup, f"net: reactions summed over {nsup} supports ({g})")
if g:
    st.close(float(g[3]), Fz, rtol=1e-4, what="net: sum of the vertical reactions [N]")
table = re.findall(r"^\s+\d+(\s+-?\d\.\d{4}e[+-]\d\d){3}", out, re.M)
st.check(len(table) == 0, f"net: no node table ({len(table)} node rows)")
st.check("rx [rad]" not in out and "rz [rad]" not in out, "net: no rotation columns")
st.check(len(out.splitlines()) < 40, f"net: a short summary ({len(out.splitlines())} lines)")
st.check("assemblies:" not in out and "commits" not in out, "net: no developer counters without -verbose")
_, outv = st.run("summary_hypar_verbose", os.path.join(RUNS, "hypar_net.yaml"), np_=1, args=["-verbose"])
st.check("assemblies:" in outv and re.search(r"\d+ commits, \d+ forced", outv) is not None, "net: -verbose prints the counters")

# ---- sail: membrane resultants
h5, out = st.run("summary_sail", os.path.join(RUNS, "sail.yaml"), np_=2)
print("\n".join("  | " + l for l in out.splitlines() if l.startswith((" cables", " membranes", " node that"))))
with st.h5(h5) as f:
    n11, n22, n12 = (f[f"cell/triangles/membrane_{c}"][-1] for c in ("n11", "n22", "n12"))
    tri = f["mesh/triangles_element"][:]
    node, umax = moving_node(f)
c, r = 0.5 * (n11 + n22), np.hypot(0.5 * (n11 - n22), n12)
n1, n2 = c + r, c - r
g = num(r"membranes \(last step\): principal stress resultant n1 max (\S+) N/m \(element (\d+)\), n2 min (\S+) N/m "
        r"\(element (\d+)\); (\d+) of (\d+) wrinkled", out)
st.check(g is not None, "sail: the membrane line is printed")
if g:
    st.close(float(g[0]), np.max(n1), rtol=1e-4, what="sail: n1 max [N/m]")
    e1, e2 = tri[n1 == np.max(n1)].min(), tri[n2 == np.min(n2)].min()
    st.check(int(g[1]) == e1, f"sail: element of n1 max {g[1]} (file: {e1})")
    st.close(float(g[2]), np.min(n2), rtol=1e-4, what="sail: n2 min [N/m]")
    st.check(int(g[3]) == e2, f"sail: element of n2 min {g[3]} (file: {e2})")
    st.check(int(g[4]) == int(np.sum(n2 <= 0)) and int(g[5]) == len(n1), f"sail: wrinkled count {g[4]} of {g[5]}")
g = num(r"node that moves most \(last step\): node (\d+)", out)
st.check(g is not None and int(g[0]) == node, f"sail: the node that moves most {g} (file: node {node})")
st.check(re.search(r" reactions \(last step\)\n node      Fx \[N\]      Fy \[N\]      Fz \[N\]\n(\s+\d+( +-?\d\.\d{4}e[+-]\d\d){3}\n){4}", out)
         is not None, "sail: the 4 reactions listed, without moment columns")
st.done()
