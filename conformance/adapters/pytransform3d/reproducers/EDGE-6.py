#!/usr/bin/env python3
"""rotorcert reproducer: pytransform3d functions of the zero quaternion and of a zero real part, clause EDGE-6.

EDGE-6 (spec/SPEC.md 9): a quaternion whose four components are +-0, or a dual quaternion whose real part is
zero, is not a rotation or rigid motion: DOMAIN_ERROR, every output a quiet NaN (an exception, for a library
without a status channel). pytransform3d 3.17.0 validates its inputs with check_quaternion /
check_dual_quaternion ("Raises ValueError: If input is invalid") but lets zero through, and then answers
with the identity rotation:
  - check_quaternion(q) normalises with norm_vector, which returns the zero vector unchanged
    (rotations/_utils.py:44-45; norm_vector documents "nd unit vector with norm 1 or the zero vector"),
    so matrix_from_quaternion(0) is the identity matrix, q_prod_vector(0, v) returns v,
    axis_angle_from_quaternion(0) returns [1, 0, 0, 0] (angle 0) and norm_vector(0) itself returns 0
    (rotorcert's worst input, normalize);
  - check_dual_quaternion replaces a zero real part by [1, 0, 0, 0] (transformations/_dual_quaternion.py:72-73),
    so norm_dual_quaternion([0, 0, 0, 0, 0, 1, 0, 0]) is a unit dual quaternion and dq_prod_vector of it
    moves the origin to (2, 0, 0) (EX-EDGE-6-i, -j).
Upstream: no matching issue found in dfki-ric/pytransform3d.
Exit 0: defect shown; 1: not shown (fixed); 77: pytransform3d cannot be imported.
"""
import math
import sys

CLAUSE = "EDGE-6"
try:
    from importlib.metadata import version
    import numpy as np
    import pytransform3d.rotations as pr
    import pytransform3d.transformations as pt
    VERSION = version("pytransform3d")
except Exception as exc:  # noqa: BLE001 - any import failure is a skip
    print("rotorcert reproducer: pytransform3d ? %s: SKIP: cannot import pytransform3d: %s" % (CLAUSE, exc))
    sys.exit(77)

np.seterr(all="ignore")
zero = np.array([0.0, 0.0, 0.0, 0.0])              # (w, x, y, z)
dq = np.array([0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0])  # (pw, px, py, pz, qw, qx, qy, qz) of EX-EDGE-6-i/j:
# rotorcert's d = [0, 0, 0, 0, 1, 0, 0, 0] is [real xyzw, dual xyzw], a zero real part and the dual part i
calls = [
    ("pytransform3d.rotations.matrix_from_quaternion([0, 0, 0, 0])", "q = 0", lambda: pr.matrix_from_quaternion(zero)),
    ("pytransform3d.rotations.q_prod_vector([0, 0, 0, 0], [1, 0, 0])", "q = 0, v = [0x1p+0, 0x0p+0, 0x0p+0]",
     lambda: pr.q_prod_vector(zero, np.array([1.0, 0.0, 0.0]))),
    ("pytransform3d.rotations.axis_angle_from_quaternion([0, 0, 0, 0])", "q = 0", lambda: pr.axis_angle_from_quaternion(zero)),
    ("pytransform3d.rotations.norm_vector([0, 0, 0, 0])", "q = 0", lambda: pr.norm_vector(zero)),
    ("pytransform3d.transformations.norm_dual_quaternion([0, 0, 0, 0, 0, 1, 0, 0])",
     "dq (pw, px, py, pz, qw, qx, qy, qz) = [0x0p+0, 0x0p+0, 0x0p+0, 0x0p+0, 0x0p+0, 0x1p+0, 0x0p+0, 0x0p+0]",
     lambda: pt.norm_dual_quaternion(dq)),
    ("pytransform3d.transformations.dq_prod_vector([0, 0, 0, 0, 0, 1, 0, 0], [0, 0, 0])",
     "dq = [0x0p+0, 0x0p+0, 0x0p+0, 0x0p+0, 0x0p+0, 0x1p+0, 0x0p+0, 0x0p+0], p = [0x0p+0, 0x0p+0, 0x0p+0]",
     lambda: pt.dq_prod_vector(dq, np.zeros(3))),
]
print("rotorcert reproducer: pytransform3d %s %s: the zero quaternion and a zero dual real part are accepted as "
      "the identity, with no error" % (VERSION, CLAUSE))
shown = False
for call, inp, fn in calls:
    try:
        out = fn()
        values = [float(c) for c in np.ravel(out)]
        refused = all(math.isnan(c) for c in values)
        result = "[%s]" % ", ".join(c.hex() if math.isfinite(c) else repr(c) for c in values)
    except Exception as exc:  # noqa: BLE001 - an exception is a correct refusal (DOMAIN_ERROR)
        refused, result = True, "raised %s: %s" % (type(exc).__name__, exc)
    shown = shown or not refused
    print("  call:    %s" % call)
    print("  input:   %s" % inp)
    print("  library: %s%s" % (result, "" if refused else "  (status OK)  <-- DEFECT"))
    print("  correct: DOMAIN_ERROR: an exception (pytransform3d's ValueError) or every output NaN (EDGE-6, RESULT-2)")
print("DEFECT SHOWN" if shown else "DEFECT NOT SHOWN")
sys.exit(0 if shown else 1)
