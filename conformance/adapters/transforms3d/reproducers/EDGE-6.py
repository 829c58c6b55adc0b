#!/usr/bin/env python3
"""rotorcert reproducer: transforms3d axangle2quat of a zero axis, clause EDGE-6.

EDGE-6 (spec/SPEC.md 9): a zero axis (AXANG-2; also with angle 0) is no rotation: DOMAIN_ERROR, every
output a quiet NaN (an exception, for a library without a status channel). Since spec 2.2.0 ACC-1
zero_sentinel also accepts status OK with every output 0, or exactly the identity's answer (+z at angle 0:
[w, x, y, z] = [1, 0, 0, 0]). transforms3d 0.4.2 has no zero check in axangle2quat: it divides the axis by
its norm, 0/0 = NaN, and returns cos(theta/2) beside it (quaternions.py:509-518): a partly-NaN
quaternion, which is neither a refusal nor a sentinel (RESULT-2: a finite component fails). (quat2mat(0) =
I, quat2axangle(0) = angle 0, qlog(0) = qeye and qmult(0, b) = 0 are ACC-1 zero_sentinel answers since
2.2.0 and no longer a defect.)
Upstream: no matching issue found in matthew-brett/transforms3d.
Exit 0: defect shown; 1: not shown (fixed); 77: transforms3d cannot be imported.
"""
import math
import sys
import warnings

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
warnings.simplefilter("ignore")  # numpy's 0/0 RuntimeWarning; it changes no value
# rotorcert's worst input: EX-AXANG-2-g, from_axis_angle angle = pi/2 (rounded), axis = 0.
theta = float.fromhex("0x1.921fb54442d18p+0")
axis = [0.0, 0.0, 0.0]
print("rotorcert reproducer: transforms3d %s %s: axangle2quat of a zero axis returns [cos(theta/2), nan, nan, nan] "
      "with no error" % (VERSION, CLAUSE))
try:
    out = [float(c) for c in tq.axangle2quat(axis, theta)]  # [w, x, y, z]
    nonfinite = all(not math.isfinite(c) for c in out)
    zeros = all(c == 0 for c in out)
    identity = out == [1.0, 0.0, 0.0, 0.0]
    shown = not (nonfinite or zeros or identity)
    result = "[%s] (w, x, y, z)%s" % (", ".join(c.hex() for c in out), "  (partly NaN, status OK)  <-- DEFECT" if shown else "")
except Exception as exc:  # noqa: BLE001 - an exception is a correct refusal (DOMAIN_ERROR)
    shown, result = False, "raised %s: %s" % (type(exc).__name__, exc)
print("  call:    transforms3d.quaternions.axangle2quat(vector, theta)   (is_normalized=False, its default)")
print("  input:   vector = [%s], theta = %s" % (", ".join(c.hex() for c in axis), theta.hex()))
print("  library: %s" % result)
print("  correct: DOMAIN_ERROR: an exception or every output NaN (EDGE-6, RESULT-2); acceptable (ACC-1 "
      "zero_sentinel): [0, 0, 0, 0] or the identity [1, 0, 0, 0]")
print("DEFECT SHOWN" if shown else "DEFECT NOT SHOWN")
sys.exit(0 if shown else 1)
