#!/usr/bin/env python3
"""rotorcert reproducer: pyquaternion Quaternion.slerp is a normalised lerp for close pairs, clause SLERP-1.

SLERP-1 (spec/SPEC.md 8.2): slerp(a, b, t) = (sin((1 - t) W) a + sin(t W) b') / sin W, constant angular
velocity on the shorter arc, for every pair including near-identical ones (class eps16: METRIC-1,
loose bar 256 eps; "as W -> 0 the result MUST tend to a without 0/0"). pyquaternion's Quaternion.slerp
(pyquaternion/quaternion.py:886-889, taken from Wikipedia's sample code in PR #31) returns
normalise(a + t (b - a)) whenever the dot product exceeds 0.9995, i.e. for every pair less than
2 acos(0.9995) = 0.063 rad of rotation apart: that is nlerp, not slerp, and misses the slerp point by up
to ~1e-6 rad (here 8.4e-7 rad = 3.8e9 eps), with the non-constant speed of nlerp. The docstring
promises "a specified distance along the minor arc of a great circle". sin(tW)/sin(W) needs no such
branch when W comes from atan2 (or from a series).
Upstream: KieranWynn/pyquaternion#24 ("Bug in Slerp Interpolation") led to PR #31, which introduced
this implementation; no issue reports the lerp branch itself.
Exit 0: defect shown; 1: not shown (fixed); 77: pyquaternion cannot be imported.
"""
import sys

CLAUSE = "SLERP-1"
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

SUMMARY = ("Quaternion.slerp of a pair 0.03 rad apart is a normalised lerp (its dot > 0.9995 branch), "
           "3.8e9 eps off the slerp point")
A = ["0x1.b2b4ed0c8b8ffp-3", "-0x1.cfdcd603e3ebbp-7", "0x1.44c04e1f5a53ap-2", "0x1.d93253b2ff66p-1"]
B = ["0x1.83b6d09d9e97bp-3", "-0x1.2d857e1c762e1p-7", "0x1.34b747cb9dd6ap-2", "0x1.de6f6c0b895c8p-1"]
T = "0x1.585c370a5be32p-3"

EPS = 2.0 ** -52
LOOSE = 256  # eps16 loose bar (spec/clauses.json)
h = float.fromhex
a = [h(s) for s in A]  # (x, y, z, w), as rotorcert's vectors store them
b = [h(s) for s in B]
t = h(T)


def slerp_reference(a, b, t):
    """SLERP-1 at 60 digits: a, b normalised; b' = -b iff a.b < 0; (sin((1-t)W) a + sin(tW) b') / sin W."""
    a = [D(c) / dnorm([D(c) for c in a]) for c in a]
    b = [D(c) / dnorm([D(c) for c in b]) for c in b]
    if sum(p * q for p, q in zip(a, b)) < 0:
        b = [-c for c in b]
    W = 2 * datan2(dnorm([p - q for p, q in zip(a, b)]), dnorm([p + q for p, q in zip(a, b)]))
    t = D(t)
    return [(dsin((1 - t) * W) * p + dsin(t * W) * q) / dsin(W) for p, q in zip(a, b)]


print("rotorcert reproducer: pyquaternion %s %s: %s" % (VERSION, CLAUSE, SUMMARY))
A_, B_ = Quaternion(a[3], a[0], a[1], a[2]), Quaternion(b[3], b[0], b[1], b[2])
dot = A_.q @ B_.q
r = Quaternion.slerp(A_, B_, amount=t)
got = [r.x, r.y, r.z, r.w]
ref = slerp_reference(a, b, t)
err = float(rotation_distance([D(c) for c in got], ref))
bad = not (err <= LOOSE * EPS)
print("  call:    Quaternion.slerp(Quaternion(aw, ax, ay, az), Quaternion(bw, bx, by, bz), amount=t)")
print("  input:   a (x, y, z, w) = [%s]" % ", ".join(c.hex() for c in a))
print("           b (x, y, z, w) = [%s]" % ", ".join(c.hex() for c in b))
print("           t = %s   (a.b = %.17g: |a.b| > 0.9995 takes the normalised-lerp branch)" % (t.hex(), dot))
print("  library: (x, y, z, w) = [%s]" % ", ".join("%.17g" % c for c in got))
print("  correct: (x, y, z, w) = [%s]  (slerp, 60 digits)" % ", ".join("%.17g" % float(c) for c in ref))
print("  error:   %.3g rad = %.3g eps (METRIC-1 rotation distance; bar %d eps)%s" % (err, err / EPS, LOOSE, "  <-- DEFECT" if bad else ""))
print("DEFECT SHOWN" if bad else "DEFECT NOT SHOWN")
sys.exit(0 if bad else 1)

