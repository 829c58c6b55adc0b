#!/usr/bin/env python3
"""rotorcert reproducer: transforms3d quaternions.quat2axangle's angle alone, clause AXANG-3.

AXANG-3 (spec/SPEC.md 6, level Extended, eps16: absolute error in radians, loose bar 256 eps =
2^-44 rad): the angle alone, theta = 2 atan2(|v|, w) of AXANG-1 (an angle of the same rotation, 2 pi
- theta or signed, is acceptable: the error is |rho(angle) - rho(theta)|, rho the angle in [0, pi]).
transforms3d 0.4.2 has no angle-only call; its angle is the theta of quat2axangle (quaternions.py:
521-590), which normalises q and computes theta = 2 * math.acos(max(min(quat[0], 1), -1)): for a
rotation of 2.7e-8 rad, w = cos(theta/2) rounds to 1 - 2^-53 or 1 and acos returns 2^-26 or 0, so the
angle of every rotation below ~2e-8 rad is lost, and angles up to ~1e-3 rad (and as close to a full
turn) carry errors of ~1e-16/theta rad. 2 atan2(|v|, w) is accurate at every angle. The AXANG-1 defect
(AXANG-1.py), met by the angle query alone.
Upstream: no matching issue found in matthew-brett/transforms3d.
Exit 0: defect shown; 1: not shown (fixed); 77: transforms3d cannot be imported.
"""
import sys

CLAUSE = "AXANG-3"
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


def rho(a):
    """The angle in [0, pi] of the rotation by a about some axis (ACC-1 angle_range)."""
    return 2 * mpmath.atan2(abs(mpmath.sin(a / 2)), abs(mpmath.cos(a / 2)))


# rotorcert's worst input (to_angle, "angle sweep 1e-9 .. pi", seed 1), stored (x, y, z, w);
# transforms3d takes [w, x, y, z].
x, y, z, w = (h("0x1.f72fb3b9384dfp-30"), h("0x1.a8bba3bd4419dp-27"), h("-0x1.6bb2933e06dcdp-28"),
              h("0x1.fffffffffffffp-1"))
theta = tq.quat2axangle(np.array([w, x, y, z]))[1]
X, Y, Z, W = (mpmath.mpf(c) for c in (x, y, z, w))
ref = 2 * mpmath.atan2(mpmath.sqrt(X * X + Y * Y + Z * Z), W)
err = abs(rho(mpmath.mpf(float(theta))) - rho(ref))
err_eps = float(err / EPS)
shown = not (err_eps <= LOOSE)
print("rotorcert reproducer: transforms3d %s %s: the angle of quat2axangle, 2 acos(w), is 0 for a rotation of "
      "2.7e-8 rad" % (VERSION, CLAUSE))
print("  call:    theta = transforms3d.quaternions.quat2axangle([w, x, y, z])[1]")
print("  input:   q (x, y, z, w) = [%s]" % ", ".join(c.hex() for c in (x, y, z, w)))
print("  library: theta = %s (%r)" % (float(theta).hex(), float(theta)))
print("  correct: theta = 2 atan2(|v|, w) = %s (%s, 256-bit mpmath)" % (float(ref).hex(), mpmath.nstr(ref, 17)))
print("  error:   %s rad = %.4g eps (absolute, under any angle range; bar %d eps)%s"
      % (mpmath.nstr(err, 6), err_eps, LOOSE, "  <-- DEFECT" if shown else ""))
print("DEFECT SHOWN" if shown else "DEFECT NOT SHOWN")
sys.exit(0 if shown else 1)
