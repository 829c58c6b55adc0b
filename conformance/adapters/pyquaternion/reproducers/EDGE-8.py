#!/usr/bin/env python3
"""rotorcert reproducer: pyquaternion normalised and log of a subnormal quaternion, clause EDGE-8.

EDGE-8 (spec/SPEC.md 9): subnormal components are ordinary nonzero values: normalize((2^-1074, -0, 0, 0))
= (1, -0, 0, 0) (class eps4, loose bar 64 eps). pyquaternion's normalised (_normalise,
pyquaternion/quaternion.py:504-511) divides by sqrt(w^2 + x^2 + y^2 + z^2) only "if n > 0": the squares
of a subnormal quaternion underflow to 0, so it returns its input unchanged, a quaternion of norm
2^-1074 that the documentation calls "guaranteed to be a unit quaternion" (docs/index.md:391); every
rotation property that normalises first (rotate, rotation_matrix, slerp) then works on it, and
Quaternion.log treats it as zero (q_norm < 1e-17: scalar -inf, vector NaN, quaternion.py:681-683).
Upstream: no matching issue found in KieranWynn/pyquaternion.
Exit 0: defect shown; 1: not shown (fixed); 77: pyquaternion cannot be imported.
"""
import math
import sys
from decimal import Decimal as D, getcontext

CLAUSE = "EDGE-8"
try:
    from importlib.metadata import version
    from pyquaternion import Quaternion
    VERSION = version("pyquaternion")
except Exception as exc:  # noqa: BLE001 - any import failure is a skip
    print("rotorcert reproducer: pyquaternion ? %s: SKIP: cannot import pyquaternion: %s" % (CLAUSE, exc))
    sys.exit(77)
getcontext().prec = 60  # the reference: exact inputs, 60-digit sums, quotients and square roots

EPS = 2.0 ** -52
LOOSE = 64  # eps4 loose bar (spec/clauses.json)
q = [float.fromhex("0x0.0000000000001p-1022"), -0.0, 0.0, 0.0]  # (x, y, z, w): x = 2^-1074 (EX-EDGE-8-a)
ref = [1.0, -0.0, 0.0, 0.0]  # closed form: q/|q| with |q| = x

print("rotorcert reproducer: pyquaternion %s %s: normalised of a quaternion with a subnormal component "
      "returns it unchanged (norm 2^-1074), not a unit quaternion" % (VERSION, CLAUSE))
x, y, z, w = q
r = Quaternion(w, x, y, z).normalised
got = [r.x, r.y, r.z, r.w]
err = max(abs(g - c) for g, c in zip(got, ref)) if all(map(math.isfinite, got)) else math.nan
bad = not (err <= LOOSE * EPS)
print("  call:    Quaternion(w, x, y, z).normalised")
print("  input:   q (x, y, z, w) = [%s]" % ", ".join(c.hex() for c in q))
print("  library: [%s]" % ", ".join(c.hex() for c in got))
print("  correct: [%s]  (q/|q|, |q| = 2^-1074: closed form)" % ", ".join(c.hex() for c in ref))
print("  error:   %s = %s eps (max componentwise; bar %d eps)%s" % (err, err / EPS, LOOSE, "  <-- DEFECT" if bad else ""))
lg = Quaternion.log(Quaternion(w, x, y, z))
print("  also:    Quaternion.log(Quaternion(w, x, y, z)) = %r (the log of q/|q| is (pi/2, 0, 0) in x, y, z)" % (lg,))
print("DEFECT SHOWN" if bad else "DEFECT NOT SHOWN")
sys.exit(0 if bad else 1)
