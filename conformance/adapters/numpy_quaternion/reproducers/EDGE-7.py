#!/usr/bin/env python3
"""rotorcert reproducer: numpy-quaternion np.exp turns a NaN into the identity, clause EDGE-7.

EDGE-7 (spec/SPEC.md 9): NaN or +-Inf in any input is DOMAIN_ERROR with every output NaN (or an
exception), "even if the result would be mathematically defined" (class outcome). numpy-quaternion's
quaternion_exp (src/quaternion.c:109-122) tests "if (vnorm > _QUATERNION_EPS)", which is False for a
NaN |v|, and then returns {exp(w), 0, 0, 0}: np.exp(quaternion(0, NaN, 0, 0)) is exactly 1, the
identity rotation, and so is quaternion.from_rotation_vector([NaN, 0, 0]), which calls np.exp
(quaternion/__init__.py:443-463). The NaN disappears without a trace; numpy's own functions
propagate NaN. (The clause also counts partly-NaN results: normalized() of (1, Inf, 0, 0) is
[0, nan, 0, 0], products with Inf give +-Inf, as_rotation_matrix of an Inf w has a finite 1 on the
diagonal.)
Upstream: no matching issue found in moble/quaternion.
Exit 0: defect shown; 1: not shown (fixed); 77: numpy-quaternion cannot be imported.
"""
import math
import sys

CLAUSE = "EDGE-7"
try:
    from importlib.metadata import version
    import numpy as np
    import quaternion
    VERSION = version("numpy-quaternion")
except Exception as exc:  # noqa: BLE001 - any import failure is a skip
    print("rotorcert reproducer: numpy-quaternion ? %s: SKIP: cannot import quaternion: %s" % (CLAUSE, exc))
    sys.exit(77)
np.seterr(all="ignore")  # numpy prints RuntimeWarnings for the 0/0 shown below; values unchanged

nan = float("nan")
print("rotorcert reproducer: numpy-quaternion %s %s: np.exp of a pure quaternion with a NaN component "
      "returns exactly 1 (the identity), and so does from_rotation_vector([nan, 0, 0])" % (VERSION, CLAUSE))
shown = False
for call, fn in (("np.exp(np.quaternion(0, nan, 0, 0))", lambda: np.exp(np.quaternion(0.0, nan, 0.0, 0.0))),
                 ("quaternion.from_rotation_vector([nan, 0.0, 0.0])", lambda: quaternion.from_rotation_vector([nan, 0.0, 0.0]))):
    try:
        r = fn()
        out = [r.w, r.x, r.y, r.z]
        refused = all(math.isnan(c) for c in out)
        result = "quaternion(w, x, y, z) = [%s]" % ", ".join(c.hex() if math.isfinite(c) else str(c) for c in out)
    except Exception as exc:  # noqa: BLE001 - an exception is a refusal: the required outcome
        refused, result = True, "raised %s: %s" % (type(exc).__name__, exc)
    shown = shown or not refused
    print("  call:    %s" % call)
    print("  library: %s%s" % (result, "" if refused else "  <-- DEFECT (NaN input, finite output, no error)"))
print("  input:   v (x, y, z) = [nan, 0x0p+0, 0x0p+0] (EX-EDGE-7-d)")
print("  correct: DOMAIN_ERROR: an exception or every output NaN")
print("DEFECT SHOWN" if shown else "DEFECT NOT SHOWN")
sys.exit(0 if shown else 1)
