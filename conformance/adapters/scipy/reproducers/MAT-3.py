#!/usr/bin/env python3
"""rotorcert reproducer: scipy Rotation.from_matrix of a matrix whose determinant underflows, clause MAT-3.

MAT-3 (spec/SPEC.md 8.1): a finite M with det M > 0 has a nearest rotation (its orthogonal polar
factor); DOMAIN_ERROR is for det M <= 0 only, or where the format cannot decide the sign of det M
(|det M| <= 8u per(|M|)). Rotation.from_matrix documents "If the input is not orthogonal, an
approximation is created by orthogonalizing the input matrix" (scipy/spatial/transform/_rotation.py,
from_matrix), and orthogonalizes with an SVD (U V^T), which is exact for any scale. But its domain test
is dets = np.linalg.det(matrix); `if np.any(dets <= 0): raise ValueError("Non-positive determinant
(left-handed or null coordinate frame) ...")` (_rotation_cy.pyx from_matrix; _rotation_xp.py:53 for the
other array backends): det M computed without scaling underflows to 0 whenever |det M| < 2^-1074,
e.g. for s I with s < ~1e-108, and the call raises for a matrix whose determinant is positive and whose
nearest rotation is the identity. Testing the sign on M scaled by a power of two (or the sign of the SVD's
singular values with det(U V^T)) fixes it.
Upstream: no matching issue found in scipy/scipy; the check came with the SVD orthogonalization of
scipy/scipy#22418 ("handling arbitrary user inputs").
Exit 0: defect shown; 1: not shown (fixed); 77: scipy cannot be imported.
"""
import math
import sys

CLAUSE = "MAT-3"
try:
    from importlib.metadata import version
    from scipy.spatial.transform import Rotation
    import numpy as np
    VERSION = version("scipy")
except Exception as exc:  # noqa: BLE001 - any import failure is a skip
    print("rotorcert reproducer: scipy ? %s: SKIP: cannot import scipy: %s" % (CLAUSE, exc))
    sys.exit(77)

EPS = 2.0 ** -52
h = float.fromhex
# (matrix as rows, its nearest rotation as scipy's [x, y, z, w], why)
CASES = [
    ([[2.0 ** -400, 0, 0], [0, 2.0 ** -400, 0], [0, 0, 2.0 ** -400]], [0.0, 0.0, 0.0, 1.0],
     "2^-400 I: det = 2^-1200 > 0, polar factor I"),
    # The suite's worst input (column-major m = [0x1p-960, 0, 0, 0, -0x1p-648, 0, 0, 0, -0x1p-25]):
    # diag(2^-960, -2^-648, -2^-25), det = 2^-1633 > 0, polar factor diag(1, -1, -1), a half turn about x.
    ([[h("0x1p-960"), 0, 0], [0, -h("0x1p-648"), 0], [0, 0, -h("0x1p-25")]], [1.0, 0.0, 0.0, 0.0],
     "diag(2^-960, -2^-648, -2^-25): det = 2^-1633 > 0, polar factor diag(1, -1, -1)"),
]

print("rotorcert reproducer: scipy %s %s: Rotation.from_matrix raises 'Non-positive determinant' for "
      "matrices with det > 0 whose determinant underflows" % (VERSION, CLAUSE))
shown = False
for rows, want, why in CASES:
    try:
        got = [float(c) for c in Rotation.from_matrix(np.array(rows)).as_quat()]
        # q and -q are one rotation: compare against the nearer sign.
        err = min(max(abs(a - b) for a, b in zip(got, want)), max(abs(a + b) for a, b in zip(got, want)))
        result = "[%s]" % ", ".join(c.hex() for c in got)
    except Exception as exc:  # noqa: BLE001 - refusing a matrix with det > 0 is the defect (wrong status)
        result, err = "raised %s: %s" % (type(exc).__name__, str(exc).splitlines()[0]), math.nan
    bad = math.isnan(err)  # the status is wrong; any unit answer near the polar factor would pass
    shown = shown or bad
    print("  call:    Rotation.from_matrix(M).as_quat()")
    print("  input:   M (rows) = %s  (%s)" % ([[float(c).hex() for c in r] for r in rows], why))
    print("  library: %s" % result)
    print("  correct: [%s] (the polar factor's quaternion, exact)" % ", ".join(c.hex() for c in want))
    print("  error:   %s%s" % ("a spurious DOMAIN_ERROR" if bad else "eps: %g" % (err / EPS), "  <-- DEFECT" if bad else ""))
print("DEFECT SHOWN" if shown else "DEFECT NOT SHOWN")
sys.exit(0 if shown else 1)
