"""SPACAR Light MATLAB scripts -> Sinew scenes.

    scene = sinew.from_spacar("crosshinge.m")     # a sinew.Scene (scene.data is the scene dict)
    scene.write("crosshinge.yaml")

Reads the subset of MATLAB that SPACAR Light scripts use: assignments `nodes = [...]`,
`elements = [...]`, `nprops(i).field = value`, `eprops(i).field = value`, `opt.field = value`,
`opt.rls(i).def = [...]`, plain variables and arithmetic (+ - * / ^ and their element-wise forms,
ranges a:b and a:s:b, [..] matrices, {..} cells, 'strings', true/false, pi, sqrt, sin, cos, tan,
asin, acos, atan, atan2, exp, log, abs, deg2rad, rad2deg, zeros, ones, numel, length, size(v, d),
indexing v(i), v(i, j), v(end)), `for k = range ... end` loops (nested), and the call
`out = spacarlight(nodes, elements, nprops, eprops, opt)`, whose argument names say which variables
are the model. `clc`, `clear`, `close all`, `disp(...)`, `fprintf(...)` and `figure` lines are
skipped. Anything else is an error naming the line, never guessed.

nprops(i) is node i and eprops(i) property set i, as in SPACAR Light; opt.rls(i).def releases
modes of element i. Logical fields given as 0/1 become true/false."""
import math
import re

import numpy as np

# SPACAR Light fields that are logical (0/1 in a script means false/true)
BOOL_FIELDS = {"fix", "fix_pos", "fix_orien", "fix_x", "fix_y", "fix_z", "cw", "hide", "calcbuck", "calccompl",
               "calcfreq", "silent", "showinputonly", "spavisual", "stressperelement", "rigidstress"}


# fields that are lists in a Sinew scene even when a script gives one number (eprops(1).elems = 3)
VECTOR_FIELDS = {"elems", "flex", "dim", "orien", "force", "force_initial", "moment", "moment_initial", "mominertia",
                 "gravity", "compliance_nodes", "rot", "rot_initial"}


class SpacarError(ValueError):
    """A script line the converter cannot read (message: file, line, what)."""


class Struct(dict):
    """A MATLAB struct: field -> value (a struct array is a dict index -> Struct)."""


class StructArray(dict):
    """A MATLAB struct array: 1-based index -> Struct."""


# ---------------------------------------------------------------------------------------------- lexer
TOKEN = re.compile(r"""
    (?P<num>(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?[ij]?)
  | (?P<str>'(?:[^']|'')*'|"[^"]*")
  | (?P<name>[A-Za-z_]\w*)
  | (?P<op>\.\*|\./|\.\^|\.'|==|~=|<=|>=|&&|\|\||[-+*/^:()\[\]{},;=.'<>~&|@])
  | (?P<ws>[ \t]+)
""", re.X)


def tokens(text, line):
    out, pos = [], 0
    while pos < len(text):
        m = TOKEN.match(text, pos)
        if not m:
            raise SpacarError(f"line {line}: cannot read '{text[pos:pos + 20]}'")
        kind = m.lastgroup
        val = m.group()
        # a quote right after an operand is a transpose, not a string
        if kind == "str" and val.startswith("'") and out and (out[-1][0] in ("num", "name") or out[-1][1] in (")", "]", "'", ".'")):
            out.append(("op", "'"))
            pos += 1
            continue
        out.append((kind, val))
        pos = m.end()
    return out


# --------------------------------------------------------------------------------------------- parser
class Parser:
    """Recursive-descent parser of one expression into nested tuples."""

    def __init__(self, toks, line, in_matrix=False):
        self.t = [t for t in toks]
        self.i = 0
        self.line = line

    def skip_ws(self):
        while self.i < len(self.t) and self.t[self.i][0] == "ws":
            self.i += 1

    def peek(self, ws=False):
        """The next token (ws: whitespace counts as a token); never moves."""
        j = self.i
        while not ws and j < len(self.t) and self.t[j][0] == "ws":
            j += 1
        return self.t[j] if j < len(self.t) else (None, None)

    def take(self, val=None):
        self.skip_ws()
        tok = self.peek()
        if val is not None and tok[1] != val:
            raise SpacarError(f"line {self.line}: expected '{val}', got '{tok[1]}'")
        self.i += 1
        return tok

    def done(self):
        return self.peek()[0] is None

    # precedence: range < or/and < comparison < additive < multiplicative < unary < power < postfix
    def expr(self):
        a = self.additive()
        if self.peek()[1] == ":":
            self.take(":")
            b = self.additive()
            if self.peek()[1] == ":":
                self.take(":")
                c = self.additive()
                return ("range", a, b, c)
            return ("range", a, ("num", 1.0), b)
        return a

    def additive(self, matrix=False):
        a = self.term(matrix)
        while True:
            # inside [..]: "1 -2" is two elements, "1 - 2" and "1-2" one
            if matrix and self.i < len(self.t) and self.t[self.i][0] == "ws":
                nxt = self.t[self.i + 1] if self.i + 1 < len(self.t) else (None, None)
                after = self.t[self.i + 2] if self.i + 2 < len(self.t) else (None, None)
                if nxt[1] in ("+", "-") and after[0] != "ws":
                    return a
            op = self.peek()[1]
            if op in ("+", "-"):
                self.take()
                a = (op, a, self.term(matrix))
            else:
                return a

    def term(self, matrix=False):
        a = self.unary(matrix)
        while self.peek()[1] in ("*", "/", ".*", "./"):
            op = self.take()[1]
            a = (op, a, self.unary(matrix))
        return a

    def unary(self, matrix=False):
        if self.peek()[1] in ("-", "+"):
            op = self.take()[1]
            v = self.unary(matrix)
            return ("neg", v) if op == "-" else v
        if self.peek()[1] == "~":
            self.take()
            return ("not", self.unary(matrix))
        return self.power(matrix)

    def power(self, matrix=False):
        a = self.postfix()
        while self.peek(ws=True)[1] in ("^", ".^"):
            op = self.take()[1]
            a = (op, a, self.unaryless())
        return a

    def unaryless(self):
        if self.peek()[1] == "-":
            self.take()
            return ("neg", self.postfix())
        return self.postfix()

    def postfix(self):
        a = self.primary()
        while True:
            tok = self.peek(ws=True)
            if tok[1] == "(":
                self.take("(")
                args = self.args(")")
                a = ("call", a, args)
            elif tok[1] in ("'", ".'"):
                self.take()
                a = ("transpose", a)
            elif tok[1] == "." and self.i + 1 < len(self.t) and self.t[self.i + 1][0] == "name":
                self.take(".")
                a = ("field", a, self.take()[1])
            else:
                return a

    def args(self, close):
        out = []
        if self.peek()[1] == close:
            self.take(close)
            return out
        while True:
            if self.peek()[1] == ":":  # a whole dimension, v(:, 1)
                self.take(":")
                out.append(("colon",))
            else:
                out.append(self.expr())
            tok = self.take()
            if tok[1] == close:
                return out
            if tok[1] != ",":
                raise SpacarError(f"line {self.line}: expected ',' or '{close}', got '{tok[1]}'")

    def primary(self):
        kind, val = self.take()
        if kind == "num":
            if val[-1] in "ij":
                raise SpacarError(f"line {self.line}: complex numbers are not SPACAR Light input")
            return ("num", float(val))
        if kind == "str":
            return ("str", val[1:-1].replace("''", "'"))
        if kind == "name":
            if val == "end":
                return ("end",)
            return ("name", val)
        if val == "(":
            e = self.expr()
            self.take(")")
            return e
        if val in ("[", "{"):
            return self.matrix("]" if val == "[" else "}", val == "{")
        raise SpacarError(f"line {self.line}: unexpected '{val}'")

    def matrix(self, close, cell):
        rows, row = [], []
        while True:
            tok = self.peek()
            if tok[1] == close:
                self.take()
                if row:
                    rows.append(row)
                return ("cell" if cell else "matrix", rows)
            if tok[1] == ";":
                self.take()
                rows.append(row)
                row = []
                continue
            if tok[1] == ",":
                self.take()
                continue
            if tok[0] is None:
                raise SpacarError(f"line {self.line}: '{close}' missing")
            start = self.i
            row.append(self.matrix_element())
            if self.i == start:
                raise SpacarError(f"line {self.line}: cannot read the matrix")

    def matrix_element(self):
        a = self.additive(matrix=True)
        if self.peek(ws=True)[1] == ":":
            self.take(":")
            b = self.additive(matrix=True)
            if self.peek(ws=True)[1] == ":":
                self.take(":")
                return ("range", a, b, self.additive(matrix=True))
            return ("range", a, ("num", 1.0), b)
        return a


# ------------------------------------------------------------------------------------------ evaluator
FUNCTIONS = {
    "sqrt": np.sqrt, "sin": np.sin, "cos": np.cos, "tan": np.tan, "asin": np.arcsin, "acos": np.arccos,
    "atan": np.arctan, "exp": np.exp, "log": np.log, "abs": np.abs, "deg2rad": np.deg2rad, "rad2deg": np.rad2deg,
    "atan2": np.arctan2, "round": np.round, "floor": np.floor, "ceil": np.ceil,
}
SKIPPED = re.compile(r"^\s*(clc|clear\b.*|close\b.*|figure\b.*|hold\b.*|format\b.*|disp\s*\(.*\)|fprintf\s*\(.*\)|addpath\s*\(.*\))\s*$")


def as_array(v):
    return np.atleast_2d(np.asarray(v, dtype=float))


class Interpreter:
    def __init__(self, source="script"):
        self.vars = {"pi": math.pi, "true": True, "false": False, "Inf": math.inf, "inf": math.inf}
        self.source = source
        self.call = None  # argument names of the spacarlight(...) call
        self.line = 0

    def fail(self, msg):
        raise SpacarError(f"{self.source} line {self.line}: {msg}")

    # ---- values
    def value(self, node, end=None):
        kind = node[0]
        if kind == "num":
            return node[1]
        if kind == "str":
            return node[1]
        if kind == "end":
            if end is None:
                self.fail("'end' outside an index")
            return float(end)
        if kind == "name":
            if node[1] not in self.vars:
                self.fail(f"unknown variable or function '{node[1]}'")
            return self.vars[node[1]]
        if kind == "neg":
            v = self.value(node[1], end)
            return -np.asarray(v, dtype=float) if not np.isscalar(v) else -v
        if kind == "not":
            return not bool(self.value(node[1], end))
        if kind in ("+", "-", "*", "/", ".*", "./", "^", ".^"):
            a, b = self.value(node[1], end), self.value(node[2], end)
            a = float(a) if isinstance(a, bool) else a
            b = float(b) if isinstance(b, bool) else b
            if kind == "+":
                return np.add(a, b)
            if kind == "-":
                return np.subtract(a, b)
            if kind in ("*", ".*"):
                if kind == "*" and not np.isscalar(a) and not np.isscalar(b):
                    return as_array(a) @ as_array(b)
                return np.multiply(a, b)
            if kind in ("/", "./"):
                return np.divide(a, b)
            return np.power(a, b)
        if kind == "transpose":
            return as_array(self.value(node[1], end)).T
        if kind == "range":
            a, s, b = (float(np.asarray(self.value(x, end)).ravel()[0]) for x in node[1:])
            if s == 0:
                return np.zeros((1, 0))
            n = int(math.floor((b - a) / s + 1e-10)) + 1
            return np.array([[a + k * s for k in range(max(n, 0))]])
        if kind == "matrix":
            rows = []
            for row in node[1]:
                parts = [self.value(e, end) for e in row]
                parts = [as_array(float(p) if isinstance(p, bool) else p) for p in parts if not isinstance(p, str)] \
                    if not any(isinstance(p, str) for p in parts) else None
                if parts is None:
                    strs = [self.value(e, end) for e in row]
                    return "".join(strs)
                parts = [p for p in parts if p.size]
                if parts:
                    rows.append(np.hstack(parts))
            if not rows:
                return np.zeros((0, 0))
            try:
                return np.vstack(rows)
            except ValueError:
                self.fail("matrix rows of different lengths")
        if kind == "cell":
            return [self.value(e, end) for row in node[1] for e in row]
        if kind == "field":
            base = self.value(node[1], end)
            if not isinstance(base, dict) or node[2] not in base:
                self.fail(f"no field '{node[2]}'")
            return base[node[2]]
        if kind == "call":
            return self.call_or_index(node[1], node[2])
        self.fail(f"cannot evaluate {kind}")

    def call_or_index(self, target, args):
        if target[0] == "name" and target[1] not in self.vars:
            name = target[1]
            vals = [self.value(a) for a in args]
            if name in FUNCTIONS:
                r = FUNCTIONS[name](*[np.asarray(v, dtype=float) for v in vals])
                return float(r) if np.ndim(r) == 0 else as_array(r)
            if name in ("zeros", "ones"):
                shape = [int(v) for v in vals] if len(vals) > 1 else [int(vals[0])] * 2
                return (np.zeros if name == "zeros" else np.ones)(shape)
            if name in ("numel", "length"):
                v = as_array(vals[0])
                return float(v.size if name == "numel" else max(v.shape))
            if name == "size":
                v = as_array(vals[0])
                return float(v.shape[int(vals[1]) - 1]) if len(vals) > 1 else np.array([list(v.shape)], dtype=float)
            if name == "eye":
                return np.eye(int(vals[0]))
            if name == "norm":
                return float(np.linalg.norm(np.asarray(vals[0], dtype=float)))
            self.fail(f"unknown function '{name}'")
        base = self.value(target)
        if isinstance(base, StructArray):
            if len(args) != 1:
                self.fail("a struct array takes one index")
            k = int(self.value(args[0]))
            if k not in base:
                self.fail(f"index {k} not assigned")
            return base[k]
        if isinstance(base, list):
            k = int(self.value(args[0], len(base)))
            return base[k - 1]
        arr = as_array(base)
        if len(args) == 1:
            flat = arr.T.ravel()  # MATLAB's column-major linear index
            idx = self.indices(args[0], flat.size)
            r = flat[idx]
            return float(r[0]) if r.size == 1 else r.reshape(1, -1)
        if len(args) == 2:
            i = self.indices(args[0], arr.shape[0])
            j = self.indices(args[1], arr.shape[1])
            r = arr[np.ix_(i, j)]
            return float(r[0, 0]) if r.size == 1 else r
        self.fail("at most two indices")

    def indices(self, node, n):
        if node[0] == "colon":
            return np.arange(n)
        v = np.asarray(self.value(node, n), dtype=float).ravel()
        if np.any(v < 1) or np.any(v > n) or np.any(v != np.round(v)):
            self.fail(f"index {v.tolist()} outside 1..{n}")
        return v.astype(int) - 1

    # ---- assignment targets: name, name(i), .field, chains
    def assign(self, target, val):
        chain = []
        node = target
        while node[0] in ("field", "call"):
            chain.append(node)
            node = node[1]
        if node[0] != "name":
            self.fail("cannot assign to this expression")
        chain.reverse()
        name = node[1]
        if not chain:
            self.vars[name] = val
            return
        container = self.vars
        key = name
        for step in chain:
            cur = container.get(key) if isinstance(container, dict) else None
            if step[0] == "field":
                if not isinstance(cur, dict) or isinstance(cur, StructArray):
                    if isinstance(cur, StructArray) and 1 in cur and len(cur) == 1:
                        cur = cur[1]
                    elif cur is None or (not isinstance(cur, dict)):
                        cur = Struct()
                    container[key] = cur
                container, key = cur, step[2]
            else:  # (index)
                if len(step[2]) != 1:
                    if len(step[2]) == 2 and step is chain[-1] and not isinstance(cur, dict):
                        container[key] = self.assign_matrix(cur, step[2], val)
                        return
                    self.fail("a struct array takes one index")
                k = int(self.value(step[2][0]))
                if k < 1:
                    self.fail(f"index {k} below 1")
                if step is chain[-1] and not isinstance(val, dict) and not isinstance(cur, StructArray):
                    arr = as_array(cur if cur is not None else np.zeros((1, 0))).ravel().tolist()
                    while len(arr) < k:
                        arr.append(0.0)
                    arr[k - 1] = float(val)
                    container[key] = np.array([arr])
                    return
                if not isinstance(cur, StructArray):
                    cur = StructArray()
                    container[key] = cur
                if k not in cur:
                    cur[k] = Struct()
                container, key = cur, k
                if step is chain[-1]:
                    cur[k] = val
                    return
        container[key] = val

    def assign_matrix(self, cur, index, val):
        """v(i, j) = x with i, j numbers, vectors or ':'; the matrix grows with zeros as in MATLAB."""
        arr = as_array(cur if cur is not None else np.zeros((0, 0))).copy()
        rhs = as_array(float(val) if isinstance(val, bool) else val)

        def rows_of(node, n, count):
            if node[0] == "colon":
                return np.arange(max(n, count))
            v = np.asarray(self.value(node, n), dtype=float).ravel()
            if np.any(v < 1) or np.any(v != np.round(v)):
                self.fail(f"index {v.tolist()} below 1 or not whole")
            return v.astype(int) - 1
        i = rows_of(index[0], arr.shape[0], rhs.shape[0] if rhs.size > 1 else 1)
        j = rows_of(index[1], arr.shape[1], rhs.shape[1] if rhs.size > 1 else 1)
        shape = (max(arr.shape[0], int(i.max()) + 1 if i.size else 0), max(arr.shape[1], int(j.max()) + 1 if j.size else 0))
        if shape != arr.shape:
            grown = np.zeros(shape)
            grown[:arr.shape[0], :arr.shape[1]] = arr
            arr = grown
        if rhs.size != 1 and rhs.size != i.size * j.size:
            self.fail(f"assigning {rhs.size} values to a {i.size} x {j.size} block")
        arr[np.ix_(i, j)] = rhs.reshape(i.size, j.size) if rhs.size != 1 else float(rhs.ravel()[0])
        return arr

    # ---- statements
    def run(self, text):
        lines = self.logical_lines(text)
        self.block(lines, 0, len(lines))

    @staticmethod
    def logical_lines(text):
        """(first physical line, statement) pairs: comments stripped, '...' continuations and the
        rows of a matrix written over several lines joined (a line break in [..] or {..} is ';')."""
        out, buf, first = [], "", None
        for n, raw in enumerate(text.splitlines(), start=1):
            line = strip_comment(raw)
            if first is None:
                first = n
            if line.rstrip().endswith("..."):
                buf += line.rstrip()[:-3] + " "
                continue
            buf += line
            if bracket_depth(buf) > 0:
                buf += ";"
                continue
            for stmt in split_statements(buf):
                if stmt.strip():
                    out.append((first, stmt.strip()))
            buf, first = "", None
        if buf.strip():
            raise SpacarError(f"line {first}: a bracket opened here is not closed")
        return out

    def block(self, lines, i, stop):
        while i < stop:
            self.line, stmt = lines[i]
            m = re.match(r"^for\s+(\w+)\s*=\s*(.+)$", stmt)
            if m:
                depth, j = 1, i + 1
                while j < stop and depth:
                    s = lines[j][1]
                    if re.match(r"^(for|if|while|switch)\b", s):
                        depth += 1
                    elif s == "end":
                        depth -= 1
                    j += 1
                if depth:
                    self.fail("'for' without 'end'")
                rng = as_array(self.evaluate(m.group(2))).T  # MATLAB loops over columns
                for col in rng:
                    self.vars[m.group(1)] = float(col[0]) if col.size == 1 else col.reshape(-1, 1)
                    self.block(lines, i + 1, j - 1)
                i = j
                continue
            if re.match(r"^(if|while|switch|function)\b", stmt):
                self.fail(f"'{stmt.split()[0]}' is not read by the converter (write the values out)")
            if SKIPPED.match(stmt):
                i += 1
                continue
            self.statement(stmt)
            i += 1

    def evaluate(self, text):
        p = Parser(tokens(text, self.line), self.line)
        e = p.expr()
        if not p.done():
            self.fail(f"cannot read '{text}'")
        return self.value(e)

    def statement(self, stmt):
        toks = tokens(stmt, self.line)
        # find a top-level '=' (not ==)
        depth, eq = 0, None
        for k, (kind, val) in enumerate(toks):
            if val in ("(", "[", "{"):
                depth += 1
            elif val in (")", "]", "}"):
                depth -= 1
            elif val == "=" and depth == 0:
                eq = k
                break
        rhs_toks = toks[eq + 1:] if eq is not None else toks
        p = Parser(rhs_toks, self.line)
        rhs = p.expr()
        if not p.done():
            self.fail(f"cannot read '{stmt}'")
        if rhs[0] == "call" and rhs[1] == ("name", "spacarlight"):
            names = [a[1] if a[0] == "name" else None for a in rhs[2]]
            if len(names) < 5 or None in names[:5]:
                self.fail("spacarlight(nodes, elements, nprops, eprops, opt): give the five model variables by name")
            self.call = names[:5]
            return
        if eq is None:
            self.fail(f"'{stmt}' is not an assignment")
        lp = Parser(toks[:eq], self.line)
        target = lp.postfix()
        if not lp.done():
            self.fail(f"cannot assign to '{stmt[:stmt.index('=')].strip()}'")
        self.assign(target, self.value(rhs))


def scan(text):
    """(index, character, inside a string) for each character: 'single' strings with '' inside,
    "double" strings; a quote right after an operand (a, 2, ), ], }, ', .) is a transpose."""
    quote, prev, i = None, "", 0
    while i < len(text):
        ch = text[i]
        if quote:
            if ch == quote and i + 1 < len(text) and text[i + 1] == quote:
                yield i, ch, True
                yield i + 1, ch, True
                i += 2
                continue
            if ch == quote:
                quote = None
            yield i, ch, True
        else:
            if ch == '"' or (ch == "'" and not (prev.isalnum() or prev in ")]}'._")):
                quote = ch
                yield i, ch, True
            else:
                yield i, ch, False
        prev = ch
        i += 1


def strip_comment(line):
    for i, ch, inside in scan(line):
        if ch == "%" and not inside:
            return line[:i]
    return line


def bracket_depth(text):
    """Open ( [ { minus closed ones outside strings."""
    depth = 0
    for _, ch, inside in scan(text):
        if not inside:
            depth += ch in "([{"
            depth -= ch in ")]}"
    return depth


def split_statements(line):
    """Splits at top-level ';' and ',' (not inside brackets or strings)."""
    out, start, depth = [], 0, 0
    for i, ch, inside in scan(line):
        if inside:
            continue
        if ch in "([{":
            depth += 1
        elif ch in ")]}":
            depth -= 1
        elif ch in ";," and depth == 0:
            out.append(line[start:i])
            start = i + 1
    out.append(line[start:])
    return out


# -------------------------------------------------------------------------------------------- to scene
def plain(v, field=None):
    """A MATLAB value -> YAML-friendly Python (lists, numbers, bools, strings, dicts)."""
    if isinstance(v, Struct):
        return {k: plain(x, k) for k, x in v.items()}
    if isinstance(v, StructArray):
        return [plain(v[k]) for k in sorted(v)]
    if isinstance(v, list):
        return [plain(x) for x in v]
    if isinstance(v, (bool, np.bool_)):
        return bool(v)
    if isinstance(v, str):
        return v
    a = np.asarray(v, dtype=float)
    if field in BOOL_FIELDS and a.size == 1 and float(a.ravel()[0]) in (0.0, 1.0):
        return bool(a.ravel()[0])
    if a.size == 1 and field in VECTOR_FIELDS:
        return [number(a.ravel()[0])]
    if a.size == 1:
        x = float(a.ravel()[0])
        return int(x) if x.is_integer() and abs(x) < 2**53 else x
    if a.ndim == 2 and a.shape[0] > 1 and a.shape[1] > 1:
        return [[number(x) for x in row] for row in a]
    return [number(x) for x in a.ravel()]


def number(x):
    x = float(x)
    return int(x) if x.is_integer() and abs(x) < 2**53 else x


def convert(text, source="script"):
    """SPACAR Light script text -> Sinew scene dict (nodes, elements, nprops, eprops, opt)."""
    it = Interpreter(source)
    it.run(text)
    names = it.call or ["nodes", "elements", "nprops", "eprops", "opt"]
    missing = [n for n in names[:2] if n not in it.vars]
    if missing:
        raise SpacarError(f"{source}: no '{missing[0]}' assigned (SPACAR Light's {['nodes', 'elements'][names.index(missing[0])]})")
    nodes = as_array(it.vars[names[0]])
    elements = as_array(it.vars[names[1]])
    scene = {"title": source, "nodes": [[number(x) for x in row] for row in nodes],
             "elements": [[int(x) for x in row] for row in elements]}
    nprops = it.vars.get(names[2])
    if nprops is not None:
        if not isinstance(nprops, StructArray):
            raise SpacarError(f"{source}: {names[2]} must be a struct array (nprops(i).field = value)")
        scene["nprops"] = {int(k): plain(v) for k, v in sorted(nprops.items()) if v}
    eprops = it.vars.get(names[3])
    if eprops is not None:
        if not isinstance(eprops, StructArray):
            raise SpacarError(f"{source}: {names[3]} must be a struct array (eprops(i).field = value)")
        scene["eprops"] = [{k: plain(x, k) for k, x in v.items()} for _, v in sorted(eprops.items()) if v]
    opt = it.vars.get(names[4])
    if opt is not None:
        if not isinstance(opt, dict):
            raise SpacarError(f"{source}: {names[4]} must be a struct (opt.field = value)")
        o = {}
        for k, v in opt.items():
            if k == "rls":
                rls = v if isinstance(v, StructArray) else StructArray({1: v})
                o["rls"] = {int(e): plain(s["def"]) if isinstance(plain(s["def"]), list) else [plain(s["def"])]
                            for e, s in sorted(rls.items()) if isinstance(s, dict) and "def" in s}
            elif k == "filename":
                o[k] = str(v)
            else:
                o[k] = plain(v, k)
        if "filename" in o:
            scene["title"] = o["filename"]
        scene["opt"] = o
    return scene
