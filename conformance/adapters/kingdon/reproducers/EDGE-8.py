#!/usr/bin/env python3
"""rotorcert reproducer: kingdon MultiVector.normalized() of a subnormal rotor, clause EDGE-8.

EDGE-8 (spec/SPEC.md 9): subnormal components are ordinary nonzero values: normalize((2^-1074, -0, 0, 0))
= (1, -0, 0, 0); "an implementation that flushes them to zero and reports DOMAIN_ERROR fails" (class
eps4, loose bar 64 eps; also NORM-1). kingdon's normalized() ("Normalized version of this multivector")
divides by sqrt(w^2 + b12^2 + b13^2 + b23^2) computed without scaling: (2^-1074)^2 underflows to 0 and
the Python float division raises ZeroDivisionError. No precondition is documented. (The >> sandwich
with such a rotor is NOT reported here: kingdon documents that the versor must satisfy x ~x = 1.)
Upstream: no matching issue found in tBuLi/kingdon.
Exit 0: defect shown; 1: not shown (fixed); 77: kingdon cannot be imported.
"""
import math
import sys

CLAUSE = "EDGE-8"
try:
    from importlib.metadata import version
    from kingdon import Algebra
    VERSION = version("kingdon")
except Exception as exc:  # noqa: BLE001 - any import failure is a skip
    print("rotorcert reproducer: kingdon ? %s: SKIP: cannot import kingdon: %s" % (CLAUSE, exc))
    sys.exit(77)

# Conventions (rotorcert Q2R-1, as conformance/adapters/kingdon does it): quaternion (x, y, z, w)
# <-> rotor R = w - x e23 - y e31 - z e12. kingdon's Algebra(3, 0, 0) names the bivectors e12, e13,
# e23, and e31 = -e13, so R = w - z e12 + y e13 - x e23 (set blade by blade, Python float coefficients,
# kingdon's default); back: x = -R.e23, y = +R.e13, z = -R.e12, w = R.e.
alg = Algebra(3, 0, 0)
EPS = 2.0 ** -52
LOOSE = 64  # eps4 loose bar (spec/clauses.json)
q = [float.fromhex("0x0.0000000000001p-1022"), -0.0, 0.0, 0.0]  # (x, y, z, w): x = 2^-1074
ref = [1.0, -0.0, 0.0, 0.0]  # closed form: q/|q| with |q| = x

print("rotorcert reproducer: kingdon %s %s: normalized() of a rotor with a subnormal component raises "
      "ZeroDivisionError (the squared norm underflows to 0)" % (VERSION, CLAUSE))
x, y, z, w = q
try:
    R = alg.multivector(e=w, e12=-z, e13=y, e23=-x).normalized()
    got = [-R.e23, R.e13, -R.e12, R.e]
    result = "[%s]" % ", ".join(c.hex() for c in got)
    err = max(abs(g - r) for g, r in zip(got, ref)) if all(map(math.isfinite, got)) else math.nan
except Exception as exc:  # noqa: BLE001 - refusing a finite nonzero q is the defect (wrong status)
    result, err = "raised %s: %s" % (type(exc).__name__, exc), math.nan
bad = not (err <= LOOSE * EPS)
print("  call:    R = alg.multivector(e=w, e12=-z, e13=y, e23=-x); R.normalized()")
print("  input:   q (x, y, z, w) = [%s]" % ", ".join(c.hex() for c in q))
print("  library: %s" % result)
print("  correct: [%s]  (q/|q|, |q| = 2^-1074: closed form)" % ", ".join(c.hex() for c in ref))
print("  error:   %s = %s eps (max componentwise; bar %d eps)%s" % (err, err / EPS, LOOSE, "  <-- DEFECT" if bad else ""))
print("DEFECT SHOWN" if bad else "DEFECT NOT SHOWN")
sys.exit(0 if bad else 1)
