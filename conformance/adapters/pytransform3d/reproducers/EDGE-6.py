#!/usr/bin/env python3
"""rotorcert reproducer: pytransform3d dual quaternions with a zero real part, clause EDGE-6.

EDGE-6 (spec/SPEC.md 9): a dual quaternion whose real part is zero is not a rigid motion: DOMAIN_ERROR, every
output a quiet NaN (an exception, for a library without a status channel). Since spec 2.2.0 ACC-1
zero_sentinel also accepts status OK with every output 0, or exactly the output of the identity motion
substituted for the whole dual quaternion. pytransform3d 3.17.0 validates its inputs with
check_dual_quaternion ("Raises ValueError: If input is invalid"), which instead replaces a zero real part by
[1, 0, 0, 0] and keeps the dual part (transformations/_dual_quaternion.py:71-73: "if real_norm == 0.0:
return np.r_[1, 0, 0, 0, dq[4:]]"): the zero real part becomes a translation by 2 (dual part), so
norm_dual_quaternion([0, 0, 0, 0, 0, 1, 0, 0]) is a unit dual quaternion and dq_prod_vector of it moves the
origin to (2, 0, 0) (EX-EDGE-6-i, -j), neither an error nor all zero nor the identity motion's answer.
(The zero quaternion's answers, matrix_from_quaternion(0) = I, q_prod_vector(0, v) = v,
axis_angle_from_quaternion(0) = [1, 0, 0, 0] and norm_vector(0) = 0, are ACC-1 zero_sentinel answers since
2.2.0 and no longer a defect.)
Upstream: no matching issue found in dfki-ric/pytransform3d.
Exit 0: defect shown; 1: not shown (fixed); 77: pytransform3d cannot be imported.
"""
import math
import sys

CLAUSE = "EDGE-6"
try:
    from importlib.metadata import version
    import numpy as np
    import pytransform3d.transformations as pt
    VERSION = version("pytransform3d")
except Exception as exc:  # noqa: BLE001 - any import failure is a skip
    print("rotorcert reproducer: pytransform3d ? %s: SKIP: cannot import pytransform3d: %s" % (CLAUSE, exc))
    sys.exit(77)

np.seterr(all="ignore")
dq = np.array([0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0])  # (pw, px, py, pz, qw, qx, qy, qz) of EX-EDGE-6-i/j:
# rotorcert's d = [0, 0, 0, 0, 1, 0, 0, 0] is [real xyzw, dual xyzw], a zero real part and the dual part i
# (call, input, function, the identity motion's answer: ACC-1 zero_sentinel)
calls = [
    ("pytransform3d.transformations.norm_dual_quaternion([0, 0, 0, 0, 0, 1, 0, 0])",
     "dq (pw, px, py, pz, qw, qx, qy, qz) = [0x0p+0, 0x0p+0, 0x0p+0, 0x0p+0, 0x0p+0, 0x1p+0, 0x0p+0, 0x0p+0]",
     lambda: pt.norm_dual_quaternion(dq), [1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]),
    ("pytransform3d.transformations.dq_prod_vector([0, 0, 0, 0, 0, 1, 0, 0], [0, 0, 0])",
     "dq = [0x0p+0, 0x0p+0, 0x0p+0, 0x0p+0, 0x0p+0, 0x1p+0, 0x0p+0, 0x0p+0], p = [0x0p+0, 0x0p+0, 0x0p+0]",
     lambda: pt.dq_prod_vector(dq, np.zeros(3)), [0.0, 0.0, 0.0]),
]
print("rotorcert reproducer: pytransform3d %s %s: a zero dual real part is replaced by the identity rotation and "
      "its dual part kept (a translation), with no error" % (VERSION, CLAUSE))
shown = False
for call, inp, fn, identity in calls:
    try:
        out = fn()
        values = [float(c) for c in np.ravel(out)]
        refused = all(not math.isfinite(c) for c in values) or all(c == 0 for c in values) or values == identity
        result = "[%s]" % ", ".join(c.hex() if math.isfinite(c) else repr(c) for c in values)
    except Exception as exc:  # noqa: BLE001 - an exception is a correct refusal (DOMAIN_ERROR)
        refused, result = True, "raised %s: %s" % (type(exc).__name__, exc)
    shown = shown or not refused
    print("  call:    %s" % call)
    print("  input:   %s" % inp)
    print("  library: %s%s" % (result, "" if refused else "  (status OK)  <-- DEFECT"))
    print("  correct: DOMAIN_ERROR: an exception (pytransform3d's ValueError) or every output NaN (EDGE-6, RESULT-2); "
          "acceptable (ACC-1 zero_sentinel): all zero, or the identity motion's answer [%s]" % ", ".join(c.hex() for c in identity))
print("DEFECT SHOWN" if shown else "DEFECT NOT SHOWN")
sys.exit(0 if shown else 1)
