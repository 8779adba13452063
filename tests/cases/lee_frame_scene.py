"""Lee's frame from 10 elements (column 5, beam 1 + 4; the scale of runs/lee_frame.yaml: the load factor
is P L^2 / EI) followed by arc length, as the accuracy studies of docs/accuracy.md run it; shared by
test_accuracy_path.py, test_accuracy_path_reuse.py and scripts/study_accuracy_reuse.py."""


def lee(title, ds, stop=-0.5, opt=None):
    """The frame with arc-length steps ds (ds_max 0.3, 40 steps at most) to the load point's v = stop
    (no stop criterion when None); opt: more opt fields (target_error, ...)."""
    c = {"method": "arclength", "ds": ds, "ds_max": 0.3, "node": 3, "direction": "y", "max_steps": 40}
    if stop is not None:
        c["stop_displacement"] = stop
    beam = {"flex": [1, 2, 3, 4, 5, 6], "emod": 72e9, "smod": 27.7e9, "cshape": "rect", "dim": [0.03, 0.02],
            "orien": [0, 0, 1]}
    return {"title": title, "nodes": [[0, 0, 0], [0, 1.2, 0], [0.24, 1.2, 0], [1.2, 1.2, 0]],
            "elements": [[1, 2], [2, 3], [3, 4]],
            "nprops": {1: {"fix_pos": True}, 4: {"fix_pos": True}, 2: {"fix_z": True},
                       3: {"fix_z": True, "force": [0, -1000.0, 0]}},
            "eprops": [dict(beam, elems=[1], nbeams=5), dict(beam, elems=[2], nbeams=1), dict(beam, elems=[3], nbeams=4)],
            "opt": {"calccompl": False, "continuation": c, **(opt or {})}}
