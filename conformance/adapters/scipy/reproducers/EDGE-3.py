#!/usr/bin/env python3
"""rotorcert reproducer: scipy RigidTransform.__pow__ (ScLERP) across a relative half turn, clause EDGE-3.

EDGE-3 (spec/SPEC.md 9): where the real parts are orthogonal (a_r . b_r = 0, a relative half turn) ScLERP
may take either hemisphere (ACC-1 hemisphere_tie), but the interpolation along the one it takes must be
within the class (dq_sclerp: eps32, loose bar 512 eps). scipy takes the principal root of the relative
transform (the __pow__ docstring), which at a tie is a legitimate choice; but the numpy (Cython) backend
declares the exponent as a C float (scipy/spatial/transform/_rigid_transform_cy.pyx:237
`def pow(double[:, :, :] matrix, float n)`), so the screw is advanced by binary32(t) instead of t.
(Same root cause as DQ-5: with the exponent kept in binary64, the certificate's worst input is 3.4 eps
from the other-hemisphere answer; as computed it is 7.7e6 eps from it.)
Upstream: no matching issue found in scipy/scipy.
Exit 0: defect shown; 1: not shown (fixed); 77: scipy cannot be imported.
"""
import math
import sys

CLAUSE = "EDGE-3"
try:
    from importlib.metadata import version
    import numpy as np
    from scipy.spatial.transform import RigidTransform, Rotation
    VERSION = version("scipy")
except Exception as exc:  # noqa: BLE001 - any import failure is a skip
    print("rotorcert reproducer: scipy ? %s: SKIP: cannot import scipy: %s" % (CLAUSE, exc))
    sys.exit(77)

EPS = 2.0 ** -52
LOOSE = 512  # eps32 loose bar of dq_sclerp
t = float.fromhex("0x1.03923404ae0ccp-1")  # the certificate's worst t

print("rotorcert reproducer: scipy %s %s: ScLERP from the identity to a half turn about z with a translation "
      "of 2 along z advances the screw by binary32(t), not t" % (VERSION, CLAUSE))
# B: the half turn about z (quaternion (0, 0, 1, 0): dot with the identity exactly 0) and the
# translation 2 along the axis. Its t-th power is the rotation by +-t pi about z (either hemisphere)
# and the translation 2 t along z (the same for both): a screw along its own axis.
B = RigidTransform.from_components([0.0, 0.0, 2.0], Rotation.from_quat([0.0, 0.0, 1.0, 0.0]))
got = B ** t
rv = got.rotation.as_rotvec()
tr = got.translation
angle = abs(rv[2])
err_rot = abs(angle - t * math.pi) + abs(rv[0]) + abs(rv[1])  # t * math.pi: within 2 ulps of t pi
err_tr = math.sqrt(tr[0] ** 2 + tr[1] ** 2 + (tr[2] - 2 * t) ** 2) / max(1.0, 2 * t)
err = max(err_rot, err_tr)
print("  call:    B = RigidTransform.from_components([0, 0, 2], Rotation.from_quat([0, 0, 1, 0])); (B ** t)")
print("  input:   t = %s (binary32(t) = %s)" % (t.hex(), float(np.float32(t)).hex()))
print("  library: rotvec [%s], translation [%s]" % (", ".join(float(c).hex() for c in rv), ", ".join(float(c).hex() for c in tr)))
print("  correct: rotvec [0, 0, +-%s] (+-t pi, either hemisphere), translation [0, 0, %s] (2 t)  (closed form)"
      % ((t * math.pi).hex(), (2 * t).hex()))
print("  error:   rotation %.3g rad, translation %.3g relative = %.4g eps (METRIC-7, bar %d eps)%s"
      % (err_rot, err_tr, err / EPS, LOOSE, "  <-- DEFECT" if err / EPS > LOOSE else ""))
shown = err / EPS > LOOSE
print("DEFECT SHOWN" if shown else "DEFECT NOT SHOWN")
sys.exit(0 if shown else 1)
