#!/usr/bin/env python3
"""rotorcert reproducer: scipy RigidTransform.__pow__ rounds its exponent to binary32, clause DQ-5.

DQ-5 (spec/SPEC.md 8.4): ScLERP(a, b, t) = a (a* b')^t of unit dual quaternions, tolerance eps32 (loose
bar 512 eps, METRIC-7: rotation distance and translation error relative to max(1, |t|)).
RigidTransform.__pow__ is documented as "screw linear interpolation (ScLERP) between p and the identity
transform, where the angle of the rotation component is scaled by n" (scipy/spatial/transform/
_rigid_transform.py:1543-1641). The numpy (Cython) backend declares the exponent as a C float:
scipy/spatial/transform/_rigid_transform_cy.pyx:237 `def pow(double[:, :, :] matrix, float n)`, so every
fractional power is computed with n rounded to binary32 (relative error up to 2^-24, about 3e7 eps of
binary64): (RigidTransform.from_translation([1, 0, 0]) ** 0.1).translation is 0.10000000149011612. The
array-API backend (_rigid_transform_xp.py:219 pow(matrix, n: float | Array)) keeps n in binary64, and so
does Rotation.__pow__ (_rotation_cy.pyx:1289, untyped n); scipy's own equivalent spelling
RigidTransform.from_exp_coords(p.as_exp_coords() * n) (the __pow__ docstring) gives the right result.
Introduced with RigidTransform (scipy PR #22267, kept by #22972), still in scipy main (2026-08).
Upstream: no matching issue found in scipy/scipy.
Exit 0: defect shown; 1: not shown (fixed); 77: scipy cannot be imported.
"""
import math
import sys

CLAUSE = "DQ-5"
try:
    from importlib.metadata import version
    import numpy as np
    from scipy.spatial.transform import RigidTransform, Rotation
    VERSION = version("scipy")
except Exception as exc:  # noqa: BLE001 - any import failure is a skip
    print("rotorcert reproducer: scipy ? %s: SKIP: cannot import scipy: %s" % (CLAUSE, exc))
    sys.exit(77)

EPS = 2.0 ** -52
LOOSE = 512  # eps32 loose bar (spec/clauses.json)
h = float.fromhex
t = h("0x1.e54d2cf471b3ap-1")  # the certificate's worst t
t32 = float(np.float32(t))

print("rotorcert reproducer: scipy %s %s: RigidTransform ** n rounds n to binary32 "
      "(_rigid_transform_cy.pyx:237 `float n`), so ScLERP is off by up to 2^-24 relative" % (VERSION, CLAUSE))

# 1. A screw about its own axis (the z axis through the origin): rotation by 1 rad about z and
#    translation 4 along z. Its t-th power is the rotation by t rad about z and the translation 4 t
#    along z, exactly (both products are exact in binary64).
B = RigidTransform.from_components([0.0, 0.0, 4.0], Rotation.from_rotvec([0.0, 0.0, 1.0]))
got = B ** t
angle = got.rotation.as_rotvec()[2]
trans = got.translation
err_rot = abs(angle - t)  # the rotations are about the same axis: the distance is the angle difference
err_tr = math.sqrt(trans[0] ** 2 + trans[1] ** 2 + (trans[2] - 4 * t) ** 2) / max(1.0, 4 * t)
err1 = max(err_rot, err_tr)
print("  call:    B = RigidTransform.from_components([0, 0, 4], Rotation.from_rotvec([0, 0, 1])); (B ** t)")
print("  input:   t = %s  (as binary32: %s)" % (t.hex(), t32.hex()))
print("  library: rotation angle about z %s, translation [%s]" % (angle.hex(), ", ".join(float(c).hex() for c in trans)))
print("  correct: rotation angle about z %s (= t), translation [0x0p+0, 0x0p+0, %s] (= 4 t)  (closed form)"
      % (t.hex(), (4 * t).hex()))
print("  error:   %.3g rad, translation %.3g relative = %.4g eps (METRIC-7; bar %d eps)%s"
      % (err_rot, err_tr, err1 / EPS, LOOSE, "  <-- DEFECT" if err1 / EPS > LOOSE else ""))

# 2. The certificate's worst input, ScLERP(a, b, t) = A * (A.inv() * B) ** t, beside the same
#    expression with the power written as scipy documents it, from_exp_coords(as_exp_coords() * t).
a = [h(x) for x in ("-0x1.2a535abd5a995p-1", "0x1.2beb11d662b28p-1", "-0x1.ebb43e511d209p-2", "-0x1.2dac4d9497b9fp-2",
                    "0x1.ef2514a7f07b1p+2", "0x1.4b047e33ce81ep+0", "-0x1.60c65f70dfe9dp+3", "0x1.4f3cba51e7636p+2")]
b = [h(x) for x in ("-0x1.73a8969ba231p-3", "0x1.16316ca526b0cp-2", "-0x1.11f5f6c11da28p-3", "0x1.df0850a8e5916p-1",
                    "-0x1.2f4420081648bp-1", "-0x1.4378a7e5f0327p-6", "0x1.d1560c658d05ap-3", "-0x1.3a08b98264dccp-4")]
A, Bw = RigidTransform.from_dual_quat(a), RigidTransform.from_dual_quat(b)
rel = A.inv() * Bw
lib = A * rel ** t
f64 = A * RigidTransform.from_exp_coords(rel.as_exp_coords() * t)
diff = np.max(np.abs(lib.as_matrix() - f64.as_matrix()))
print("  call:    A, B = RigidTransform.from_dual_quat(a), (b); A * (A.inv() * B) ** t")
print("  input:   a = [%s]" % ", ".join(c.hex() for c in a))
print("           b = [%s]" % ", ".join(c.hex() for c in b))
print("           t = %s" % t.hex())
print("  library: translation [%s]" % ", ".join("%.17g" % c for c in lib.translation))
print("  binary64 exponent, A * from_exp_coords((A.inv() * B).as_exp_coords() * t): [%s]"
      % ", ".join("%.17g" % c for c in f64.translation))
print("  difference of the 4x4 matrices: %.3g (rotorcert's reference: 4.79e+09 eps off for the library,"
      " 25.6 eps for the binary64 exponent)" % diff)

shown = err1 / EPS > LOOSE
print("DEFECT SHOWN" if shown else "DEFECT NOT SHOWN")
sys.exit(0 if shown else 1)
