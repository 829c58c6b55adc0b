#!/usr/bin/env python3
"""rotorcert reproducer: numpy-quaternion accepts the zero quaternion in the product, np.log and slerp, clause EDGE-6.

EDGE-6 (spec/SPEC.md 9): a quaternion whose four components are +-0 is no rotation; compose, log and
every other rotation operation return DOMAIN_ERROR for it (an exception or all outputs NaN; class
outcome). numpy-quaternion is a general quaternion algebra and follows numpy's arithmetic:
  - np.quaternion(0, 0, 0, 0) * b is the zero quaternion (quaternion_multiply, src/quaternion.h), with
    no error;
  - np.log(np.quaternion(0, 0, 0, 0)) is (-inf, 0, 0, 0) (src/quaternion.c:64-76: |v| = 0 <= 1e-14 |w|,
    w = 0 is not < 0, so {log(w), 0, 0, 0}): the vector part, the rotation log, is the zero vector,
    i.e. the identity;
  - (inverse(), normalized(), as_rotation_matrix and rotate_vectors refuse it: ZeroDivisionError or NaN.)
Note for a maintainer: 0 * b = 0 and log 0 = -inf + 0 are the algebra's answers (numpy's np.log(0.0)
is -inf too); what rotorcert's clause asks is that a rotation library refuse them. This file shows the
behaviour the certificate records; whether numpy-quaternion should change it is the maintainer's call.
Upstream: no matching issue found in moble/quaternion.
Exit 0: defect shown; 1: not shown (fixed); 77: numpy-quaternion cannot be imported.
"""
import math
import sys

CLAUSE = "EDGE-6"
try:
    from importlib.metadata import version
    import numpy as np
    import quaternion
    VERSION = version("numpy-quaternion")
except Exception as exc:  # noqa: BLE001 - any import failure is a skip
    print("rotorcert reproducer: numpy-quaternion ? %s: SKIP: cannot import quaternion: %s" % (CLAUSE, exc))
    sys.exit(77)
np.seterr(all="ignore")  # numpy prints RuntimeWarnings for the 0/0 shown below; values unchanged

h = float.fromhex
b = (h("-0x1.6bc4b6dfc72a7p-2"), h("-0x1.9e235dc153f17p-2"), h("-0x1.ac77698dac623p-1"), h("-0x1.98009e358a0fep-4"))  # (w, x, y, z)
print("rotorcert reproducer: numpy-quaternion %s %s: the zero quaternion composes to 0 and has the rotation "
      "log (0, 0, 0), with no error" % (VERSION, CLAUSE))
shown = False
for call, fn in (("np.quaternion(0, 0, 0, 0) * np.quaternion(*b)", lambda: np.quaternion(0, 0, 0, 0) * np.quaternion(*b)),
                 ("np.log(np.quaternion(0, 0, 0, 0))", lambda: np.log(np.quaternion(0, 0, 0, 0)))):
    try:
        r = fn()
        out = [r.w, r.x, r.y, r.z]
        refused = all(math.isnan(c) for c in out[1:]) if "log" in call else all(math.isnan(c) for c in out)
        result = "quaternion(w, x, y, z) = [%s]" % ", ".join(c.hex() if math.isfinite(c) else str(c) for c in out)
    except Exception as exc:  # noqa: BLE001 - an exception is a refusal: the required outcome
        refused, result = True, "raised %s: %s" % (type(exc).__name__, exc)
    shown = shown or not refused
    print("  call:    %s" % call)
    print("  library: %s%s" % (result, "" if refused else "  <-- no error, not NaN"))
print("  input:   a (w, x, y, z) = [0x0p+0, 0x0p+0, 0x0p+0, 0x0p+0]; b (w, x, y, z) = [%s]" % ", ".join(c.hex() for c in b))
print("  correct: DOMAIN_ERROR (an exception or all outputs NaN): the zero quaternion is no rotation")
print("DEFECT SHOWN" if shown else "DEFECT NOT SHOWN")
sys.exit(0 if shown else 1)
