#!/usr/bin/env python3
"""rotorcert reproducer: clifford (pygae) MultiVector.normal() of a subnormal rotor, clause EDGE-8.

EDGE-8 (spec/SPEC.md 9): subnormal components are ordinary nonzero values: normalize((2^-1074, -0, 0, 0))
= (1, -0, 0, 0) (class eps4, loose bar 64 eps; also NORM-1). MultiVector.normal() is
self / abs(self) with abs = sqrt(<~M M>0) and no scaling: (2^-1074)^2 underflows to 0, so the result
is 2^-1074/0 = inf and 0/0 = nan, returned without any error. normal() documents no precondition
("Return the (mostly) normalized multivector ... M/|M| up to a sign").
Upstream: no matching issue found in pygae/clifford.
Exit 0: defect shown; 1: not shown (fixed); 77: clifford cannot be imported.
"""
import math
import sys
import warnings

CLAUSE = "EDGE-8"
try:
    import clifford
except Exception as exc:  # noqa: BLE001 - any import failure is a skip
    print("rotorcert reproducer: clifford ? %s: SKIP: cannot import clifford: %s" % (CLAUSE, exc))
    sys.exit(77)
warnings.simplefilter("ignore")  # numpy's 0/0 RuntimeWarning; it changes no value

# Conventions (rotorcert Q2R-1, as conformance/adapters/clifford does it): quaternion (x, y, z, w)
# <-> rotor R = w - x e23 - y e31 - z e12. clifford.Cl(3) names the bivectors e12, e13, e23 and
# e31 = -e13, so R = w - x*e23 + y*e13 - z*e12; back: x = -R[e23], y = +R[e13], z = -R[e12], w = R[scalar].
layout, blades = clifford.Cl(3)
e12, e13, e23 = blades["e12"], blades["e13"], blades["e23"]


def quat(R):
    return [-float(R[(2, 3)]), float(R[(1, 3)]), -float(R[(1, 2)]), float(R[()])]


EPS = 2.0 ** -52
LOOSE = 64  # eps4 loose bar (spec/clauses.json)
q = [float.fromhex("0x0.0000000000001p-1022"), -0.0, 0.0, 0.0]  # (x, y, z, w): x = 2^-1074
ref = [1.0, -0.0, 0.0, 0.0]  # closed form: q/|q| with |q| = x

print("rotorcert reproducer: clifford %s %s: MultiVector.normal() of a rotor with a subnormal component "
      "returns [inf, nan, nan, nan] (the squared norm underflows to 0)" % (clifford.__version__, CLAUSE))
R = q[3] - q[0] * e23 + q[1] * e13 - q[2] * e12
got = quat(R.normal())
err = max(abs(g - r) for g, r in zip(got, ref)) if all(math.isfinite(g) for g in got) else math.nan
bad = not (err <= LOOSE * EPS)
print("  call:    R = w - x*e23 + y*e13 - z*e12; R.normal()")
print("  input:   q (x, y, z, w) = [%s]" % ", ".join(c.hex() for c in q))
print("  library: [%s]" % ", ".join(c.hex() for c in got))
print("  correct: [%s]  (q/|q|, |q| = 2^-1074: closed form)" % ", ".join(c.hex() for c in ref))
print("  error:   %s = %s eps (max componentwise; bar %d eps)%s" % (err, err / EPS, LOOSE, "  <-- DEFECT" if bad else ""))
print("DEFECT SHOWN" if bad else "DEFECT NOT SHOWN")
sys.exit(0 if bad else 1)
