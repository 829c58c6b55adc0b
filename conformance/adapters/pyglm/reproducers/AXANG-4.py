#!/usr/bin/env python3
"""rotorcert reproducer: PyGLM glm.axis alone loses the axis near a full turn, clause AXANG-4.

AXANG-4 (spec/SPEC.md 6, level Extended, eps16: METRIC-3 with s = 1, loose bar 256 eps): the axis
alone, u = v/|v| of AXANG-1, for every angle; only the identity (v = 0) may have any axis, and -u is
acceptable where w < 0 (the axis that goes with 2 pi - theta, ACC-1 angle_range). glm.axis(q) is
GLM's axis() (PyGLM_lib/glm/glm/ext/quaternion_trigonometric.inl:20-27, GLM 1.0.1 code):
    tmp1 = 1 - w*w; if tmp1 <= 0: return (0, 0, 1); return v / sqrt(tmp1)
It takes |v| as sqrt(1 - w^2), which cancels when w is near +-1: in binary32 w*w rounds to 1 for
every rotation within about 4.9e-4 rad of the identity or of a full turn, where glm.axis returns
(0, 0, 1) whatever v holds. Here q is a unit quaternion (binary32, w = -1) of a rotation 8.3e-7 rad
short of a full turn about (-0.0253, 0.00605, -0.9997): glm.axis answers (0, 0, 1), neither u nor
-u. The AXANG-1 defect of glm.axis (AXANG-1.py), met by the axis query alone.
Upstream: no matching issue found in g-truc/glm or Zuzu-Typ/PyGLM.
Exit 0: defect shown; 1: not shown (fixed); 77: PyGLM cannot be imported.
"""
import sys

CLAUSE = "AXANG-4"
try:
    from importlib.metadata import version
    import glm
    VERSION = version("PyGLM")
except Exception as exc:  # noqa: BLE001 - any import failure is a skip
    print("rotorcert reproducer: PyGLM ? %s: SKIP: cannot import glm: %s" % (CLAUSE, exc))
    sys.exit(77)

from decimal import Decimal as D, getcontext  # noqa: E402 - after the skip

getcontext().prec = 60
EPS = 2.0 ** -23  # glm.quat is binary32
LOOSE = 256       # eps16 loose bar (spec/clauses.json)


def hx(f):
    """A binary32 value as the report prints it: C99 hexfloat without trailing zeros."""
    s = float(f).hex()
    if "p" not in s:
        return s
    m, e = s.split("p")
    return m.rstrip("0").rstrip(".") + "p" + e


h = float.fromhex
x, y, z, w = h("-0x1.69a0dap-28"), h("0x1.594d6ap-30"), h("-0x1.bdc41cp-23"), h("-0x1p+0")  # the suite's worst input
q = glm.quat(w, x, y, z)
axis = glm.axis(q)
v = [D(x), D(y), D(z)]
n = sum(c * c for c in v).sqrt()
u = [c / n for c in v]
got = [D(axis.x), D(axis.y), D(axis.z)]
e = float(sum((a - b) ** 2 for a, b in zip(got, u)).sqrt())
e_minus = float(sum((a + b) ** 2 for a, b in zip(got, u)).sqrt())  # against -u (acceptable: w < 0)
print("rotorcert reproducer: PyGLM %s %s: glm.axis of a rotation 8.3e-7 rad short of a full turn returns (0, 0, 1) "
      "(1 - w*w cancels to 0)" % (VERSION, CLAUSE))
print("  call:    glm.axis(glm.quat(w, x, y, z))")
print("  input:   q (x, y, z, w) = [%s]" % ", ".join(hx(c) for c in (x, y, z, w)))
print("  library: axis [%s] = [%.6g, %.6g, %.6g]" % (", ".join(hx(c) for c in (axis.x, axis.y, axis.z)), axis.x, axis.y, axis.z))
print("  correct: axis [%s]  (v/|v|, 60 digits; -u is acceptable too, w < 0)" % ", ".join("%.6g" % c for c in u))
print("  error:   %.3g = %.3g eps against u, %.3g eps against -u (METRIC-3; bar %d eps)"
      % (e, e / EPS, e_minus / EPS, LOOSE))
bad = min(e, e_minus) / EPS > LOOSE
print("DEFECT SHOWN" if bad else "DEFECT NOT SHOWN")
sys.exit(0 if bad else 1)
