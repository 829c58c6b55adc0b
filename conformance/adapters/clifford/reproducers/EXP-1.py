#!/usr/bin/env python3
"""rotorcert reproducer: clifford (pygae) MultiVector.exp() of a bivector, clause EXP-1.

EXP-1 (spec/SPEC.md 8.2): exp(B) = cos|B| + B sin|B|/|B| for every finite bivector, tolerance eps16
(loose bar 256 eps). MultiVector.exp() is clifford.taylor_expansions.exp: it scales by a power of two
above max|coefficient| (not |B|), sums at most 14 Taylor terms, stops as soon as every coefficient of a
term is < 1e-12 (clifford._settings._eps) and squares back: the truncation error ~1e-13 is amplified
by the squarings, so ordinary rotation bivectors come out ~4e5 eps wrong. Its scaling loop also uses
a 64-bit int: a finite coefficient >= 2^62 makes `max_val <<= 1` overflow and exp() never returns.
(The module docstring concedes that closed forms "would likely be faster and more accurate".)
Upstream: no matching issue found in pygae/clifford.
Exit 0: defect shown; 1: not shown (fixed); 77: clifford cannot be imported.
"""
import multiprocessing
import sys
import warnings

CLAUSE = "EXP-1"
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
# R = w - x*e23 + y*e13 - z*e12 and back x = -R[e23], y = +R[e13], z = -R[e12], w = R[scalar].
# A quaternion-view log v = (x, y, z) is the bivector Phi(v) = -(x e23 + y e31 + z e12)
# = -x*e23 + y*e13 - z*e12, so that exp(Phi(v)) = Phi((sin|v| v/|v|, cos|v|)).
layout, blades = clifford.Cl(3)
e12, e13, e23 = blades["e12"], blades["e13"], blades["e23"]


def quat(R):
    return [-float(R[(2, 3)]), float(R[(1, 3)]), -float(R[(1, 2)]), float(R[()])]


EPS = 2.0 ** -52
LOOSE = 256  # eps16 loose bar (spec/clauses.json)
h = float.fromhex
v = [h("-0x1.6e5fb3ba7ad4bp+0"), h("0x1.5a15cec0de3c9p+0"), h("0x1.bcb72148d959cp+0")]

print("rotorcert reproducer: clifford %s %s: MultiVector.exp() (Taylor series) of a rotation bivector "
      "is ~4e5 eps wrong; a finite coefficient >= 2^62 never returns" % (clifford.__version__, CLAUSE))
B = -v[0] * e23 + v[1] * e13 - v[2] * e12
got = quat(B.exp())
r = norm(v)
s, c = sincos(r)
ref = [D(x) / r * s for x in v] + [c]
e1_, e6_ = dist(got, ref), abs(norm(got) - 1)  # METRIC-1 (radians) and METRIC-6 (norm defect)
err = max(e1_, e6_)
bad = not (err <= LOOSE * D(EPS))
print("  call:    B = -x*e23 + y*e13 - z*e12; B.exp()")
print("  input:   v (x, y, z) = [%s]" % ", ".join(c.hex() for c in v))
print("  library: [%s]  (x, y, z, w)" % ", ".join(c.hex() for c in got))
print("  correct: [%s]  (sin|v| v/|v|, cos|v|) at 60 digits" % ", ".join(float(c).hex() for c in ref))
print("  error:   METRIC-1 %.3e rad = %.4g eps, METRIC-6 %.3e = %.4g eps (bar %d eps)%s"
      % (e1_, e1_ / D(EPS), e6_, e6_ / D(EPS), LOOSE, "  <-- DEFECT" if bad else ""))


# Second: a finite bivector with a coefficient >= 2^62 (EXP-1 puts no bound on |B|) never returns.
# The call runs in a forked child (the parent compiled exp() above) and is stopped after 3 s.
def returns_within(mv, seconds):
    ctx = multiprocessing.get_context("fork")
    child = ctx.Process(target=mv.exp)
    child.start()
    child.join(seconds)
    if child.is_alive():
        child.kill()
        child.join()
        return False
    return True


big = 2.0 ** 62
ok = returns_within(big * e12, 3.0)
print("  call:    (%s * e12).exp()   (v = (0, 0, -2^62); a normal call takes well under 1 ms)" % big.hex())
print("  library: %s" % ("returned" if ok else "did not return within 3 s  <-- DEFECT"))
print("  correct: (0, 0, -sin(2^62), cos(2^62)), a unit quaternion")
bad = bad or not ok
print("DEFECT SHOWN" if bad else "DEFECT NOT SHOWN")
sys.exit(0 if bad else 1)
