#!/usr/bin/env python3
"""rotorcert reproducer: pyquaternion normalised, inverse, angle of far-from-unit quaternions, clause EDGE-5.

EDGE-5 (spec/SPEC.md 9): a finite nonzero q is the rotation q/|q| at every scale the format holds, and
unit-valued outputs stay unit (class eps16, loose bar 256 eps); INV-1 is defined on the unnormalised q
(q* / |q|^2). pyquaternion squares the components without scaling (_sum_of_squares, norm:
pyquaternion/quaternion.py:481, 497-498): at |q| ~ 2^900 the sum of squares overflows, norm is inf and
normalised (_normalise, quaternion.py:504-511) returns the zero quaternion, which every rotation
property then uses (rotate, rotation_matrix, angle/axis, slerp, log); at |q| ~ 2^-900 it underflows to 0
and inverse raises ZeroDivisionError ("a zero quaternion cannot be inverted") for a nonzero q. The
documentation promises a unit result for every nonzero quaternion (docs/index.md:391).
Upstream: no matching issue found in KieranWynn/pyquaternion.
Exit 0: defect shown; 1: not shown (fixed); 77: pyquaternion cannot be imported.
"""
import math
import sys
from decimal import Decimal as D, getcontext

CLAUSE = "EDGE-5"
try:
    from importlib.metadata import version
    from pyquaternion import Quaternion
    VERSION = version("pyquaternion")
except Exception as exc:  # noqa: BLE001 - any import failure is a skip
    print("rotorcert reproducer: pyquaternion ? %s: SKIP: cannot import pyquaternion: %s" % (CLAUSE, exc))
    sys.exit(77)
getcontext().prec = 60  # the reference: exact inputs, 60-digit sums, quotients and square roots

EPS = 2.0 ** -52
LOOSE = 256  # eps16 loose bar (spec/clauses.json)
h = float.fromhex
huge = [2.0 ** 1023] * 4  # (x, y, z, w): EX-NORM-1-f, q/|q| = (1/2, 1/2, 1/2, 1/2)
tiny = [h("-0x1.fce3c6dc657fep-901"), h("-0x1.8a9b59ecd5d55p-905"), h("-0x1.a12056e880dafp-900"), h("-0x1.c423be70e784fp-903")]


def dn(q):
    return sum(D(c) * D(c) for c in q).sqrt()


print("rotorcert reproducer: pyquaternion %s %s: normalised of a quaternion of norm 2^1024 is the zero "
      "quaternion, inverse of one of norm ~2^-900 raises ZeroDivisionError (unscaled sums of squares)" % (VERSION, CLAUSE))
shown = False
cases = (("normalised", huge, [D(c) / dn(huge) for c in huge], "q/|q|"),
         ("inverse", tiny, [-D(c) / dn(tiny) ** 2 for c in tiny[:3]] + [D(tiny[3]) / dn(tiny) ** 2], "q*/|q|^2"))
for name, q, ref, what in cases:
    x, y, z, w = q
    try:
        r = getattr(Quaternion(w, x, y, z), name)
        got = [r.x, r.y, r.z, r.w]
        result = "[%s]" % ", ".join(c.hex() for c in got)
        nr = sum(c * c for c in ref).sqrt()  # componentwise error relative to |ref|
        err = float(max(abs(D(g) - c) for g, c in zip(got, ref)) / nr) if all(map(math.isfinite, got)) else math.nan
    except Exception as exc:  # noqa: BLE001 - refusing a finite nonzero q is the defect (wrong status)
        result, err = "raised %s: %s" % (type(exc).__name__, exc), math.nan
    bad = not (err <= LOOSE * EPS)
    shown = shown or bad
    print("  call:    Quaternion(w, x, y, z).%s" % name)
    print("  input:   q (x, y, z, w) = [%s]" % ", ".join(c.hex() for c in q))
    print("  library: %s" % result)
    print("  correct: [%s]  (%s, 60 digits)" % (", ".join(float(c).hex() for c in ref), what))
    print("  error:   %s = %s eps (componentwise, relative to |correct|; bar %d eps)%s"
          % (err, err / EPS, LOOSE, "  <-- DEFECT" if bad else ""))
print("DEFECT SHOWN" if shown else "DEFECT NOT SHOWN")
sys.exit(0 if shown else 1)
