#!/usr/bin/env python3
"""rotorcert reproducer: PyGLM glm.log / glm.normalize / glm.mat3_cast of subnormal quaternions, clause EDGE-8.

EDGE-8 (spec/SPEC.md 9): subnormal components are ordinary nonzero values, -0 counts as +0; the result
is the operation's on q/|q| (eps4 numeric part, or the op's class). glm.quat is binary32, and every
component below is a binary32 subnormal (or -0): their squares underflow to 0.
  - glm.log(q) (PyGLM_lib/glm/glm/ext/quaternion_exponential.inl:17-38) compares |v| with the absolute
    epsilon<float>() = 2^-23; for |v| < epsilon it treats q as real, and with w = -0 (neither > 0 nor
    < 0) it returns (inf, inf, inf, inf) (:29-30): the clause's worst input, whose log is
    atan2(|v|, 0) v/|v| = (pi/2) u;
  - glm.normalize(q) divides by sqrt(dot(q, q)), which underflows to 0, and returns the identity
    ("if(len <= 0)", ext/quaternion_geometric.inl:19-21), pi rad from q/|q|;
  - glm.mat3_cast(q) builds 1 - 2(y^2 + z^2), ... from q as given (gtc/quaternion.inl:47-72): every
    square underflows and the identity matrix comes back for a half turn.
(q * v, glm.slerp and glm.log of a subnormal vector part beside w = -1 fail likewise; see
expected_failures.json.)
Upstream: no matching issue found in g-truc/glm or Zuzu-Typ/PyGLM.
Exit 0: defect shown; 1: not shown (fixed); 77: PyGLM cannot be imported.
"""
import math
import sys

CLAUSE = "EDGE-8"
try:
    from importlib.metadata import version
    import glm
    VERSION = version("PyGLM")
except Exception as exc:  # noqa: BLE001 - any import failure is a skip
    print("rotorcert reproducer: PyGLM ? %s: SKIP: cannot import glm: %s" % (CLAUSE, exc))
    sys.exit(77)

from fractions import Fraction as F  # noqa: E402 - after the skip
from decimal import Decimal as D, getcontext  # noqa: E402

getcontext().prec = 60
EPS = 2.0 ** -23  # glm.quat is binary32
LOOSE = 256       # the loosest bar of the ops below (eps16); EDGE-8's own class is eps4 (64)
h = float.fromhex
# pi to 60 digits (for the log's reference atan2(|v|, 0) = pi/2)
PI = D("3.14159265358979323846264338327950288419716939937510582097494")


def hx(f):
    """A binary32 value as the report prints it: C99 hexfloat without trailing zeros."""
    s = float(f).hex()
    if "p" not in s:
        return s
    m, e = s.split("p")
    return m.rstrip("0").rstrip(".") + "p" + e


def report(call, q, got, ref, err, metric):
    print("  call:    %s" % call)
    print("  input:   q (x, y, z, w) = [%s]" % ", ".join(hx(c) for c in q))
    print("  library: [%s]" % ", ".join(hx(c) for c in got))
    print("  correct: [%s]" % ", ".join("%.6g" % c for c in ref))
    print("  error:   %s (%s)%s" % ("%.3g eps" % err if math.isfinite(err) else "not finite", metric,
                                    "  <-- DEFECT" if not err <= LOOSE else ""))
    return err


print("rotorcert reproducer: PyGLM %s %s: subnormal quaternions: glm.log gives inf, glm.normalize and "
      "glm.mat3_cast the identity" % (VERSION, CLAUSE))
errors = []

# 1. glm.log (the clause's worst input): w = -0, so the log is (pi/2) v/|v|.
q = [h("0x1p-138"), h("0x1p-145"), h("0x1.4p-142"), -0.0]
r = glm.log(glm.quat(q[3], q[0], q[1], q[2]))
got = [r.x, r.y, r.z]
n = sum(D(c) ** 2 for c in q[:3]).sqrt()
ref = [PI / 2 * D(c) / n for c in q[:3]]
err = (float(sum((D(g) - c) ** 2 for g, c in zip(got, ref)).sqrt()) / EPS
       if all(math.isfinite(g) for g in got) else math.inf)
errors.append(report("glm.log(glm.quat(w, x, y, z)), vector part", q, got, [float(c) for c in ref], err, "METRIC-5"))

# 2. glm.normalize: the identity instead of q/|q|.
q = [h("0x1.cp-143"), h("0x1p-145"), h("0x1p-146"), -0.0]
r = glm.normalize(glm.quat(q[3], q[0], q[1], q[2]))
got = [r.x, r.y, r.z, r.w]
n = sum(D(c) ** 2 for c in q).sqrt()
ref = [D(c) / n for c in q]
dm = sum((D(g) - c) ** 2 for g, c in zip(got, ref)).sqrt()
dp = sum((D(g) + c) ** 2 for g, c in zip(got, ref)).sqrt()
err = 4 * math.atan2(float(min(dm, dp)), float(max(dm, dp))) / EPS
errors.append(report("glm.normalize(glm.quat(w, x, y, z))", q, got, [float(c) for c in ref], err, "METRIC-1"))

# 3. glm.mat3_cast: the identity instead of the matrix of q/|q| (a half turn, w = -0).
q = [h("0x1p-137"), h("0x1p-148"), h("0x1.8p-140"), -0.0]
m = glm.mat3_cast(glm.quat(q[3], q[0], q[1], q[2]))
got = [m[c][r] for c in range(3) for r in range(3)]  # column-major
x, y, z, w = (F(c) for c in q)
n2 = x * x + y * y + z * z + w * w
rows = [[1 - 2 * (y * y + z * z) / n2, 2 * (x * y - w * z) / n2, 2 * (x * z + w * y) / n2],
        [2 * (x * y + w * z) / n2, 1 - 2 * (x * x + z * z) / n2, 2 * (y * z - w * x) / n2],
        [2 * (x * z - w * y) / n2, 2 * (y * z + w * x) / n2, 1 - 2 * (x * x + y * y) / n2]]
ref = [rows[r][c] for c in range(3) for r in range(3)]
err = max(float(abs(F(g) - c)) for g, c in zip(got, ref)) / EPS
errors.append(report("glm.mat3_cast(glm.quat(w, x, y, z)), column-major", q, got, [float(c) for c in ref], err,
                     "METRIC-4"))

bad = any(not e <= LOOSE for e in errors)
print("DEFECT SHOWN" if bad else "DEFECT NOT SHOWN")
sys.exit(0 if bad else 1)
