#!/usr/bin/env python3
"""rotorcert reproducer: clifford (pygae) clifford.tools.g3c.square_roots_of_rotor, clause SQRT-1.

SQRT-1 (spec/SPEC.md 6, level Extended, eps16: METRIC-1 and METRIC-6, loose bar 256 eps): the rotor
square root s = (1 + R^)/|1 + R^| of R^ = R/|R|, (cos(theta/4), sin(theta/4) u), any unit bivector for
R^ = -1; "1 + w of q^ cancels near q^ = -1 and SHOULD be formed as |v^|^2/(1 - w^) there".
clifford's square root is clifford.tools.g3c.square_roots_of_rotor(R) ("Square Root and Logarithm of
Rotors in 3D Conformal Geometric Algebra Using Polar Decomposition", Dorst and Valkenburg) =
pos_twiddle_root(1 + R), [0] being the root clifford's own n_th_rotor_root takes: the normalisation of
1 + R. It adds the scalar 1 where |R| is meant: for a rotor a rounding away from unit (|R| - 1 ~ 1e-17)
near a full turn, 1 + w loses everything (w = -1 exactly: 1 + w = 0 while |R| + w = |v|^2/2), so the
scalar part of the root, cos(theta/4) ~ |v|/2, comes back 0 (a rotation 1.1e-8 rad off, 4.7e7 eps);
and for R = -1 it is 0/0: NaN.
Upstream: no matching issue found in pygae/clifford.
Exit 0: defect shown; 1: not shown (fixed); 77: clifford cannot be imported.
"""
import math
import sys
import warnings

CLAUSE = "SQRT-1"
try:
    import numpy as np
    import clifford
    from clifford.tools.g3 import quaternion_to_rotor, rotor_to_quaternion
    from clifford.tools.g3c import square_roots_of_rotor
except Exception as exc:  # noqa: BLE001 - any import failure is a skip
    print("rotorcert reproducer: clifford ? %s: SKIP: cannot import clifford: %s" % (CLAUSE, exc))
    sys.exit(77)
warnings.simplefilter("ignore")
np.seterr(all="ignore")

from decimal import Decimal as D, getcontext  # noqa: E402 - after the skip
getcontext().prec = 60
EPS = 2.0 ** -52
LOOSE = 256  # eps16 loose bar (spec/clauses.json)


def hx(f):
    """C99 hexfloat without trailing zeros, as the report prints it."""
    m, e = f.hex().split("p")
    return (m.rstrip("0").rstrip(".") if "." in m else m) + "p" + e


def reference(q):
    """s = (|q| + q)/||q| + q| of q = [w, x, y, z], 60 digits."""
    w, x, y, z = (D(c) for c in q)
    n = (w * w + x * x + y * y + z * z).sqrt()
    a = [n + w, x, y, z]
    m = sum(c * c for c in a).sqrt()
    return [float(c / m) for c in a]


def error(got, ref):
    """METRIC-1 (sign-free distance of the normalised outputs) and METRIC-6 (norm defect), the larger."""
    n = math.sqrt(sum(g * g for g in got))
    u = [g / n for g in got]
    dm = math.sqrt(sum((g - r) ** 2 for g, r in zip(u, ref)))
    dp = math.sqrt(sum((g + r) ** 2 for g, r in zip(u, ref)))
    return max(4 * math.atan2(min(dm, dp), max(dm, dp)), abs(n - 1))


print("rotorcert reproducer: clifford %s %s: square_roots_of_rotor normalises 1 + R, which loses the root near a "
      "full turn and is NaN for -1" % (clifford.__version__, CLAUSE))
print("  call:    square_roots_of_rotor(quaternion_to_rotor([w, x, y, z]))[0], read by rotor_to_quaternion")
# 1. The suite's worst input (near a full turn: 2 pi - 1e-9 .. 1e-1), (x, y, z, w) as the report prints it.
h = float.fromhex
x, y, z, w = (h("-0x1.48c4912edc91fp-27"), h("-0x1.32fa50568700ap-29"), h("-0x1.0320dd3e7b485p-28"), h("-0x1p+0"))
got = [float(c) for c in rotor_to_quaternion(square_roots_of_rotor(quaternion_to_rotor(np.array([w, x, y, z])))[0])]
ref = reference([w, x, y, z])
err = error(got, ref)
print("  input:   q (x, y, z, w) = [%s]   (%.3g rad short of a full turn)" % (", ".join(hx(c) for c in (x, y, z, w)),
                                                                         2 * math.hypot(x, y, z)))
print("  library: (w, x, y, z) = [%s]" % ", ".join(repr(c) for c in got))
print("  correct: (w, x, y, z) = [%s]  ((|q| + q)/||q| + q|, 60 digits)" % ", ".join(repr(c) for c in ref))
print("  error:   %.3g rad = %.3g eps (METRIC-1 and METRIC-6; loose bar %d eps)" % (err, err / EPS, LOOSE))
# 2. -1: 1 + R = 0.
m = [float(c) for c in rotor_to_quaternion(square_roots_of_rotor(quaternion_to_rotor(np.array([-1.0, 0.0, 0.0, 0.0])))[0])]
print("  input:   q = -1 = (w, x, y, z) [-1, 0, 0, 0]")
print("  library: (w, x, y, z) = [%s]" % ", ".join(repr(c) for c in m))
print("  correct: (w, x, y, z) = [0, 0, 0, 1], +z (any unit pure quaternion is accepted)")
bad = err / EPS > LOOSE and all(math.isnan(c) for c in m)
print("DEFECT SHOWN" if bad else "DEFECT NOT SHOWN")
sys.exit(0 if bad else 1)
