#!/usr/bin/env python3
"""rotorcert reproducer: PyGLM glm.axis returns (0, 0, 1) for rotations of 1e-9 .. 1e-3 rad, clause EDGE-2.

EDGE-2 (spec/SPEC.md 9): for rotation angles of 1e-9 .. 1e-3 rad every result is within the
operation's class (to_axis_angle: AXANG-1, eps16, loose bar 256 eps), "acos-based angles fail here".
glm.axis(q) (PyGLM_lib/glm/glm/ext/quaternion_trigonometric.inl:22-26) divides v by sqrt(1 - w*w); in
binary32 w*w rounds to 1 below about 4.9e-4 rad, tmp1 = 0, and it returns (0, 0, 1) whatever the
axis (above that, up to 1e-3 rad, a non-unit axis). Here a 1.86e-4 rad rotation about (0.0014,
-0.0493, -0.9988) gets (0, 0, 1), nearly the opposite axis: 1.68e7 eps. Same root cause as AXANG-1
(AXANG-1.py). glm.angle is accurate here (2 asin|v|), and every other op passes EDGE-2 (exp too:
PyGLM's GLM_FORCE_CTOR_INIT makes exp's below-epsilon branch return the identity).
Upstream: no matching issue found in g-truc/glm or Zuzu-Typ/PyGLM.
Exit 0: defect shown; 1: not shown (fixed); 77: PyGLM cannot be imported.
"""
import sys

CLAUSE = "EDGE-2"
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


print("rotorcert reproducer: PyGLM %s %s: glm.axis of a 1.86e-4 rad rotation returns (0, 0, 1) "
      "(1 - w*w rounds to 0)" % (VERSION, CLAUSE))
print("  call:    q = glm.quat(w, x, y, z); glm.angle(q), glm.axis(q)")
h = float.fromhex
worst = check(h("0x1.0e475ap-23"), h("-0x1.3396c6p-18"), h("-0x1.854ad8p-14"), h("0x1p+0"))
print("  and a 1e-6 rad turn about x built by glm.angleAxis(1e-6, vec3(1, 0, 0)):")
r = glm.angleAxis(1e-6, glm.vec3(1.0, 0.0, 0.0))
worst = max(worst, check(r.x, r.y, r.z, r.w))
bad = worst > LOOSE
print("DEFECT SHOWN" if bad else "DEFECT NOT SHOWN")
sys.exit(0 if bad else 1)
