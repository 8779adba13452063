#!/usr/bin/python3
"""Mutated scenes for robustness testing of the scene reader and validation (issue 13).

Deterministic for a seed: mutant k of seed s is always the same text. Each mutant applies one
mutation to one source scene (runs/*.yaml and tests/scenes/good/*.yaml by default):
  delete_line      a line removed
  swap_type        a value replaced by one of another type (string, list, map, bool, null)
  extreme_number   a number replaced by 1e308, -1e308, 1e-308, 1e400, .nan, .inf, -.inf, nan, 0 or -0
  truncate         the file cut at a byte
  duplicate_key    a `key: value` line repeated
  indentation      a line indented by more or fewer spaces
  node_range       a node, element or set number replaced by 0, -1 or one far out of range
  duplicate_row    an element row repeated (a duplicated element)
  extra_document   a second YAML document appended
`mesh:` paths are made absolute first, so a mutant can be written anywhere.

  scripts/fuzz_corpus.py --seed 1 --count 200 --out build/fuzz_corpus   # writes NNNN_<source>_<mutation>.yaml + index.txt
"""
import argparse
import glob
import os
import random
import re

SOURCE = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
EXTREMES = ["1e308", "-1e308", "1e-308", "1e400", ".nan", ".inf", "-.inf", "nan", "0", "-0"]
OTHER_TYPES = ["abc", "[1, 2]", "{a: 1}", "true", "null", "''", "[]", "{}"]
NUMBER = re.compile(r"(?<![\w.])[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?(?![\w.])")
INTEGER = re.compile(r"(?<![\w.\-])\d+(?![\w.])")
MUTATIONS = ["delete_line", "swap_type", "extreme_number", "truncate", "duplicate_key", "indentation", "node_range",
             "duplicate_row", "extra_document"]


def default_sources():
    return sorted(glob.glob(os.path.join(SOURCE, "runs", "*.yaml"))) + \
        sorted(glob.glob(os.path.join(SOURCE, "tests", "scenes", "good", "*.yaml")))


def absolute_mesh(text, path):
    """`mesh: rel.msh` -> `mesh: /abs/rel.msh` (relative to the scene file)."""
    def repl(m):
        p = m.group(2).strip()
        if p and not os.path.isabs(p):
            p = os.path.normpath(os.path.join(os.path.dirname(path), p))
        return m.group(1) + p
    return re.sub(r"^(mesh:\s*)(\S+)", repl, text, flags=re.M)


def content_lines(lines):
    """Indices of lines that hold YAML content (not blank, not comments)."""
    return [i for i, ln in enumerate(lines) if ln.strip() and not ln.lstrip().startswith("#")]


def replace_match(rng, text, pattern, choices):
    """Replaces one random match of pattern by one of choices; None when there is no match."""
    matches = [m for m in pattern.finditer(text) if "#" not in text[:m.start()].rsplit("\n", 1)[-1]]  # not in comments
    if not matches:
        return None
    m = rng.choice(matches)
    new = rng.choice(choices) if isinstance(choices, list) else choices(m.group(0))
    line = text.count("\n", 0, m.start()) + 1
    return text[:m.start()] + new + text[m.end():], f"line {line}: {m.group(0)} -> {new}"


def mutate(rng, text, kind):
    """Applies one mutation; returns (text, description) or None when it does not apply."""
    lines = text.split("\n")
    body = content_lines(lines)
    if kind == "delete_line" and body:
        i = rng.choice(body)
        return "\n".join(lines[:i] + lines[i + 1:]), f"line {i + 1} deleted: {lines[i].strip()[:60]}"
    if kind == "swap_type":
        values = [i for i in body if re.search(r":\s*\S", lines[i])]
        if not values:
            return None
        i = rng.choice(values)
        key, _, _ = lines[i].partition(":")
        new = rng.choice(OTHER_TYPES)
        lines[i] = key + ": " + new
        return "\n".join(lines), f"line {i + 1}: value of '{key.strip()}' -> {new}"
    if kind == "extreme_number":
        return replace_match(rng, text, NUMBER, EXTREMES)
    if kind == "truncate" and len(text) > 1:
        cut = rng.randrange(1, len(text))
        return text[:cut], f"truncated at byte {cut} of {len(text)}"
    if kind == "duplicate_key":
        keyed = [i for i in body if re.match(r"\s*[A-Za-z_][\w]*\s*:", lines[i])]
        if not keyed:
            return None
        i = rng.choice(keyed)
        return "\n".join(lines[:i + 1] + [lines[i]] + lines[i + 1:]), f"line {i + 1} repeated: {lines[i].strip()[:60]}"
    if kind == "indentation" and body:
        i = rng.choice(body)
        shift = rng.choice([-4, -2, -1, 1, 2, 3])
        old = len(lines[i]) - len(lines[i].lstrip(" "))
        lines[i] = " " * max(0, old + shift) + lines[i].lstrip(" ")
        return "\n".join(lines), f"line {i + 1}: indentation {old} -> {max(0, old + shift)}"
    if kind == "node_range":
        return replace_match(rng, text, INTEGER, lambda s: rng.choice(["0", "-1", str(int(s) + 1000), "2147483648"]))
    if kind == "duplicate_row":
        try:
            start = lines.index("elements:")
        except ValueError:
            return None
        rows = [i for i in range(start + 1, len(lines)) if lines[i].lstrip().startswith("- [")]
        rows = [i for i in rows if all(lines[j].lstrip().startswith(("- [", "#")) or not lines[j].strip()
                                       for j in range(start + 1, i + 1))]
        if not rows:
            return None
        i = rng.choice(rows)
        return "\n".join(lines[:i + 1] + [lines[i]] + lines[i + 1:]), f"element row at line {i + 1} repeated: {lines[i].strip()}"
    if kind == "extra_document":
        return text + "\n---\ntitle: a second document\n", "a second YAML document appended"
    return None


def generate(seed, count, sources=None, mutations=None):
    """count mutants: list of (name, source path, mutation, description, text)."""
    sources = sources or default_sources()
    mutations = mutations or MUTATIONS
    texts = {}
    for path in sources:
        with open(path) as f:
            texts[path] = absolute_mesh(f.read(), path)
    rng = random.Random(seed)
    out = []
    while len(out) < count:
        path = sources[len(out) % len(sources)]
        kind = mutations[rng.randrange(len(mutations))]
        result = mutate(rng, texts[path], kind)
        if result is None or result[0] == texts[path]:
            continue
        text, what = result
        name = f"{len(out):04d}_{os.path.splitext(os.path.basename(path))[0]}_{kind}"
        out.append((name, path, kind, what, text))
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--count", type=int, default=200)
    ap.add_argument("--out", required=True, help="directory for the mutants and index.txt")
    ap.add_argument("sources", nargs="*", help="scenes to mutate (default: runs/*.yaml, tests/scenes/good/*.yaml)")
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    with open(os.path.join(args.out, "index.txt"), "w") as index:
        for name, path, kind, what, text in generate(args.seed, args.count, args.sources or None):
            with open(os.path.join(args.out, name + ".yaml"), "w") as f:
                f.write(text)
            index.write(f"{name}.yaml\t{os.path.relpath(path, SOURCE)}\t{kind}\t{what}\n")
    print(f"{args.count} mutants (seed {args.seed}) in {args.out}")


if __name__ == "__main__":
    main()
