# ctest-processors: 1
# ctest-labels: smoke
"""The code's rooms (DEVELOPERS.md, "Map of the code"), checked on the sources:
1. every folder under src/ is a known room, and a room includes only the rooms listed before it
   (so the include graph of the rooms has no cycle); include/sinew includes only itself;
2. no C++ file under src/ or include/ has more than 800 lines;
3. no room directly under src/ (with its sub-rooms) holds more than 15 % of src/'s C++ lines;
4. options are read only in src/settings/ and no concrete element kernel is cast to outside
   src/elements/."""
import os
import re

import sinewtest as st

SRC = os.path.join(st.SOURCE, "src")
# lowest first; a room may include itself and the rooms before it
ROOMS = ["sinew", "math", "elements", "scene", "settings", "parallel", "mesh", "assembly", "solvers",
         "solvers/ancf", "output", "restart", "analysis", "step", "dynamics", "accuracy", "app", "app/phases", "python"]
SAME_ROOM = {"app/phases": "app"}  # the phases are part of the app room: they include its plan and summary


def room_of(path):
    """room of a folder path relative to src/ (or of an include path's folder)."""
    if path.startswith("sinew"):
        return "sinew"
    return path if path in ROOMS else None


def cxx_files(top):
    for d, _, fs in os.walk(top):
        for f in fs:
            if f.endswith((".cpp", ".hpp")):
                yield os.path.join(d, f)


lines_per_room = {}
total = 0
for path in cxx_files(SRC):
    rel = os.path.relpath(os.path.dirname(path), SRC)
    room = room_of(rel)
    st.check(room is not None, f"{os.path.relpath(path, st.SOURCE)}: folder src/{rel} is no room of DEVELOPERS.md's map")
    text = open(path, encoding="utf-8").read()
    n = text.count("\n")
    total += n
    top = rel.split("/")[0]
    lines_per_room[top] = lines_per_room.get(top, 0) + n
    st.check(n <= 800, f"{os.path.relpath(path, st.SOURCE)}: {n} lines (at most 800)")
    if room is None:
        continue
    mine = ROOMS.index(SAME_ROOM.get(room, room))
    for inc in re.findall(r'#include "([^"]+)"', text):
        target = room_of(os.path.dirname(inc))
        if target is None:
            continue  # a file of the same folder included by its bare name
        st.check(ROOMS.index(SAME_ROOM.get(target, target)) <= mine,
                 f"{os.path.relpath(path, st.SOURCE)} includes {inc}: room {target} is above room {room}")
    if not rel.startswith("settings"):
        st.check(not re.search(r"PetscOptions(Get|HasName)", text),
                 f"{os.path.relpath(path, st.SOURCE)} reads PETSc options (settings are read in src/settings/)")
    if not rel.startswith("elements"):
        st.check(not re.search(r"dynamic_cast<\s*(const\s+)?(Cable3D|Membrane|AncfCable2D|BeamCorotational)", text),
                 f"{os.path.relpath(path, st.SOURCE)} casts to a concrete element kernel")
for path in cxx_files(os.path.join(st.SOURCE, "include", "sinew")):
    text = open(path, encoding="utf-8").read()
    st.check(text.count("\n") <= 800, f"{os.path.relpath(path, st.SOURCE)}: more than 800 lines")
    for inc in re.findall(r'#include "([^"]+)"', text):
        st.check(inc.startswith("sinew/"), f"{os.path.relpath(path, st.SOURCE)} includes {inc} (public headers include only sinew/)")
for room, n in sorted(lines_per_room.items(), key=lambda kv: -kv[1]):
    print(f"  src/{room}: {n} lines, {100.0 * n / total:.1f} % of {total}")
    st.check(n <= 0.15 * total, f"src/{room} holds {100.0 * n / total:.1f} % of src/'s lines (at most 15 %)")
st.done()
