#!/usr/bin/env python3
"""rotorcert reproducer: numpy-quaternion normalized(), as_rotation_matrix and np.log of subnormal quaternions, clause EDGE-8.

EDGE-8 (spec/SPEC.md 9): subnormal components are ordinary nonzero values: normalize((2^-1074, -0, 0, 0))
= (1, -0, 0, 0) (class eps4, loose bar 64 eps). numpy-quaternion squares them without scaling:
  - normalized() (quaternion_normalized, src/quaternion.h: q / sqrt(w^2 + x^2 + y^2 + z^2)) divides by
    0: [nan, inf, nan, nan] in (w, x, y, z) order;
  - as_rotation_matrix (quaternion/__init__.py:238-241) raises ZeroDivisionError "has zero norm" for a
    nonzero q, and rotate_vectors with it;
  - np.log (src/quaternion.c:64-76) finds |v| = 0 and returns the zero vector, the identity.
Upstream: no matching issue found in moble/quaternion.
Exit 0: defect shown; 1: not shown (fixed); 77: numpy-quaternion cannot be imported.
"""
import math
import sys

CLAUSE = "EDGE-8"
try:
    from importlib.metadata import version
    import numpy as np
    import quaternion
    VERSION = version("numpy-quaternion")
except Exception as exc:  # noqa: BLE001 - any import failure is a skip
    print("rotorcert reproducer: numpy-quaternion ? %s: SKIP: cannot import quaternion: %s" % (CLAUSE, exc))
    sys.exit(77)
np.seterr(all="ignore")  # numpy prints RuntimeWarnings for the 0/0 shown below; values unchanged

EPS = 2.0 ** -52
LOOSE = 64  # eps4 loose bar (spec/clauses.json)
tiny = float.fromhex("0x0.0000000000001p-1022")  # 2^-1074
q = (0.0, tiny, -0.0, 0.0)  # (w, x, y, z): EX-EDGE-8-a, x = 2^-1074
ref = [0.0, 1.0, -0.0, 0.0]  # closed form: q/|q| with |q| = x
print("rotorcert reproducer: numpy-quaternion %s %s: normalized() of a quaternion with a subnormal component "
      "is [nan, inf, nan, nan]; as_rotation_matrix raises ZeroDivisionError" % (VERSION, CLAUSE))
r = np.quaternion(*q).normalized()
got = [r.w, r.x, r.y, r.z]
err = max(abs(g - c) for g, c in zip(got, ref)) if all(map(math.isfinite, got)) else math.nan
bad = not (err <= LOOSE * EPS)
print("  call:    np.quaternion(w, x, y, z).normalized()")
print("  input:   q (w, x, y, z) = [%s]" % ", ".join(c.hex() for c in q))
print("  library: [%s]" % ", ".join(c.hex() if math.isfinite(c) else str(c) for c in got))
print("  correct: [%s]  (q/|q|, |q| = 2^-1074: closed form)" % ", ".join(c.hex() for c in ref))
print("  error:   %s = %s eps (max componentwise; bar %d eps)%s" % (err, err / EPS, LOOSE, "  <-- DEFECT" if bad else ""))
try:
    m = quaternion.as_rotation_matrix(np.quaternion(*q))
    print("  also:    as_rotation_matrix(q) = %s" % m.tolist())
except Exception as exc:  # noqa: BLE001
    print("  also:    as_rotation_matrix(q) raised %s: %s  (correct: the half turn about x, diag(1, -1, -1))" % (type(exc).__name__, exc))
print("DEFECT SHOWN" if bad else "DEFECT NOT SHOWN")
sys.exit(0 if bad else 1)
