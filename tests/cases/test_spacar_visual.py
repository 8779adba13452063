#!/usr/bin/python3
"""SPACAR Light's element look is used where Sinew draws (issue 10, item 5). Four beams on 2 ranks:
element 1 `color: darkgreen` (seed table name) with `opacity: 0.5`, element 2 `color: [255, 0, 0]`
(0..255 form) with `hide: true`, element 3 in no set (rigid: grey), element 4 `color: 3` (index of
the table: darkblue). The result file holds /mesh/lines_color, _opacity, _visible per cell (checked
through /mesh/lines_element), the XDMF the cell attributes color, opacity, visible, and
scripts/plot_input.py and plot_results.py draw element 1 half transparent dark green, element 4 dark
blue, and leave the hidden red element out (pixels of the PNGs). Without look fields in the scene
there are no look datasets and the pictures are drawn in the default blue. Both scripts draw the rigid
element 3 (in no eprops set) in the seed's grey 198/255, with and without look fields (issue 24 item 14)."""
import os

import matplotlib.image as mpimg
import numpy as np

import sinewtest as st

# the seed's darkblue (0, 124, 176)/255; RIGID_GREY: the rigid colour of the look datasets (runner.cpp fillLook) and of the pictures; GREY: the former 0.7
DARKGREEN, DARKBLUE, GREY, RED = (0.1, 0.4, 0.1), (0.0, 124 / 255, 176 / 255), (0.7, 0.7, 0.7), (1.0, 0.0, 0.0)
RIGID_GREY = (198 / 255,) * 3  # how the scripts draw rigid elements (the seed's grey)
beam = {"flex": [1, 2, 3, 4, 5, 6], "emod": 210e9, "smod": 80e9, "cshape": "circ", "dim": 0.01}
scene = {
    "nodes": [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [2, 0, 0]],
    "elements": [[1, 2], [2, 3], [3, 4], [2, 5]],
    "nprops": {1: {"fix": True}, 5: {"force": [0, 1, 0]}},
    "eprops": [dict(beam, elems=[1], color="darkgreen", opacity=0.5),
               dict(beam, elems=[2], color=[255, 0, 0], hide=True),
               dict(beam, elems=[4], color=3)],
    "opt": {"loadsteps": 1, "calccompl": False},
}
expected = {1: DARKGREEN + (0.5, 1), 2: RED + (1, 0), 3: RIGID_GREY + (1, 1), 4: DARKBLUE + (1, 1)}

out, log = st.run("spacar_visual", scene)
with st.h5(out) as f:
    st.check(all(f"mesh/lines_{k}" in f for k in ("color", "opacity", "visible")), "look datasets written")
    owner = f["mesh/lines_element"][()]
    got = np.column_stack([f["mesh/lines_color"][()], f["mesh/lines_opacity"][()], f["mesh/lines_visible"][()]])
for e, want in expected.items():
    rows = got[owner == e]
    st.check(len(rows) > 0, f"element {e} has cells")
    st.close(rows, np.tile(want, (len(rows), 1)), atol=1e-15, what=f"element {e}: r, g, b, opacity, visible")
xdmf = open(os.path.splitext(out)[0] + ".xdmf").read()
for name, kind in (("color", "Vector"), ("opacity", "Scalar"), ("visible", "Scalar")):
    st.check(f'<Attribute Name="{name}" AttributeType="{kind}" Center="Cell">' in xdmf and f"/mesh/lines_{name}" in xdmf,
             f"XDMF cell attribute {name}")


def pixels(png, rgb, tol=0.04):
    img = mpimg.imread(png)[..., :3]
    return int(np.count_nonzero(np.all(np.abs(img - np.array(rgb)) < tol, axis=-1)))


def rigid_grey(png):
    """The rigid element's grey 198/255 outweighs the 0.7 grey (antialiased edges of other lines and text
    pass through both; a rigid element drawn in 0.7 or blue does not give 198/255 the lead)."""
    seed, other = pixels(png, RIGID_GREY, 0.015), pixels(png, GREY, 0.015)
    print(f"  {os.path.basename(png)}: pixels grey 198/255 {seed}, grey 0.7 {other}")
    return seed > 500 and seed > 2 * other


def script(name, *args):
    p = st.script(name, *args)
    text = p.stdout + p.stderr
    st.check(p.returncode == 0, f"{name} exit {p.returncode}: {text[-500:]}")
    return text


half_green = tuple(0.5 * c + 0.5 for c in DARKGREEN)  # 50 % opacity over the white background
pictures = {}
for name, extra in (("plot_input.py", []), ("plot_results.py", ["--scale", "1"])):
    png = os.path.join(st.WORK, "spacar_visual_" + name.replace(".py", ".png"))
    text = script(name, out, "-o", png, *extra)
    print(f"  {name}: " + " | ".join(ln for ln in text.splitlines() if "look" in ln))
    st.check("1 hidden" in text, f"{name}: says one hidden element/cell: {text}")
    counts = {c: pixels(png, rgb) for c, rgb in (("half green", half_green), ("dark blue", DARKBLUE), ("red", RED))}
    print(f"  {name}: pixels {counts}")
    st.check(counts["half green"] > 20, f"{name}: element 1 drawn dark green at opacity 0.5")
    st.check(counts["dark blue"] > 20, f"{name}: element 4 drawn dark blue")
    st.check(counts["red"] == 0, f"{name}: the hidden red element is not drawn")
    st.check(rigid_grey(png) and "rigid elements (in no eprops set)" in text,
             f"{name}: the rigid element 3 drawn in the seed's grey 198/255")
    pictures[name] = png

# without look fields: no look datasets, default blue pictures
plain = dict(scene, eprops=[dict(beam, elems=[1, 2, 4])])
out, _ = st.run("spacar_visual_plain", plain)
with st.h5(out) as f:
    st.check("mesh/lines_color" not in f, "no look datasets without color/opacity/hide")
png = os.path.join(st.WORK, "spacar_visual_plain.png")
text = script("plot_input.py", out, "-o", png)
st.check("look" not in text, "plot_input.py: no look note without look fields")
st.check(pixels(png, (0.0, 0.447, 0.741)) > 20 and pixels(png, half_green) == 0, "plain scene drawn in the default blue")
st.check(rigid_grey(png), "plot_input.py: the rigid element in the seed's grey without look fields")
png = os.path.join(st.WORK, "spacar_visual_plain_results.png")
text = script("plot_results.py", out, "-o", png, "--scale", "1")
st.check(rigid_grey(png), "plot_results.py: the rigid element in the seed's grey without look fields")
st.done()
