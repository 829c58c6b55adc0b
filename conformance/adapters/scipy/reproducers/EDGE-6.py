#!/usr/bin/env python3
"""rotorcert reproducer: scipy RigidTransform.from_dual_quat of a zero real part, clause EDGE-6.

EDGE-6 (spec/SPEC.md 9): a dual quaternion whose real part is zero is no rigid motion: DOMAIN_ERROR (an
error, or every output NaN). RigidTransform.from_dual_quat ("Initialize from a unit dual quaternion ...
This function will enforce both properties through normalization", scipy/spatial/transform/
_rigid_transform.py:809-822) instead replaces a zero real part by the identity
(_rigid_transform_cy.pyx:380-383 "# special case: real quaternion is 0, we set it to identity") and
reads the translation off the dual part, with no error and no warning; the docstring says nothing of
it. Rotation.from_quat refuses the same zero quaternion ("Found zero norm quaternions in `quat`"), so
from_dual_quat([0, 0, 0, 0, 1, 0, 0, 0]) silently becomes a translation by (2, 0, 0) where
Rotation.from_quat([0, 0, 0, 0]) raises. Every RigidTransform built from such a dual quaternion (apply,
*, **, as_dual_quat) inherits the made-up motion.
Upstream: no matching issue found in scipy/scipy (the identity substitution dates from RigidTransform's
first implementation, scipy PR #22267, and was kept by #22618 and #22972).
Exit 0: defect shown; 1: not shown (fixed); 77: scipy cannot be imported.
"""
import math
import sys

CLAUSE = "EDGE-6"
try:
    from importlib.metadata import version
    from scipy.spatial.transform import RigidTransform, Rotation
    VERSION = version("scipy")
except Exception as exc:  # noqa: BLE001 - any import failure is a skip
    print("rotorcert reproducer: scipy ? %s: SKIP: cannot import scipy: %s" % (CLAUSE, exc))
    sys.exit(77)

d = [0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0]  # real part [x, y, z, w] = 0, dual part (1, 0, 0, 0) (EX-EDGE-6-j)
p = [0.0, 0.0, 0.0]

print("rotorcert reproducer: scipy %s %s: RigidTransform.from_dual_quat accepts a zero real part and "
      "returns a translation, with no error" % (VERSION, CLAUSE))
try:
    Rotation.from_quat(d[:4])
    quat = "returned a rotation"
except Exception as exc:  # noqa: BLE001
    quat = "raised %s: %s" % (type(exc).__name__, exc)
refused = True
for call, fn in (("RigidTransform.from_dual_quat(d).as_dual_quat()", lambda: RigidTransform.from_dual_quat(d).as_dual_quat()),
                 ("RigidTransform.from_dual_quat(d).apply(p)", lambda: RigidTransform.from_dual_quat(d).apply(p))):
    try:
        out = [float(c) for c in fn()]
        result = "[%s]" % ", ".join(c.hex() for c in out)
        ok = all(math.isnan(c) for c in out)
    except Exception as exc:  # noqa: BLE001 - an exception is a correct refusal (DOMAIN_ERROR)
        result, ok = "raised %s: %s" % (type(exc).__name__, exc), True
    refused = refused and ok
    print("  call:    %s" % call)
    print("  input:   d = [%s], p = [%s]" % (", ".join(c.hex() for c in d), ", ".join(c.hex() for c in p)))
    print("  library: %s%s" % (result, "" if ok else "  (status OK: no error)  <-- DEFECT"))
print("  correct: DOMAIN_ERROR: an exception or all NaN (RESULT-2), as Rotation.from_quat(d[:4]) does: %s" % quat)
print("DEFECT SHOWN" if not refused else "DEFECT NOT SHOWN")
sys.exit(0 if not refused else 1)
