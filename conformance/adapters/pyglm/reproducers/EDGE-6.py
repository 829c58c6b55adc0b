#!/usr/bin/env python3
"""rotorcert reproducer: PyGLM glm.log and glm.slerp take the zero quaternion without an error, clause EDGE-6.

EDGE-6 (spec/SPEC.md 9): a zero quaternion has no rotation; an operation that reads it as one is
DOMAIN_ERROR (an exception, or all outputs NaN; class outcome). ACC-1's zero_sentinel also accepts an
all-zero output or exactly the identity rotation's output, and algebraic_product the product 0 for
compose. PyGLM (GLM) has no zero check and returns finite or infinite numbers:
  - glm.log(quat(0, 0, 0, 0)) is (+inf, +inf, +inf, +inf): GLM returns infinity in all four
    components on purpose when |v| < epsilon and w == 0 (PyGLM_lib/glm/glm/ext/quaternion_exponential.inl:23-30);
    the log's vector part is (inf, inf, inf), neither NaN nor zero;
  - glm.slerp(quat(0, 0, 0, 0), b, t) interpolates towards b from the zero quaternion: dot = 0, so
    the angle is acos(0) = pi/2 and the result is sin(t pi/2) b (ext/quaternion_common.inl:41-72), a
    non-unit multiple of b (EX-EDGE-6-g: [0, 0, 0.5, 0.5] for b = [0, 0, 0.7071, 0.7071], t = 1/2);
    with a zero b it is sin((1 - t) pi/2) a.
Not reported here (acceptable under zero_sentinel / algebraic_product): glm.normalize(0) = identity
(ext/quaternion_geometric.inl:20-21), quat(0) * v = v, glm.mat3_cast(0) = I, 0 * b = 0;
glm.inverse(0) is 0/0 = NaN in every component, a correct DOMAIN_ERROR.
Upstream: no matching issue found in g-truc/glm or Zuzu-Typ/PyGLM.
Exit 0: defect shown; 1: not shown (fixed); 77: PyGLM cannot be imported.
"""
import math
import sys

CLAUSE = "EDGE-6"
try:
    from importlib.metadata import version
    import glm
    VERSION = version("PyGLM")
except Exception as exc:  # noqa: BLE001 - any import failure is a skip
    print("rotorcert reproducer: PyGLM ? %s: SKIP: cannot import glm: %s" % (CLAUSE, exc))
    sys.exit(77)


def hx(f):
    """A binary32 value as the report prints it: C99 hexfloat without trailing zeros."""
    s = float(f).hex()
    if "p" not in s:
        return s
    m, e = s.split("p")
    return m.rstrip("0").rstrip(".") + "p" + e


def xyzw(q):
    return [q.x, q.y, q.z, q.w]


def show(call, fn, accepted):
    """Calls fn; returns True when it neither raised nor returned all NaN nor an accepted output."""
    try:
        got = fn()
    except Exception as e:  # noqa: BLE001 - a refusal is the correct answer
        print("  %-52s raises %s: DOMAIN_ERROR, correct" % (call, type(e).__name__))
        return False
    if all(math.isnan(c) for c in got):
        print("  %-52s [%s]: all NaN, DOMAIN_ERROR, correct" % (call, ", ".join(hx(c) for c in got)))
        return False
    ok = any(got == a for a in accepted)
    print("  %-52s [%s] with no error%s" % (call, ", ".join(hx(c) for c in got),
                                            " (accepted: zero_sentinel)" if ok else "  <-- DEFECT"))
    return not ok


print("rotorcert reproducer: PyGLM %s %s: glm.log of the zero quaternion is (inf, inf, inf) and glm.slerp "
      "from it returns a non-unit multiple of b, with no error" % (VERSION, CLAUSE))
print("  input:   q (x, y, z, w) = [0x0p+0, 0x0p+0, 0x0p+0, 0x0p+0]; b = [0x0p+0, 0x0p+0, 0x1.6a09e6p-1, "
      "0x1.6a09e6p-1]; t = 0x1p-1")
print("  correct: DOMAIN_ERROR (NaN outputs or an exception); zero_sentinel also accepts all zeros or the")
print("           identity's output (log: [0, 0, 0]; slerp: glm.slerp(quat(), b, t))")
zero = glm.quat(0.0, 0.0, 0.0, 0.0)
s = float.fromhex("0x1.6a09e6p-1")
b = glm.quat(s, 0.0, 0.0, s)  # quat(w, x, y, z): a quarter turn about z
identity_slerp = xyzw(glm.slerp(glm.quat(), b, 0.5))
bad = False
bad |= show("glm.log(q) (vector part)", lambda: xyzw(glm.log(zero))[:3], [[0.0, 0.0, 0.0]])
bad |= show("glm.slerp(q, b, t)", lambda: xyzw(glm.slerp(zero, b, 0.5)), [[0.0] * 4, identity_slerp])
bad |= show("glm.slerp(b, q, t)", lambda: xyzw(glm.slerp(b, zero, 0.5)), [[0.0] * 4, identity_slerp])
print("  not counted: glm.normalize(q) = [%s], q * (1, 2, 3) = [%s] (zero_sentinel)"
      % (", ".join(hx(c) for c in xyzw(glm.normalize(zero))),
         ", ".join(hx(c) for c in (lambda v: [v.x, v.y, v.z])(zero * glm.vec3(1, 2, 3)))))
print("DEFECT SHOWN" if bad else "DEFECT NOT SHOWN")
sys.exit(0 if bad else 1)
