#!/usr/bin/env python3
"""rotorcert reproducer: transforms3d quaternions.quat2axangle of a small rotation, clause AXANG-1.

AXANG-1 (spec/SPEC.md 6): theta = 2 atan2(|v|, w), u = v/|v|; "Implementations MUST NOT compute theta as
2 acos(w) (loses accuracy near theta = 0 and 2 pi)". Tolerance eps16: absolute error of theta, loose bar
256 eps (2^-44 rad). transforms3d 0.4.2 quat2axangle (quaternions.py:588) normalises q, then computes
theta = 2 * math.acos(max(min(quat[0], 1), -1)). For a rotation of 2.6e-8 rad, w = cos(theta/2) rounds to
exactly 1 (or to 1 - 2^-53), so acos returns 0 (or 2^-26): the angle of every rotation below ~2e-8 rad is
lost entirely, and angles up to ~1e-3 rad carry absolute errors of ~1e-16/theta rad -- although the
axis it returns beside it is accurate. 2 atan2(|v|, w) is accurate at every angle.
Upstream: no matching issue found in matthew-brett/transforms3d.
Exit 0: defect shown; 1: not shown (fixed); 77: transforms3d cannot be imported.
"""
import sys

CLAUSE = "AXANG-1"
try:
    from importlib.metadata import version
    import numpy as np
    import mpmath
    from transforms3d import quaternions as tq
    VERSION = version("transforms3d")
except Exception as exc:  # noqa: BLE001 - any import failure is a skip
    print("rotorcert reproducer: transforms3d ? %s: SKIP: cannot import transforms3d: %s" % (CLAUSE, exc))
    sys.exit(77)

mpmath.mp.prec = 256
EPS = 2.0 ** -52
LOOSE = 256  # eps16 loose bar (spec/clauses.json)
h = float.fromhex
# rotorcert's worst input (to_axis_angle, "angle sweep 1e-9 .. pi", seed 1), stored (x, y, z, w);
# transforms3d takes [w, x, y, z].
x, y, z, w = (h("0x1.98561d5f59371p-27"), h("0x1.11d6755063652p-29"), h("0x1.7856859b30e24p-28"),
              h("0x1.fffffffffffffp-1"))
vector, theta = tq.quat2axangle(np.array([w, x, y, z]))
X, Y, Z, W = (mpmath.mpf(c) for c in (x, y, z, w))
ref = 2 * mpmath.atan2(mpmath.sqrt(X * X + Y * Y + Z * Z), W)
err = abs(mpmath.mpf(float(theta)) - ref)
err_eps = float(err / EPS)
shown = not (err_eps <= LOOSE)
print("rotorcert reproducer: transforms3d %s %s: quat2axangle computes theta = 2 acos(w) and returns the angle "
      "0 for a rotation of 2.6e-8 rad" % (VERSION, CLAUSE))
print("  call:    vector, theta = transforms3d.quaternions.quat2axangle([w, x, y, z])")
print("  input:   q (x, y, z, w) = [%s]" % ", ".join(c.hex() for c in (x, y, z, w)))
print("  library: theta = %s (%r), vector = [%s]" % (float(theta).hex(), float(theta), ", ".join(float(c).hex() for c in vector)))
print("  correct: theta = 2 atan2(|v|, w) = %s (%s, 256-bit mpmath)" % (float(ref).hex(), mpmath.nstr(ref, 17)))
print("  error:   %s rad = %.4g eps (absolute; bar %d eps)%s" % (mpmath.nstr(err, 6), err_eps, LOOSE,
                                                                "  <-- DEFECT" if shown else ""))
print("DEFECT SHOWN" if shown else "DEFECT NOT SHOWN")
sys.exit(0 if shown else 1)
