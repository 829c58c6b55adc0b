#!/usr/bin/env python3
"""rotorcert reproducer: PyGLM returns partly-NaN or infinite results for NaN / Inf inputs, clause EDGE-7.

EDGE-7 (spec/SPEC.md 9): NaN or +-Inf in any input component is DOMAIN_ERROR with every output NaN
(class outcome), e.g. normalize((Inf, 0, 0, 1)) is DOMAIN_ERROR, not (1, 0, 0, 0). PyGLM (GLM) checks
no input for finiteness and raises nothing, so the results are whatever the arithmetic gives, with
finite components beside the NaNs:
  - glm.normalize(quat(1, 0, inf, 0)) (EX-EDGE-7-b, the clause's worst input): len = inf, 1/len = 0,
    so [0, nan, 0, 0] (PyGLM_lib/glm/glm/ext/quaternion_geometric.inl:17-24);
  - q1 * q2 with an Inf component: +-inf in all four components (detail/type_quat.inl:298-308);
  - glm.mat3_cast of a q with a NaN w: the diagonal, 1 - 2(y^2 + z^2) etc., does not read w and is
    finite, the other six entries are NaN (gtc/quaternion.inl:47-72);
  - glm.inverse, glm.log, glm.slerp, q * v and glm.quat_cast likewise return partly finite results.
Upstream: no matching issue found in g-truc/glm or Zuzu-Typ/PyGLM.
Exit 0: defect shown; 1: not shown (fixed); 77: PyGLM cannot be imported.
"""
import math
import sys

CLAUSE = "EDGE-7"
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


def show(call, inputs, fn):
    """True when fn neither raised nor returned all NaN (the status rule of RESULT-2)."""
    print("  call:    %s" % call)
    print("  input:   %s" % inputs)
    try:
        got = fn()
    except Exception as e:  # noqa: BLE001 - a refusal is the correct answer
        print("  library: raises %s: DOMAIN_ERROR, correct" % type(e).__name__)
        return False
    nan = all(math.isnan(c) for c in got)
    print("  library: [%s]%s" % (", ".join(hx(c) for c in got),
                                 ": all NaN, DOMAIN_ERROR, correct" if nan else " with no error  <-- DEFECT"))
    return not nan


print("rotorcert reproducer: PyGLM %s %s: no finiteness check: glm.normalize of (x, y, z, w) = (0, inf, 0, 1) "
      "is [0, nan, 0, 0], a product with Inf is infinite, mat3_cast of a NaN w is partly finite" % (VERSION, CLAUSE))
print("  correct: DOMAIN_ERROR (every output NaN, or an exception) for each call below")
h = float.fromhex
inf, nan = math.inf, math.nan
bad = False
bad |= show("glm.normalize(glm.quat(w, x, y, z))", "q (x, y, z, w) = [0x0p+0, inf, 0x0p+0, 0x1p+0]",
            lambda: xyzw(glm.normalize(glm.quat(1.0, 0.0, inf, 0.0))))
a = glm.quat(h("-0x1.50583cp-4"), inf, h("0x1.bd3872p-2"), h("-0x1.07cf0ep-1"))
b = glm.quat(h("0x1.37794cp-2"), h("0x1.5f20ecp-1"), h("-0x1.e472a4p-2"), h("-0x1.d8f99p-2"))
bad |= show("glm.quat(w, x, y, z) * glm.quat(w, x, y, z)",
            "a (x, y, z, w) = [%s], b = [%s]" % (", ".join(hx(c) for c in xyzw(a)), ", ".join(hx(c) for c in xyzw(b))),
            lambda: xyzw(a * b))
q = glm.quat(nan, h("0x1.4f4628p-1"), h("-0x1.205be4p-1"), h("0x1.315e12p-2"))
bad |= show("glm.mat3_cast(glm.quat(w, x, y, z)), column-major",
            "q (x, y, z, w) = [%s, %s, %s, nan]" % (hx(q.x), hx(q.y), hx(q.z)),
            lambda: (lambda m: [m[c][r] for c in range(3) for r in range(3)])(glm.mat3_cast(q)))
print("DEFECT SHOWN" if bad else "DEFECT NOT SHOWN")
sys.exit(0 if bad else 1)
