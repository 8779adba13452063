"""SPACAR Light's `out` structure from a Sinew result file (HDF5), as numpy arrays.

    out = sinew.load("out/crosshinge.h5")
    out.node[5].p          # (ns, 3) positions of node 5 (1-based, as in the scene and SPACAR Light)
    out.node[5].CMglob     # (ns, 6, 6) compliance in global axes, when computed
    out.freq               # (ns, k) natural frequencies in Hz; out.buck (ns, k) buckling multipliers
    out.step[2].node[5].p  # SPACAR Light's per-step view: (3,) position at load step 2
    out.ndof, out.converged, out.load_factor (or out.time)
    out.accuracy           # -target_error's study (docs/accuracy.md): out.accuracy["error"], ["quantities"], ...

Every dataset of the file is also reachable as out.data["node/p"] (a numpy array).

The datasets come from one of two sources, giving the same object: a result file (load) or the
in-memory results of a run in this process (from_memory, what Scene.run returns by default)."""
import functools

import h5py
import numpy as np

# per-node datasets (/node/<name>, [ns, nn, ...]) and SPACAR Light's names for them
NODE_FIELDS = ("p", "r_eulzyx", "r_axang", "r_quat", "Freac", "Mreac", "CMglob", "CMloc", "slope")


class Node:
    """One node's results over the steps: p (ns, 3), r_eulzyx (ns, 3), r_axang (ns, 4),
    r_quat (ns, 4), Freac, Mreac (ns, 3), CMglob, CMloc (ns, 6, 6), slope (ns, 2) where present."""

    def __init__(self, fields, number):
        self.number = number
        for name, value in fields.items():
            setattr(self, name, value)

    def __repr__(self):
        return f"<node {self.number}: {', '.join(k for k in vars(self) if k != 'number')}>"


class OneBased:
    """A list indexed from 1 (SPACAR Light's node and step numbers)."""

    def __init__(self, items, what):
        self._items, self._what = items, what

    def __getitem__(self, i):
        if not isinstance(i, (int, np.integer)) or not 1 <= i <= len(self._items):
            raise IndexError(f"{self._what} {i}: expected 1..{len(self._items)}")
        return self._items[i - 1]

    def __len__(self):
        return len(self._items)

    def __iter__(self):
        return iter(self._items)


class Step:
    """SPACAR Light's out.step(k): node results of one step (node[i].p has shape (3,))."""

    def __init__(self, out, k, ns):
        self.number = k
        rows = out.data.get("step_analysis_rows")
        analysed = None if rows is None else np.flatnonzero(np.asarray(rows).astype(int) == k - 1)

        def row(table):
            """Step k's row of a table: every step has one, or (step analyses run at some steps only,
            /step_analysis_rows) the analysed steps have one; None at a step without one."""
            if len(table) == ns:
                return table[k - 1]
            return table[analysed[0]] if analysed is not None and analysed.size else None

        self.node = OneBased([Node({n: row(getattr(nd, n)) for n in vars(nd) if n != "number"}, nd.number)
                              for nd in out.node], "node")
        for name in ("freq", "buck", "stressmax", "load_factor", "time"):
            table = getattr(out, name, None)
            if table is not None:
                setattr(self, name, row(table))


class Results:
    """SPACAR Light's `out`: node results, frequencies, buckling multipliers, stresses, state space,
    sensors and the step values of a Sinew run (see load())."""

    def __init__(self, data, attrs, scene_text=None):
        self.data = data
        self.attrs = attrs
        self._scene_text = scene_text
        self.converged = bool(attrs.get("converged", 0))
        self.ndof = int(attrs["ndof"]) if "ndof" in attrs else None
        self.load_factor = data.get("load_factor")
        self.time = data.get("time")
        for name in ("freq", "buck", "stressmax"):
            setattr(self, name, data.get(name))
        self.statespace = {k[len("statespace/"):]: v for k, v in data.items() if k.startswith("statespace/")} or None
        self.sensors = {k[len("sensors/"):]: v for k, v in data.items() if k.startswith("sensors/")} or None
        self.accuracy = None

    def _set_accuracy(self, texts):
        """out.accuracy: -target_error's study (docs/accuracy.md, the /accuracy group): its datasets
        (level, nbeams_factor, unknowns, wall_time, worst_error, limiting, error, order, status, value,
        extrapolated) and attributes (quantities as a list of names, target, met, level, stop_reason,
        refinement); None for a run without target_error."""
        acc = {k[len("accuracy/"):]: v for k, v in self.data.items() if k.startswith("accuracy/")}
        if not acc:
            return self
        for k, v in texts.items():
            v = v.decode("utf-8", "replace") if isinstance(v, bytes) else v
            acc[k] = (float(v) if k == "target" else int(v)) if k in ("target", "met", "level") else v
        acc["quantities"] = [n for n in str(acc.get("quantities", "")).split("\n") if n]
        self.accuracy = acc
        return self

    @functools.cached_property
    def scene(self):
        """The scene text (the file's scene attribute; an in-process run of a dict makes it here, at
        the first use)."""
        if "scene" in self.attrs or self._scene_text is None:
            return self.attrs.get("scene", "")
        return self._scene_text()

    # node and step are made at their first use (a loop of runs that reads out.freq makes neither)
    @functools.cached_property
    def node(self):
        """The nodes' results, 1-based: node[i].p (ns, 3), ..."""
        nn = self.data["node/p"].shape[1] if "node/p" in self.data else 0
        return OneBased([Node({f: self.data[f"node/{f}"][:, i] for f in NODE_FIELDS if f"node/{f}" in self.data}, i + 1)
                         for i in range(nn)], "node")

    @functools.cached_property
    def step(self):
        """SPACAR Light's per-step view, 1-based: step[k].node[i].p (3,), step[k].freq, ..."""
        return OneBased([Step(self, k, self.ns) for k in range(1, self.ns + 1)], "step")

    @property
    def ns(self):
        """Number of written steps (rows)."""
        return self.data["node/p"].shape[0] if "node/p" in self.data else 0

    def __repr__(self):
        have = [n for n in ("freq", "buck", "stressmax", "statespace", "sensors") if getattr(self, n) is not None]
        return (f"<Sinew results: {self.ns} steps, {len(self.node)} nodes, ndof {self.ndof}, "
                f"converged {self.converged}; {', '.join(have) or 'no step analyses'}>")


def h5_datasets(path):
    """The datasets (without the restart checkpoint) and root attributes of a result file."""
    data, attrs = {}, {}
    with h5py.File(path, "r") as f:
        for k, v in f.attrs.items():
            attrs[k] = v.decode("utf-8", "replace") if isinstance(v, bytes) else (v.item() if hasattr(v, "item") else v)

        def visit(name, obj):
            if isinstance(obj, h5py.Dataset) and not name.startswith("checkpoint"):
                data[name] = obj[()]
        f.visititems(visit)
    return data, attrs


def memory_datasets(run):
    """The datasets and root attributes of an in-process run (sinew._core.run's answer)."""
    data = {k: v for k, v in run["datasets"].items() if not k.startswith("checkpoint")}
    return data, dict(run["attrs"])


def load(path):
    """Reads a Sinew result file (from the command line or Scene.run) into a Results object."""
    with h5py.File(path, "r") as f:
        texts = {k: (v.item() if hasattr(v, "item") else v) for k, v in f["accuracy"].attrs.items()} \
            if "accuracy" in f else {}
    return Results(*h5_datasets(path))._set_accuracy(texts)


def from_memory(run):
    """The Results object of an in-process run (sinew._core.run), the same as load() of its file."""
    return Results(*memory_datasets(run), run.get("scene_text"))._set_accuracy(run.get("group_attrs", {}).get("accuracy", {}))
