#!/usr/bin/env python3
"""rotorcert reproducer: PyGLM glm.sqrt of a quaternion near a full turn and of -1, clause SQRT-1.

SQRT-1 (spec/SPEC.md 6, level Extended, eps16: METRIC-1 and METRIC-6, loose bar 256 eps): the rotor
square root s of q^ = q/|q| with s*s = q^ and s.w > 0, (cos(theta/4), sin(theta/4) u); any unit pure
quaternion for q^ = -1. glm.sqrt(q) ('Returns the square root of a quaternion') is GLM's
sqrt(qua) = pow(q, 0.5) (PyGLM_lib/glm/glm/ext/quaternion_exponential.inl:40-85, GLM 1.0.1 code):
  - pow takes the half angle as asin(|v|/|q|) whenever |w|/|q| > cos(1/2), for w < 0 too, where the
    half angle is pi - asin(|v|/|q|): for a turn theta in (2 pi - 1, 2 pi) the result is the square
    root of another rotation (s*s is not q);
  - for |v|^2 < FLT_MIN it returns (pow(w, 0.5), 0, 0, 0): sqrt(-1) = (nan, 0, 0, 0).
(pow also scales the result by |q|^(1/2), the algebraic root; not at issue here, q is unit.)
The same code as GLM 0.9.9.8's glm::sqrt (conformance/adapters/glm/reproducers/SQRT-1.cpp), whose
|v|^2 < epsilon branch GLM 1.0.1 narrowed to FLT_MIN.
Upstream: no issue found for pow/sqrt in g-truc/glm or Zuzu-Typ/PyGLM; the same w < 0 branch error was
fixed in glm::angle by https://github.com/g-truc/glm/pull/1038, not in pow.
Exit 0: defect shown; 1: not shown (fixed); 77: PyGLM cannot be imported.
"""
import math
import sys

CLAUSE = "SQRT-1"
try:
    from importlib.metadata import version
    import glm
    VERSION = version("PyGLM")
except Exception as exc:  # noqa: BLE001 - any import failure is a skip
    print("rotorcert reproducer: PyGLM ? %s: SKIP: cannot import glm: %s" % (CLAUSE, exc))
    sys.exit(77)

EPS = 2.0 ** -23  # glm.quat is binary32
LOOSE = 256       # eps16 loose bar (spec/clauses.json)


def hx(f):
    """A binary32 value as the report prints it: C99 hexfloat without trailing zeros."""
    s = float(f).hex()
    if "p" not in s:
        return s
    m, e = s.split("p")
    return m.rstrip("0").rstrip(".") + "p" + e


print("rotorcert reproducer: PyGLM %s %s: glm.sqrt (= pow(q, 0.5)) takes the wrong branch near a full turn "
      "and returns NaN for -1" % (VERSION, CLAUSE))
# 1. A 6 rad turn about +z: w = cos 3 < -cos(1/2). The correct root is (cos 1.5, 0, 0, sin 1.5).
q = glm.angleAxis(6.0, glm.vec3(0.0, 0.0, 1.0))
s = glm.sqrt(q)
s2 = s * s
ref = (math.cos(1.5), 0.0, 0.0, math.sin(1.5))  # (w, x, y, z)
got = (s.w, s.x, s.y, s.z)
dm = math.sqrt(sum((a - b) ** 2 for a, b in zip(got, ref)))
dp = math.sqrt(sum((a + b) ** 2 for a, b in zip(got, ref)))
err = 4 * math.atan2(min(dm, dp), max(dm, dp))  # METRIC-1, sign-free
print("  call:    glm.sqrt(q)")
print("  input:   q = glm.angleAxis(6.0, vec3(0, 0, 1)) = (w, x, y, z) (%s, %s, %s, %s)"
      % (hx(q.w), hx(q.x), hx(q.y), hx(q.z)))
print("  library: s = (%.9g, %.9g, %.9g, %.9g); s*s = (%.9g, %.9g, %.9g, %.9g), a %.3g rad turn"
      % (got + (s2.w, s2.x, s2.y, s2.z, 2 * math.atan2(math.hypot(s2.x, s2.y, s2.z), abs(s2.w)))))
print("  correct: s = (cos 1.5, 0, 0, sin 1.5) = (%.9g, 0, 0, %.9g): s*s = q, the 6 rad turn" % (ref[0], ref[3]))
print("  error:   %.3g rad = %.3g eps (METRIC-1; bar %d eps)" % (err, err / EPS, LOOSE))
# 2. -1 (the suite's worst input, status): pow(-1, 0.5) = NaN.
m = glm.sqrt(glm.quat(-1.0, 0.0, 0.0, 0.0))
print("  input:   q (x, y, z, w) = [0x0p+0, 0x0p+0, 0x0p+0, -0x1p+0]")
print("  library: s (x, y, z, w) = [%s, %s, %s, %s]" % (m.x, m.y, m.z, m.w))
print("  correct: s = [0, 0, 1, 0], +z (any unit pure quaternion is accepted)")
bad = err / EPS > LOOSE and math.isnan(m.w)
print("DEFECT SHOWN" if bad else "DEFECT NOT SHOWN")
sys.exit(0 if bad else 1)
