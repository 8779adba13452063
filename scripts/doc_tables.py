#!/usr/bin/python3
"""Generated parts of the docs: the study and benchmark scripts (scripts/study_*.py, bench_*.py)
replace only the text between a pair of markers in a docs/*.md file,

    <!-- BEGIN GENERATED: name -->
    ... tables and measured figures, rewritten by the script ...
    <!-- END GENERATED: name -->

and keep everything else (headings, explanations, findings written by hand). A script calls
`doc_tables.write_block("accuracy_beam.md", "beam_rollup", text)` with the file name under docs/ and
the block name as literals (tests/cases/test_doc_tables.py finds the calls and checks the markers).

usage: scripts/doc_tables.py      lists the generated blocks of every docs/*.md"""
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DOCS = os.environ.get("SINEW_DOCS_DIR", os.path.join(ROOT, "docs"))  # another directory: to try a script out


def begin(name):
    return f"<!-- BEGIN GENERATED: {name} -->"


def end(name):
    return f"<!-- END GENERATED: {name} -->"


def blocks(text):
    """Names of the generated blocks of a document, in order."""
    return re.findall(r"^<!-- BEGIN GENERATED: (\S+) -->$", text, flags=re.M)


def replace_block(text, name, body):
    """The text with the block `name` replaced by body. ValueError when its markers are missing,
    repeated or out of order (nothing is guessed: the hand-written text stays as it is)."""
    b, e = begin(name), end(name)
    nb, ne = text.count(b + "\n"), text.count("\n" + e)
    if nb != 1 or ne != 1:
        raise ValueError(f"generated block '{name}': expected one '{b}' line and one '{e}' line, "
                         f"found {nb} and {ne}")
    i = text.index(b + "\n") + len(b) + 1
    j = text.index("\n" + e)
    if j < i - 1:
        raise ValueError(f"generated block '{name}': '{e}' comes before '{b}'")
    body = body.strip("\n")
    return text[:i] + (body + "\n" if body else "") + text[j + 1:]


def write_block(doc, name, body):
    """Replaces the block `name` of docs/<doc> by body; exits with a message when the markers are missing."""
    path = os.path.join(DOCS, doc)
    if not os.path.exists(path):
        sys.exit(f"{path} does not exist: create it with the markers\n{begin(name)}\n{end(name)}")
    with open(path) as f:
        text = f.read()
    try:
        new = replace_block(text, name, body)
    except ValueError as err:
        sys.exit(f"{path}: {err}; add the two marker lines where the generated part belongs")
    with open(path, "w") as f:
        f.write(new)
    print(f"updated {os.path.relpath(path, ROOT)} (block {name})")


def main():
    for doc in sorted(os.listdir(DOCS)):
        if doc.endswith(".md"):
            with open(os.path.join(DOCS, doc)) as f:
                names = blocks(f.read())
            if names:
                print(f"docs/{doc}: {', '.join(names)}")


if __name__ == "__main__":
    main()
