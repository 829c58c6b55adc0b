#!/usr/bin/env python3
"""rotorcert reproducer: pyquaternion slerp from the zero quaternion returns the other endpoint, clause EDGE-6.

EDGE-6 (spec/SPEC.md 9): a zero quaternion has no rotation: DOMAIN_ERROR (an exception, or all outputs
NaN; class outcome). Since spec 2.2.0 ACC-1 zero_sentinel also accepts status OK with every output 0, or
exactly the identity's answer (the zero quaternion replaced by the identity (0, 0, 0, 1)). pyquaternion's
Quaternion.slerp normalises its endpoints with _fast_normalise, which returns a zero quaternion unchanged
(pyquaternion/quaternion.py:519-522), so for q0 = 0 the dot product is 0, theta_0 = pi/2 and the result
s1 q1 is normalised to q1 (quaternion.py:872-901): slerp(0, b, t) = b for every t > 0, neither an error,
nor zero, nor slerp(1, b, t). (rotate, rotation_matrix, angle/axis, normalised and the product of the zero
quaternion give zeros or the identity's answer: ACC-1 zero_sentinel since 2.2.0, no longer a defect.)
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

EPS, LOOSE = 2.0 ** -52, 256  # eps16 loose bar (spec/clauses.json)
print("rotorcert reproducer: pyquaternion %s %s: Quaternion.slerp(0, b, t) returns b, with no error"
      % (VERSION, CLAUSE))
# EX-EDGE-6-g, the suite's worst input: a = 0, b = a quarter turn about z, t = 1/2 (spec order [x, y, z, w]).
a = [0.0, 0.0, 0.0, 0.0]
b = [0.0, 0.0, float.fromhex("0x1.6a09e667f3bcdp-1"), float.fromhex("0x1.6a09e667f3bcdp-1")]
t = 0.5
try:
    r = Quaternion.slerp(Quaternion(a[3], a[0], a[1], a[2]), Quaternion(b[3], b[0], b[1], b[2]), amount=t)
    got = [float(r.x), float(r.y), float(r.z), float(r.w)]
except Exception as exc:  # noqa: BLE001 - an exception is a refusal: the required outcome
    got = None
    result = "raised %s: %s" % (type(exc).__name__, exc)
# The identity's answer (ACC-1 zero_sentinel): slerp(1, b, 1/2) turns by half of b's 90 degrees about z.
half = math.atan2(b[2], b[3]) * t
identity = [0.0, 0.0, math.sin(half), math.cos(half)]
if got is None:
    shown = False
else:
    dist = min(math.dist(got, identity), math.dist(got, [-c for c in identity]))
    accepted = (all(not math.isfinite(c) for c in got) or all(c == 0 for c in got) or dist <= LOOSE * EPS)
    shown = not accepted
    result = "[%s] (x, y, z, w)%s" % (", ".join(c.hex() for c in got), "  (= b, status OK)  <-- DEFECT" if shown else "")
print("  call:    Quaternion.slerp(Quaternion(w, x, y, z) of a, Quaternion(w, x, y, z) of b, amount=t)")
print("  input:   a (x, y, z, w) = [%s], b = [%s], t = %s" % (", ".join(c.hex() for c in a),
                                                           ", ".join(c.hex() for c in b), t.hex()))
print("  library: %s" % result)
print("  correct: DOMAIN_ERROR: an exception or all outputs NaN; acceptable (ACC-1 zero_sentinel): [0, 0, 0, 0] "
      "or the identity's answer slerp(1, b, t) = [%s]" % ", ".join(c.hex() for c in identity))
print("DEFECT SHOWN" if shown else "DEFECT NOT SHOWN")
sys.exit(0 if shown else 1)
