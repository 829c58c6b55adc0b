#!/usr/bin/env python3
"""rotorcert reproducer: numpy-quaternion np.sqrt of a rotation near a full turn, clause SQRT-1.

SQRT-1 (spec/SPEC.md 6, level Extended, eps16: METRIC-1 and METRIC-6, loose bar 256 eps): the rotor
square root s = (1 + q^)/|1 + q^| of q^ = q/|q|, i.e. (cos(theta/4), sin(theta/4) u): half the
rotation about the same axis; "1 + w of q^ cancels near q^ = -1 and SHOULD be formed as
|v^|^2/(1 - w^) there". numpy-quaternion's quaternion_sqrt (src/quaternion.c:41-58, the np.sqrt
ufunc and q.sqrt(), "Return the square-root of the quaternion") forms exactly that sum:
  c = sqrt(0.5 / (|q| + w)), s = ((|q| + w) c, x c, y c, z c),
so for a rotation delta short of a full turn (w near -|q|) |q| + w ~ delta^2/8 keeps only the
digits of the rounding of |q| and w: the error grows like 1/delta^2 (1.6e6 eps at delta = 1e-3),
and where |q| + w < 1e-14 |q| (delta below ~3e-7) it returns (0, sqrt|q|, 0, 0), the x axis,
whatever axis v has: a half turn about x instead of one about v/|v|, another rotation.
Upstream: no matching issue found in moble/quaternion.
Exit 0: defect shown; 1: not shown (fixed); 77: numpy-quaternion cannot be imported.
"""
import math
import sys
from decimal import Decimal, getcontext

CLAUSE = "SQRT-1"
try:
    from importlib.metadata import version
    import numpy as np
    import quaternion  # noqa: F401 - registers np.quaternion and its ufuncs
    VERSION = version("numpy-quaternion")
except Exception as exc:  # noqa: BLE001 - any import failure is a skip
    print("rotorcert reproducer: numpy-quaternion ? %s: SKIP: cannot import quaternion: %s" % (CLAUSE, exc))
    sys.exit(77)

EPS = 2.0 ** -52
LOOSE = 256  # eps16 loose bar (spec/clauses.json)
getcontext().prec = 60


def reference(q):
    """s = (|q| + q)/||q| + q| in 60-digit decimal arithmetic, (w, x, y, z) order (w > 0)."""
    w, x, y, z = (Decimal(c) for c in q)
    n = (w * w + x * x + y * y + z * z).sqrt()
    a = [n + w, x, y, z]
    norm = sum(c * c for c in a).sqrt()
    return [float(c / norm) for c in a]


def metric1(a, b):
    """Rotation distance of two unit quaternions, sign-free (METRIC-1): 4 atan2(min, max)."""
    dm = math.sqrt(sum((p - r) ** 2 for p, r in zip(a, b)))
    dp = math.sqrt(sum((p + r) ** 2 for p, r in zip(a, b)))
    return 4 * math.atan2(min(dm, dp), max(dm, dp))


def run(q, label):
    s = np.sqrt(np.quaternion(*q))
    got = [s.w, s.x, s.y, s.z]
    ref = reference(q)
    err = max(metric1(got, ref), abs(math.sqrt(sum(c * c for c in got)) - 1))  # METRIC-1 and METRIC-6
    theta = 2 * math.atan2(math.sqrt(sum(c * c for c in q[1:])), q[0])
    print("  call:    np.sqrt(np.quaternion(w, x, y, z))   [%s: %.3g rad short of a full turn]" % (label, 2 * math.pi - theta))
    print("  input:   q (w, x, y, z) = [%s]" % ", ".join(c.hex() for c in q))
    print("  library: [%s]" % ", ".join(repr(c) for c in got))
    print("  correct: [%s]  ((|q| + q)/||q| + q|, 60 digits)" % ", ".join(repr(c) for c in ref))
    print("  error:   %.3g rad = %.3g eps (METRIC-1, sign-free, and METRIC-6; loose bar %d eps)%s"
          % (err, err / EPS, LOOSE, "  <-- DEFECT" if err > LOOSE * EPS else ""))
    return err > LOOSE * EPS


print("rotorcert reproducer: numpy-quaternion %s %s: np.sqrt forms |q| + w, which cancels near a full turn, and "
      "returns the x axis below |q| + w = 1e-14 |q|" % (VERSION, CLAUSE))
# The suite's worst input (near a full turn: 2 pi - 1e-9 .. 1e-1), (w, x, y, z) of the report's [x, y, z, w].
worst = tuple(float.fromhex(h) for h in ("-0x1.fffffffffffffp-1", "-0x1.306b405fc2ca4p-35", "-0x1.27753211db02p-27",
                                         "-0x1.cad1e76f22aaap-28"))
bad = run(worst, "the suite's worst input")
# The cancellation above the threshold: a unit rotation 1e-3 rad short of a full turn about (2, -3, 6)/7.
th = 2 * math.pi - 1e-3
q2 = (math.cos(th / 2),) + tuple(math.sin(th / 2) * c / 7.0 for c in (2.0, -3.0, 6.0))
bad = run(q2, "also") and bad
print("DEFECT SHOWN" if bad else "DEFECT NOT SHOWN")
sys.exit(0 if bad else 1)
