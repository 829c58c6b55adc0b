#!/usr/bin/env python3
"""rotorcert reproducer: kingdon MultiVector.normalized() of very small / very large rotors, clause EDGE-5 (NORM-1's extreme inputs, judged at Robust by LEVEL-1).

NORM-1 (spec/SPEC.md 8.1): normalize(q) = q/|q| "MUST be computed without intermediate overflow or
underflow for every finite nonzero input of the format" (class eps4, loose bar 64 eps). kingdon's
normalized() ("Normalized version of this multivector", kingdon/multivector.py) is self / self.norm()
with norm = sqrt(normsq) and normsq = w^2 + b12^2 + b13^2 + b23^2 generated without scaling: for
|q| ~ 2^-998 the squared norm underflows to 0 and the division raises ZeroDivisionError (Python
floats); for components 2^1023 it overflows to inf and the result is the zero rotor. No precondition
is documented (docs: "Normalize a: a / sqrt(a ~a)").
Upstream: no matching issue found in tBuLi/kingdon.
Exit 0: defect shown; 1: not shown (fixed); 77: kingdon cannot be imported.
"""
import math
import sys

CLAUSE = "EDGE-5"
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


def rotor(x, y, z, w):
    return alg.multivector(e=w, e12=-z, e13=y, e23=-x)


def quat(R):
    return [-R.e23, R.e13, -R.e12, R.e]


EPS = 2.0 ** -52
LOOSE = 64  # eps4 loose bar (spec/clauses.json)
h = float.fromhex
CASES = [  # (q as (x, y, z, w), its q/|q| by closed form, how)
    ([h("0x1.8p-999"), 0.0, 0.0, h("0x1p-998")], [0.6, 0.0, 0.0, 0.8], "(1.5, 0, 0, 2) * 2^-999 -> (3, 0, 0, 4)/5 (EX-NORM-1-h)"),
    ([h("0x1p+1023")] * 4, [0.5] * 4, "(1, 1, 1, 1) * 2^1023 -> (1, 1, 1, 1)/2 (EX-NORM-1-f)"),
]

print("rotorcert reproducer: kingdon %s %s: normalized() of a finite rotor raises ZeroDivisionError "
      "(squared norm underflows) or returns 0 (it overflows)" % (VERSION, CLAUSE))
shown = False
for q, ref, why in CASES:
    try:
        got = quat(rotor(*q).normalized())
        result = "[%s]" % ", ".join(c.hex() for c in got)
        err = max(abs(g - r) for g, r in zip(got, ref))
        err = max(err, abs(math.sqrt(sum(g * g for g in got)) - 1.0))  # METRIC-6: the output must be unit
    except Exception as exc:  # noqa: BLE001 - refusing a finite nonzero q is the defect (wrong status)
        result, err = "raised %s: %s" % (type(exc).__name__, exc), math.nan
    bad = not (err <= LOOSE * EPS)
    shown = shown or bad
    print("  call:    R = alg.multivector(e=w, e12=-z, e13=y, e23=-x); R.normalized()")
    print("  input:   q (x, y, z, w) = [%s]" % ", ".join(c.hex() for c in q))
    print("  library: %s" % result)
    print("  correct: [%s]   %s" % (", ".join(c.hex() for c in ref), why))
    print("  error:   %s = %s eps (max componentwise and norm defect; bar %d eps)%s"
          % (err, err / EPS, LOOSE, "  <-- DEFECT" if bad else ""))
print("DEFECT SHOWN" if shown else "DEFECT NOT SHOWN")
sys.exit(0 if shown else 1)
