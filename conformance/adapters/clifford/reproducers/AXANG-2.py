#!/usr/bin/env python3
"""rotorcert reproducer: clifford (pygae) rotor from angle and axis, exp(-(angle/2) I u/|u|), clause AXANG-2.

AXANG-2 (spec/SPEC.md 7/8.1): the quaternion of angle theta about axis u is (sin(theta/2) u/|u|,
cos(theta/2)), tolerance eps16 (loose bar 256 eps). clifford has no axis-angle constructor; its
documented idiom is R = e^(-theta/2 B^) with the unit plane B^ = I u/|u| (clifford's tutorial
docs/tutorials/g3-algebra-of-space.ipynb, "Rotation"). MultiVector.exp() is the Taylor series
of clifford.taylor_expansions.exp (stops when a term is < 1e-12, at most 14 terms, then squarings),
so an ordinary rotation (here theta = 2pi/3 rounded, about (1, 1, 1): nearly (1, 1, 1, 1)/2) comes
out ~7.6e3 eps off in angle (METRIC-1) and ~5.7e3 eps off unit norm (METRIC-6). Root cause as EXP-1.
Upstream: no matching issue found in pygae/clifford.
Exit 0: defect shown; 1: not shown (fixed); 77: clifford cannot be imported.
"""
import sys
import warnings

CLAUSE = "AXANG-2"
try:
    import clifford
except Exception as exc:  # noqa: BLE001 - any import failure is a skip
    print("rotorcert reproducer: clifford ? %s: SKIP: cannot import clifford: %s" % (CLAUSE, exc))
    sys.exit(77)
warnings.simplefilter("ignore")

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
# x = -R[e23], y = +R[e13], z = -R[e12], w = R[scalar]. I = e123, and I e1 = e23, I e2 = e31,
# I e3 = e12, so exp(-(theta/2) I u/|u|) = cos(theta/2) - sin(theta/2)(ux e23 + uy e31 + uz e12)/|u|,
# i.e. the quaternion (sin(theta/2) u/|u|, cos(theta/2)): a right-handed rotation by theta about u.
layout, blades = clifford.Cl(3)
e1, e2, e3, e123 = blades["e1"], blades["e2"], blades["e3"], blades["e123"]
e12, e13, e23 = blades["e12"], blades["e13"], blades["e23"]


def quat(R):
    return [-float(R[(2, 3)]), float(R[(1, 3)]), -float(R[(1, 2)]), float(R[()])]


EPS = 2.0 ** -52
LOOSE = 256  # eps16 loose bar (spec/clauses.json)
theta = float.fromhex("0x1.0c152382d7366p+1")
axis = [1.0, 1.0, 1.0]

print("rotorcert reproducer: clifford %s %s: exp(-(theta/2) I u/|u|) (Taylor-series exp) is ~8e3 eps "
      "off the rotation of theta about u" % (clifford.__version__, CLAUSE))
u = axis[0] * e1 + axis[1] * e2 + axis[2] * e3
got = quat((-(theta / 2) * (e123 * u.normal())).exp())
s, c = sincos(D(theta) / 2)
nu = norm(axis)
ref = [D(a) / nu * s for a in axis] + [c]
e1_, e6_ = dist(got, ref), abs(norm(got) - 1)  # METRIC-1 (radians) and METRIC-6 (norm defect)
err = max(e1_, e6_)
bad = not (err <= LOOSE * D(EPS))
print("  call:    u = x*e1 + y*e2 + z*e3; (-(theta / 2) * (e123 * u.normal())).exp()")
print("  input:   theta = %s, axis u = [%s]" % (theta.hex(), ", ".join(a.hex() for a in axis)))
print("  library: [%s]  (x, y, z, w)" % ", ".join(x.hex() for x in got))
print("  correct: [%s]  (sin(theta/2) u/|u|, cos(theta/2)) at 60 digits" % ", ".join(float(x).hex() for x in ref))
print("  error:   METRIC-1 %.3e rad = %.4g eps, METRIC-6 %.3e = %.4g eps (bar %d eps)%s"
      % (e1_, e1_ / D(EPS), e6_, e6_ / D(EPS), LOOSE, "  <-- DEFECT" if bad else ""))
print("DEFECT SHOWN" if bad else "DEFECT NOT SHOWN")
sys.exit(0 if bad else 1)
