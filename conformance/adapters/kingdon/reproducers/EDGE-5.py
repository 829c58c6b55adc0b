#!/usr/bin/env python3
"""rotorcert reproducer: kingdon MultiVector.normalized() and .inv() of non-unit rotors, clause EDGE-5.

EDGE-5 (spec/SPEC.md 9): a finite nonzero q is the rotation q/|q| at every scale the format holds and
unit-valued outputs stay unit (class eps16, loose bar 256 eps); INV-1 is defined on the unnormalised
input (q^-1 = q*/|q|^2). kingdon's normalized() ("Normalized version of this multivector") divides by
sqrt(w^2 + b12^2 + b13^2 + b23^2) computed without scaling: at |q| ~ 2^-900 the squared norm underflows
and it raises ZeroDivisionError; at |q| ~ 2^900 it overflows and the result is the zero rotor.
inv() ("Inverse of this multivector", ~R / (R ~R)) fails the same way at 2^-900 and 2^900.
Neither documents a scale restriction. (The >> sandwich with a non-unit rotor is NOT reported here:
kingdon documents that the versor must satisfy x ~x = 1.)
Upstream: no matching issue found in tBuLi/kingdon.
Exit 0: defect shown; 1: not shown (fixed); 77: kingdon cannot be imported.
"""
import math
import sys
from decimal import Decimal as D, getcontext

CLAUSE = "EDGE-5"
try:
    from importlib.metadata import version
    from kingdon import Algebra
    VERSION = version("kingdon")
except Exception as exc:  # noqa: BLE001 - any import failure is a skip
    print("rotorcert reproducer: kingdon ? %s: SKIP: cannot import kingdon: %s" % (CLAUSE, exc))
    sys.exit(77)
getcontext().prec = 60  # the reference: exact inputs, 60-digit sums, quotients and square root

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
LOOSE = 256  # eps16 loose bar (spec/clauses.json)
h = float.fromhex
tiny = [h("0x1.b8f03cdecadc2p-902"), h("0x1.875a4c8436b3dp-911"), h("-0x1.b04b1d7237c6dp-904"), h("0x1.fa16f76413dbdp-901")]
huge = [2.0 ** 900] * 4

print("rotorcert reproducer: kingdon %s %s: normalized() and inv() of a finite rotor of norm ~2^-900 raise "
      "ZeroDivisionError; at ~2^900 they return the zero rotor" % (VERSION, CLAUSE))
shown = False
for name, q in (("normalized", tiny), ("normalized", huge), ("inv", tiny), ("inv", huge)):
    n2 = sum(D(c) * D(c) for c in q)
    if name == "normalized":
        ref, what = [D(c) / n2.sqrt() for c in q], "q/|q|"
    else:
        ref, what = [-D(c) / n2 for c in q[:3]] + [D(q[3]) / n2], "q*/|q|^2"
    try:
        got = quat(getattr(rotor(*q), name)())
        result = "[%s]" % ", ".join(c.hex() for c in got)
        nr = sum(r * r for r in ref).sqrt()  # componentwise relative error (INV-1's metric)
        err = float(max(abs(D(g) - r) for g, r in zip(got, ref)) / nr) if all(map(math.isfinite, got)) else math.nan
    except Exception as exc:  # noqa: BLE001 - refusing a finite nonzero q is the defect (wrong status)
        result, err = "raised %s: %s" % (type(exc).__name__, exc), math.nan
    bad = not (err <= LOOSE * EPS)
    shown = shown or bad
    print("  call:    R = alg.multivector(e=w, e12=-z, e13=y, e23=-x); R.%s()" % name)
    print("  input:   q (x, y, z, w) = [%s]" % ", ".join(c.hex() for c in q))
    print("  library: %s" % result)
    print("  correct: [%s]  (%s, 60 digits)" % (", ".join(float(c).hex() for c in ref), what))
    print("  error:   %s = %s eps (componentwise relative; bar %d eps)%s" % (err, err / EPS, LOOSE, "  <-- DEFECT" if bad else ""))
print("DEFECT SHOWN" if shown else "DEFECT NOT SHOWN")
sys.exit(0 if shown else 1)
