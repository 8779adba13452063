"""scripts/plot_results.py (issue 9, item 6): pictures without ParaView.
A small cantilever with natural frequencies on 2 ranks; the script writes the deformed shape of the
last step and of step 2 (PNG), mode 1 (PNG) and animated GIFs of mode 2 and of the load path.
Checks: the files are real images (size, more than one colour, GIF frame counts: 24 per mode period,
one per load step), the titles (printed, and the PNG's "Title" metadata) carry the frequency read
from /freq, the load factor of the step and the scene title; axis labels in m; node numbers drawn for
a few nodes and not for 300 (a synthetic 3D result file); a missing mode is an error naming it.
Also: plot_input.py --step K counts from 1 like the summary; plot_sensors.py names each sensor's
components and units (a 2D ANCF cantilever with a Displacement and a ForceLocal sensor) and writes
<result>_sensors.png beside the result file; plot_loadpath.py adds the load axis F_z = load factor x
(-20 N) of the cantilever's one ramped force."""
import os

import h5py
import numpy as np
from PIL import Image

import sinewtest as st

SCRIPT = os.path.join(st.SOURCE, "scripts", "plot_results.py")
scene = """title: Plot test cantilever
nodes: [[0, 0, 0], [1, 0, 0]]
elements: [[1, 2]]
nprops:
  1: {fix: true}
  2: {force: [0, 0, -20]}
eprops:
  - {elems: [1], flex: [1, 2, 3, 4, 5, 6], emod: 210e9, smod: 80e9, dens: 7800, cshape: rect, dim: [0.02, 0.01],
     orien: [0, 1, 0], nbeams: 8}
opt: {loadsteps: 4, calcfreq: true, nfreq: 3, calccompl: false}
"""
h5, _ = st.run("plots_cantilever", scene, np_=2)


def plot(*args, expect=0):
    p = st.script("plot_results.py", h5, *args)
    text = p.stdout + p.stderr
    print("  $ plot_results.py " + " ".join(args) + "\n    " + text.strip().replace("\n", "\n    "))
    st.check(p.returncode == expect, f"plot_results.py {' '.join(args)}: exit {p.returncode}, expected {expect}")
    return text


def title_of(out):
    lines = out.splitlines()
    i = next((n for n, l in enumerate(lines) if l.startswith("title: ")), None)
    return "\n".join([lines[i][7:]] + lines[i + 1:i + 2]) if i is not None else ""


def image_ok(path, frames=1):
    if not st.check(os.path.exists(path) and os.path.getsize(path) > 5000, f"{path} written (> 5 kB)"):
        return None
    im = Image.open(path)
    w, h = im.size
    st.check(w >= 400 and h >= 300, f"{os.path.basename(path)}: size {w} x {h}")
    colours = im.convert("RGB").getcolors(maxcolors=1 << 20)
    st.check(colours is None or len(colours) > 10, f"{os.path.basename(path)}: {len(colours or [])} colours")
    n = getattr(im, "n_frames", 1)
    st.check(n == frames, f"{os.path.basename(path)}: {n} frames, expected {frames}")
    return im


with st.h5(h5) as f:
    freq = f["freq"][-1]
    lam = f["load_factor"][:]
work = os.path.dirname(h5)
outs = {name: os.path.join(work, "plots_" + name) for name in ("last.png", "step2.png", "mode1.png", "mode2.gif",
                                                                "path.gif")}
for path in outs.values():
    if os.path.exists(path):
        os.remove(path)

out = plot("-o", outs["last.png"])
im = image_ok(outs["last.png"])
t = title_of(out)
st.check("Plot test cantilever" in t and f"load factor {lam[-1]:.6g}" in t and "step 4 of 4" in t,
         f"deformed-shape title names the scene, the step and its load factor: {t!r}")
st.check(im is not None and im.info.get("Title") == t, "PNG metadata Title = printed title")
st.check("node numbers: drawn (2 nodes)" in out, "node numbers drawn for 2 nodes")
st.check("axes: x [m], z [m]" in out, "2D view (the beam bends in xz), axis labels in m")

out = plot("--step", "2", "-o", outs["step2.png"])
image_ok(outs["step2.png"])
st.check(f"step 2 of 4, load factor {lam[1]:.6g}" in title_of(out), "--step 2 is the second row (1-based)")

out = plot("--mode", "1", "-o", outs["mode1.png"])
im = image_ok(outs["mode1.png"])
t = title_of(out)
st.check(f"f = {freq[0]:.6g} Hz" in t, f"mode title carries /freq[-1, 0] = {freq[0]:.6g} Hz: {t!r}")
st.check(im is not None and f"{freq[0]:.6g} Hz" in im.info.get("Title", ""), "mode PNG metadata has the frequency")

out = plot("--animate", "mode:2", "-o", outs["mode2.gif"])
image_ok(outs["mode2.gif"], frames=24)
st.check(f"f = {freq[1]:.6g} Hz" in title_of(out), f"mode 2 animation title has {freq[1]:.6g} Hz")

out = plot("--animate", "path", "-o", outs["path.gif"])
image_ok(outs["path.gif"], frames=len(lam))

out = plot("--mode", "7", expect=1)
st.check("mode_freq_7" in out, "a missing mode is named in the error")
out = plot("--step", "9", expect=1)
st.check("step 9" in out, "a step outside 1..4 is named in the error")


# plot_loadpath.py: the second axis is the one ramped force, F_z = load factor x (-20) N
p = st.script("plot_loadpath.py", h5, "--node", "2", "--dir", "z", "-o", os.path.join(work, "plots_loadpath.png"))
print("  plot_loadpath.py: " + p.stdout.strip().replace("\n", " | "))
st.check(p.returncode == 0 and "load axis: load F_z [N] = load factor x -20 (nprops(2).force = [0, 0, -20])" in p.stdout,
         "load-stepped result: the load axis is the tip force F_z = load factor x -20 N")

# A synthetic 3D result with 300 nodes: no node numbers; 3D view (the nodes span x, y and z)
big = os.path.join(work, "plots_synthetic.h5")
n = 300
t_ = np.linspace(0, 4 * np.pi, n)
p0 = np.stack([np.cos(t_), np.sin(t_), t_ / 10], axis=1)
with h5py.File(big, "w") as f:
    f["node/p0"] = p0
    f["node/p"] = np.stack([p0, p0 + [0, 0, -0.05]])
    f["mesh/p"] = f["node/p"][()]
    f["mesh/u"] = f["node/p"][()] - p0
    f["mesh/lines"] = np.stack([np.arange(n - 1), np.arange(1, n)], axis=1)
    f["load_factor"] = [0.5, 1.0]
    f.attrs["scene"] = "title: Helix\n"
h5_cantilever, h5 = h5, big
out = plot("-o", os.path.join(work, "plots_synthetic.png"))
image_ok(os.path.join(work, "plots_synthetic.png"))
st.check("node numbers: not drawn (300 nodes)" in out, "no node numbers above 200 nodes")
st.check("axes: x [m], y [m], z [m]" in out, "3D view, axis labels in m")
t = title_of(out)
st.check("Helix" in t and "load factor 1" in t, f"synthetic title {t!r}")

# plot_input.py --step: 1-based
p = st.script("plot_input.py", h5_cantilever, "--step", "1", "-o", os.path.join(work, "plots_in1.png"))
print("  plot_input.py --step 1: " + p.stdout.strip().replace("\n", " | "))
st.check(p.returncode == 0 and f"step 1 of 4, load factor {lam[0]:.6g}" in p.stdout, "plot_input --step 1 is the first row")
p = st.script("plot_input.py", h5_cantilever, "--step", "5", "-o", os.path.join(work, "plots_in5.png"))
st.check(p.returncode != 0 and "outside 1..4" in p.stderr, f"plot_input --step 5 of 4 is an error: {p.stderr.strip()}")

# plot_sensors.py: components and units
sensors_scene = """title: ANCF sensors
nodes: [[0, 0], [2, 0]]
elements: [[1, 2]]
nprops:
  1: {fix_coords: [1, 1, 0, 1]}
  2: {force: [0, -1000]}
eprops:
  - {elems: [1], type: ancf_cable2d, physicsMassPerLength: 78, physicsBendingStiffness: 1.725e6,
     physicsAxialStiffness: 2.07e9, nbeams: 4}
opt: {loadsteps: 2, calcfreq: false}
sensors:
  - {element: 1, x: 2.0, variable: Displacement, name: tip}
  - {element: 1, x: 0.0, variable: ForceLocal, name: root}
"""
h5s, _ = st.run("plots_sensors", sensors_scene, np_=2)
png = os.path.join(work, "plots_sensors_sensors.png")  # the default: <result>_sensors.png beside the result
elsewhere = os.path.join(work, "plots_cwd")
os.makedirs(elsewhere, exist_ok=True)
for stale in (png, os.path.join(elsewhere, "sensors.png")):
    if os.path.exists(stale):
        os.remove(stale)
p = st.script("plot_sensors.py", h5s, cwd=elsewhere)
st.check(not os.listdir(elsewhere), "plot_sensors.py writes nothing in the working directory")
print("  plot_sensors.py: " + p.stdout.strip().replace("\n", " | "))
st.check(p.returncode == 0, f"plot_sensors exit {p.returncode} {p.stderr}")
st.check("panel: tip: Displacement [m]; components: tip: ux [m], tip: uy [m]" in p.stdout, "tip sensor: ux, uy in m")
st.check("panel: root: ForceLocal [N]; components: root: axial force [N]" in p.stdout, "root sensor: axial force in N")
st.check("x axis: load factor [-]" in p.stdout, "x axis named")
image_ok(png)
p = st.script("plot_results.py", h5s, "-o", os.path.join(work, "plots_ancf.png"))
st.check(p.returncode == 0 and "axes: x [m], y [m]" in p.stdout, "2D ANCF model drawn in the xy plane")
st.done()
