"""Issue 11 item 4: scripts/plot_loadpath.py on a path-following result (2 ranks).
The von Mises truss of test_continuation.py (snap-through: two limit points, unstable between them)
followed by arc length; the script draws the apex's load path. Checks: exit 0, a real PNG (> 5 kB),
the printed counts (2 stable segments, 1 unstable, 2 limit points, no bifurcation), the unstable
segment drawn in red (red pixels in the image), axis labels with units; the load F_y = load factor x
(-1 N) on a second axis (printed); two nodes at once work."""
import math
import os

from PIL import Image

import beamtools as bt
import sinewtest as st

a, H = 1.0, 0.1
d = math.sqrt(4 * 1e-3 / math.pi)
scene = bt.yaml_text({"title": "von Mises truss", "nodes": [[-a, 0, 0], [0, H, 0], [a, 0, 0]], "elements": [[1, 2], [3, 2]],
                      "nprops": {1: {"fix": True}, 3: {"fix": True}, 2: {"fix_z": True, "fix_orien": True, "force": [0, -1, 0]}},
                      "eprops": [{"elems": [1, 2], "flex": [1], "emod": 1e7, "smod": 4e6, "cshape": "circ", "dim": [d]}],
                      "opt": {"rls": {1: [2, 3, 4, 5, 6], 2: [2, 3, 4, 5, 6]}, "calccompl": False,
                              "continuation": {"method": "arclength", "ds": 0.01, "node": 2, "direction": "y",
                                               "stop_displacement": -0.25}}})
h5, _ = st.run("plot_loadpath_truss", scene)
png = os.path.join(st.WORK, "plot_loadpath_truss.png")
if os.path.exists(png):
    os.remove(png)
script = os.path.join(st.SOURCE, "scripts", "plot_loadpath.py")
p = st.script("plot_loadpath.py", h5, "--node", "2", "--dir", "y", "-o", png)
print("  " + p.stdout.strip().replace("\n", "\n  "))
st.check(p.returncode == 0, f"plot_loadpath.py exit {p.returncode}")
st.check("segments: stable 2, unstable 1; limit points 2, bifurcation points 0" in p.stdout,
         "counts: 2 stable segments, 1 unstable, 2 limit points")
st.check("load axis: load F_y [N] = load factor x -1 (nprops(2).force = [0, -1, 0])" in p.stdout,
         "the load itself on a second axis: F_y = load factor x (-1 N), the apex's one ramped force")
if st.check(os.path.exists(png) and os.path.getsize(png) > 5000, "PNG written (> 5 kB)"):
    img = Image.open(png).convert("RGB")
    px = img.getdata()
    red = sum(1 for r, g, b in px if r > 180 and g < 90 and b < 90)
    st.check(red > 50, f"unstable segment drawn in red ({red} red pixels)")
src = open(script).read()
st.check('f"{label} [m]"' in src and "load factor [-]" in src, "axis labels carry units ([m], [-])")
png2 = os.path.join(st.WORK, "plot_loadpath_truss2.png")
p = st.script("plot_loadpath.py", h5, "--node", "2", "1", "--dir", "abs", "-o", png2)
st.check(p.returncode == 0 and os.path.exists(png2), "two nodes at once")
st.done()
