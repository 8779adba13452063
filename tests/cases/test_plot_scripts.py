# ctest-processors: 1
"""The plot scripts' pictures of issue 24 item 14 (1 rank each; scenes from runs/ read, not changed).
- plot_results.py colours the deformed shape by stress: runs/sail_masts.yaml (membrane, edge cables,
  beam masts) gives filled membranes in viridis with a colour bar "membrane first principal resultant
  n1 [N/m]" and cables in plasma ("cable axial force [N]"), both ranges as computed here from
  /cell/triangles/membrane_n* and /cell/lines/axial_force of the step; the masts stay blue. With
  `color: darkgreen` on the cable set the scene's colour wins (dark green pixels, no cable colour bar).
  The path GIF of runs/membrane_5node.yaml is coloured too (one frame per written row).
- --animate path of a shallow clamped arch (path following; largest displacement 4.5 % of the model
  size) is magnified to 10 % of the model size with the factor in the title (it was drawn true to scale).
- plot_input.py draws a scene file through sinew's input check; a text file is one line, exit 2;
  a scene with an error gives Sinew's error line, exit 2.
- every plot script given a missing file or a text file prints one line and exits non-zero (no traceback)."""
import os
import subprocess

import numpy as np
from matplotlib import colormaps
from PIL import Image

import path_scenes
import sinewtest as st

SCRIPTS = os.path.join(st.SOURCE, "scripts")
RUNS = os.path.join(st.SOURCE, "runs")
work = st.WORK
os.makedirs(work, exist_ok=True)


def script(name, *args, expect=0, process=False):
    """Runs scripts/<name>: in this process (sinewtest.script), or as `/usr/bin/python3 scripts/<name>`
    where what the command line prints is checked (process=True). Returns stdout and stderr together."""
    if process:
        p = subprocess.run(["/usr/bin/python3", os.path.join(SCRIPTS, name)] + list(args), stdout=subprocess.PIPE,
                           stderr=subprocess.STDOUT, text=True, timeout=300)
        text = p.stdout
    else:
        p = st.script(name, *args)
        text = p.stdout + p.stderr
    print(f"  $ {name} {' '.join(os.path.basename(x) for x in args)}  (exit {p.returncode})\n    "
          + text.strip().replace("\n", "\n    "))
    st.check(p.returncode == expect if expect is not None else p.returncode != 0,
             f"{name} {' '.join(args)}: exit {p.returncode}, expected {expect if expect is not None else 'non-zero'}")
    return text


def near(png, rgbs, tol):
    """Pixels of the PNG within tol (each channel, 0..1) of any of the colours rgbs."""
    colours = Image.open(png).convert("RGB").getcolors(maxcolors=1 << 24)
    counts = np.array([c for c, _ in colours])
    px = np.array([rgb for _, rgb in colours], float) / 255
    d = np.min(np.max(np.abs(px[:, None, :] - np.asarray(rgbs, float)[None, :, :]), axis=2), axis=1)
    return int(counts[d < tol].sum())


def line_with(out, prefix):
    return next((ln for ln in out.splitlines() if ln.startswith(prefix)), "")


VIRIDIS = colormaps["viridis"](np.linspace(0, 1, 256))[:, :3]
PLASMA = colormaps["plasma"](np.linspace(0, 1, 256))[:, :3]
BLUE, DARKGREEN = (0.0, 0.447, 0.741), (0.1, 0.4, 0.1)

# ---- stress colours: membrane, cables, beams (runs/sail_masts.yaml)
scene_text = open(os.path.join(RUNS, "sail_masts.yaml")).read().replace(
    "mesh: ../meshes/", f"mesh: {os.path.join(st.SOURCE, 'meshes')}/")
h5, _ = st.run("plot_scripts_sail", scene_text, np_=1)
with st.h5(h5) as f:
    n11, n22, n12 = (f[f"cell/triangles/membrane_{c}"][-1] for c in ("n11", "n22", "n12"))
    n1 = 0.5 * (n11 + n22) + np.sqrt(0.25 * (n11 - n22) ** 2 + n12 ** 2)
    force = f["cell/lines/axial_force"][-1]
    force = force[np.isfinite(force)]
png = os.path.join(work, "plot_scripts_sail.png")
out = script("plot_results.py", h5, "-o", png)
want = (f"colours: membrane first principal resultant n1 [N/m] {n1.min():.4g} .. {n1.max():.4g}, "
        f"cable axial force [N] {force.min():.4g} .. {force.max():.4g}")
st.check(line_with(out, "colours:") == want, f"colour scales as computed from the file: {want!r}")
counts = {what: near(png, rgbs, 0.02) for what, rgbs in (("viridis", VIRIDIS), ("plasma", PLASMA), ("blue", [BLUE]))}
print(f"  pixels: {counts}")
st.check(counts["viridis"] > 5000, "membranes filled in the membrane colour map (colour bar and faces)")
st.check(counts["plasma"] > 2000, "cables and their colour bar in the cable colour map")
st.check(counts["blue"] > 20, "the beam masts stay blue")
st.check("coloured by membrane stress and cable force" in out, "the title says what the colours are")

coloured = scene_text.replace("    type: cable\n", "    type: cable\n    color: darkgreen\n")
st.check(coloured != scene_text, "cable set found in runs/sail_masts.yaml")
h5c, _ = st.run("plot_scripts_sail_look", coloured, np_=1)
png = os.path.join(work, "plot_scripts_sail_look.png")
out = script("plot_results.py", h5c, "-o", png)
st.check("cable axial force" not in out and "membrane first principal" in line_with(out, "colours:"),
         "cables coloured by the scene: no cable colour scale, the membrane keeps its scale")
green = near(png, [DARKGREEN], 0.03)
st.check(green > 100, f"cables drawn in the scene's dark green ({green} pixels)")

h5m, _ = st.run("plot_scripts_5node", os.path.join(RUNS, "membrane_5node.yaml"), np_=1)
gif = os.path.join(work, "plot_scripts_5node.gif")
out = script("plot_results.py", h5m, "--animate", "path", "--stress", "vonmises", "-o", gif)
st.check("colours: membrane Von Mises resultant" in out, "path GIF coloured by the Von Mises resultant")
with st.h5(h5m) as f:
    rows = len(f["load_factor"])
st.check(os.path.exists(gif) and getattr(Image.open(gif), "n_frames", 1) == rows, f"GIF of {rows} frames")
st.check(near(gif, VIRIDIS, 0.03) > 1000 if os.path.exists(gif) else False,
         "GIF frames carry the colour map")

# ---- --animate path of a shallow arch: magnified with the factor in the title
arch, centre = path_scenes.clamped_arch(2.5e-3, n=10, ds=0.06, max_steps=14)
h5a, _ = st.run("plot_scripts_arch", arch, np_=1)
with st.h5(h5a) as f:
    u = f["mesh/p"][()] - f["mesh/p0"][()]
    pts = np.concatenate([f["mesh/p0"][()], f["node/p0"][()]])
dmax, size = np.max(np.linalg.norm(u, axis=2)), np.linalg.norm(np.ptp(pts, axis=0))
factor = float(f"{0.1 * size / dmax:.2g}")
print(f"  arch: largest displacement {dmax:.4g} m = {100 * dmax / size:.3g} % of the model size {size:.4g} m")
st.check(0.02 < dmax / size < 0.1, "the arch moves between 2 % and 10 % of its size (drawn true to scale before)")
out = script("plot_results.py", h5a, "--animate", "path", "-o", os.path.join(work, "plot_scripts_arch.gif"))
st.check(f"(displacements x {factor:g})" in line_with(out, "title:") + out, f"path magnified x {factor:g}, said in the title")

# ---- plot_input.py on a scene file, a text file and a scene with an error
scene = st.scene_file("plot_scripts_arch_scene", arch)
png = os.path.join(work, "plot_scripts_arch_scene_input.png")
if os.path.exists(png):
    os.remove(png)
out = script("plot_input.py", scene)
st.check("input check:" in out and os.path.exists(png) and os.path.getsize(png) > 5000,
         "a scene is drawn through sinew's input check, beside the scene as <scene>_input.png")
text = os.path.join(work, "plot_scripts_text.txt")
with open(text, "w") as f:
    f.write("not a scene, not a result\n")
out = script("plot_input.py", text, expect=2, process=True)
st.check(len(out.strip().splitlines()) == 1 and "neither" in out, "a text file: one line, exit 2")
bad = st.scene_file("plot_scripts_bad_scene", "nodes: [[0, 0, 0]]\nelements: [[1, 5]]\n")
out = script("plot_input.py", bad, expect=2, process=True)
st.check(out.startswith("error: elements(1,2)") and "Traceback" not in out, "a scene error is Sinew's line, exit 2")

# ---- every plot script: a missing file and a text file are one line, non-zero, no traceback
for name, extra in (("plot_results.py", []), ("plot_input.py", []), ("plot_loadpath.py", ["--node", "1"]),
                    ("plot_sensors.py", []), ("bode.py", []), ("h5check.py", [])):
    for path in (os.path.join(work, "plot_scripts_missing.h5"), text):
        out = script(name, path, *extra, expect=None, process=True)
        st.check(len(out.strip().splitlines()) == 1 and "Traceback" not in out,
                 f"{name} {os.path.basename(path)}: one line, no traceback")
st.done()
