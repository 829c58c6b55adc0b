#!/usr/bin/env python3
"""rotorcert reproducer: kingdon MultiVector.normalized() of a rotor with an Inf component, clause EDGE-7.

EDGE-7 (spec/SPEC.md 9): NaN or +-Inf in any input component is DOMAIN_ERROR with all output components
quiet NaN (or an error), "even if the result would be mathematically defined (normalize((Inf, 0, 0, 1))
is DOMAIN_ERROR, not (1, 0, 0, 0))". kingdon's normalized() ("Normalized version of this multivector")
has no finiteness check: (0, inf, 0, 1) gives (0, nan, 0, 0), a partly finite result with no error.
The geometric product passes Inf through the same way. No precondition is documented. (The >> sandwich
with a NaN rotor is NOT reported here: kingdon documents that the versor must satisfy x ~x = 1.)
Upstream: no matching issue found in tBuLi/kingdon.
Exit 0: defect shown; 1: not shown (fixed); 77: kingdon cannot be imported.
"""
import math
import sys

CLAUSE = "EDGE-7"
try:
    from importlib.metadata import version
    from kingdon import Algebra
    VERSION = version("kingdon")
except Exception as exc:  # noqa: BLE001 - any import failure is a skip
    print("rotorcert reproducer: kingdon ? %s: SKIP: cannot import kingdon: %s" % (CLAUSE, exc))
    sys.exit(77)

# Conventions (rotorcert Q2R-1, as conformance/adapters/kingdon does it): quaternion (x, y, z, w)
# <-> rotor R = w - x e23 - y e31 - z e12. kingdon's Algebra(3, 0, 0) names the bivectors e12, e13,
# e23, and e31 = -e13, so R = w - z e12 + y e13 - x e23 (set blade by blade, Python float coefficients,
# kingdon's default); back: x = -R.e23, y = +R.e13, z = -R.e12, w = R.e.
alg = Algebra(3, 0, 0)
q = [0.0, math.inf, 0.0, 1.0]  # (x, y, z, w) (EX-EDGE-7-b)

print("rotorcert reproducer: kingdon %s %s: normalized() of a rotor with an Inf component returns a partly "
      "finite rotor (0, nan, 0, 0) with no error" % (VERSION, CLAUSE))
x, y, z, w = q
try:
    R = alg.multivector(e=w, e12=-z, e13=y, e23=-x).normalized()
    got = [-R.e23, R.e13, -R.e12, R.e]
    result, refused = "[%s]" % ", ".join(c.hex() for c in got), all(math.isnan(c) for c in got)
except Exception as exc:  # noqa: BLE001 - an exception is a correct refusal (DOMAIN_ERROR)
    result, refused = "raised %s: %s" % (type(exc).__name__, exc), True
print("  call:    R = alg.multivector(e=w, e12=-z, e13=y, e23=-x); R.normalized()")
print("  input:   q (x, y, z, w) = [%s]" % ", ".join(c.hex() for c in q))
print("  library: %s%s" % (result, "" if refused else "  (partly finite, no error)  <-- DEFECT"))
print("  correct: DOMAIN_ERROR: an exception or [nan, nan, nan, nan] (RESULT-2)")
print("DEFECT SHOWN" if not refused else "DEFECT NOT SHOWN")
sys.exit(0 if not refused else 1)
