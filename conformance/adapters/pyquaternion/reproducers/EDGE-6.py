#!/usr/bin/env python3
"""rotorcert reproducer: pyquaternion rotates by the zero quaternion without an error, clause EDGE-6.

EDGE-6 (spec/SPEC.md 9): a zero quaternion has no rotation; every operation that reads it as one is
DOMAIN_ERROR (an exception, or all outputs NaN; class outcome). pyquaternion's rotation properties
normalise first and _normalise skips the division for a zero norm (pyquaternion/quaternion.py:504-511),
so with Quaternion(0, 0, 0, 0):
  - rotate([1, 2, 3]) returns [0, 0, 0] (quaternion.py:607-608: 0 v 0*), a "rotation" that does not
    preserve length;
  - rotation_matrix returns the zero matrix, documented as "A 3x3 orthogonal rotation matrix";
  - angle is 0 and axis the undefined axis: the identity rotation;
  - Quaternion.slerp(zero, b, t) returns b for every t.
No error is raised and nothing is NaN. (normalised of zero returning zero is documented,
docs/index.md:389-391, and the product 0 * b = 0 is the algebra's; they are recorded by the clause but
are not what this file reports.)
Upstream: no matching issue found in KieranWynn/pyquaternion.
Exit 0: defect shown; 1: not shown (fixed); 77: pyquaternion cannot be imported.
"""
import math
import sys

CLAUSE = "EDGE-6"
try:
    from importlib.metadata import version
    from pyquaternion import Quaternion
    VERSION = version("pyquaternion")
except Exception as exc:  # noqa: BLE001 - any import failure is a skip
    print("rotorcert reproducer: pyquaternion ? %s: SKIP: cannot import pyquaternion: %s" % (CLAUSE, exc))
    sys.exit(77)

print("rotorcert reproducer: pyquaternion %s %s: the zero quaternion rotates [1, 2, 3] to [0, 0, 0], has the "
      "zero matrix as its rotation_matrix and angle 0, with no error" % (VERSION, CLAUSE))
shown = False


def show(call, fn):
    global shown
    try:
        value = fn()
        flat = [float(c) for c in (value if hasattr(value, "__len__") else [value])] if not hasattr(value, "shape") else [float(c) for c in value.ravel()]
        refused = all(math.isnan(c) for c in flat)
        result = "%r" % (value if not hasattr(value, "tolist") else value.tolist(),)
    except Exception as exc:  # noqa: BLE001 - an exception is a refusal: the required outcome
        refused, result = True, "raised %s: %s" % (type(exc).__name__, exc)
    shown = shown or not refused
    print("  call:    %s" % call)
    print("  library: %s%s" % (result, "" if refused else "  <-- DEFECT (no error, not NaN)"))


print("  input:   q (x, y, z, w) = [0x0p+0, 0x0p+0, 0x0p+0, 0x0p+0], v = [0x1p+0, 0x1p+1, 0x1.8p+1]")
print("  correct: DOMAIN_ERROR: an exception or all outputs NaN (the zero quaternion is no rotation)")
show("Quaternion(0, 0, 0, 0).rotate([1.0, 2.0, 3.0])", lambda: Quaternion(0, 0, 0, 0).rotate([1.0, 2.0, 3.0]))
show("Quaternion(0, 0, 0, 0).rotation_matrix", lambda: Quaternion(0, 0, 0, 0).rotation_matrix)
show("Quaternion(0, 0, 0, 0).angle", lambda: Quaternion(0, 0, 0, 0).angle)
show("Quaternion.slerp(Quaternion(0, 0, 0, 0), Quaternion(0, 1, 0, 0), 0.25)",
     lambda: Quaternion.slerp(Quaternion(0, 0, 0, 0), Quaternion(0, 1, 0, 0), 0.25).q)
print("DEFECT SHOWN" if shown else "DEFECT NOT SHOWN")
sys.exit(0 if shown else 1)
