#!/usr/bin/env python3
"""rotorcert reproducer: pyquaternion Quaternion.slerp of a near-antipodal pair, clause SLERP-2.

SLERP-2 (spec/SPEC.md 8.2): the rotor interpolation exp(t log(R_B ~R_A)) R_A with the hemisphere flip
equals slerp(a, b, t) for every t (class eps16, METRIC-1, loose bar 256 eps). For a near-antipodal pair
(a.b close to -1) pyquaternion's Quaternion.slerp negates its first argument (in place,
pyquaternion/quaternion.py:881-883), after which the dot product exceeds 0.9995 and the result is
normalise(a' + t (b - a')) (quaternion.py:886-889), a normalised lerp instead of slerp: 6.4e-7 rad
(2.9e9 eps) from the rotor interpolation here. Same root cause as SLERP-1.
Upstream: KieranWynn/pyquaternion#24 / PR #31 introduced this implementation; no issue reports the
lerp branch itself.
Exit 0: defect shown; 1: not shown (fixed); 77: pyquaternion cannot be imported.
"""
import sys

CLAUSE = "SLERP-2"
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

SUMMARY = ("Quaternion.slerp of a near-antipodal pair flips a, then takes its normalised-lerp branch: "
           "2.9e9 eps off the rotor interpolation")
A = ["0x1.966d5214e2b4fp-1", "-0x1.9159470f6aef3p-2", "0x1.7e530a01ed29ap-2", "-0x1.1be2efc6729dcp-2"]
B = ["-0x1.9028235faf5c1p-1", "0x1.a99b2c3eedb3p-2", "-0x1.820ac977924eap-2", "0x1.171d6167a7f7ap-2"]
T = "0x1.d7dd4e8f2225ep-3"

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

