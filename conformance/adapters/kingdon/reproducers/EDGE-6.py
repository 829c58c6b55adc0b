#!/usr/bin/env python3
"""rotorcert reproducer: kingdon geometric product with the zero rotor, clause EDGE-6.

EDGE-6 (spec/SPEC.md 9): a quaternion whose four components are +-0 is DOMAIN_ERROR: every output
component quiet NaN (or an error). Composing rotations in kingdon is the geometric product a * b
(no documented precondition); with a = 0 it returns the zero rotor [-0, 0, -0, 0] and no error, so a
zero "rotation" silently propagates. (normalized() and inv() of the zero rotor do refuse, by
ZeroDivisionError; the >> sandwich of the zero rotor, which returns its argument unchanged, is NOT
reported here: kingdon documents that the versor must satisfy x ~x = 1.)
Upstream: no matching issue found in tBuLi/kingdon.
Exit 0: defect shown; 1: not shown (fixed); 77: kingdon cannot be imported.
"""
import math
import sys

CLAUSE = "EDGE-6"
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
# kingdon's default); back: x = -R.e23, y = +R.e13, z = -R.e12, w = R.e. compose(a, b) = a b (b first).
alg = Algebra(3, 0, 0)


def rotor(x, y, z, w):
    return alg.multivector(e=w, e12=-z, e13=y, e23=-x)


h = float.fromhex
a = [0.0, 0.0, 0.0, 0.0]  # (x, y, z, w): the zero quaternion
b = [h("-0x1.9e235dc153f17p-2"), h("-0x1.ac77698dac623p-1"), h("-0x1.98009e358a0fep-4"), h("-0x1.6bc4b6dfc72a7p-2")]

print("rotorcert reproducer: kingdon %s %s: the geometric product of the zero rotor and a unit rotor "
      "returns the zero rotor with no error" % (VERSION, CLAUSE))
try:
    R = rotor(*a) * rotor(*b)
    got = [-R.e23, R.e13, -R.e12, R.e]
    result, refused = "[%s]" % ", ".join(c.hex() for c in got), all(math.isnan(c) for c in got)
except Exception as exc:  # noqa: BLE001 - an exception is a correct refusal (DOMAIN_ERROR)
    result, refused = "raised %s: %s" % (type(exc).__name__, exc), True
print("  call:    A = alg.multivector(e=w, e12=-z, e13=y, e23=-x) (likewise B); A * B")
print("  input:   a = [%s]" % ", ".join(c.hex() for c in a))
print("           b = [%s]  (x, y, z, w), |b| = 1 to rounding" % ", ".join(c.hex() for c in b))
print("  library: %s%s" % (result, "" if refused else "  (status OK)  <-- DEFECT"))
print("  correct: DOMAIN_ERROR: an exception or [nan, nan, nan, nan] (a zero quaternion is no rotation)")
print("DEFECT SHOWN" if not refused else "DEFECT NOT SHOWN")
sys.exit(0 if not refused else 1)
