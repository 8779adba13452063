# ctest-labels: smoke
"""-help lists every flag Sinew reads (issue 24 item 11). The flags are found in the sources, not in
the registry: every settings field (the field tables of src/settings/fields.cpp), every
PetscOptionsGet*/HasName/SetValue call with a literal name (and its prefix) and every
applySolverOptionDefault("-name", ...) in src/ and include/, and every scene opt field
(sceneOptionDocs in src/scene/options.cpp: each is a flag). Each must appear exactly once in
`sinew -help` or `sinew -help_dev` (testing aids and solver internals) as a line "  -name default
meaning", on 1 and 2 ranks (printed by rank 0 only) and with -h. The help is Sinew's alone (no PETSc
banner; PETSc's options are -help_petsc's), starts with Sinew's name, and every line is under 100
characters. -help <flag> prints one flag in full; a misspelt one is exit 2 with the nearest name.
A flag read in the code but missing from the registry fails this test, and so does an option read
outside src/settings/ (settings are read once there, src/settings/read_settings.cpp, and handed to
the code that uses them)."""
import glob
import os
import re
import subprocess

import sinewtest as st

TIMEOUT = 120
CALL = re.compile(r'PetscOptions(?:Get\w+|HasName|SetValue)\s*\(\s*[^,()]+,\s*(?:(?:nullptr|NULL|PETSC_NULL)\s*,\s*'
                  r'|"(\w*)"\s*,\s*)?"-(\w+)"')
DEFAULT = re.compile(r'applySolverOptionDefault\s*\(\s*"-(\w+)"')
READ = re.compile(r'PetscOptions(?:Get\w+|HasName)\s*\(')


outside = []  # sources reading the options database outside src/settings/


def flags_in_sources():
    found = {}
    for path in glob.glob(os.path.join(st.SOURCE, "src", "**", "*.[ch]pp"), recursive=True) + \
            glob.glob(os.path.join(st.SOURCE, "include", "**", "*.hpp"), recursive=True):
        with open(path) as f:
            text = f.read()
        rel = os.path.relpath(path, st.SOURCE)
        for prefix, name in CALL.findall(text):
            found.setdefault(prefix + name, rel)
        for name in DEFAULT.findall(text):
            found.setdefault(name, rel)
        if READ.search(text) and not rel.startswith(os.path.join("src", "settings") + os.sep):
            outside.append(rel)
    with open(os.path.join(st.SOURCE, "src", "settings", "fields.cpp")) as f:
        for name in re.findall(r'^\s*\{"(\w+)",', f.read(), re.M):
            found.setdefault(name, "src/settings/fields.cpp")
    with open(os.path.join(st.SOURCE, "src", "scene", "options.cpp")) as f:
        text = f.read()
    block = text[text.index("sceneOptionDocs() {"):text.index("return docs;")]
    for name in re.findall(r'^\s*\{"(\w+)",', block, re.M):
        found.setdefault(name, "src/scene/options.cpp (opt field)")
    return found


found = flags_in_sources()
print(f"{len(found)} flags read in the sources: {' '.join('-' + n for n in sorted(found))}")
# the scan itself must work: these are read today (issue 13 names the last four as missing from -help)
for must in ("o", "loadsteps", "force_rtol", "max_cuts", "tangent_operator", "buck_eps_nev", "ff_mat_mumps_icntl_7",
             "adaptive_increments", "compliance_method", "dynamics_scheme", "freq_shift_rel"):
    st.check(must in found, f"the source scan misses -{must}")
st.check(not outside, f"options read outside src/settings/ in {', '.join(sorted(set(outside)))}: add a settings field "
                      "(src/settings/settings.hpp, fields.cpp) and pass it to the code that uses it")



def run(np_, args):
    try:
        p = subprocess.run(st.launcher(np_) + args, env=st.ENV, cwd=st.WORK, stdout=subprocess.PIPE,
                           stderr=subprocess.STDOUT, text=True, timeout=TIMEOUT)
    except subprocess.TimeoutExpired:
        st.fail(f"sinew {' '.join(args)} on {np_} rank(s): no exit within {TIMEOUT} s")
        return None, []
    return p.returncode, p.stdout.splitlines()


for np_, flag in ((1, "-help"), (2, "-help"), (1, "-h")):
    code, lines = run(np_, [flag])
    dcode, dev = run(np_, ["-help_dev"])
    tag = f"sinew {flag} on {np_} rank(s)"
    st.check(code == 0 and dcode == 0, f"{tag}: exit {code}, -help_dev exit {dcode}")
    if not lines or not dev:
        continue
    st.check(lines[0].startswith("Sinew ") and dev[0].startswith("Sinew "), f"{tag}: first line {lines[0]!r}")
    for ln in lines + dev:
        st.check(len(ln) < 100, f"{tag}: a line of {len(ln)} characters: {ln!r}")
        st.check("PETSc Team" not in ln and "SLEPc Team" not in ln, f"{tag}: PETSc's banner in Sinew's help: {ln!r}")
    missing = []
    for name, where in sorted(found.items()):
        hits = [ln for ln in lines if re.match(rf"  -{name} ", ln)]
        dev_hits = [ln for ln in dev if re.match(rf"  -{name} ", ln)]
        if not hits and not dev_hits:
            missing.append(f"-{name} ({where})")
        st.check(len(hits) + len(dev_hits) <= 1, f"{tag}: -{name} listed {len(hits)} + {len(dev_hits)} times")
    st.check(not missing, f"{tag} lacks {', '.join(missing)}: add them as settings fields (src/settings/fields.cpp)")
    # one line per flag with its default; developer flags only under -help_dev
    for expected in ("  -max_cuts 10 ", "  -loadsteps 10 ", "  -adaptive_increments true ", "  -compliance_method selinv ",
                     "  -dynamics_scheme arnold_bruls ", "  -freq_shift_rel 1e-8 "):
        st.check(sum(ln.startswith(expected) for ln in lines) == 1, f"{tag}: no line '{expected}'")
    for dev_flag in ("stop_after_step", "assembly_coo", "dynamics_chain_lu"):
        st.check(not any(ln.startswith(f"  -{dev_flag} ") for ln in lines) and
                 any(ln.startswith(f"  -{dev_flag} ") for ln in dev), f"{tag}: -{dev_flag} belongs to -help_dev only")
    print(f"{tag}: exit {code}, {len(lines)} + {len(dev)} lines, all {len(found)} flags listed" if not missing
          else f"{tag}: missing {missing}")

# -help <flag>: the flag in full; a misspelt flag name: exit 2 and the nearest name
code, lines = run(1, ["-help", "max_cuts"])
st.check(code == 0 and lines[:1] == ["-max_cuts"] and any("accepts:  an integer in 0..50" in ln for ln in lines),
         f"-help max_cuts: exit {code}, {lines}")
code, lines = run(2, ["-help", "maxcuts"])
st.check(code == 2 and lines[:1] == ["error: -help maxcuts: no such Sinew flag; did you mean max_cuts?"],
         f"-help maxcuts on 2 ranks: exit {code}, {lines}")
# -help_petsc: PETSc's own help (its options blocks)
code, lines = run(1, ["-help_petsc"])
st.check(code == 0 and any("Options for all PETSc programs" in ln for ln in lines), f"-help_petsc: exit {code}, {lines[:5]}")

st.done()
