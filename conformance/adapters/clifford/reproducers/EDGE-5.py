#!/usr/bin/env python3
"""rotorcert reproducer: clifford (pygae) MultiVector.normal() and .inv() of non-unit rotors, clause EDGE-5.

EDGE-5 (spec/SPEC.md 9): a finite nonzero q is the rotation q/|q| at every scale the format holds and
unit-valued outputs stay unit (class eps16, loose bar 256 eps); INV-1 is defined on the unnormalised
input (q^-1 = q*/|q|^2). MultiVector.normal() = self / sqrt(<~M M>0) with no scaling: for |q| ~ 2^-900
the squared norm underflows to 0 and the "normalised" rotor is infinite. MultiVector.inv() raises
ValueError("no inverse exists for this multivector") whenever |<~M M>0| <= 1e-12 (clifford._settings._eps),
i.e. for every rotor with |q| <= 1e-6, and returns all NaN for |q| ~ 2^900 (<~M M>0 = inf). Neither
documents a scale restriction (normal(): "M/|M| up to a sign"; inv(): "Obtain the inverse M^-1").
Upstream: no matching issue found in pygae/clifford.
Exit 0: defect shown; 1: not shown (fixed); 77: clifford cannot be imported.
"""
import math
import sys
import warnings
from decimal import Decimal as D, getcontext

CLAUSE = "EDGE-5"
try:
    import clifford
except Exception as exc:  # noqa: BLE001 - any import failure is a skip
    print("rotorcert reproducer: clifford ? %s: SKIP: cannot import clifford: %s" % (CLAUSE, exc))
    sys.exit(77)
warnings.simplefilter("ignore")  # numpy's overflow / 0-division RuntimeWarnings; they change no value
getcontext().prec = 60  # the reference: exact inputs, 60-digit sums and square root

# Conventions (rotorcert Q2R-1, as conformance/adapters/clifford does it): quaternion (x, y, z, w)
# <-> rotor R = w - x e23 - y e31 - z e12. clifford.Cl(3) names the bivectors e12, e13, e23 and
# e31 = -e13, so R = w - x*e23 + y*e13 - z*e12; back: x = -R[e23], y = +R[e13], z = -R[e12], w = R[scalar].
layout, blades = clifford.Cl(3)
e12, e13, e23 = blades["e12"], blades["e13"], blades["e23"]


def rotor(x, y, z, w):
    return w - x * e23 + y * e13 - z * e12


def quat(R):
    return [-float(R[(2, 3)]), float(R[(1, 3)]), -float(R[(1, 2)]), float(R[()])]


def relerr(got, ref):  # max_i |got_i - ref_i| / |ref| (INV-1's metric; also used for normalize here)
    if not all(math.isfinite(g) for g in got):
        return math.nan
    nr = sum(r * r for r in ref).sqrt()
    return float(max(abs(D(g) - r) for g, r in zip(got, ref)) / nr)


def show(call, q, got, ref, note):
    err = relerr(got, ref) if isinstance(got, list) else math.nan
    bad = not (err <= LOOSE * EPS)
    print("  call:    %s" % call)
    print("  input:   q (x, y, z, w) = [%s]" % ", ".join(c.hex() for c in q))
    print("  library: %s" % ("[%s]" % ", ".join(c.hex() for c in got) if isinstance(got, list) else got))
    print("  correct: [%s]  (%s, 60 digits)" % (", ".join(float(c).hex() for c in ref), note))
    print("  error:   %s = %s eps (componentwise relative; bar %d eps)%s" % (err, err / EPS, LOOSE, "  <-- DEFECT" if bad else ""))
    return bad


EPS = 2.0 ** -52
LOOSE = 256  # eps16 loose bar (spec/clauses.json)
h = float.fromhex
q = [h("0x1.b8f03cdecadc2p-902"), h("0x1.875a4c8436b3dp-911"), h("-0x1.b04b1d7237c6dp-904"), h("0x1.fa16f76413dbdp-901")]
print("rotorcert reproducer: clifford %s %s: MultiVector.normal() of a rotor of norm ~2^-900 returns inf; "
      ".inv() refuses every rotor with |q| <= 1e-6" % (clifford.__version__, CLAUSE))
n = sum(D(c) * D(c) for c in q).sqrt()
bad = show("R = w - x*e23 + y*e13 - z*e12; R.normal()", q, quat(rotor(*q).normal()), [D(c) / n for c in q], "q/|q|")

for q in ([0.0, 0.0, 0.0, 2.0 ** -30], [2.0 ** 900] * 4):  # INV-1 on unnormalised input: q*/|q|^2
    n2 = sum(D(c) * D(c) for c in q)
    ref = [-D(c) / n2 for c in q[:3]] + [D(q[3]) / n2]
    try:
        got = quat(rotor(*q).inv())
    except Exception as exc:  # noqa: BLE001 - a refusal of a finite nonzero q is the defect
        got = "raised %s: %s" % (type(exc).__name__, exc)
    bad = show("R.inv()", q, got, ref, "q*/|q|^2") or bad
print("DEFECT SHOWN" if bad else "DEFECT NOT SHOWN")
sys.exit(0 if bad else 1)
