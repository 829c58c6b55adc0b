#!/usr/bin/env python3
"""rotorcert reproducer: scipy Rotation.from_quat of a quaternion with subnormal components, clause EDGE-8.

EDGE-8 (spec/SPEC.md 9): subnormal components are ordinary nonzero values: normalize((2^-1074, -0, 0, 0))
= (1, -0, 0, 0); an implementation that flushes them to zero and reports DOMAIN_ERROR fails (class eps4).
Rotation.from_quat documents "Each quaternion will be normalized to unit norm" (scipy/spatial/transform/
_rotation.py:411-413), but _normalize4 (_rotation_cy.pyx:58-70) computes sqrt(x*x + y*y + z*z + w*w)
without scaling, which is 0 for every quaternion whose components are all below about 2^-538, and
from_quat then raises "Found zero norm quaternions in `quat`" (:412-415) for a nonzero quaternion. Every
Rotation call (as_quat, apply, as_matrix, as_rotvec, Slerp) refuses such input. Dividing by the largest
|component| before squaring (or hypot) fixes it.
Upstream: no matching issue found in scipy/scipy.
Exit 0: defect shown; 1: not shown (fixed); 77: scipy cannot be imported.
"""
import math
import sys

CLAUSE = "EDGE-8"
try:
    from importlib.metadata import version
    from scipy.spatial.transform import Rotation
    VERSION = version("scipy")
except Exception as exc:  # noqa: BLE001 - any import failure is a skip
    print("rotorcert reproducer: scipy ? %s: SKIP: cannot import scipy: %s" % (CLAUSE, exc))
    sys.exit(77)

EPS = 2.0 ** -52
LOOSE = 64  # eps4 loose bar (spec/clauses.json)
q = [float.fromhex("0x0.0000000000001p-1022"), -0.0, 0.0, 0.0]  # [x, y, z, w] (EX-EDGE-8-a)
want = [1.0, -0.0, 0.0, 0.0]  # q/|q|, exactly

print("rotorcert reproducer: scipy %s %s: Rotation.from_quat([2^-1074, -0, 0, 0]) raises 'Found zero norm "
      "quaternions' for a nonzero quaternion" % (VERSION, CLAUSE))
try:
    got = [float(c) for c in Rotation.from_quat(q).as_quat()]
    result = "[%s]" % ", ".join(c.hex() for c in got)
    err = max(abs(a - b) for a, b in zip(got, want))
except Exception as exc:  # noqa: BLE001 - refusing a nonzero quaternion is the defect (wrong status)
    result, err = "raised %s: %s" % (type(exc).__name__, exc), math.nan
bad = not (err / EPS <= LOOSE)
print("  call:    Rotation.from_quat(q).as_quat()")
print("  input:   q (x, y, z, w) = [%s]" % ", ".join(c.hex() for c in q))
print("  library: %s" % result)
print("  correct: [%s] (q/|q|, exact)" % ", ".join(c.hex() for c in want))
print("  error:   %s (%s)%s" % (err, "a spurious DOMAIN_ERROR" if math.isnan(err) else "eps: %g" % (err / EPS),
                               "  <-- DEFECT" if bad else ""))
print("DEFECT SHOWN" if bad else "DEFECT NOT SHOWN")
sys.exit(0 if bad else 1)
