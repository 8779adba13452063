# ctest-processors: 1
# ctest-labels: smoke
"""Element kinds stay in src/elements/ (DEVELOPERS.md, "Adding things / An element"): no code outside
it casts an ElementKernel to a concrete kernel class (every class in src/elements/*.hpp that derives
from ElementKernel); what callers need is part of the kernel interface (include/sinew/element_kernel.hpp:
formFinding(), hasSensors()/sensorValue(), tensionOnly()/slack(), referenceLength()). The per-set kernel data reaches the
Assembler as data (DistributedMesh::setLoads), not through process-global registration tables."""
import glob
import os
import re

import sinewtest as st

# class X [final] : public A[, public B]: the kernel classes are those whose bases reach ElementKernel
# (directly, or through a shared base of src/elements/ such as StrainRateDampedKernel)
CLASS = re.compile(r'class\s+(\w+)(?:\s+final)?\s*:\s*((?:public\s+\w+\s*,?\s*)+)\{')

bases = {}
for path in glob.glob(os.path.join(st.SOURCE, "src", "elements", "*.hpp")):
    with open(path) as f:
        for name, parents in CLASS.findall(f.read()):
            bases[name] = re.findall(r'public\s+(\w+)', parents)
kernels = {"ElementKernel"}
while True:
    more = {n for n, ps in bases.items() if n not in kernels and any(b in kernels for b in ps)}
    if not more:
        break
    kernels |= more
kernels.discard("ElementKernel")
print(f"concrete kernels: {' '.join(sorted(kernels))}")
st.check({"BeamCorotational", "Cable3D", "Membrane", "AncfCable2D"} <= kernels, "the scan finds the four kernel classes")

cast = re.compile(r'(?:dynamic|static|reinterpret)_cast\s*<\s*(?:const\s+)?(' + "|".join(sorted(kernels)) + r')\b')
offenders = []
for path in glob.glob(os.path.join(st.SOURCE, "src", "**", "*.[ch]pp"), recursive=True) + \
        glob.glob(os.path.join(st.SOURCE, "include", "**", "*.hpp"), recursive=True):
    rel = os.path.relpath(path, st.SOURCE)
    if rel.startswith("src" + os.sep + "elements" + os.sep):
        continue
    with open(path) as f:
        for number, line in enumerate(f, 1):
            if cast.search(line) or re.search(r'\bregisterSet(Pressures|Accelerations)\b', line):
                offenders.append(f"{rel}:{number}: {line.strip()}")
for o in offenders:
    print("  " + o)
st.check(not offenders, "no cast to a concrete element kernel and no per-set registration table outside src/elements/")
st.done()
