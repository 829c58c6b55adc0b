#!/usr/bin/env python3
"""rotorcert reproducer: clifford (pygae) exp(log_rotor(R)) round trip, clause EXP-2.

EXP-2 (spec/SPEC.md 8.2): exp(log R) = R for every unit R, tolerance eps16 (loose bar 256 eps),
METRIC-1. clifford's log is clifford.tools.log_rotor ("Logarithm of a simple rotor") and its exp is
MultiVector.exp(), the Taylor series of clifford.taylor_expansions.exp (stops when a term is < 1e-12,
at most 14 terms, then squarings): an ordinary unit rotor comes back ~3e5 eps away. (For R = +-1 and
|<R>2| < 1e-12 the round trip cannot even start: log_rotor raises NameError, see LOG-2 / EDGE-1.)
Upstream: no matching issue found in pygae/clifford.
Exit 0: defect shown; 1: not shown (fixed); 77: clifford cannot be imported.
"""
import contextlib
import io
import sys
import warnings

CLAUSE = "EXP-2"
try:
    import clifford
    import clifford.tools
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
# log_rotor and exp are used on the rotor directly (no conversion between them).
layout, blades = clifford.Cl(3)
e12, e13, e23 = blades["e12"], blades["e13"], blades["e23"]


def quat(R):
    return [-float(R[(2, 3)]), float(R[(1, 3)]), -float(R[(1, 2)]), float(R[()])]


EPS = 2.0 ** -52
LOOSE = 256  # eps16 loose bar (spec/clauses.json)
h = float.fromhex
q = [h("0x1.572571f68bbbfp-1"), h("0x1.55aed00a115dcp-1"), h("-0x1.2cec99b444853p-2"), h("0x1.1b1611a30b0ebp-3")]

print("rotorcert reproducer: clifford %s %s: log_rotor(R).exp() of a unit rotor comes back ~3e5 eps "
      "away from R (Taylor-series exp)" % (clifford.__version__, CLAUSE))
R = q[3] - q[0] * e23 + q[1] * e13 - q[2] * e12
with contextlib.redirect_stdout(io.StringIO()):  # log_rotor may print() its argument
    L = clifford.tools.log_rotor(R)
got = quat(L.exp())
e1_, e6_ = dist(got, q), abs(norm(got) - 1)  # METRIC-1 against q itself; METRIC-6 for information
bad = not (e1_ <= LOOSE * D(EPS))
print("  call:    clifford.tools.log_rotor(R).exp(), R = w - x*e23 + y*e13 - z*e12")
print("  input:   q (x, y, z, w) = [%s]  (| |q| - 1 | = %.1e)" % (", ".join(c.hex() for c in q), abs(norm(q) - 1)))
print("  library: [%s]" % ", ".join(c.hex() for c in got))
print("  correct: q itself (the same rotation; METRIC-1 normalises both)")
print("  error:   METRIC-1 %.3e rad = %.4g eps (bar %d eps)%s; METRIC-6 %.3e = %.4g eps"
      % (e1_, e1_ / D(EPS), LOOSE, "  <-- DEFECT" if bad else "", e6_, e6_ / D(EPS)))
print("DEFECT SHOWN" if bad else "DEFECT NOT SHOWN")
sys.exit(0 if bad else 1)
