#!/usr/bin/env python3
"""rotorcert reproducer: clifford (pygae) MultiVector.normal(), clause EDGE-5 (NORM-1's extreme inputs, judged at Robust by LEVEL-1).

NORM-1 (spec/SPEC.md 8.1): normalize(q) = q/|q| "MUST be computed without intermediate overflow or
underflow for every finite nonzero input of the format". clifford's MultiVector.normal() is
self / abs(self) with abs = sqrt(<~M M>0) (clifford/_multivector.py): no scaling, so the sum of
squares underflows to 0 for small rotors (0/0, x/0) and overflows to inf for large ones (x/inf = 0).
normal() documents no precondition ("Return the (mostly) normalized multivector ... M/|M| up to a sign").
Upstream: no matching issue found in pygae/clifford.
Exit 0: defect shown; 1: not shown (fixed); 77: clifford cannot be imported.
"""
import math
import sys
import warnings

CLAUSE = "EDGE-5"
try:
    import clifford
except Exception as exc:  # noqa: BLE001 - any import failure is a skip
    print("rotorcert reproducer: clifford ? %s: SKIP: cannot import clifford: %s" % (CLAUSE, exc))
    sys.exit(77)
warnings.simplefilter("ignore")  # numpy's 0/0 and overflow RuntimeWarnings; they change no value

# Conventions (rotorcert Q2R-1, as conformance/adapters/clifford does it): quaternion (x, y, z, w)
# <-> rotor R = w - x e23 - y e31 - z e12. clifford.Cl(3) names the bivectors e12, e13, e23 and
# e31 = -e13, so R = w - x*e23 + y*e13 - z*e12; back: x = -R[e23], y = +R[e13], z = -R[e12], w = R[scalar].
layout, blades = clifford.Cl(3)
e12, e13, e23 = blades["e12"], blades["e13"], blades["e23"]


def rotor(x, y, z, w):
    return w - x * e23 + y * e13 - z * e12


def quat(R):
    return [-float(R[(2, 3)]), float(R[(1, 3)]), -float(R[(1, 2)]), float(R[()])]


EPS = 2.0 ** -52
LOOSE = 64  # eps4 loose bar (spec/clauses.json)
h = float.fromhex
# (input q as (x, y, z, w), its exact q/|q| by closed form, how it was derived)
CASES = [
    ([h("0x1.8p-999"), 0.0, 0.0, h("0x1p-998")], [0.6, 0.0, 0.0, 0.8],
     "(1.5, 0, 0, 2) * 2^-999 -> (3, 0, 0, 4)/5 (EX-NORM-1-h)"),
    ([h("0x1p+1023")] * 4, [0.5, 0.5, 0.5, 0.5], "(1, 1, 1, 1) * 2^1023 -> (1, 1, 1, 1)/2 (EX-NORM-1-f)"),
]

print("rotorcert reproducer: clifford %s %s: MultiVector.normal() of a finite rotor underflows to "
      "inf/nan or overflows to 0 (no scaling before squaring)" % (clifford.__version__, CLAUSE))
shown = False
for q, ref, why in CASES:
    got = quat(rotor(*q).normal())
    if all(math.isfinite(c) for c in got):
        err = max(abs(g - r) for g, r in zip(got, ref))  # componentwise; the reference is unit
        # ... and the norm defect (METRIC-6): the output must be unit
        err = max(err, abs(math.sqrt(sum(g * g for g in got)) - 1.0))
    else:
        err = math.nan
    bad = not (err <= LOOSE * EPS)
    shown = shown or bad
    print("  call:    R = w - x*e23 + y*e13 - z*e12; R.normal()")
    print("  input:   q (x, y, z, w) = [%s]" % ", ".join(c.hex() for c in q))
    print("  library: [%s]" % ", ".join(c.hex() for c in got))
    print("  correct: [%s]   %s" % (", ".join(c.hex() for c in ref), why))
    print("  error:   %s = %s eps (max componentwise and norm defect; bar %d eps)%s"
          % (err, err / EPS, LOOSE, "  <-- DEFECT" if bad else ""))
if shown:
    print("DEFECT SHOWN")
    sys.exit(0)
print("DEFECT NOT SHOWN")
sys.exit(1)
