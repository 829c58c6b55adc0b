#!/usr/bin/env python3
"""rotorcert reproducer: pytransform3d functions of NaN / Inf input, clause EDGE-7.

EDGE-7 (spec/SPEC.md 9): NaN or +-Inf in any input component is DOMAIN_ERROR with every output a quiet NaN
(an exception, for a library without a status channel), "even if the result would be mathematically defined
(normalize((Inf, 0, 0, 1)) is DOMAIN_ERROR, not (1, 0, 0, 0))". pytransform3d 3.17.0's input validation
(check_quaternion, check_dual_quaternion, check_pq: "Raises ValueError: If input is invalid") checks shapes
only, so non-finite input runs through and comes out partly finite with no error:
  - norm_vector of (x, y, z, w) = (0, inf, 0, 1) is (w, x, y, z) = (0, 0, nan, 0) (rotorcert's worst input,
    EX-EDGE-7-b); matrix_from_quaternion of it has finite entries beside NaN ones;
  - concatenate_quaternions passes infinities through as +-inf components;
  - dual_quaternion_from_pq with a NaN in the quaternion returns a real part with three finite components.
Upstream: no matching issue found in dfki-ric/pytransform3d.
Exit 0: defect shown; 1: not shown (fixed); 77: pytransform3d cannot be imported.
"""
import math
import sys

CLAUSE = "EDGE-7"
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
h = float.fromhex
inf, nan = math.inf, math.nan
q_inf = np.array([1.0, 0.0, inf, 0.0])  # (w, x, y, z) of (x, y, z, w) = (0, inf, 0, 1), EX-EDGE-7-b
b = np.array([0.5, 0.5, 0.5, 0.5])
# rotorcert's dq_from_rotation_translation input "NaN in q": q stored (x, y, z, w), t.
qx, qy, qz, qw = h("-0x1.90652448837d1p-1"), h("-0x1.04c01a07a76bep-1"), nan, h("-0x1.2bb409a2c5129p-3")
t = [h("0x1.05af251ba61dfp+6"), h("-0x1.698576610f253p+5"), h("-0x1.0cb7206b83cc5p+6")]

calls = [
    ("pytransform3d.rotations.norm_vector([w, x, y, z])", "q (x, y, z, w) = [0x0p+0, inf, 0x0p+0, 0x1p+0]",
     lambda: pr.norm_vector(q_inf)),
    ("pytransform3d.rotations.matrix_from_quaternion([w, x, y, z])", "q (x, y, z, w) = [0x0p+0, inf, 0x0p+0, 0x1p+0]",
     lambda: pr.matrix_from_quaternion(q_inf)),
    ("pytransform3d.rotations.concatenate_quaternions(a, b)", "a (w, x, y, z) = [0x1p-1, inf, 0x1p-1, 0x1p-1], b = [0x1p-1] * 4",
     lambda: pr.concatenate_quaternions(np.array([0.5, inf, 0.5, 0.5]), b)),
    ("pytransform3d.transformations.dual_quaternion_from_pq([tx, ty, tz, qw, qx, qy, qz])",
     "q (x, y, z, w) = [%s, %s, nan, %s], t = [%s]" % (qx.hex(), qy.hex(), qw.hex(), ", ".join(c.hex() for c in t)),
     lambda: pt.dual_quaternion_from_pq(np.array(t + [qw, qx, qy, qz]))),
]
print("rotorcert reproducer: pytransform3d %s %s: NaN/Inf input passes its input validation and gives partly "
      "finite results with no error" % (VERSION, CLAUSE))
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
    print("  library: %s%s" % (result, "" if refused else "  (not all NaN, no error)  <-- DEFECT"))
    print("  correct: DOMAIN_ERROR: an exception (pytransform3d's ValueError) or every output NaN (EDGE-7, RESULT-2)")
print("DEFECT SHOWN" if shown else "DEFECT NOT SHOWN")
sys.exit(0 if shown else 1)
