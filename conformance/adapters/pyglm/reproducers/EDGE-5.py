#!/usr/bin/env python3
"""rotorcert reproducer: PyGLM glm.inverse / glm.normalize / q * v of non-unit quaternions, clause EDGE-5.

EDGE-5 (spec/SPEC.md 9): a finite nonzero q means the rotation q/|q| at every scale the format holds
(eps16, loose bar 256 eps); INV-1's inverse q*/|q|^2 is defined on the unnormalised q. PyGLM's glm.quat
is binary32 and GLM computes without scaling:
  - glm.inverse(q) = conjugate(q) / dot(q, q) (PyGLM_lib/glm/glm/ext/quaternion_common.inl:119-122):
    for |q| ~ 2^-100 the dot product underflows to 0 and the inverse is +-inf, although q*/|q|^2
    (about 2^100) is representable (worst input of the clause);
  - glm.normalize(q) = q / sqrt(dot(q, q)) with "if(len <= 0) return identity"
    (ext/quaternion_geometric.inl:17-24): at |q| ~ 2^-100 it returns the identity (0, 0, 0, 1);
  - q * v (detail/type_quat.inl:359-366: v + 2 (w (u x v) + u x (u x v))) and glm.mat3_cast
    (gtc/quaternion.inl:47-72) are the formulas of a unit q: for q = 1 + k (|q| = sqrt 2, a quarter
    turn about z) q * (1, 0, 0) is (-1, 2, 0), not (0, 1, 0); at 2^100 they overflow to inf / NaN.
(glm.slerp of inputs near 2^100 overflows its dot product to inf and returns NaN; see
expected_failures.json.)
Upstream: no matching issue found in g-truc/glm or Zuzu-Typ/PyGLM.
Exit 0: defect shown; 1: not shown (fixed); 77: PyGLM cannot be imported.
"""
import math
import sys

CLAUSE = "EDGE-5"
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
LOOSE = 256       # eps16 loose bar (spec/clauses.json)
h = float.fromhex


def hx(f):
    """A binary32 value as the report prints it: C99 hexfloat without trailing zeros."""
    s = float(f).hex()
    if "p" not in s:
        return s
    m, e = s.split("p")
    return m.rstrip("0").rstrip(".") + "p" + e


def report(call, inputs, got, ref, err):
    print("  call:    %s" % call)
    print("  input:   %s" % inputs)
    print("  library: [%s] = [%s]" % (", ".join(hx(c) for c in got), ", ".join("%.6g" % c for c in got)))
    print("  correct: [%s]" % ", ".join("%.6g" % c for c in ref))
    print("  error:   %s%s" % ("%.3g eps" % err if math.isfinite(err) else "not finite (inf / NaN)",
                               "  <-- DEFECT" if not err <= LOOSE else ""))
    return err


print("rotorcert reproducer: PyGLM %s %s: glm.inverse of a quaternion of norm 2^-100 is inf, glm.normalize "
      "of it the identity, and q * v of a non-unit q is not the rotation of q/|q|" % (VERSION, CLAUSE))
errors = []

# 1. glm.inverse at 2^-100 (the clause's worst input): INV-1's q*/|q|^2, componentwise relative error.
x, y, z, w = h("-0x1.fce3c8p-101"), h("-0x1.8a9b5ap-105"), h("-0x1.a12056p-100"), h("-0x1.c423bep-103")
r = glm.inverse(glm.quat(w, x, y, z))
n2 = sum(F(c) ** 2 for c in (x, y, z, w))
ref = [-F(x) / n2, -F(y) / n2, -F(z) / n2, F(w) / n2]  # conjugate / |q|^2, exact
got = [r.x, r.y, r.z, r.w]
scale = max(abs(c) for c in ref)
err = (max(float(abs(F(g) - c) / scale) for g, c in zip(got, ref)) / EPS
       if all(math.isfinite(g) for g in got) else math.inf)
q_text = "q (x, y, z, w) = [%s]" % ", ".join(hx(c) for c in (x, y, z, w))
errors.append(report("glm.inverse(glm.quat(w, x, y, z))", q_text, got, [float(c) for c in ref], err))

# 2. glm.normalize at 2^-100: |q|^2 underflows to 0 and the identity comes back.
x, y, z, w = h("-0x1.6b35f8p-105"), h("-0x1.d83ae4p-101"), h("-0x1.0ec914p-100"), h("-0x1.f58be8p-107")
r = glm.normalize(glm.quat(w, x, y, z))
n = sum(D(c) ** 2 for c in (x, y, z, w)).sqrt()
ref = [D(c) / n for c in (x, y, z, w)]
got = [r.x, r.y, r.z, r.w]
dm = sum((D(g) - c) ** 2 for g, c in zip(got, ref)).sqrt()
dp = sum((D(g) + c) ** 2 for g, c in zip(got, ref)).sqrt()
err = float(4 * D(math.atan2(min(dm, dp), max(dm, dp)))) / EPS  # METRIC-1 (got is unit here)
q_text = "q (x, y, z, w) = [%s]" % ", ".join(hx(c) for c in (x, y, z, w))
errors.append(report("glm.normalize(glm.quat(w, x, y, z))", q_text, got, [float(c) for c in ref], err))

# 3. q * v with q = 1 + k (|q| = sqrt 2): the rotation of q/|q| is a quarter turn about z.
r = glm.quat(1.0, 0.0, 0.0, 1.0) * glm.vec3(1.0, 0.0, 0.0)
got, ref = [r.x, r.y, r.z], [0.0, 1.0, 0.0]
err = math.sqrt(sum((g - c) ** 2 for g, c in zip(got, ref))) / EPS  # METRIC-3, s = |v| = 1
errors.append(report("glm.quat(w, x, y, z) * glm.vec3(1, 0, 0)", "q (x, y, z, w) = [0x0p+0, 0x0p+0, 0x1p+0, 0x1p+0]",
                     got, ref, err))

bad = any(not e <= LOOSE for e in errors)
print("DEFECT SHOWN" if bad else "DEFECT NOT SHOWN")
sys.exit(0 if bad else 1)
