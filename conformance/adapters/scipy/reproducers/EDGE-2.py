#!/usr/bin/env python3
"""rotorcert reproducer: scipy RigidTransform.__pow__ (ScLERP) at small angles, clause EDGE-2.

EDGE-2 (spec/SPEC.md 9): for rotation angles from 1e-9 to 1e-3 rad (and their differences in
interpolation) the result is within the operation's own class (dq_sclerp: eps32, loose bar 512 eps;
EDGE-2's own class eps16, loose bar 256 eps). The numpy (Cython) backend of RigidTransform.__pow__
declares its exponent as a C float (scipy/spatial/transform/_rigid_transform_cy.pyx:237
`def pow(double[:, :, :] matrix, float n)`), so p ** t is the power to binary32(t): a small relative
rotation is scaled by a wrong factor. (Same root cause as DQ-5; the small-angle series of
_compute_se3_exp/log_translation_transform are fine: with t kept in binary64, through scipy's documented
equivalent from_exp_coords(p.as_exp_coords() * t), the certificate's worst input is 0.8 eps off.)
Upstream: no matching issue found in scipy/scipy.
Exit 0: defect shown; 1: not shown (fixed); 77: scipy cannot be imported.
"""
import sys

CLAUSE = "EDGE-2"
try:
    from importlib.metadata import version
    import numpy as np
    from scipy.spatial.transform import RigidTransform, Rotation
    VERSION = version("scipy")
except Exception as exc:  # noqa: BLE001 - any import failure is a skip
    print("rotorcert reproducer: scipy ? %s: SKIP: cannot import scipy: %s" % (CLAUSE, exc))
    sys.exit(77)

EPS = 2.0 ** -52
LOOSE = 512  # dq_sclerp's class eps32 (the larger of eps16 and the op's class)
h = float.fromhex
t = h("0x1.c67248fe02c8cp-1")  # the certificate's worst t
theta = 1e-4  # an ordinary small rotation (rad)

print("rotorcert reproducer: scipy %s %s: RigidTransform ** t of a 1e-4 rad rotation is the power to "
      "binary32(t) (_rigid_transform_cy.pyx:237 `float n`)" % (VERSION, CLAUSE))
# A pure rotation by theta about z: its t-th power is the rotation by t * theta about z.
P = RigidTransform.from_rotation(Rotation.from_rotvec([0.0, 0.0, theta]))
got = (P ** t).rotation.as_rotvec()
want = t * theta  # correctly rounded product: within half an ulp of the exact angle
err = abs(got[2] - want) + abs(got[0]) + abs(got[1])  # rotation distance about a common axis
print("  call:    P = RigidTransform.from_rotation(Rotation.from_rotvec([0, 0, 1e-4])); (P ** t).rotation.as_rotvec()")
print("  input:   theta = %s, t = %s (binary32(t) = %s)" % (theta.hex(), t.hex(), float(np.float32(t)).hex()))
print("  library: rotvec [%s]" % ", ".join(float(c).hex() for c in got))
print("  correct: rotvec [0x0p+0, 0x0p+0, %s] (t * theta, closed form)" % want.hex())
print("  error:   %.3g rad = %.4g eps (bar %d eps)%s" % (err, err / EPS, LOOSE, "  <-- DEFECT" if err / EPS > LOOSE else ""))

# The certificate's worst input: a and b about 2e-4 rad apart.
a = [h(x) for x in ("-0x1.8b227454d8bccp-1", "0x1.91fd4b6aef619p-3", "0x1.40399a26e227cp-7", "0x1.35a86056bbe89p-1",
                    "-0x1.f90c84bfd012dp-2", "-0x1.d41a695c4a9f6p+0", "-0x1.a2ff5c2d2e4b2p+0", "-0x1.366cbad83fcf4p-7")]
b = [h(x) for x in ("-0x1.8b149d06a9b91p-1", "0x1.9189b41c86428p-3", "0x1.47f43570496a5p-7", "0x1.35c2e66bfa384p-1",
                    "-0x1.f913fbf57f85ap-2", "-0x1.d419eff521f67p+0", "-0x1.a2ff55fab28p+0", "-0x1.35b16b992327fp-7")]
A, B = RigidTransform.from_dual_quat(a), RigidTransform.from_dual_quat(b)
rel = A.inv() * B
lib = (A * rel ** t).as_matrix()
f64 = (A * RigidTransform.from_exp_coords(rel.as_exp_coords() * t)).as_matrix()
print("  call:    A, B = RigidTransform.from_dual_quat(a), (b); A * (A.inv() * B) ** t")
print("  input:   a = [%s]" % ", ".join(c.hex() for c in a))
print("           b = [%s]" % ", ".join(c.hex() for c in b))
print("  library - binary64 exponent (from_exp_coords(as_exp_coords() * t)): max |matrix difference| = %.3g"
      " (rotorcert: 1.05e+05 eps for the library, 0.8 eps with the binary64 exponent)" % np.max(np.abs(lib - f64)))
shown = err / EPS > LOOSE
print("DEFECT SHOWN" if shown else "DEFECT NOT SHOWN")
sys.exit(0 if shown else 1)
