#!/usr/bin/env python3
"""rotorcert reproducer: transforms3d quaternion functions of subnormal quaternions, clause EDGE-8.

EDGE-8 (spec/SPEC.md 9): subnormal components are ordinary nonzero values: normalize((2^-1074, -0, 0, 0))
= (1, -0, 0, 0); "an implementation that flushes them to zero and reports DOMAIN_ERROR fails" (class eps4,
or the op's own class where looser). transforms3d 0.4.2 squares without scaling:
  - qnorm(q) = np.sqrt(np.dot(q, q)) (quaternions.py:279) is 0 for a subnormal q, so its normalisation
    q / qnorm(q) (quaternions.py:440) gives inf/nan (rotorcert's worst input, EX-EDGE-8-a) and
    rotate_vector(v, q, is_normalized=False) returns all NaN, a refusal of a valid rotation (EX-EDGE-8-f:
    q = 2^-1074 (1 + k), a quarter turn about z, should send (1, 0, 0) to (0, 1, 0));
  - quat2mat of the same q returns the identity (|q|^2 = 0 < eps, quaternions.py:131-132).
Upstream: no matching issue found in matthew-brett/transforms3d.
Exit 0: defect shown; 1: not shown (fixed); 77: transforms3d cannot be imported.
"""
import math
import sys

CLAUSE = "EDGE-8"
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
TINY = float.fromhex("0x0.0000000000001p-1022")  # 2^-1074
BARS = {"normalize": 64, "apply_vector": 128, "to_matrix": 128}  # the op's class where looser than eps4


def unit(q):
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
    return "[%s]" % ", ".join(float(c).hex() if math.isfinite(float(c)) else repr(float(c)) for c in values)


def report(op, call, q_xyzw, got, want, err, what):
    bar = BARS[op]
    bad = not (err <= bar * EPS)  # NaN compares false
    print("  call:    %s" % call)
    print("  input:   q (x, y, z, w) = %s" % fmt(q_xyzw))
    print("  library: %s" % got)
    print("  correct: %s (256-bit mpmath)" % want)
    print("  error:   %s = %s eps (%s; bar %d eps)%s" % (err, err / EPS, what, bar, "  <-- DEFECT" if bad else ""))
    return bad


print("rotorcert reproducer: transforms3d %s %s: qnorm of a subnormal quaternion is 0: its normalisation gives "
      "inf/nan, rotate_vector refuses, quat2mat returns the identity" % (VERSION, CLAUSE))
shown = False

# 1. EX-EDGE-8-a: (x, y, z, w) = (2^-1074, -0, 0, 0).
q = [TINY, -0.0, 0.0, 0.0]
Q = np.array([q[3], q[0], q[1], q[2]])
got = Q / tq.qnorm(Q)
want = unit(Q)
err = max(abs(mpmath.mpf(float(g)) - r) for g, r in zip(got, want)) if all(map(math.isfinite, got)) else math.nan
shown |= report("normalize", "Q = [w, x, y, z]; Q / transforms3d.quaternions.qnorm(Q)", q,
                "(w, x, y, z) = %s (qnorm(Q) = %s)" % (fmt(got), float(tq.qnorm(Q)).hex()),
                "q/|q| (w, x, y, z) = " + fmt(want), float(err), "componentwise")

# 2. EX-EDGE-8-f: (x, y, z, w) = (0, 0, 2^-1074, 2^-1074), a quarter turn about z; v = (1, 0, 0).
q = [0.0, 0.0, TINY, TINY]
Q = np.array([q[3], q[0], q[1], q[2]])
v = [1.0, 0.0, 0.0]
got = tq.rotate_vector(np.array(v), Q, is_normalized=False)
R = matrix(Q)
want = [sum(R[r][c] * mpmath.mpf(v[c]) for c in range(3)) for r in range(3)]
err = (mpmath.sqrt(sum((mpmath.mpf(float(g)) - w) ** 2 for g, w in zip(got, want)))
       if all(map(math.isfinite, got)) else math.nan)
shown |= report("apply_vector", "transforms3d.quaternions.rotate_vector([1, 0, 0], [w, x, y, z], is_normalized=False)", q,
                fmt(got) + ("  (all NaN: a spurious refusal)" if all(map(math.isnan, got)) else ""),
                "R(q/|q|) v = " + fmt(want), float(err), "METRIC-3, relative to |v| = 1")

# 3. quat2mat of the same quaternion.
M = tq.quat2mat(Q)
err = max(abs(mpmath.mpf(float(M[r][c])) - R[r][c]) for r in range(3) for c in range(3))
shown |= report("to_matrix", "transforms3d.quaternions.quat2mat([w, x, y, z])", q,
                "rows %s" % [fmt(row) for row in M], "rows %s" % [fmt(row) for row in R], float(err),
                "METRIC-4, max |entry|")

print("DEFECT SHOWN" if shown else "DEFECT NOT SHOWN")
sys.exit(0 if shown else 1)
