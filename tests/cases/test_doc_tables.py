"""Generated doc tables and the scripts' conventions (issue 9, item 7).
1. scripts/doc_tables.py replaces the text between the markers of one block and keeps every other
   character of the document (text before, between two blocks, after); missing or repeated markers
   are an error, and write_block leaves the file untouched then.
2. Every block a study/bench script writes (doc_tables.write_block("<doc>", "<name>", ...) calls,
   found in the scripts' source) has exactly one pair of markers in docs/<doc>; no script writes a
   docs/*.md file by itself (open(..., "w") on a docs path), so hand-written text is never lost.
3. Every python script in scripts/ starts with #!/usr/bin/python3 and has its run bit."""
import ast
import os
import shutil
import subprocess
import sys
import tempfile

import sinewtest as st

SCRIPTS = os.path.join(st.SOURCE, "scripts")
DOCS = os.path.join(st.SOURCE, "docs")
sys.path.insert(0, SCRIPTS)
import doc_tables  # noqa: E402

# --- 1. the helper
doc = ("# Title\n\nHand-written intro.\n\n<!-- BEGIN GENERATED: t1 -->\n| a |\n|---|\n| 1 |\n<!-- END GENERATED: t1 -->\n\n"
       "Findings written by hand.\n\n<!-- BEGIN GENERATED: t2 -->\nold\n<!-- END GENERATED: t2 -->\nTail.\n")
new = doc_tables.replace_block(doc, "t1", "| a |\n|---|\n| 2 |\n| 3 |\n")
st.check(new == doc.replace("| 1 |\n", "| 2 |\n| 3 |\n"), f"t1 replaced, everything else kept:\n{new}")
new2 = doc_tables.replace_block(new, "t2", "fresh")
st.check(new2 == new.replace("\nold\n", "\nfresh\n"), "t2 replaced, t1 and the text kept")
st.check(doc_tables.replace_block(new2, "t2", "fresh") == new2, "replacing with the same text is a no-op")
st.check(doc_tables.blocks(doc) == ["t1", "t2"], f"blocks() lists the blocks: {doc_tables.blocks(doc)}")
for bad, why in ((doc.replace("<!-- END GENERATED: t1 -->\n", ""), "missing end marker"),
                 (doc + "<!-- BEGIN GENERATED: t1 -->\nx\n<!-- END GENERATED: t1 -->\n", "repeated block"),
                 (doc, "unknown block")):
    try:
        doc_tables.replace_block(bad, "t1" if why != "unknown block" else "t3", "x")
        st.fail(f"{why}: no error")
    except ValueError as err:
        print(f"  {why}: ValueError ({err})")

# write_block on a copy of the docs: the marked block changes, nothing else; no markers -> exit, file kept
tmp = tempfile.mkdtemp(prefix="doc_tables_")
try:
    with open(os.path.join(tmp, "x.md"), "w") as f:
        f.write(doc)
    with open(os.path.join(tmp, "plain.md"), "w") as f:
        f.write("# no markers\n")
    code = ("import sys; sys.path.insert(0, %r); import doc_tables; doc_tables.DOCS = %r; "
            "doc_tables.write_block(sys.argv[1], sys.argv[2], 'NEW')") % (SCRIPTS, tmp)
    p = subprocess.run(["/usr/bin/python3", "-c", code, "x.md", "t2"], capture_output=True, text=True, timeout=60)
    st.check(p.returncode == 0, f"write_block x.md t2: exit {p.returncode} {p.stderr}")
    st.check(open(os.path.join(tmp, "x.md")).read() == doc.replace("\nold\n", "\nNEW\n"), "write_block wrote only t2")
    p = subprocess.run(["/usr/bin/python3", "-c", code, "plain.md", "t1"], capture_output=True, text=True, timeout=60)
    st.check(p.returncode != 0 and "BEGIN GENERATED: t1" in p.stderr, f"no markers: error naming them ({p.stderr.strip()})")
    st.check(open(os.path.join(tmp, "plain.md")).read() == "# no markers\n", "file without markers untouched")
finally:
    shutil.rmtree(tmp)


# --- 2. every generated block of every script has its markers; no direct writes of docs
def calls(tree):
    for node in ast.walk(tree):
        if isinstance(node, ast.Call):
            yield node


writers = {}
for name in sorted(os.listdir(SCRIPTS)):
    if not name.endswith(".py") or name == "doc_tables.py":
        continue
    tree = ast.parse(open(os.path.join(SCRIPTS, name)).read(), name)
    for c in calls(tree):
        f = c.func
        if isinstance(f, ast.Attribute) and f.attr == "write_block":
            ok = len(c.args) >= 2 and all(isinstance(a, ast.Constant) and isinstance(a.value, str) for a in c.args[:2])
            if st.check(ok, f"{name}:{c.lineno}: write_block with literal doc and block names"):
                writers.setdefault((c.args[0].value, c.args[1].value), []).append(name)
        if isinstance(f, ast.Name) and f.id == "open" and len(c.args) >= 2:
            mode = c.args[1].value if isinstance(c.args[1], ast.Constant) else ""
            target = ast.unparse(c.args[0])
            st.check(not ("w" in str(mode) and ("docs" in target or ".md" in target)),
                     f"{name}:{c.lineno}: writes {target} directly (use doc_tables.write_block)")
        if isinstance(f, ast.Attribute) and f.attr == "savefig":
            pass  # figures are whole files, regenerated as a whole
for s in ("study_beam.py", "study_ancf.py", "study_modal.py", "study_formfinding.py", "bench_ancf.py", "bench_beam.py",
          "bench_formfinding.py", "bench_compliance.py", "bench_modal.py"):
    st.check(any(s in v for v in writers.values()), f"{s} writes its tables through doc_tables")
for (docname, block), who in sorted(writers.items()):
    path = os.path.join(DOCS, docname)
    if not st.check(os.path.exists(path), f"{', '.join(who)}: docs/{docname} exists"):
        continue
    text = open(path).read()
    nb = text.count(doc_tables.begin(block) + "\n")
    ne = text.count("\n" + doc_tables.end(block))
    st.check(nb == 1 and ne == 1, f"docs/{docname}: block {block} ({', '.join(who)}) has one pair of markers ({nb}, {ne})")
    try:
        doc_tables.replace_block(text, block, "x")
    except ValueError as err:
        st.fail(f"docs/{docname}: {err}")
print(f"  {len(writers)} generated blocks checked: {', '.join(f'{d}:{b}' for d, b in sorted(writers))}")
# every marked block in the docs belongs to a script (no stale markers)
for docname in sorted(os.listdir(DOCS)):
    if docname.endswith(".md"):
        for block in doc_tables.blocks(open(os.path.join(DOCS, docname)).read()):
            st.check((docname, block) in writers, f"docs/{docname}: block {block} is written by some script")

# --- 3. shebang and run bit
for name in sorted(os.listdir(SCRIPTS)):
    if name.endswith(".py"):
        path = os.path.join(SCRIPTS, name)
        first = open(path).readline().rstrip("\n")
        st.check(first == "#!/usr/bin/python3", f"scripts/{name}: first line {first!r}")
        st.check(os.access(path, os.X_OK), f"scripts/{name} is executable")
st.done()
