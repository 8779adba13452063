#!/usr/bin/python3
"""Validation of the form-finding scene fields (issue 10 item 16), 2 ranks, on the C2 five-node
membrane (ffscenes.c2_scene, 3 URS steps):
- mue_relax outside [0, 1], lambda_max < 1, and stress adaption that cannot act (lambda_max 1
  without distortion_max) are scene errors (exit 2) naming the field; mue_relax 1 with stress
  adaption (allowed by CARAT++: no adaption) runs with a warning and the unadapted C2 values;
- a membrane set with emod: 0 form-finds (Kratos uses E = 0): the same node 5 uz after steps 1-3 as
  with emod 1000 (-35/19, -2.324760220, -2.453273210, reference C2); refused (exit 2, naming
  eprops[0].emod) where it would have to carry loads or has no formfinding block;
- a JSON scene (object keys are strings) sets nprops with "1": {...}."""
import copy
import json
import os
import sys

sys.path.insert(0, os.path.dirname(__file__))
from sinewtest import run, h5, close, check, done, WORK  # noqa: E402
from ffscenes import c2_scene, to_yaml  # noqa: E402

os.makedirs(WORK, exist_ok=True)
C2 = [-35 / 19, -2.324760220, -2.453273210]


def error_line(log):
    return next((l for l in log.splitlines() if l.startswith("error")), "")


def refused(name, sc, field, what):
    out, log = run(name, to_yaml(sc), expect_exit=2)
    line = error_line(log)
    print(f"  {what}: {line}")
    check(field in line, f"{what}: exit 2, the message names {field}")


base = c2_scene()
for v in (1.5, -0.1):
    sc = copy.deepcopy(base)
    sc["formfinding"].update({"stress_adaption": [1], "mue_relax": v})
    refused(f"ffv_mue_{v}", sc, "formfinding.mue_relax", f"mue_relax {v}")
# mue_relax 1 with stress adaption: CARAT++ allows it (issue 24 item 15): a warning naming the field,
# and the prestress stays as without adaption (the C2 reference values)
sc = copy.deepcopy(base)
sc["formfinding"].update({"stress_adaption": [1], "mue_relax": 1})
out, log = run("ffv_mue_1", to_yaml(sc))
warn = next((l for l in log.splitlines() if "mue_relax" in l and "warning" in l), "")
print(f"  mue_relax 1 with stress_adaption: {warn}")
check("formfinding.mue_relax" in warn, "mue_relax 1 with stress_adaption: a warning naming formfinding.mue_relax")
with h5(out) as f:
    close(f["node/p"][:3, 4, 2] - 5.0, C2, atol=1e-8, what="mue_relax 1: C2 node 5 uz after steps 1-3 (no adaption)")
sc = copy.deepcopy(base)
sc["formfinding"].update({"lambda_max": 0.9})
refused("ffv_lmax_09", sc, "formfinding.lambda_max", "lambda_max 0.9")
sc = copy.deepcopy(base)
sc["formfinding"].update({"stress_adaption": [1], "lambda_max": 1})
refused("ffv_lmax_1", sc, "formfinding.lambda_max", "lambda_max 1 with stress_adaption, no distortion_max")
# lambda_max 1 with distortion_max > 1 is the documented combination (docs/formfinding.md)
sc = copy.deepcopy(base)
sc["formfinding"].update({"stress_adaption": [1], "lambda_max": 1, "distortion_max": 1.1})
run("ffv_lmax_1_dist", to_yaml(sc))

# emod 0: form finding only
sc = copy.deepcopy(base)
sc["eprops"][0]["emod"] = 0
out, log = run("ffv_emod0", to_yaml(sc))
with h5(out) as f:
    close(f["node/p"][:3, 4, 2] - 5.0, C2, atol=1e-8, what="emod 0: C2 node 5 uz after steps 1-3")
    check(int(f.attrs["converged"]) == 1, "emod 0: converged")
ld = copy.deepcopy(sc)
ld["nprops"]["5"] = {"force": [0, 0, -1]}
refused("ffv_emod0_load", ld, "eprops(1).emod", "emod 0 with a load after form finding")
nf = copy.deepcopy(sc)
del nf["formfinding"]
refused("ffv_emod0_noff", nf, "eprops(1).emod", "emod 0 without form finding")
dp = copy.deepcopy(sc)
dp["formfinding"]["elastic_restart_method"] = "DISPLACEMENT"
refused("ffv_emod0_disp", dp, "eprops(1).emod", "emod 0 with elastic_restart_method DISPLACEMENT")

# JSON scene: nprops keys are strings
js = json.dumps(base, indent=1)
check('"1": {' in js, "the JSON scene has string node keys")
out, log = run("ffv_json", js)
with h5(out) as f:
    close(f["node/p"][:3, 4, 2] - 5.0, C2, atol=1e-8, what="JSON scene with \"1\": nprops keys: C2 values")
done()
