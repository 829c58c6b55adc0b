#!/usr/bin/env python3
"""rotorcert reproducer: transforms3d quaternion functions of NaN / Inf input, clause EDGE-7.

EDGE-7 (spec/SPEC.md 9): NaN or +-Inf in any input component is DOMAIN_ERROR with every output a quiet NaN
(an exception, for a library without a status channel), "even if the result would be mathematically defined
(normalize((Inf, 0, 0, 1)) is DOMAIN_ERROR, not (1, 0, 0, 0))". transforms3d 0.4.2 has no finiteness check
and returns partly finite results without an error:
  - q / qnorm(q) (its normalisation, quaternions.py:440) of (x, y, z, w) = (0, inf, 0, 1) is
    (w, x, y, z) = (0, 0, nan, 0) (rotorcert's worst input, EX-EDGE-7-b);
  - mat2quat of a matrix with one infinite entry returns the finite unit quaternion [0, 1, 0, 0];
  - quat2mat of a quaternion with w = inf returns a matrix with 1 on the diagonal and NaN elsewhere;
  - qmult passes infinities through as +-inf components.
(quat2axangle documents its answer to non-finite input -- a NaN angle beside the vector [1, 0, 0],
quaternions.py:555-559 -- which is still partly finite, but is not what this reproducer relies on.)
Upstream: no matching issue found in matthew-brett/transforms3d.
Exit 0: defect shown; 1: not shown (fixed); 77: transforms3d cannot be imported.
"""
import math
import sys

CLAUSE = "EDGE-7"
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
inf = math.inf
q_inf = np.array([1.0, 0.0, inf, 0.0])  # [w, x, y, z] of (x, y, z, w) = (0, inf, 0, 1), EX-EDGE-7-b
# rotorcert's from_matrix input "+Inf in m" (column-major m[c*3 + r]), as the row-major M transforms3d takes.
m = [h(s) for s in ("-0x1.6d3e312fc4669p-1", "0x1.610b3b2c837ccp-2", "-0x1.38616b22654e5p-1", "-0x1.c816a296cd785p-2",
                    "-0x1.ca58bc7b781d7p-1", "0x1.e84983a9ef1c7p-7", "-0x1.1503e5c8b4bb5p-1", "0x1.2127308e72ee5p-2")] + [inf]
M = np.array(m).reshape(3, 3).T
b = np.array([0.5, 0.5, 0.5, 0.5])

calls = [
    ("Q = [w, x, y, z]; Q / transforms3d.quaternions.qnorm(Q)", "q (x, y, z, w) = [0x0p+0, inf, 0x0p+0, 0x1p+0]",
     lambda: q_inf / tq.qnorm(q_inf)),
    ("transforms3d.quaternions.mat2quat(M)", "M (rows) = %s" % [[float(c).hex() for c in row] for row in M],
     lambda: tq.mat2quat(M)),
    ("transforms3d.quaternions.quat2mat([w, x, y, z])", "q (w, x, y, z) = [inf, 0x1p-1, 0x1p-1, 0x1p-1]",
     lambda: tq.quat2mat(np.array([inf, 0.5, 0.5, 0.5]))),
    ("transforms3d.quaternions.qmult(a, b)", "a (w, x, y, z) = [0x1p-1, inf, 0x1p-1, 0x1p-1], b = [0x1p-1] * 4",
     lambda: tq.qmult(np.array([0.5, inf, 0.5, 0.5]), b)),
]
print("rotorcert reproducer: transforms3d %s %s: NaN/Inf input gives partly finite results with no error "
      "(normalisation, mat2quat, quat2mat, qmult)" % (VERSION, CLAUSE))
shown = False
for call, inp, fn in calls:
    try:
        out = fn()
        values = [float(c) for c in np.ravel(out)]
        refused = all(math.isnan(c) for c in values)
        result = "[%s]" % ", ".join(c.hex() if math.isfinite(c) else repr(c) for c in values)
    except Exception as exc:  # noqa: BLE001 - an exception is a correct refusal (DOMAIN_ERROR)
        refused, result = True, "raised %s: %s" % (type(exc).__name__, exc)
    shown = shown or not refused
    print("  call:    %s" % call)
    print("  input:   %s" % inp)
    print("  library: %s%s" % (result, "" if refused else "  (not all NaN, no error)  <-- DEFECT"))
    print("  correct: DOMAIN_ERROR: an exception or every output NaN (EDGE-7, RESULT-2)")
print("DEFECT SHOWN" if shown else "DEFECT NOT SHOWN")
sys.exit(0 if shown else 1)
