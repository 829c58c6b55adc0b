#!/usr/bin/env python3
"""rotorcert reproducer: pytransform3d quaternion functions at non-unit scales, clause EDGE-5.

EDGE-5 (spec/SPEC.md 9): a finite nonzero q means the rotation q/|q| at every scale the format holds, and
unit-valued outputs stay unit (class eps16, loose bar 256 eps). pytransform3d 3.17.0 normalises every
quaternion input with check_quaternion -> norm_vector (rotations/_quaternion.py:42-43, _utils.py:43-47),
which divides by np.linalg.norm(v), the unscaled sqrt(dot(v, v)): at |q| ~ 2^900 the norm overflows to inf
and q becomes the zero quaternion, at |q| ~ 2^-900 it underflows to 0 and q is returned unchanged (not
unit). So axis_angle_from_quaternion of a rotation of 5.84 rad at scale 2^900 returns the identity
(rotorcert's worst input), norm_vector of (2^1023, 2^1023, 2^1023, 2^1023) returns (0, 0, 0, 0), and
quaternion_slerp at scale 2^900 returns all NaN (a refusal of valid input). pytransform3d documents its
quaternion inputs as "Unit quaternion to represent rotation" but normalises them itself
(check_quaternion(q, unit=True): "Normalize the quaternion so that it is a unit quaternion"), so these
scales are within what it accepts.
Upstream: no matching issue found in dfki-ric/pytransform3d.
Exit 0: defect shown; 1: not shown (fixed); 77: pytransform3d cannot be imported.
"""
import math
import sys

CLAUSE = "EDGE-5"
try:
    from importlib.metadata import version
    import numpy as np
    import mpmath
    import pytransform3d.rotations as pr
    VERSION = version("pytransform3d")
except Exception as exc:  # noqa: BLE001 - any import failure is a skip
    print("rotorcert reproducer: pytransform3d ? %s: SKIP: cannot import pytransform3d: %s" % (CLAUSE, exc))
    sys.exit(77)

np.seterr(all="ignore")  # numpy's warnings only; the values are the same
mpmath.mp.prec = 256
EPS = 2.0 ** -52
LOOSE = 256  # eps16 loose bar (spec/clauses.json)
h = float.fromhex


def unit(q):
    m = [mpmath.mpf(c) for c in q]
    n = mpmath.sqrt(sum(c * c for c in m))
    return [c / n for c in m]


def metric1(a, b):
    """METRIC-1: the rotation angle between the rotations of a and b (sign-blind), 256-bit mpmath."""
    a, b = unit(a), unit(b)
    d = mpmath.sqrt(sum((p - q) ** 2 for p, q in zip(a, b)))
    s = mpmath.sqrt(sum((p + q) ** 2 for p, q in zip(a, b)))
    return 4 * mpmath.atan2(min(d, s), max(d, s))


def fmt(values):
    return "[%s]" % ", ".join(float(c).hex() if math.isfinite(float(c)) else repr(float(c)) for c in values)


def report(call, q_xyzw, got, want, err, what):
    bad = not (err <= LOOSE * EPS)  # NaN compares false
    print("  call:    %s" % call)
    print("  input:   %s" % q_xyzw)
    print("  library: %s" % got)
    print("  correct: %s (256-bit mpmath)" % want)
    print("  error:   %s = %s eps (%s; bar %d eps)%s" % (err, err / EPS, what, LOOSE, "  <-- DEFECT" if bad else ""))
    return bad


print("rotorcert reproducer: pytransform3d %s %s: norm_vector's unscaled np.linalg.norm overflows at 2^900: "
      "axis_angle_from_quaternion returns the identity, norm_vector 0, quaternion_slerp NaN" % (VERSION, CLAUSE))
shown = False

# 1. rotorcert's worst input (to_axis_angle, "non-unit scale 2^900"), stored (x, y, z, w).
q = [h(s) for s in ("-0x1.67d03980bdfc8p+898", "-0x1.65cb1935842a9p+896", "0x1.cfceb29e939c5p+896", "-0x1.b396ced2e7989p+900")]
Q = np.array([q[3], q[0], q[1], q[2]])
a = pr.axis_angle_from_quaternion(Q)
half = mpmath.mpf(float(a[3])) / 2
got_q = [mpmath.cos(half)] + [mpmath.sin(half) * mpmath.mpf(float(c)) for c in a[:3]]  # its rotation, (w, x, y, z)
err = metric1(got_q, Q) if all(map(math.isfinite, a)) else math.nan
W, X, Y, Z = (mpmath.mpf(c) for c in Q)
theta = 2 * mpmath.atan2(mpmath.sqrt(X * X + Y * Y + Z * Z), W)
shown |= report("pytransform3d.rotations.axis_angle_from_quaternion([w, x, y, z])  -> (x, y, z, angle)",
                "q (x, y, z, w) = " + fmt(q), "(axis, angle) = " + fmt(a),
                "the rotation of q/|q|: angle %s (or %s about the flipped axis, pytransform3d's [0, pi) range)"
                % (mpmath.nstr(theta, 12), mpmath.nstr(2 * mpmath.pi - theta, 12)),
                float(err), "METRIC-1 between the returned rotation and q's, in rad")

# 2. EX-NORM-1-f: (2^1023, 2^1023, 2^1023, 2^1023).
Q = np.array([h("0x1p+1023")] * 4)
got = pr.norm_vector(Q)
want = unit(Q)
err = max(abs(mpmath.mpf(float(g)) - r) for g, r in zip(got, want))
shown |= report("pytransform3d.rotations.norm_vector([w, x, y, z])", "q = [0x1p+1023, 0x1p+1023, 0x1p+1023, 0x1p+1023]",
                fmt(got), "q/|q| = " + fmt(want), float(err), "componentwise")

# 3. rotorcert's worst wrong status (slerp, "non-unit scale 2^900"), stored (x, y, z, w).
a_ = [h(s) for s in ("-0x1.3403fcfc92afcp+900", "0x1.010af362783c3p+900", "0x1.e71f6f04e1554p+899", "0x1.523fa08a49dd5p+899")]
b_ = [h(s) for s in ("0x1.04a75ab1f0414p+900", "-0x1.478cd13192e37p+900", "-0x1.0ebcce80eb769p+897", "0x1.0d3fc1d213899p+900")]
t = h("0x1.91c31624c3a08p-1")
A, B = np.array([a_[3]] + a_[:3]), np.array([b_[3]] + b_[:3])
got = pr.quaternion_slerp(A, B, t, shortest_path=True)
ua, ub = unit(A), unit(B)
if sum(p * q for p, q in zip(ua, ub)) < 0:
    ub = [-c for c in ub]
om = 2 * mpmath.atan2(mpmath.sqrt(sum((p - q) ** 2 for p, q in zip(ua, ub))), mpmath.sqrt(sum((p + q) ** 2 for p, q in zip(ua, ub))))
want = [(mpmath.sin((1 - t) * om) * p + mpmath.sin(t * om) * q) / mpmath.sin(om) for p, q in zip(ua, ub)]
err = metric1(got, want) if all(map(math.isfinite, got)) else math.nan
shown |= report("pytransform3d.rotations.quaternion_slerp(a, b, t, shortest_path=True)",
                "a (x, y, z, w) = %s, b = %s, t = %s" % (fmt(a_), fmt(b_), t.hex()),
                fmt(got) + ("  (all NaN: a refusal of valid input)" if all(map(math.isnan, got)) else ""),
                "slerp of a/|a|, b/|b| (w, x, y, z) = " + fmt(want), float(err), "METRIC-1")

print("DEFECT SHOWN" if shown else "DEFECT NOT SHOWN")
sys.exit(0 if shown else 1)
