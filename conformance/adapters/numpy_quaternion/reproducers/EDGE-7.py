#!/usr/bin/env python3
"""rotorcert reproducer: numpy-quaternion np.exp turns a NaN into the identity, clause EDGE-7.

EDGE-7 (spec/SPEC.md 9): NaN or +-Inf in any input is DOMAIN_ERROR with every output NaN (or an
exception), "even if the result would be mathematically defined" (class outcome). Since spec 2.7.0
(ACC-1 nonfinite_propagation) an answer with at least one NaN or infinite component is ACCEPTABLE, as
IEEE arithmetic carries it when a library checks nothing; an all-finite answer to a non-finite input
stays a FAIL: no caller can tell it from a real result.
numpy-quaternion's quaternion_exp (src/quaternion.c:109-122 of v2024.0.13, compiled into
quaternion/numpy_quaternion.cpython-311-x86_64-linux-gnu.so) tests "if (vnorm > _QUATERNION_EPS)", which
is False for a NaN |v|, and then returns {exp(w), 0, 0, 0}: np.exp(quaternion(0, NaN, y, z)) is exactly 1,
the identity rotation, whatever y and z are, and so is quaternion.from_rotation_vector of a vector with
a NaN, which calls np.exp (quaternion/__init__.py:443-463). The NaN disappears without a trace; numpy's
own functions propagate NaN. (Its other answers to non-finite input -- normalized() of (1, Inf, 0, 0)
= [0, nan, 0, 0], products with Inf, np.sqrt, np.log -- keep a NaN or Inf and are acceptable now.)
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
np.seterr(all="ignore")  # numpy prints a RuntimeWarning for the NaN; values unchanged

h = float.fromhex
# rotorcert's exp inputs v = (x, y, z): EX-EDGE-7-d (the worst) and "NaN in v".
cases = [("EX-EDGE-7-d", [h("-nan"), h("0x0p+0"), h("0x0p+0")]),
         ("NaN in v", [h("-nan"), h("-0x1.944f76f316838p-3"), h("0x1.4deeb428621dap+1")])]

print("rotorcert reproducer: numpy-quaternion %s %s: np.exp of a pure quaternion with a NaN component "
      "returns exactly 1 (the identity), and so does from_rotation_vector" % (VERSION, CLAUSE))
shown = False
for label, v in cases:
    for call, fn in (("np.exp(np.quaternion(0, x, y, z))", lambda: np.exp(np.quaternion(0.0, *v))),
                     ("quaternion.from_rotation_vector([x, y, z])", lambda: quaternion.from_rotation_vector(v))):
        try:
            r = fn()
            out = [r.w, r.x, r.y, r.z]
            # the defect: a non-finite input answered with an all-finite output (the NaN is gone)
            bad = not all(math.isfinite(c) for c in v) and all(math.isfinite(c) for c in out)
            result = "quaternion(w, x, y, z) = [%s]" % ", ".join(c.hex() if math.isfinite(c) else repr(c) for c in out)
        except Exception as exc:  # noqa: BLE001 - an exception is a refusal: the required outcome
            bad, result = False, "raised %s: %s" % (type(exc).__name__, exc)
        shown = shown or bad
        print("  call:    %s" % call)
        print("  input:   v (x, y, z) = [%s] (%s)" % (", ".join(c.hex() if math.isfinite(c) else repr(c) for c in v), label))
        print("  library: %s%s" % (result, "  <-- DEFECT (NaN input, all-finite output, no error)" if bad else ""))
print("  correct: DOMAIN_ERROR: an exception or every output NaN; acceptable (ACC-1 nonfinite_propagation): "
      "some component NaN or infinite, e.g. [nan, nan, nan, nan] from exp(w) * (cos|v|, sin|v|/|v| v)")
print("DEFECT SHOWN" if shown else "DEFECT NOT SHOWN")
sys.exit(0 if shown else 1)
