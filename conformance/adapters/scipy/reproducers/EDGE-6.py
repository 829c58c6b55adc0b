#!/usr/bin/env python3
"""rotorcert reproducer: scipy RigidTransform.from_dual_quat of a zero real part, clause EDGE-6.

EDGE-6 (spec/SPEC.md 9): a dual quaternion whose real part is zero is no rigid motion: DOMAIN_ERROR (an
error, or every output NaN); since spec 2.2.0 ACC-1 zero_sentinel also accepts every output 0 or exactly
the output of the identity motion (the whole dual quaternion replaced by [0, 0, 0, 1, 0, 0, 0, 0]).
RigidTransform.from_dual_quat ("Initialize from a unit dual quaternion ...
This function will enforce both properties through normalization", scipy/spatial/transform/
_rigid_transform.py:809-822) instead replaces a zero real part by the identity
(_rigid_transform_cy.pyx:380-383 "# special case: real quaternion is 0, we set it to identity") and
reads the translation off the dual part, with no error and no warning; the docstring says nothing of
it. Rotation.from_quat refuses the same zero quaternion ("Found zero norm quaternions in `quat`"), so
from_dual_quat([0, 0, 0, 0, 1, 0, 0, 0]) silently becomes a translation by (2, 0, 0) where
Rotation.from_quat([0, 0, 0, 0]) raises: neither an error nor one of the two sentinels. Every RigidTransform built from such a dual quaternion (apply,
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
# (call, function, the identity motion's answer: ACC-1 zero_sentinel)
for call, fn, identity in (("RigidTransform.from_dual_quat(d).as_dual_quat()",
                            lambda: RigidTransform.from_dual_quat(d).as_dual_quat(), [0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0]),
                           ("RigidTransform.from_dual_quat(d).apply(p)", lambda: RigidTransform.from_dual_quat(d).apply(p), p)):
    try:
        out = [float(c) for c in fn()]
        result = "[%s]" % ", ".join(c.hex() for c in out)
        ok = all(not math.isfinite(c) for c in out) or all(c == 0 for c in out) or out == identity
    except Exception as exc:  # noqa: BLE001 - an exception is a correct refusal (DOMAIN_ERROR)
        result, ok = "raised %s: %s" % (type(exc).__name__, exc), True
    refused = refused and ok
    print("  call:    %s" % call)
    print("  input:   d = [%s], p = [%s]" % (", ".join(c.hex() for c in d), ", ".join(c.hex() for c in p)))
    print("  library: %s%s" % (result, "" if ok else "  (status OK: no error)  <-- DEFECT"))
print("  correct: DOMAIN_ERROR: an exception or all NaN (RESULT-2), as Rotation.from_quat(d[:4]) does: %s; "
      "acceptable (ACC-1 zero_sentinel): all zero, or the identity motion's answer ([0, 0, 0, 1, 0, 0, 0, 0]; p unmoved)" % quat)
print("DEFECT SHOWN" if not refused else "DEFECT NOT SHOWN")
sys.exit(0 if not refused else 1)
