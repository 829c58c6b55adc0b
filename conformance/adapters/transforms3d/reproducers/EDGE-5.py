#!/usr/bin/env python3
"""rotorcert reproducer: transforms3d quaternion functions at non-unit scales, clause EDGE-5.

EDGE-5 (spec/SPEC.md 9): a finite nonzero q means the rotation q/|q| at every scale the format holds, and
unit-valued outputs stay unit (class eps16, loose bar 256 eps). transforms3d 0.4.2 squares without scaling
and has absolute thresholds on |q|^2:
  - qnorm(q) = np.sqrt(np.dot(q, q)) (quaternions.py:279) underflows to 0 for |q| below ~1e-154 and
    overflows to inf above ~1e154, so its normalisation q / qnorm(q) -- the one rotate_vector(...,
    is_normalized=False) uses (quaternions.py:440) -- gives inf/nan at 2^-999 and a spurious all-NaN
    result (DOMAIN_ERROR) from rotate_vector at 2^-900;
  - quat2mat ("The algorithm here allows quaternions that have not been normalized") returns the identity
    whenever w^2 + x^2 + y^2 + z^2 < eps (quaternions.py:131-132), i.e. for every quaternion shorter than
    1.5e-8, whatever rotation it represents, and also when the sum overflows (s = 2/inf = 0);
  - quat2axangle returns the identity below |q|^2 < eps^2 (quaternions.py:577-578); qinverse,
    axangle2quat (axis norm) and qlog overflow or underflow the same way.
None of this is documented.
Upstream: no matching issue found in matthew-brett/transforms3d.
Exit 0: defect shown; 1: not shown (fixed); 77: transforms3d cannot be imported.
"""
import math
import sys

CLAUSE = "EDGE-5"
try:
    from importlib.metadata import version
    import numpy as np
    import mpmath
    from transforms3d import quaternions as tq
    VERSION = version("transforms3d")
except Exception as exc:  # noqa: BLE001 - any import failure is a skip
    print("rotorcert reproducer: transforms3d ? %s: SKIP: cannot import transforms3d: %s" % (CLAUSE, exc))
    sys.exit(77)

np.seterr(all="ignore")  # numpy's warnings only; the values are the same
mpmath.mp.prec = 256
EPS = 2.0 ** -52
LOOSE = 256  # eps16 loose bar (spec/clauses.json)
h = float.fromhex


def unit(q):
    """q/|q| in 256-bit mpmath, any order."""
    m = [mpmath.mpf(c) for c in q]
    n = mpmath.sqrt(sum(c * c for c in m))
    return [c / n for c in m]


def matrix(wxyz):
    """The rotation matrix of q/|q| (rows), 256-bit mpmath: products of binary64 values are exact there."""
    w, x, y, z = (mpmath.mpf(c) for c in wxyz)
    s = 2 / (w * w + x * x + y * y + z * z)
    return [[1 - s * (y * y + z * z), s * (x * y - w * z), s * (x * z + w * y)],
            [s * (x * y + w * z), 1 - s * (x * x + z * z), s * (y * z - w * x)],
            [s * (x * z - w * y), s * (y * z + w * x), 1 - s * (x * x + y * y)]]


def fmt(values):
    return "[%s]" % ", ".join(float(c).hex() for c in values)


def report(call, q_xyzw, got, want, err, what):
    bad = not (err <= LOOSE * EPS)  # NaN compares false: a NaN output is a defect
    print("  call:    %s" % call)
    print("  input:   q (x, y, z, w) = %s" % fmt(q_xyzw))
    print("  library: %s" % got)
    print("  correct: %s (256-bit mpmath)" % want)
    print("  error:   %s = %s eps (%s; bar %d eps)%s" % (err, err / EPS, what, LOOSE, "  <-- DEFECT" if bad else ""))
    return bad


print("rotorcert reproducer: transforms3d %s %s: qnorm under/overflows and quat2mat returns the identity for "
      "|q| < 1.5e-8: non-unit quaternions lose their rotation" % (VERSION, CLAUSE))
shown = False

# 1. EX-NORM-1-h, rotorcert's worst input: q = (x, y, z, w) = (1.5 2^-999, 0, 0, 2^-998) = 2^-998 (0.75, 0, 0, 1).
q = [h("0x1.8p-999"), 0.0, 0.0, h("0x1p-998")]
Q = np.array([q[3], q[0], q[1], q[2]])
n = tq.qnorm(Q)
got = Q / n
want = unit(Q)
err = max(abs(mpmath.mpf(float(g)) - r) for g, r in zip(got, want)) if all(map(math.isfinite, got)) else math.nan
print("  (qnorm(q) = %s for this nonzero q)" % float(n).hex())
shown |= report("Q = [w, x, y, z]; Q / transforms3d.quaternions.qnorm(Q)", q,
                "(w, x, y, z) = " + fmt(got), "q/|q| (w, x, y, z) = " + fmt(want), float(err), "componentwise")

# 2. quat2mat of a quaternion of norm 2^-30 (w = 0.6, x = 0.8, times 2^-30: a turn of 106 degrees about x):
#    |q|^2 = 2^-60 < eps = 2^-52.
q = [0.8 * 2.0 ** -30, 0.0, 0.0, 0.6 * 2.0 ** -30]
Q = np.array([q[3], q[0], q[1], q[2]])
M = tq.quat2mat(Q)
R = matrix(Q)
err = max(abs(mpmath.mpf(float(M[r][c])) - R[r][c]) for r in range(3) for c in range(3))
shown |= report("transforms3d.quaternions.quat2mat([w, x, y, z])", q,
                "rows %s" % [fmt(row) for row in M], "rows %s" % [fmt(row) for row in R], float(err), "METRIC-4, max |entry|")

# 3. rotate_vector with its own normalisation, rotorcert's worst input with a wrong status (2^-900 scale).
q = [h("0x1.3244838b60a13p-901"), h("-0x1.b618f58c183a7p-905"), h("-0x1.6aae7a98037c3p-901"), h("0x1.4933c5eea6375p-901")]
v = [h("0x1.5b785e94370dfp+7"), h("-0x1.e92b7413616c9p+5"), h("0x1.142ac83ae301dp+6")]
Q = np.array([q[3], q[0], q[1], q[2]])
got = tq.rotate_vector(np.array(v), Q, is_normalized=False)
R = matrix(Q)
want = [sum(R[r][c] * mpmath.mpf(v[c]) for c in range(3)) for r in range(3)]
nv = mpmath.sqrt(sum(mpmath.mpf(c) ** 2 for c in v))
err = (mpmath.sqrt(sum((mpmath.mpf(float(g)) - w) ** 2 for g, w in zip(got, want))) / nv
       if all(map(math.isfinite, got)) else math.nan)
print("  v = %s" % fmt(v))
shown |= report("transforms3d.quaternions.rotate_vector(v, [w, x, y, z], is_normalized=False)", q,
                fmt(got) + ("  (all NaN: a spurious refusal)" if all(map(math.isnan, got)) else ""),
                "R(q/|q|) v = " + fmt(want), float(err), "METRIC-3, relative to |v|")

print("DEFECT SHOWN" if shown else "DEFECT NOT SHOWN")
sys.exit(0 if shown else 1)
