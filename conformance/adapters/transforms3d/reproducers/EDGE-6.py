#!/usr/bin/env python3
"""rotorcert reproducer: transforms3d quaternion functions of the zero quaternion, clause EDGE-6.

EDGE-6 (spec/SPEC.md 9): a quaternion whose four components are +-0 is not a rotation: DOMAIN_ERROR, every
output a quiet NaN (an exception, for a library without a status channel). transforms3d 0.4.2 has no zero
check and answers with a rotation instead:
  - quat2mat(0) returns the identity matrix (quaternions.py:131-132: "if Nq < _FLOAT_EPS: return np.eye(3)");
  - quat2axangle(0) returns angle 0 about [1, 0, 0] (quaternions.py:577-578), the identity;
  - qlog(0) returns qeye (quaternions.py:360-361), whose vector part is the zero (identity) log;
  - qmult(0, b) returns the zero quaternion (rotorcert's worst input, compose).
None of these is documented as a refusal of the zero quaternion.
Upstream: no matching issue found in matthew-brett/transforms3d (PR #24's review calls returning qeye for a
zero norm "questionable").
Exit 0: defect shown; 1: not shown (fixed); 77: transforms3d cannot be imported.
"""
import math
import sys

CLAUSE = "EDGE-6"
try:
    from importlib.metadata import version
    import numpy as np
    from transforms3d import quaternions as tq
    VERSION = version("transforms3d")
except Exception as exc:  # noqa: BLE001 - any import failure is a skip
    print("rotorcert reproducer: transforms3d ? %s: SKIP: cannot import transforms3d: %s" % (CLAUSE, exc))
    sys.exit(77)

np.seterr(all="ignore")
h = float.fromhex
zero = np.array([0.0, 0.0, 0.0, 0.0])  # [w, x, y, z]
# rotorcert's worst input: compose(a = 0, b), b stored (x, y, z, w).
bx, by, bz, bw = (h(s) for s in ("-0x1.9e235dc153f17p-2", "-0x1.ac77698dac623p-1", "-0x1.98009e358a0fep-4",
                                 "-0x1.6bc4b6dfc72a7p-2"))
b = np.array([bw, bx, by, bz])


def flat(value):
    if isinstance(value, tuple):
        return [c for part in value for c in flat(part)]
    return [float(c) for c in np.ravel(value)]


calls = [
    ("transforms3d.quaternions.quat2mat([0, 0, 0, 0])", lambda: tq.quat2mat(zero)),
    ("transforms3d.quaternions.quat2axangle([0, 0, 0, 0])  -> (vector, theta)", lambda: tq.quat2axangle(zero)),
    ("transforms3d.quaternions.qlog([0, 0, 0, 0])", lambda: tq.qlog(zero)),
    ("transforms3d.quaternions.qmult([0, 0, 0, 0], b), b (w, x, y, z) = [%s]"
     % ", ".join(c.hex() for c in (bw, bx, by, bz)), lambda: tq.qmult(zero, b)),
]
print("rotorcert reproducer: transforms3d %s %s: the zero quaternion is accepted: quat2mat gives the identity, "
      "quat2axangle angle 0, qmult 0, no error" % (VERSION, CLAUSE))
shown = False
for call, fn in calls:
    try:
        out = fn()
        values = flat(out)
        refused = all(math.isnan(c) for c in values)
        result = "%r" % (out,)
    except Exception as exc:  # noqa: BLE001 - an exception is a correct refusal (DOMAIN_ERROR)
        refused, result = True, "raised %s: %s" % (type(exc).__name__, exc)
    shown = shown or not refused
    print("  call:    %s" % call)
    print("  input:   q (x, y, z, w) = [0x0p+0, 0x0p+0, 0x0p+0, 0x0p+0]")
    print("  library: %s%s" % (" ".join(result.split()), "" if refused else "  (status OK)  <-- DEFECT"))
    print("  correct: DOMAIN_ERROR: an exception or every output NaN (EDGE-6, RESULT-2)")
print("DEFECT SHOWN" if shown else "DEFECT NOT SHOWN")
sys.exit(0 if shown else 1)
