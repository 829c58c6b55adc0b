#!/usr/bin/env python3
"""rotorcert reproducer: pyquaternion passes NaN and Inf through as partly valid results, clause EDGE-7.

EDGE-7 (spec/SPEC.md 9): NaN or +-Inf in any input is DOMAIN_ERROR with every output NaN (or an
exception), "even if the result would be mathematically defined" (class outcome). pyquaternion has no
finiteness check:
  - normalised of (w, x, y, z) = (1, NaN, 0, 0): is_unit is False and "if n > 0" is False for n = NaN
    (pyquaternion/quaternion.py:508-511), so the input comes back unchanged as the "unit quaternion"
    (1, NaN, 0, 0): three finite components and one NaN;
  - a product A * B with an infinite component in A gives +-Inf components and no NaN
    (quaternion.py:389-391);
  - the angle of a quaternion with a NaN w is NaN while its axis is a finite unit vector
    (quaternion.py:1043-1096).
Upstream: no matching issue found in KieranWynn/pyquaternion.
Exit 0: defect shown; 1: not shown (fixed); 77: pyquaternion cannot be imported.
"""
import math
import sys

CLAUSE = "EDGE-7"
try:
    from importlib.metadata import version
    from pyquaternion import Quaternion
    VERSION = version("pyquaternion")
except Exception as exc:  # noqa: BLE001 - any import failure is a skip
    print("rotorcert reproducer: pyquaternion ? %s: SKIP: cannot import pyquaternion: %s" % (CLAUSE, exc))
    sys.exit(77)

nan, inf = float("nan"), float("inf")
h = float.fromhex
a = (h("-0x1.50583b526fee1p-4"), inf, h("0x1.bd3871e4b78cap-2"), h("-0x1.07cf0d274156bp-1"))  # (w, x, y, z)
b = (h("0x1.37794ce7528cbp-2"), h("0x1.5f20eb8a4502ap-1"), h("-0x1.e472a45a35deep-2"), h("-0x1.d8f98f7aa6c7cp-2"))  # (w, x, y, z)
q3 = (nan, h("-0x1.810a95e48461ap-2"), h("0x1.38a1510f9f2a8p-2"), h("0x1.bee277da5b067p-1"))  # (w, x, y, z)
print("rotorcert reproducer: pyquaternion %s %s: normalised of (w, x, y, z) = (1, NaN, 0, 0) returns its "
      "input, a product with Inf gives +-Inf, the axis of a NaN quaternion is finite: no error, not all NaN"
      % (VERSION, CLAUSE))
shown = False
for call, fn in (("Quaternion(1, nan, 0, 0).normalised", lambda: Quaternion(1, nan, 0, 0).normalised.q),
                 ("Quaternion(*a) * Quaternion(*b), a with x = inf", lambda: (Quaternion(*a) * Quaternion(*b)).q),
                 ("Quaternion(nan, x, y, z).get_axis(undefined=[0, 0, 1])", lambda: Quaternion(*q3).get_axis(undefined=[0.0, 0.0, 1.0]))):
    try:
        out = [float(c) for c in fn()]
        refused = all(math.isnan(c) for c in out)
        result = "[%s]" % ", ".join(c.hex() if math.isfinite(c) else str(c) for c in out)
    except Exception as exc:  # noqa: BLE001 - an exception is a refusal: the required outcome
        refused, result = True, "raised %s: %s" % (type(exc).__name__, exc)
    shown = shown or not refused
    print("  call:    %s" % call)
    print("  library: %s%s" % (result, "" if refused else "  <-- DEFECT (not all NaN, no error)"))
print("  input:   a (w, x, y, z) = [%s, inf, %s]" % (a[0].hex(), ", ".join(c.hex() for c in a[2:])))
print("           b (w, x, y, z) = [%s]" % ", ".join(c.hex() for c in b))
print("           last call (w, x, y, z) = [nan, %s]" % ", ".join(c.hex() for c in q3[1:]))
print("  correct: DOMAIN_ERROR: an exception or every output NaN")
print("DEFECT SHOWN" if shown else "DEFECT NOT SHOWN")
sys.exit(0 if shown else 1)
