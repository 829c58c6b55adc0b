#!/usr/bin/env python3
"""rotorcert reproducer: kingdon MultiVector.sqrt() of a rotor near a full turn and of -1, clause SQRT-1.

SQRT-1 (spec/SPEC.md 6, level Extended, eps16: METRIC-1 and METRIC-6, loose bar 256 eps): the rotor
square root s = (1 + R^)/|1 + R^| of R^ = R/|R|, (cos(theta/4), sin(theta/4) u), with s*s = R^; any
unit bivector for R^ = -1. "1 + w of q^ cancels near q^ = -1 and SHOULD be formed as |v^|^2/(1 - w^)
there". kingdon's sqrt (operators.py:433-453, "Take the square root using the study number approach";
R ** 0.5 calls it) writes R = a + bI with a = <R>_0 and forms
    cp = sqrt(0.5 * (a + sqrt(a*a - (bI)^2))),   sqrt(R) = bI / (2 cp) + cp,
i.e. cp^2 = (w + |R|)/2 for a rotor: for a rotation delta short of a full turn (w near -|R|) the sum
w + |R| ~ delta^2/8 keeps only the rounding of w and of |R|, so cp loses its digits and the root is
not unit (norm 0.73 instead of 1 at delta = 2.2e-8: 1.2e15 eps), and where w + |R| is exactly 0 (R = -1,
and rotations within ~2e-8 rad of a full turn) cp = 0 and the division raises ZeroDivisionError.
Upstream: no issue found for the cancellation or the ZeroDivisionError in tBuLi/kingdon; related:
https://github.com/tBuLi/kingdon/issues/75 (closed: sqrt() of a motor with a negative scalar part gives
imaginary coefficients, 'expected behaviour') and the open https://github.com/tBuLi/kingdon/pull/107
(square roots of '360 translations', -1 + t e0i).
Exit 0: defect shown; 1: not shown (fixed); 77: kingdon cannot be imported.
"""
import math
import sys
from decimal import Decimal as D, getcontext

CLAUSE = "SQRT-1"
try:
    from importlib.metadata import version
    from kingdon import Algebra
    VERSION = version("kingdon")
except Exception as exc:  # noqa: BLE001 - any import failure is a skip
    print("rotorcert reproducer: kingdon ? %s: SKIP: cannot import kingdon: %s" % (CLAUSE, exc))
    sys.exit(77)
getcontext().prec = 60  # the reference: exact inputs, 60-digit sums, quotients and square roots

EPS = 2.0 ** -52
LOOSE = 256  # eps16 loose bar (spec/clauses.json)
# Conventions (rotorcert Q2R-1, as conformance/adapters/kingdon does it): quaternion (x, y, z, w)
# <-> rotor R = w - x e23 - y e31 - z e12, with e31 = -e13 in kingdon's basis.
alg = Algebra(3, 0, 0)


def rotor(x, y, z, w):
    return alg.multivector(e=w, e12=-z, e13=y, e23=-x)


def quat(R):
    return [-R.e23, R.e13, -R.e12, R.e]


def reference(q):
    """s = (|q| + q)/||q| + q|, [x, y, z, w], 60 digits."""
    x, y, z, w = (D(c) for c in q)
    n = (x * x + y * y + z * z + w * w).sqrt()
    a = [x, y, z, n + w]
    m = sum(c * c for c in a).sqrt()
    return [float(c / m) for c in a]


def error(got, ref):
    """METRIC-1 (sign-free rotation distance of the normalised outputs) and METRIC-6 (norm defect),
    the larger."""
    n = math.sqrt(sum(g * g for g in got))
    u = [g / n for g in got]
    dm = math.sqrt(sum((g - r) ** 2 for g, r in zip(u, ref)))
    dp = math.sqrt(sum((g + r) ** 2 for g, r in zip(u, ref)))
    return max(4 * math.atan2(min(dm, dp), max(dm, dp)), abs(n - 1))


print("rotorcert reproducer: kingdon %s %s: MultiVector.sqrt() forms w + |R|, which cancels near a full turn, "
      "and divides by 0 for -1" % (VERSION, CLAUSE))
print("  call:    R.sqrt(), R = alg.multivector(e=w, e12=-z, e13=y, e23=-x) of Algebra(3, 0, 0)")
# 1. The suite's worst input (near a full turn: 2 pi - 1e-9 .. 1e-1), [x, y, z, w].
h = float.fromhex
q = [h("-0x1.306b405fc2ca4p-35"), h("-0x1.27753211db02p-27"), h("-0x1.cad1e76f22aaap-28"), h("-0x1.fffffffffffffp-1")]
got = quat(rotor(*q).sqrt())
ref = reference(q)
err = error(got, ref)
print("  input:   q (x, y, z, w) = [%s]   (2.2e-8 rad short of a full turn)" % ", ".join(c.hex() for c in q))
print("  library: [%s]  (norm %.6g)" % (", ".join(repr(c) for c in got), math.sqrt(sum(c * c for c in got))))
print("  correct: [%s]  ((|q| + q)/||q| + q|, 60 digits)" % ", ".join(repr(c) for c in ref))
print("  error:   %.3g = %.3g eps (METRIC-1 and METRIC-6; loose bar %d eps)" % (err, err / EPS, LOOSE))
# 2. -1 (a negative real quaternion): a + sqrt(a^2) = 0.
try:
    m = quat(rotor(0.0, 0.0, 0.0, -1.0).sqrt())
    minus_one = "returned [%s]" % ", ".join(repr(c) for c in m)
    raised = False
except ZeroDivisionError as exc:
    minus_one = "raised ZeroDivisionError: %s" % exc
    raised = True
print("  input:   q = -1 = [0, 0, 0, -1]")
print("  library: %s" % minus_one)
print("  correct: [0, 0, 1, 0], +z (any unit pure quaternion is accepted)")
bad = err / EPS > LOOSE and raised
print("DEFECT SHOWN" if bad else "DEFECT NOT SHOWN")
sys.exit(0 if bad else 1)
