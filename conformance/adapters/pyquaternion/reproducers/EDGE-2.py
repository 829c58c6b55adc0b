#!/usr/bin/env python3
"""rotorcert reproducer: pyquaternion Quaternion.log of a small rotation returns 0, clause EDGE-2.

EDGE-2 (spec/SPEC.md 9): for rotation angles of 1e-9 .. 1e-3 rad the result is within the operation's
class (LOG-1: eps16, METRIC-5, loose bar 256 eps); "acos-based angles fail here". pyquaternion's
Quaternion.log (pyquaternion/quaternion.py:688) computes acos(w/|q|): for a rotation of 2.8e-8 rad,
w/|q| rounds to exactly 1.0 and the log comes out as the zero vector instead of (theta/2) u of length
1.4e-8 (6.1e7 eps). Same root cause as LOG-1; atan2(|v|, w) v/|v| keeps every digit.
(Slerp's small-angle errors in this clause come from its normalised-lerp branch: see SLERP-1.py.)
Upstream: no matching issue found in KieranWynn/pyquaternion.
Exit 0: defect shown; 1: not shown (fixed); 77: pyquaternion cannot be imported.
"""
import sys

CLAUSE = "EDGE-2"
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
x, y, z, w = (h("-0x1.970f0a062d178p-27"), h("0x1.d029ec0b0ce76p-31"), h("-0x1.ce8d81387e9d6p-28"), h("0x1.fffffffffffffp-1"))

print("rotorcert reproducer: pyquaternion %s %s: Quaternion.log of a 2.8e-8 rad rotation is the zero "
      "vector (acos(w/|q|) with w/|q| rounded to 1)" % (VERSION, CLAUSE))
got = list(Quaternion.log(Quaternion(w, x, y, z)).vector)
v = [D(x), D(y), D(z)]
nv = dnorm(v)
ref = [c * datan2(nv, D(w)) / nv for c in v]  # atan2(|v|, w) v/|v|, 60 digits
err = float(dnorm([D(g) - r for g, r in zip(got, ref)]))
bad = not (err <= LOOSE * EPS)
print("  call:    Quaternion.log(Quaternion(w, x, y, z)).vector")
print("  input:   q (x, y, z, w) = [%s]" % ", ".join(c.hex() for c in (x, y, z, w)))
print("  library: [%s]" % ", ".join(c.hex() for c in got))
print("  correct: [%s] = [%s]  (atan2(|v|, w) v/|v|, 60 digits)" % (", ".join(float(c).hex() for c in ref), ", ".join("%.15g" % float(c) for c in ref)))
print("  error:   %.3g rad = %.3g eps (METRIC-5; bar %d eps)%s" % (err, err / EPS, LOOSE, "  <-- DEFECT" if bad else ""))
print("DEFECT SHOWN" if bad else "DEFECT NOT SHOWN")
sys.exit(0 if bad else 1)
