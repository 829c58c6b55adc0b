#!/usr/bin/env python3
"""rotorcert reproducer: numpy-quaternion from_rotation_matrix of a reflection, clause MAT-3.

MAT-3 (spec/SPEC.md 8.1): from_matrix of M with det M <= 0 (a reflection, or singular) is DOMAIN_ERROR,
since no rotation, hence no quaternion, reproduces it (also EDGE-6; class inherited-mat, the status
part). quaternion.from_rotation_matrix (quaternion/__init__.py:273-358, default nonorthogonal=True)
takes the top eigenvector of Bar-Itzhack's matrix K(M) without looking at det M and returns a unit
quaternion for every input. Its docstring says "For any orthogonal matrix rot, this function returns a
quaternion q such that, for every pure-vector quaternion v, q * v * q.conjugate() == rot @ v.vec": for
the orthogonal matrix diag(1, 1, -1) it returns 1, which leaves e3 where rot sends it to -e3. The
zero matrix gets a quaternion too.
Upstream: no matching issue found in moble/quaternion.
Exit 0: defect shown; 1: not shown (fixed); 77: numpy-quaternion cannot be imported.
"""
import math
import sys
from decimal import Decimal as D, getcontext

CLAUSE = "MAT-3"
try:
    from importlib.metadata import version
    import numpy as np
    import quaternion
    VERSION = version("numpy-quaternion")
except Exception as exc:  # noqa: BLE001 - any import failure is a skip
    print("rotorcert reproducer: numpy-quaternion ? %s: SKIP: cannot import quaternion: %s" % (CLAUSE, exc))
    sys.exit(77)
getcontext().prec = 60  # the reference: exact inputs, 60-digit sums, quotients and square roots
np.seterr(all="ignore")  # numpy prints RuntimeWarnings for the overflows shown below; values unchanged

M = np.diag([1.0, 1.0, -1.0])  # column-major [0x1p+0, 0, 0, 0, 0x1p+0, 0, 0, 0, -0x1p+0] (EX-MAT-3-e), det -1
print("rotorcert reproducer: numpy-quaternion %s %s: from_rotation_matrix(diag(1, 1, -1)), a reflection, "
      "returns a unit quaternion with no error" % (VERSION, CLAUSE))
try:
    q = quaternion.from_rotation_matrix(M)
    got = [q.w, q.x, q.y, q.z]
    refused = all(math.isnan(c) for c in got)
    result = "quaternion(w, x, y, z) = [%s]" % ", ".join(c.hex() for c in got)
except Exception as exc:  # noqa: BLE001 - an exception is the required refusal
    refused, result, q = True, "raised %s: %s" % (type(exc).__name__, exc), None
print("  call:    quaternion.from_rotation_matrix(np.diag([1.0, 1.0, -1.0]))")
print("  input:   M = diag(1, 1, -1), det M = %g" % np.linalg.det(M))
print("  library: %s%s" % (result, "" if refused else "  <-- DEFECT (no error, not NaN)"))
if q is not None and not refused:
    e3 = np.quaternion(0, 0, 0, 1)
    print("           q * e3 * q.conjugate() = %s, while M @ e3 = %s" % ((q * e3 * q.conjugate()).vec, M @ [0.0, 0.0, 1.0]))
    z = quaternion.from_rotation_matrix(np.zeros((3, 3)))
    print("           from_rotation_matrix(zeros((3, 3))) = %s" % z)
print("  correct: DOMAIN_ERROR (an exception or all NaN): no quaternion q has q v q* = M v for det M <= 0")
print("DEFECT SHOWN" if not refused else "DEFECT NOT SHOWN")
sys.exit(0 if not refused else 1)
