#!/usr/bin/env python3
"""rotorcert reproducer: PyGLM glm.axis loses the axis of small rotations, clause AXANG-1.

AXANG-1 (spec/SPEC.md 6): the axis of q = (w, v) is u = v/|v| (METRIC-3, eps16: loose bar 256 eps),
for every angle in [0, 2 pi]; the identity (v = 0) alone may have any axis. glm.axis(q) is GLM's
axis() (PyGLM_lib/glm/glm/ext/quaternion_trigonometric.inl:20-27, GLM 1.0.1 code):
    tmp1 = 1 - w*w; if tmp1 <= 0: return (0, 0, 1); return v / sqrt(tmp1)
It takes |v| as sqrt(1 - w^2), which cancels catastrophically when w is near +-1: in binary32 w*w
rounds to 1 for every rotation below about 4.9e-4 rad (and within 4.9e-4 rad of a full turn), and
glm.axis then returns (0, 0, 1) although x, y, z still hold the axis; above that the axis comes back
non-unit (relative error about eps / (theta/2)^2). Here q is a unit quaternion (binary32) of a
3.55e-5 rad rotation about (0.0348, 0.0333, -0.9988): glm.axis answers (0, 0, 1), nearly the
opposite axis. glm.angle itself is accurate (GLM 1.0.1 takes 2 asin|v| there). v / |v| keeps every
digit. The same defect is EDGE-2 on the small-angle family (EDGE-2.py).
Upstream: no matching issue found in g-truc/glm or Zuzu-Typ/PyGLM (g-truc/glm#946 and #1038 fixed
glm::angle, not glm::axis).
Exit 0: defect shown; 1: not shown (fixed); 77: PyGLM cannot be imported.
"""
import sys

CLAUSE = "AXANG-1"
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


def datan(x):
    """atan of a Decimal to 60 digits: halve the argument, then the Taylor series."""
    k = 0
    while abs(x) > D(1) / 8:
        x, k = x / (1 + (1 + x * x).sqrt()), k + 1
    s, term, n, x2 = D(0), x, 1, x * x
    while abs(term) > D(10) ** -70:
        s, term, n = s + term / n, -term * x2, n + 2
    return s * 2 ** k


def check(x, y, z, w):
    """glm.angle and glm.axis of quat(w, x, y, z) against 2 atan2(|v|, w) and v/|v|; error in eps."""
    q = glm.quat(w, x, y, z)
    angle, axis = glm.angle(q), glm.axis(q)
    v = [D(x), D(y), D(z)]
    n = sum(c * c for c in v).sqrt()
    theta = 2 * datan(n / D(w))  # w > 0 here
    u = [c / n for c in v]
    e_axis = float(sum((D(a) - b) ** 2 for a, b in zip((axis.x, axis.y, axis.z), u)).sqrt())
    e_angle = float(abs(D(angle) - theta))
    err = max(e_axis, e_angle) / EPS
    print("  input:   q (x, y, z, w) = [%s]" % ", ".join(hx(c) for c in (x, y, z, w)))
    print("  library: angle %s (%.9g), axis [%s] = [%.6g, %.6g, %.6g]"
          % (hx(angle), angle, ", ".join(hx(c) for c in (axis.x, axis.y, axis.z)), axis.x, axis.y, axis.z))
    print("  correct: angle %.9g, axis [%s]  (2 atan2(|v|, w) and v/|v|, 60 digits)"
          % (theta, ", ".join("%.6g" % c for c in u)))
    print("  error:   axis %.3g, angle %.3g rad: %.3g eps (METRIC-3 of u; bar %d eps)%s"
          % (e_axis, e_angle, err, LOOSE, "  <-- DEFECT" if err > LOOSE else ""))
    return err


print("rotorcert reproducer: PyGLM %s %s: glm.axis of a 3.55e-5 rad rotation returns (0, 0, 1) "
      "(1 - w*w cancels to 0)" % (VERSION, CLAUSE))
print("  call:    q = glm.quat(w, x, y, z); glm.angle(q), glm.axis(q)")
h = float.fromhex
worst = check(h("0x1.4bf1dcp-21"), h("0x1.3dbdecp-21"), h("-0x1.29ae14p-16"), h("0x1p+0"))
print("  and a 0.01 rad rotation, q = glm.angleAxis(0.01, vec3(0.6, 0.8, 0)): the axis is not unit")
r = glm.angleAxis(0.01, glm.vec3(0.6, 0.8, 0.0))
worst = max(worst, check(r.x, r.y, r.z, r.w))
bad = worst > LOOSE
print("DEFECT SHOWN" if bad else "DEFECT NOT SHOWN")
sys.exit(0 if bad else 1)
