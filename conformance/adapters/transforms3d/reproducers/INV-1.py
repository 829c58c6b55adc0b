#!/usr/bin/env python3
"""rotorcert reproducer: transforms3d quaternions.qinverse of a non-unit quaternion, clause INV-1.

INV-1 (spec/SPEC.md 8.1): q^-1 = q*/|q|^2, defined on the unnormalised input; tolerance eps4
(componentwise relative error max_i |q_i - r_i| / |r|, loose bar 64 eps). transforms3d 0.4.2 qinverse
("Return multiplicative inverse of quaternion `q`") returns qconjugate(q) / qnorm(q) (quaternions.py:300):
it divides by |q|, not |q|^2, so for |q| != 1 the result is the unit conjugate q*/|q|, not the inverse --
q * qinverse(q) = |q|, not 1. Worked example EX-INV-1-d: q = 4 + 3i gives (0.8, -0.6, 0, 0) instead of
(0.16, -0.12, 0, 0). (For unit q the two agree, which is why its tests pass.)
Upstream: matthew-brett/transforms3d pull request #63 "Fixed qinverse function" (open since 2024-02-06:
"The denominator should be squared qnorm instead of qnorm").
Exit 0: defect shown; 1: not shown (fixed); 77: transforms3d cannot be imported.
"""
import sys
from fractions import Fraction as F

CLAUSE = "INV-1"
try:
    from importlib.metadata import version
    import numpy as np
    from transforms3d import quaternions as tq
    VERSION = version("transforms3d")
except Exception as exc:  # noqa: BLE001 - any import failure is a skip
    print("rotorcert reproducer: transforms3d ? %s: SKIP: cannot import transforms3d: %s" % (CLAUSE, exc))
    sys.exit(77)

EPS = 2.0 ** -52
LOOSE = 64  # eps4 loose bar (spec/clauses.json)
h = float.fromhex
# EX-INV-1-d, stored (x, y, z, w) = (3, 0, 0, 4) by rotorcert; transforms3d takes [w, x, y, z].
hexes = ["0x1.8p+1", "0x0p+0", "0x0p+0", "0x1p+2"]
x, y, z, w = (h(s) for s in hexes)
got = tq.qinverse(np.array([w, x, y, z]))
n2 = sum(F(c) * F(c) for c in (w, x, y, z))  # exact |q|^2
ref = [F(w) / n2, -F(x) / n2, -F(y) / n2, -F(z) / n2]  # q*/|q|^2, exact, (w, x, y, z)
nr = float(sum(r * r for r in ref)) ** 0.5
err = max(abs(F(float(g)) - r) for g, r in zip(got, ref))
err_rel = float(err) / nr
err_eps = err_rel / EPS
shown = not (err_eps <= LOOSE)
print("rotorcert reproducer: transforms3d %s %s: qinverse returns conj(q)/|q| instead of conj(q)/|q|^2 "
      "(q * qinverse(q) = |q|, not 1)" % (VERSION, CLAUSE))
print("  call:    transforms3d.quaternions.qinverse([w, x, y, z])")
print("  input:   q (x, y, z, w) = [%s]  (w, x, y, z) = (4, 3, 0, 0)" % ", ".join(hexes))
print("  library: (w, x, y, z) = [%s]  = %s" % (", ".join(float(c).hex() for c in got), [float(c) for c in got]))
print("  correct: conj(q)/|q|^2 = [%s]  = %s (exact fractions)" % (", ".join(float(r).hex() for r in ref),
                                                                    [str(r) for r in ref]))
print("  check:   qmult(q, qinverse(q)) = %s (should be [1, 0, 0, 0])" % [float(c) for c in tq.qmult([w, x, y, z], got)])
print("  error:   %.6g (componentwise relative) = %.4g eps (bar %d eps)%s" % (err_rel, err_eps, LOOSE,
                                                                          "  <-- DEFECT" if shown else ""))
print("DEFECT SHOWN" if shown else "DEFECT NOT SHOWN")
sys.exit(0 if shown else 1)
