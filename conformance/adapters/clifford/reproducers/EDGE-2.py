#!/usr/bin/env python3
"""rotorcert reproducer: clifford (pygae) clifford.tools.log_rotor at a small angle, clause EDGE-2.

EDGE-2 (spec/SPEC.md 9): angles from 1e-9 to 1e-3 give results within the operation's class, "no 0/0,
no NaN"; LOG-1: near v = 0 the factor atan2(|v|, w)/|v| MUST be evaluated without 0/0. tools.log_rotor
("Logarithm of a simple rotor") computes theta = arccos(<R>0) and returns <R>2 / sinc(theta) with
sinc(x) = sin(x)/x. For a unit rotor of angle ~2e-9 the scalar part rounds to exactly 1.0, so
theta = 0 and sinc(0) = 0/0: every coefficient of the result is NaN. (Below |<R>2| < 1e-12 it takes
the NameError branch of LOG-2 instead.)
Upstream: no matching issue found in pygae/clifford.
Exit 0: defect shown; 1: not shown (fixed); 77: clifford cannot be imported.
"""
import contextlib
import io
import math
import sys
import warnings

CLAUSE = "EDGE-2"
try:
    import clifford
    import clifford.tools
except Exception as exc:  # noqa: BLE001 - any import failure is a skip
    print("rotorcert reproducer: clifford ? %s: SKIP: cannot import clifford: %s" % (CLAUSE, exc))
    sys.exit(77)
warnings.simplefilter("ignore")  # numpy's 0/0 RuntimeWarning

# ---- independent reference: 60-digit decimal arithmetic (standard library only) -------------------
from decimal import Decimal as D, getcontext  # noqa: E402
getcontext().prec = 60
TINY = D(10) ** -70
def sincos(x):  # sin, cos of a Decimal by the Taylor series of e^(ix) (|x| < 10 here)
    s = c = D(0); t, n = D(1), 0
    while n < 2 or abs(t) > TINY:
        k = n % 4
        if k == 0: c += t
        elif k == 1: s += t
        elif k == 2: c -= t
        else: s -= t
        n += 1; t = t * x / n
    return s, c
def atan(x):  # halve the angle until |x| < 1/8, then the alternating series
    k = 0
    while abs(x) > D(1) / 8: x, k = x / (1 + (1 + x * x).sqrt()), k + 1
    s, p, n = D(0), x, 0
    while abs(p) > TINY: s, p, n = s + p / (2 * n + 1), -p * x * x, n + 1
    return s * 2 ** k
def atan2(y, x):
    r = (x * x + y * y).sqrt()
    if r == 0: return D(0)
    if x > 0: return 2 * atan(y / (r + x))
    return 4 * atan(D(1)) if y == 0 else 2 * atan((r - x) / y)
def norm(v): return sum(D(c) * D(c) for c in v).sqrt()
def dist(a, b):  # METRIC-1: 4 atan2(min(|a-b|,|a+b|), max(..)) of the normalised quaternions
    na, nb = norm(a), norm(b); a, b = [D(c) / na for c in a], [D(c) / nb for c in b]
    m, p = norm([x - y for x, y in zip(a, b)]), norm([x + y for x, y in zip(a, b)])
    return 4 * atan2(min(m, p), max(m, p))


# ---- conventions --------------------------------------------------------------------------------
# rotorcert Q2R-1, as conformance/adapters/clifford does it: quaternion (x, y, z, w) <-> rotor
# R = w - x e23 - y e31 - z e12; clifford.Cl(3) names e12, e13, e23 and e31 = -e13, so
# R = w - x*e23 + y*e13 - z*e12. A quaternion-view log v = (x, y, z) is the bivector
# -(x e23 + y e31 + z e12) = -x*e23 + y*e13 - z*e12, so back: x = -L[e23], y = +L[e13], z = -L[e12].
layout, blades = clifford.Cl(3)
e12, e13, e23 = blades["e12"], blades["e13"], blades["e23"]

EPS = 2.0 ** -52
LOOSE = 256  # eps16 loose bar (spec/clauses.json)
q = [0.0, 0.0, float.fromhex("0x1.12e0be826d695p-30"), 1.0]  # (x, y, z, w): |q| = 1 to within 1e-18

print("rotorcert reproducer: clifford %s %s: clifford.tools.log_rotor of a unit rotor of angle 2e-9 "
      "returns all NaN (arccos(1) = 0, then sin(0)/0)" % (clifford.__version__, CLAUSE))
R = q[3] - q[0] * e23 + q[1] * e13 - q[2] * e12
printed = io.StringIO()
try:
    with contextlib.redirect_stdout(printed):  # log_rotor may print() its argument
        L = clifford.tools.log_rotor(R)
    got = [-float(L[(2, 3)]), float(L[(1, 3)]), -float(L[(1, 2)])]
    result = "[%s]" % ", ".join(c.hex() for c in got)
except Exception as exc:  # noqa: BLE001 - an exception is the defect too
    got, result = [math.nan] * 3, "raised %s: %s" % (type(exc).__name__, exc)
v = [D(c) for c in q[:3]]
nv = norm(v)
ref = [c / nv * atan2(nv, D(q[3])) for c in v]  # LOG-1: atan2(|v|, w) v/|v|
err = norm([D(g) - r for g, r in zip(got, ref)]) if all(math.isfinite(g) for g in got) else None
bad = err is None or not (err <= LOOSE * D(EPS))
print("  call:    clifford.tools.log_rotor(R), R = w - x*e23 + y*e13 - z*e12")
print("  input:   q (x, y, z, w) = [%s]" % ", ".join(c.hex() for c in q))
print("  library: %s" % result)
print("  correct: [%s]  atan2(|v|, w) v/|v| at 60 digits" % ", ".join(float(c).hex() for c in ref))
print("  error:   %s (METRIC-5, radians; bar %d eps)%s"
      % ("NaN" if err is None else "%.3e = %.4g eps" % (err, err / D(EPS)), LOOSE, "  <-- DEFECT" if bad else ""))
print("DEFECT SHOWN" if bad else "DEFECT NOT SHOWN")
sys.exit(0 if bad else 1)
