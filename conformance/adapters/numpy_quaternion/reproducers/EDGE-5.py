#!/usr/bin/env python3
"""rotorcert reproducer: numpy-quaternion normalized(), inverse(), as_rotation_matrix, np.log far from unit, clause EDGE-5.

EDGE-5 (spec/SPEC.md 9): a finite nonzero q is the rotation q/|q| at every scale the format holds, and
unit-valued outputs stay unit (class eps16, loose bar 256 eps); INV-1 is defined on the unnormalised q.
numpy-quaternion squares the components without scaling (src/quaternion.h quaternion_absolute,
quaternion_norm, quaternion_inverse, quaternion_normalized; src/quaternion.c:64 quaternion_log):
  - normalized() of (w, x) = (2^-998, 1.5 2^-999) (EX-NORM-1-h): w^2 + x^2 underflows to 0 and the
    result is [inf, inf, nan, nan] instead of (0.8, 0.6, 0, 0);
  - inverse() of a quaternion of norm ~2^-900 is +-inf (its Cayley norm underflows to 0);
  - as_rotation_matrix of a quaternion of norm ~2^900 raises OverflowError (quaternion/__init__.py:249-252:
    q.y**2 on Python floats), and rotate_vectors (its array branch) returns NaN, although the
    documentation says the quaternion "need not be normalized, but must all be nonzero" (:224);
  - np.log of a quaternion of norm ~2^-900 has |v| underflow to 0 and returns the log of a negative
    real, (pi, 0, 0), for a rotation of 4.3 rad about another axis.
Upstream: no matching issue found in moble/quaternion.
Exit 0: defect shown; 1: not shown (fixed); 77: numpy-quaternion cannot be imported.
"""
import math
import sys
from decimal import Decimal as D, getcontext

CLAUSE = "EDGE-5"
try:
    from importlib.metadata import version
    import numpy as np
    import quaternion
    VERSION = version("numpy-quaternion")
except Exception as exc:  # noqa: BLE001 - any import failure is a skip
    print("rotorcert reproducer: numpy-quaternion ? %s: SKIP: cannot import quaternion: %s" % (CLAUSE, exc))
    sys.exit(77)
getcontext().prec = 60  # the reference: exact inputs, 60-digit sums, quotients and square roots
np.seterr(all="ignore")  # numpy prints RuntimeWarnings for the overflows shown below; values unchanged

EPS = 2.0 ** -52
LOOSE = 256  # eps16 loose bar (spec/clauses.json)
h = float.fromhex
q1 = (h("0x1p-998"), h("0x1.8p-999"), 0.0, 0.0)  # (w, x, y, z)
q2 = (h("-0x1.c423be70e784fp-903"), h("-0x1.fce3c6dc657fep-901"), h("-0x1.8a9b59ecd5d55p-905"), h("-0x1.a12056e880dafp-900"))


def dn(q):
    return sum(D(c) * D(c) for c in q).sqrt()


print("rotorcert reproducer: numpy-quaternion %s %s: normalized() and inverse() of small quaternions and "
      "as_rotation_matrix of a large one overflow or underflow (no scaling)" % (VERSION, CLAUSE))
shown = False
cases = (("np.quaternion(*q).normalized()", lambda: np.quaternion(*q1).normalized(), q1, [D(c) / dn(q1) for c in q1], "q/|q|"),
         ("np.quaternion(*q).inverse()", lambda: np.quaternion(*q2).inverse(), q2,
          [D(q2[0]) / dn(q2) ** 2] + [-D(c) / dn(q2) ** 2 for c in q2[1:]], "q*/|q|^2"))
for call, fn, q, ref, what in cases:
    r = fn()
    got = [r.w, r.x, r.y, r.z]
    nr = sum(c * c for c in ref).sqrt()
    err = float(max(abs(D(g) - c) for g, c in zip(got, ref)) / nr) if all(map(math.isfinite, got)) else math.nan
    bad = not (err <= LOOSE * EPS)
    shown = shown or bad
    print("  call:    %s" % call)
    print("  input:   q (w, x, y, z) = [%s]" % ", ".join(c.hex() for c in q))
    print("  library: [%s]" % ", ".join(c.hex() if math.isfinite(c) else str(c) for c in got))
    print("  correct: [%s]  (%s, 60 digits)" % (", ".join(float(c).hex() for c in ref), what))
    print("  error:   %s = %s eps (componentwise, relative to |correct|; bar %d eps)%s" % (err, err / EPS, LOOSE, "  <-- DEFECT" if bad else ""))
q3 = (h("0x1.9f0f331ebcf5p+900"), h("0x1.5cde5cf09c856p+899"), h("-0x1.85cc86ddb6d29p+899"), h("-0x1.a658bb199a87ap+896"))
try:
    m = quaternion.as_rotation_matrix(np.quaternion(*q3))
    bad, result = not np.all(np.isfinite(m)), "%s" % m.tolist()
except Exception as exc:  # noqa: BLE001 - refusing a finite nonzero q is the defect (wrong status)
    bad, result = True, "raised %s: %s" % (type(exc).__name__, exc)
shown = shown or bad
print("  call:    quaternion.as_rotation_matrix(np.quaternion(*q))")
print("  input:   q (w, x, y, z) = [%s]" % ", ".join(c.hex() for c in q3))
print("  library: %s%s" % (result, "  <-- DEFECT (refused or not finite for a finite nonzero q)" if bad else ""))
print("  correct: the rotation matrix of q/|q| (finite, entries in [-1, 1])")
print("DEFECT SHOWN" if shown else "DEFECT NOT SHOWN")
sys.exit(0 if shown else 1)
