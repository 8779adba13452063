"""SPACAR Light's call from Python: out = sinew.spacarlight(nodes, elements, nprops, eprops, opt)."""
import numpy as np

from .scene import Scene


def _fields(d):
    out = {}
    for k, v in (d or {}).items():
        out[k] = v.tolist() if isinstance(v, np.ndarray) else v
    return out


def spacarlight(nodes, elements, nprops, eprops, opt=None, np_ranks=1, flags=(), check=False, process=None, comm=None,
                **extra):
    """Builds the scene from SPACAR Light's five inputs and runs it; returns SPACAR Light's `out`
    (a sinew.Results).
    - nodes: (nn, 3) (or (nn, 2)) coordinates; elements: (ne, 2) node numbers, 1-based;
    - nprops: a list whose k-th entry (from 0) holds the fields of node k + 1 (None or {} for none),
      or a dict {node number: fields}; SPACAR Light's field names (fix, force, moment_initial, ...);
    - eprops: a list of property sets with SPACAR Light's fields (elems 1-based, emod, dim, ...);
    - opt: a dict of SPACAR Light's opt fields (rls as {element: modes} or a list of {'def': modes}
      per element, from element 1);
    - extra: other scene blocks (formfinding=..., sensors=..., title=...).
    Runs in this process on comm's ranks (default: all ranks of the job); np_ranks > 1 from a
    one-rank interpreter, or process=True, starts the sinew executable (Scene.run). flags: extra
    command-line flags (-loadsteps 5 ...)."""
    if isinstance(nprops, dict):
        np_map = {int(k): _fields(v) for k, v in nprops.items() if v}
    else:
        np_map = {k + 1: _fields(v) for k, v in enumerate(nprops or []) if v}
    o = dict(opt or {})
    if isinstance(o.get("rls"), (list, tuple)):
        o["rls"] = {k + 1: list(np.atleast_1d(r["def"]).tolist()) for k, r in enumerate(o["rls"]) if r and "def" in r}
    data = {"title": str(o.get("filename", "spacarlight")),
            "nodes": np.asarray(nodes, dtype=float).tolist(),
            "elements": np.asarray(elements, dtype=int).tolist(),
            "nprops": np_map,
            "eprops": [_fields(e) for e in (eprops or []) if e],
            "opt": {k: (v.tolist() if isinstance(v, np.ndarray) else v) for k, v in o.items()}}
    data.update(extra)
    return Scene(data).run(np=np_ranks, flags=flags, check=check, process=process, comm=comm)
