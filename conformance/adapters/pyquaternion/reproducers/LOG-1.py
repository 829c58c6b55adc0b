#!/usr/bin/env python3
"""rotorcert reproducer: pyquaternion Quaternion.log near a full turn, clause LOG-1.

LOG-1 (spec/SPEC.md 8.2): log q = atan2(|v|, w) v/|v| = (theta/2) u, the principal branch, also for
w < 0 (class eps16: METRIC-5, the Euclidean error of the three coefficients, loose bar 256 eps).
pyquaternion's Quaternion.log (pyquaternion/quaternion.py:688, docs/index.md:439:
"log(q) := (log(|q|), v/|v|acos(w/|q|))") takes the angle as acos(w/|q|). Near w/|q| = -1 (a rotation
a little short of a full turn) acos has an infinite derivative: the rounding of w/|q| (|q| itself is
rounded) moves the result by ~sqrt(eps), here 1.4e-8 rad = 6.4e7 eps. atan2(|v|, w) has no such loss.
(The vector part of pyquaternion's quaternion logarithm is the spec's quaternion-view log; the scalar
part log|q| is not part of it.)
Upstream: no matching issue found in KieranWynn/pyquaternion.
Exit 0: defect shown; 1: not shown (fixed); 77: pyquaternion cannot be imported.
"""
import sys

CLAUSE = "LOG-1"
try:
    from importlib.metadata import version
    from pyquaternion import Quaternion
    VERSION = version("pyquaternion")
except Exception as exc:  # noqa: BLE001 - any import failure is a skip
    print("rotorcert reproducer: pyquaternion ? %s: SKIP: cannot import pyquaternion: %s" % (CLAUSE, exc))
    sys.exit(77)

# --- 60-digit reference arithmetic (standard library decimal; inputs converted exactly) -----------
from decimal import Decimal as D, getcontext
getcontext().prec = 60


def _atan_small(x):  # |x| <= 1/8: Taylor series
    s, term, n, x2 = D(0), x, 1, x * x
    while abs(term) > D(10) ** -70:
        s += term / n
        term, n = -term * x2, n + 2
    return s


def datan(x):
    k = 0
    while abs(x) > D(1) / 8:  # atan(x) = 2 atan(x / (1 + sqrt(1 + x^2)))
        x, k = x / (1 + (1 + x * x).sqrt()), k + 1
    return _atan_small(x) * 2 ** k


PI = 16 * datan(D(1) / 5) - 4 * datan(D(1) / 239)


def datan2(y, x):
    if x > 0:
        return datan(y / x)
    if x < 0:
        return datan(y / x) + (PI if y >= 0 else -PI)
    return PI / 2 if y > 0 else -PI / 2 if y < 0 else D(0)


def dsin(x):
    s, term, n = D(0), x, 1
    while abs(term) > D(10) ** -70:
        s += term
        term, n = -term * x * x / ((n + 1) * (n + 2)), n + 2
    return s


def dcos(x):
    return dsin(PI / 2 - x)


def dnorm(v):
    return sum(c * c for c in v).sqrt()


def rotation_distance(a, b):
    """METRIC-1: 4 atan2(min(|a-b|, |a+b|), max(...)) of the normalised quaternions, radians."""
    a = [c / dnorm(a) for c in a]
    b = [c / dnorm(b) for c in b]
    m = dnorm([x - y for x, y in zip(a, b)])
    p = dnorm([x + y for x, y in zip(a, b)])
    return 4 * datan2(min(m, p), max(m, p))

EPS = 2.0 ** -52
LOOSE = 256  # eps16 loose bar (spec/clauses.json)
h = float.fromhex
# (x, y, z, w), as rotorcert's vectors store it; pyquaternion takes Quaternion(w, x, y, z)
x, y, z, w = (h("-0x1.a84342447b0abp-27"), h("-0x1.a211ea065eb7dp-28"), h("-0x1.af698e602caa4p-29"), h("-0x1.fffffffffffffp-1"))

print("rotorcert reproducer: pyquaternion %s %s: Quaternion.log computes the angle as acos(w/|q|) and "
      "loses half the digits near a full turn (w/|q| close to -1)" % (VERSION, CLAUSE))
got = list(Quaternion.log(Quaternion(w, x, y, z)).vector)
v = [D(x), D(y), D(z)]
nv = dnorm(v)
ref = [c * datan2(nv, D(w)) / nv for c in v]  # atan2(|v|, w) v/|v|, 60 digits
err = float(dnorm([D(g) - r for g, r in zip(got, ref)]))
bad = not (err <= LOOSE * EPS)
print("  call:    Quaternion.log(Quaternion(w, x, y, z)).vector")
print("  input:   q (x, y, z, w) = [%s]" % ", ".join(c.hex() for c in (x, y, z, w)))
print("  library: [%s] = [%s]" % (", ".join(c.hex() for c in got), ", ".join("%.15g" % c for c in got)))
print("  correct: [%s] = [%s]  (atan2(|v|, w) v/|v|, 60 digits)" % (", ".join(float(c).hex() for c in ref), ", ".join("%.15g" % float(c) for c in ref)))
print("  error:   %.3g rad = %.3g eps (METRIC-5; bar %d eps)%s" % (err, err / EPS, LOOSE, "  <-- DEFECT" if bad else ""))
print("DEFECT SHOWN" if bad else "DEFECT NOT SHOWN")
sys.exit(0 if bad else 1)
