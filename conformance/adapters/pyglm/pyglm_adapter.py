#!/usr/bin/env python3
"""rotorcert test-vector adapter for PyGLM (https://github.com/Zuzu-Typ/PyGLM), glm.quat (binary32).

    python pyglm_adapter.py --vectors DIR --out RESULTS.json

Runs the binary32 vectors of `rotorcert vectors export` through PyGLM, the Python binding of GLM
(OpenGL Mathematics), and writes a results file for `rotorcert vectors check`
(conformance/VECTORS.md). PyGLM compiles its own copy of GLM into its extension module (the
Zuzu-Typ/glm fork, branch PyGLM, at g-truc/glm master d03194c of 2024-10-11, between the 1.0.1 and
1.0.2 tags: its setup.hpp says 1.0.2; the quaternion sources are those of GLM 1.0.1), configured by
PyGLM/imports.h with GLM_FORCE_CTOR_INIT (a default-constructed quaternion is the identity) and
GLM_FORCE_QUAT_DATA_WXYZ (memory order w, x, y, z). Each function below is the PyGLM call a PyGLM
user makes; PyGLM's wrappers (PyGLM_lib/PyGLM/functions/...) convert the arguments and call the GLM
template of the same name, nothing else.

Reading, writing and the status rule are the rotorcert_vectors package's (conformance/packages/python,
installed into the adapter's environment by scripts/setup-adapters): a Python exception raised by
PyGLM -> DOMAIN_ERROR (every output NaN); every output component NaN -> DOMAIN_ERROR (PyGLM has no
status channel, RESULT-2); anything else -> OK with PyGLM's numbers as computed. The adapter adds no
domain checks, no rescaling, no hemisphere flips and no renormalisation that PyGLM does not do itself.

Number format: glm.quat, glm.vec3 and glm.mat3 hold C floats (binary32) and GLM computes in float,
so the binary32 vectors are answered (scalar "float"): every input is a binary32 value, which PyGLM
converts from the Python float exactly, and every output is a binary32 value that PyGLM returns as a
Python float exactly. `SCALARS` also holds the binary64 twin (glm.dquat, glm.dvec3, glm.dmat3: the
same GLM templates in double): `implementation("double", name)` builds it for a second manifest that
answers the binary64 vectors (a vectors adapter answers one number format; see adapter.json).

Conventions (LAYOUT-1 <-> PyGLM):
  - glm.quat(w, x, y, z) takes the scalar first (PyGLM_lib/PyGLM/type_methods/qua.h qua_init,
    keywords "w", "x", "y", "z"; wiki Using-quaternions.md "quat(1, 2, 3, 4) # returns quaternion
    (1 + 2i + 3j + 4k)"); its members .x .y .z .w are read by name, never by index (q[0] is w under
    GLM_FORCE_QUAT_DATA_WXYZ). A spec quaternion [x, y, z, w] is glm.quat(w, x, y, z) and is read back
    as [q.x, q.y, q.z, q.w].
  - Hamilton product: q1 * q2 is GLM's qua::operator*= (ij = k; checked at start-up), so
    compose(a, b) = A * B, b applied first (wiki: "Multiplying two quaternions will return their cross
    product", s1 s2 - v1.v2, s1 v2 + s2 v1 + v1 x v2).
  - Active rotation: q * v for a vec3 is v + 2 (w (u x v) + u x (u x v)), u = (x, y, z): q v q* for a
    unit q (wiki: "Multiplying a quaternion by a vector (vec3 or vec4) will return a rotated vector";
    v * q rotates by the inverse).
  - Matrices are column-major: glm.mat3_cast(q)[c][r] is row r of column c, the ABI's m[c*3 + r];
    glm.mat3(m0, ..., m8) takes the nine values column by column (GLM's constructor), so the ABI
    array is passed in order and read back as [M[c][r] for c, r]. mat3_cast(quarter turn about z)
    maps x to y (checked at start-up).
  - Angles are radians (glm.angleAxis "angle: Angle expressed in radians", glm.angle).
  - log: glm.log(q) is GLM's full quaternion logarithm (w = log|q|, vector atan(|v|, w) v/|v|); its
    vector part is LOG-1's (theta/2) u of q/|q| (atan2 is scale-free), read as [l.x, l.y, l.z]; the
    log of the norm has no place in the ABI's output and is dropped.
  - exp: the ABI's exp(v) is the exponential of the pure quaternion (0, v): glm.exp(glm.quat(0, vx,
    vy, vz)) (GLM's exp reads only the vector part: (cos|v|, sin|v| v/|v|)).

Operations (what a PyGLM user calls; Q = glm.quat(w, x, y, z)):
  normalize        glm.normalize(Q)
  compose          A * B
  inverse          glm.inverse(Q)              (conjugate(q) / dot(q, q))
  apply_vector     Q * glm.vec3(v)
  to_matrix        glm.mat3_cast(Q)
  from_matrix      glm.quat_cast(glm.mat3(*m))  (declared precondition from_matrix:rotation_matrix)
  to_axis_angle    (glm.angle(Q), glm.axis(Q)) (declared precondition to_axis_angle:unit_quaternion)
  from_axis_angle  glm.angleAxis(angle, glm.vec3(axis))  (declared from_axis_angle:unit_axis)
  log              glm.log(Q), vector part
  exp              glm.exp(glm.quat(0, vx, vy, vz))
  slerp            glm.slerp(A, B, t)
  log_exp_round_trip   exp of what log returned (rotorcert_vectors.round_trip)
  to_angle         glm.angle(Q)                (declared precondition to_angle:unit_quaternion)
  to_axis          glm.axis(Q)
  sqrt             glm.sqrt(Q)                 (GLM's sqrt(qua) = pow(q, 0.5))
Not mapped (NOT_SUPPORTED; adapter.json says why for each): apply_bivector, apply_trivector, nlerp
(glm.lerp is the unnormalised, oriented lerp and asserts t in [0, 1]), blend_qlb, blend_log, every
dual-quaternion op (PyGLM does not expose gtx/dual_quaternion; dq_to_rotation_translation too),
rotate_about_axis, skin_linear, skin_dual_quaternion. glm.mix(x, y, a), GLM's oriented slerp, is a second slerp: a table has one
slerp slot, which holds glm.slerp (adapter.json, conventions).
"""
import sys
from importlib.metadata import version as _dist_version

import glm
from rotorcert_vectors import run_adapter, Implementation

PYGLM_VERSION = _dist_version("PyGLM")

# The PyGLM types of each number format: quaternion, vec3, mat3.
SCALARS = {
    "float": (glm.quat, glm.vec3, glm.mat3),
    "double": (glm.dquat, glm.dvec3, glm.dmat3),
}
# The scalar this script certifies (adapter.json "scalars"): glm.quat, PyGLM's default quaternion.
SCALAR = "float"


def _check_conventions(quat, vec3, mat3):
    """Stops the adapter (not an assert, which -O removes) if PyGLM's constructor order, product
    rule, rotation direction or matrix layout is not the one the mapping above assumes."""
    q = quat(1, 2, 3, 4)
    if [q.w, q.x, q.y, q.z] != [1.0, 2.0, 3.0, 4.0]:
        raise RuntimeError("glm.quat(w, x, y, z) is not scalar-first")
    i, j, k = quat(0, 1, 0, 0), quat(0, 0, 1, 0), quat(0, 0, 0, 1)
    ij, ijk = i * j, i * j * k
    if [ij.x, ij.y, ij.z, ij.w] != [0.0, 0.0, 1.0, 0.0] or [ijk.x, ijk.y, ijk.z, ijk.w] != [0.0, 0.0, 0.0, -1.0]:
        raise RuntimeError("PyGLM's quaternion product is not Hamilton's")
    r = quat(0.5, 0.5, 0.5, 0.5)  # a third of a turn about (1, 1, 1): x -> y, exact in binary32
    v = r * vec3(1, 0, 0)
    if [v.x, v.y, v.z] != [0.0, 1.0, 0.0]:
        raise RuntimeError("q * v is not the active rotation q v q*")
    m = glm.mat3_cast(r)
    if [m[0][0], m[0][1], m[0][2]] != [0.0, 1.0, 0.0]:
        raise RuntimeError("mat3_cast(q)[c] is not column c (the image of e_c)")
    m = mat3(1, 2, 3, 4, 5, 6, 7, 8, 9)
    if [m[0][0], m[0][1], m[1][0]] != [1.0, 2.0, 4.0]:
        raise RuntimeError("glm.mat3(nine values) does not take them column by column")


def make_ops(scalar):
    """{ABI op: function} for PyGLM's types of `scalar` ("float": glm.quat; "double": glm.dquat)."""
    quat, vec3, mat3 = SCALARS[scalar]
    _check_conventions(quat, vec3, mat3)

    def Q(q):
        """A spec quaternion [x, y, z, w] as PyGLM's quat(w, x, y, z)."""
        x, y, z, w = q
        return quat(w, x, y, z)

    def xyzw(q):
        return [q.x, q.y, q.z, q.w]

    def xyz(v):
        return [v.x, v.y, v.z]

    # --- Core ------------------------------------------------------------------------------------

    def normalize(q):
        return xyzw(glm.normalize(Q(q)))

    def compose(a, b):
        return xyzw(Q(a) * Q(b))

    def inverse(q):
        return xyzw(glm.inverse(Q(q)))

    def apply_vector(q, v):
        return xyz(Q(q) * vec3(*v))

    def to_matrix(q):
        m = glm.mat3_cast(Q(q))  # m[c][r]
        return [m[c][r] for c in range(3) for r in range(3)]  # column-major, as the ABI

    def from_matrix(m):
        return xyzw(glm.quat_cast(mat3(*m)))  # mat3 takes the values column by column

    def to_axis_angle(q):
        g = Q(q)
        return glm.angle(g), xyz(glm.axis(g))

    def to_angle(q):
        return glm.angle(Q(q))

    def to_axis(q):
        return xyz(glm.axis(Q(q)))

    def from_axis_angle(angle, axis):
        return xyzw(glm.angleAxis(angle, vec3(*axis)))

    # --- Interp ----------------------------------------------------------------------------------

    def log(q):
        return xyz(glm.log(Q(q)))  # the vector part of the full quaternion log

    def exp(v):
        return xyzw(glm.exp(quat(0, *v)))

    def slerp(a, b, t):
        return xyzw(glm.slerp(Q(a), Q(b), t))

    def sqrt(q):
        return xyzw(glm.sqrt(Q(q)))

    return {
        "normalize": normalize, "compose": compose, "inverse": inverse, "apply_vector": apply_vector,
        "to_matrix": to_matrix, "from_matrix": from_matrix,
        "to_axis_angle": to_axis_angle, "from_axis_angle": from_axis_angle,
        "log": log, "exp": exp, "slerp": slerp,
        "to_angle": to_angle, "to_axis": to_axis, "sqrt": sqrt,
    }


# DECL-1: what GLM and PyGLM document (the citations are in adapter.json).
PRECONDITIONS = ["from_axis_angle:unit_axis", "from_matrix:rotation_matrix", "to_axis_angle:unit_quaternion",
                 "to_angle:unit_quaternion"]


def implementation(scalar=SCALAR, name="pyglm"):
    quat = SCALARS[scalar][0].__name__
    return Implementation(
        name=name, version=PYGLM_VERSION, scalar=scalar, ops=make_ops(scalar), preconditions=PRECONDITIONS,
        description=(
            "PyGLM %s (PyPI), glm.%s (%s) over its bundled GLM (1.0.1 quaternion code, "
            "GLM_FORCE_CTOR_INIT, GLM_FORCE_QUAT_DATA_WXYZ): quat(w, x, y, z) read back as [x, y, z, w]; "
            "normalize, *, inverse, q * vec3, mat3_cast, quat_cast, angle/axis, angleAxis, the vector part of "
            "log, exp of a pure quaternion, slerp, angle and axis alone, sqrt. No status channel: an exception raised by PyGLM is graded "
            "DOMAIN_ERROR (outputs NaN), all outputs NaN is DOMAIN_ERROR, anything else OK as computed "
            "(rotorcert_vectors)" % (PYGLM_VERSION, quat, "binary32" if scalar == "float" else "binary64")))


if __name__ == "__main__":
    sys.exit(run_adapter(__doc__.splitlines()[0], implementation()))
