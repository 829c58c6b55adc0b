#!/usr/bin/env python3
"""rotorcert reproducer: pyquaternion Quaternion.exp(Quaternion.log(q)) != q, clause EXP-2.

EXP-2 (spec/SPEC.md 8.2): exp(log R) = R for every unit R, including w < 0 (class eps16: METRIC-1, the
rotation angle between exp(log q) and q, loose bar 256 eps). pyquaternion's Quaternion.log takes the
angle as acos(w/|q|) (pyquaternion/quaternion.py:688); near w/|q| = -1 acos loses half the digits, so
the round trip through its own Quaternion.exp comes back 3.1e-8 rad (1.4e8 eps) away from q. Same root
cause as LOG-1 (atan2(|v|, w) would keep every digit).
Upstream: no matching issue found in KieranWynn/pyquaternion.
Exit 0: defect shown; 1: not shown (fixed); 77: pyquaternion cannot be imported.
"""
import sys

CLAUSE = "EXP-2"
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
x, y, z, w = (h("0x1.ed1af5cf74d79p-28"), h("-0x1.e93ee2f4806bp-28"), h("-0x1.9dd6dc9667343p-27"), h("-0x1.fffffffffffffp-1"))

print("rotorcert reproducer: pyquaternion %s %s: Quaternion.exp(Quaternion.log(q)) misses q by 1.4e8 eps "
      "near a full turn (the acos in Quaternion.log)" % (VERSION, CLAUSE))
r = Quaternion.exp(Quaternion.log(Quaternion(w, x, y, z)))
got = [r.x, r.y, r.z, r.w]
err = float(rotation_distance([D(c) for c in got], [D(c) for c in (x, y, z, w)]))
bad = not (err <= LOOSE * EPS)
print("  call:    Quaternion.exp(Quaternion.log(Quaternion(w, x, y, z)))")
print("  input:   q (x, y, z, w) = [%s]" % ", ".join(c.hex() for c in (x, y, z, w)))
print("  library: (x, y, z, w) = [%s] = [%s]" % (", ".join(c.hex() for c in got), ", ".join("%.15g" % c for c in got)))
print("  correct: q itself = [%s]" % ", ".join("%.15g" % c for c in (x, y, z, w)))
print("  error:   %.3g rad = %.3g eps (METRIC-1 rotation distance, 60 digits; bar %d eps)%s" % (err, err / EPS, LOOSE, "  <-- DEFECT" if bad else ""))
print("DEFECT SHOWN" if bad else "DEFECT NOT SHOWN")
sys.exit(0 if bad else 1)
