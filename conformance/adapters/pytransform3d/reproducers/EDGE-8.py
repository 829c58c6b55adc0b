#!/usr/bin/env python3
"""rotorcert reproducer: pytransform3d functions of subnormal quaternions, clause EDGE-8.

EDGE-8 (spec/SPEC.md 9): subnormal components are ordinary nonzero values: normalize((2^-1074, -0, 0, 0))
= (1, -0, 0, 0); "an implementation that flushes them to zero and reports DOMAIN_ERROR fails" (class eps4,
or the op's own class where looser). pytransform3d 3.17.0 normalises with norm_vector (rotations/_utils.py:
43-47): np.linalg.norm(v), unscaled, underflows to 0 for a subnormal quaternion, and norm_vector then
returns the input unchanged (its zero-vector branch). So norm_vector((2^-1074, 0, 0, 0)) is not unit,
matrix_from_quaternion of a subnormal q is the identity whatever rotation q represents (rotorcert's worst
input), and quaternion_slerp of subnormal inputs returns all NaN (angle_between_vectors divides by the
zero norm), a refusal of valid input.
Upstream: no matching issue found in dfki-ric/pytransform3d.
Exit 0: defect shown; 1: not shown (fixed); 77: pytransform3d cannot be imported.
"""
import math
import sys

CLAUSE = "EDGE-8"
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
BARS = {"normalize": 64, "to_matrix": 128, "slerp": 256}  # eps4, or the op's class where looser
h = float.fromhex


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


def report(op, call, inp, got, want, err, what):
    bar = BARS[op]
    bad = not (err <= bar * EPS)  # NaN compares false
    print("  call:    %s" % call)
    print("  input:   %s" % inp)
    print("  library: %s" % got)
    print("  correct: %s (256-bit mpmath)" % want)
    print("  error:   %s = %s eps (%s; bar %d eps)%s" % (err, err / EPS, what, bar, "  <-- DEFECT" if bad else ""))
    return bad


print("rotorcert reproducer: pytransform3d %s %s: np.linalg.norm of a subnormal quaternion is 0: norm_vector "
      "returns it unnormalised, matrix_from_quaternion the identity, quaternion_slerp NaN" % (VERSION, CLAUSE))
shown = False

# 1. rotorcert's worst input (to_matrix, "subnormal and -0 components"), stored (x, y, z, w).
q = [h(s) for s in ("0x0.0000000001p-1022", "0x0.0000000000002p-1022", "0x0.00000000003p-1022", "-0x0p+0")]
Q = np.array([q[3], q[0], q[1], q[2]])
M = pr.matrix_from_quaternion(Q)
R = matrix(Q)
err = max(abs(mpmath.mpf(float(M[r][c])) - R[r][c]) for r in range(3) for c in range(3))
shown |= report("to_matrix", "pytransform3d.rotations.matrix_from_quaternion([w, x, y, z])", "q (x, y, z, w) = " + fmt(q),
                "rows %s" % [fmt(row) for row in M], "rows %s" % [fmt(row) for row in R], float(err), "METRIC-4, max |entry|")

# 2. EX-EDGE-8-a: (x, y, z, w) = (2^-1074, -0, 0, 0).
q = [h("0x0.0000000000001p-1022"), -0.0, 0.0, 0.0]
Q = np.array([q[3], q[0], q[1], q[2]])
got = pr.norm_vector(Q)
want = unit(Q)
err = max(abs(mpmath.mpf(float(g)) - r) for g, r in zip(got, want))
shown |= report("normalize", "pytransform3d.rotations.norm_vector([w, x, y, z])", "q (x, y, z, w) = " + fmt(q),
                "(w, x, y, z) = " + fmt(got), "q/|q| = " + fmt(want), float(err), "componentwise")

# 3. rotorcert's worst wrong status (slerp, "subnormal and -0 components"), stored (x, y, z, w).
a_ = [h(s) for s in ("-0x0p+0", "0x0.0000000000038p-1022", "0x0.00000000000cp-1022", "0x0.00000000002p-1022")]
b_ = [h(s) for s in ("-0x0p+0", "0x0.00000000005p-1022", "0x0.0000000000002p-1022", "0x0.00000000008p-1022")]
t = h("0x1.2e4718fe44ed9p-1")
got = pr.quaternion_slerp(np.array([a_[3]] + a_[:3]), np.array([b_[3]] + b_[:3]), t, shortest_path=True)
ua, ub = unit([a_[3]] + a_[:3]), unit([b_[3]] + b_[:3])
if sum(p * r for p, r in zip(ua, ub)) < 0:
    ub = [-c for c in ub]
om = 2 * mpmath.atan2(mpmath.sqrt(sum((p - r) ** 2 for p, r in zip(ua, ub))), mpmath.sqrt(sum((p + r) ** 2 for p, r in zip(ua, ub))))
want = [(mpmath.sin((1 - t) * om) * p + mpmath.sin(t * om) * r) / mpmath.sin(om) for p, r in zip(ua, ub)]
if all(map(math.isfinite, got)):
    g = unit(got)
    d = mpmath.sqrt(sum((p - r) ** 2 for p, r in zip(g, want)))
    s = mpmath.sqrt(sum((p + r) ** 2 for p, r in zip(g, want)))
    err = 4 * mpmath.atan2(min(d, s), max(d, s))
else:
    err = math.nan
shown |= report("slerp", "pytransform3d.rotations.quaternion_slerp(a, b, t, shortest_path=True)",
                "a (x, y, z, w) = %s, b = %s, t = %s" % (fmt(a_), fmt(b_), t.hex()),
                fmt(got) + ("  (all NaN: a refusal of valid input)" if all(map(math.isnan, got)) else ""),
                "slerp of a/|a|, b/|b| (w, x, y, z) = " + fmt(want), float(err), "METRIC-1")

print("DEFECT SHOWN" if shown else "DEFECT NOT SHOWN")
sys.exit(0 if shown else 1)
