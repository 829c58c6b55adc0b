#!/usr/bin/env python3
"""rotorcert test-vector adapter for numpy-quaternion (https://github.com/moble/quaternion), binary64.

    python numpy_quaternion_adapter.py --vectors DIR --out RESULTS.json

Runs the binary64 vectors of `rotorcert vectors export` through numpy-quaternion (`import quaternion`:
the numpy dtype np.quaternion, its C ufuncs and the module's conversion functions) and writes a
results file for `rotorcert vectors check` (conformance/VECTORS.md). Reading, writing and the status
rule are the rotorcert_vectors package's (conformance/packages/python, installed into the adapter's
environment by scripts/setup-adapters): a Python exception raised by numpy-quaternion ->
DOMAIN_ERROR (every output NaN); every output component NaN -> DOMAIN_ERROR (numpy-quaternion has no
status channel, RESULT-2); anything else -> OK with its numbers as computed. The adapter adds no
domain checks, no rescaling, no hemisphere flips and no renormalisation that numpy-quaternion does
not do itself.

Conventions (LAYOUT-1 <-> numpy-quaternion):
  - np.quaternion(w, x, y, z) is scalar-first (as_float_array gives [w, x, y, z]): a spec quaternion
    [x, y, z, w] is np.quaternion(w, x, y, z) and is read back as [q.x, q.y, q.z, q.w].
  - Hamilton product (quaternion_multiply in src/quaternion.h, ij = k, checked at start-up):
    compose(a, b) = a * b, b applied first.
  - Active rotation: rotate_vectors(R, v) = as_rotation_matrix(R) @ v, documented as R v R^-1,
    the spec's v' = q v q*.
  - as_rotation_matrix returns m[row][col] acting on column vectors: stored column-major,
    m[c*3 + r] = M[r][c]; from_rotation_matrix gets the row-major array.
  - Rotation vectors are theta u (as_rotation_vector = 2 log(q/|q|)); the spec's log [x, y, z] is the
    quaternion-view (theta/2) u (LOG-1), which is the vector part of numpy-quaternion's quaternion
    logarithm np.log(q) = (log|q|, atan2(|v|, w) v/|v|) itself: the adapter maps log to np.log and
    reads its vector part (leaving out the scalar log|q|; the spec's log is of q/|q|), with no factor
    of 2. exp(v) is np.exp of the pure quaternion (0, v) = (cos|v|, sin|v| v/|v|), EXP-1 itself.
  - from_axis_angle is from_rotation_vector(angle * axis): the library's axis-angle constructor takes
    the rotation vector theta u, documented as "axis of the rotation, with norm proportional to the
    angle"; the adapter forms angle * axis and does not normalise the axis (declared precondition
    from_axis_angle:unit_axis in adapter.json).

Operations (what a numpy-quaternion user calls; q = np.quaternion(w, x, y, z)):
  normalize        q.normalized()
  compose          a * b
  inverse          q.inverse()
  apply_vector     quaternion.rotate_vectors(q, v)
  to_matrix        quaternion.as_rotation_matrix(q)
  from_matrix      quaternion.from_rotation_matrix(M)    (default nonorthogonal=True: Bar-Itzhack, scipy)
  from_axis_angle  quaternion.from_rotation_vector(angle * axis)
  log              np.log(q).vec
  exp              np.exp(np.quaternion(0, x, y, z))
  slerp            quaternion.slerp_evaluate(a, b, t)        ("between two rotors": declared precondition
                                                            slerp:unit_quaternion; it does not normalise)
  log_exp_round_trip   exp of what log returned (rotorcert_vectors.round_trip)
  to_angle         q.angle()                             ("Angle through which rotor rotates", 2 |log q|;
                                                            declared precondition to_angle:unit_quaternion)
  sqrt             np.sqrt(q)                            (quaternion_sqrt, "the square-root of the quaternion")
Not mapped (NOT_SUPPORTED; adapter.json says why for each): to_axis_angle, to_axis, apply_bivector,
apply_trivector, nlerp, blend_qlb, blend_log and every dual-quaternion, rigid and skinning op
(dq_to_rotation_translation included).
"""
import sys
import warnings
from importlib.metadata import version as _dist_version

import numpy as np
import quaternion
from rotorcert_vectors import round_trip, run_adapter

NUMPY_QUATERNION_VERSION = _dist_version("numpy-quaternion")

# numpy's RuntimeWarnings (0/0, overflow inside numpy-quaternion's numpy code) only print;
# silencing them changes no value.
np.seterr(all="ignore")
warnings.simplefilter("ignore")


def _check_conventions():
    """Stops the adapter (not an assert, which -O removes) if numpy-quaternion's storage order or
    product rule is not the one the mapping above assumes."""
    i, j, k = np.quaternion(0, 1, 0, 0), np.quaternion(0, 0, 1, 0), np.quaternion(0, 0, 0, 1)
    if list(quaternion.as_float_array(i * j)) != [0.0, 0.0, 0.0, 1.0] or (i * j * k) != np.quaternion(-1, 0, 0, 0):
        raise RuntimeError("numpy-quaternion's product is not Hamilton's with q = [w, x, y, z]")
    q = np.quaternion(1, 2, 3, 4)
    if [q.w, q.x, q.y, q.z] != [1.0, 2.0, 3.0, 4.0]:
        raise RuntimeError("np.quaternion is not scalar-first")


_check_conventions()


def quat(q):
    """A spec quaternion [x, y, z, w] as np.quaternion(w, x, y, z)."""
    x, y, z, w = q
    return np.quaternion(w, x, y, z)


def xyzw(q):
    return [q.x, q.y, q.z, q.w]


# --- Core ----------------------------------------------------------------------------------------

def normalize(q):
    return xyzw(quat(q).normalized())


def compose(a, b):
    return xyzw(quat(a) * quat(b))


def inverse(q):
    return xyzw(quat(q).inverse())


def apply_vector(q, v):
    return quaternion.rotate_vectors(quat(q), np.array(v, dtype=float))


def to_matrix(q):
    M = quaternion.as_rotation_matrix(quat(q))  # M[row][col]
    return [M[r][c] for c in range(3) for r in range(3)]  # column-major


def from_matrix(m):
    M = np.array([[m[c * 3 + r] for c in range(3)] for r in range(3)])  # column-major -> M[row][col]
    return xyzw(quaternion.from_rotation_matrix(M))


def from_axis_angle(angle, axis):
    return xyzw(quaternion.from_rotation_vector(angle * np.array(axis, dtype=float)))


def to_angle(q):
    return quat(q).angle()


# --- Interp --------------------------------------------------------------------------------------

def log(q):
    return list(np.log(quat(q)).vec)


def exp(v):
    x, y, z = v
    return xyzw(np.exp(np.quaternion(0.0, x, y, z)))


def slerp(a, b, t):
    return xyzw(quaternion.slerp_evaluate(quat(a), quat(b), t))


def sqrt(q):
    return xyzw(np.sqrt(quat(q)))


OPS = {
    "normalize": normalize, "compose": compose, "inverse": inverse, "apply_vector": apply_vector,
    "to_matrix": to_matrix, "from_matrix": from_matrix, "from_axis_angle": from_axis_angle,
    "log": log, "exp": exp, "slerp": slerp,
    "log_exp_round_trip": round_trip(log, exp),
    "to_angle": to_angle, "sqrt": sqrt,
}

IMPLEMENTATION = {
    "name": "numpy_quaternion",
    "version": NUMPY_QUATERNION_VERSION,
    "scalar": "double",
    "description": (
        "numpy-quaternion %s (PyPI, import quaternion) on binary64: np.quaternion(w, x, y, z) read back as "
        "[x, y, z, w]; Hamilton product, normalized(), inverse(), rotate_vectors, as_rotation_matrix, "
        "from_rotation_matrix (Bar-Itzhack through scipy), from_rotation_vector(angle * axis), the vector "
        "part of np.log, np.exp of a pure quaternion, slerp_evaluate, q.angle(), np.sqrt. No status channel: an exception "
        "raised by numpy-quaternion is graded DOMAIN_ERROR (outputs NaN), all outputs NaN is DOMAIN_ERROR, "
        "anything else OK as computed (rotorcert_vectors)" % NUMPY_QUATERNION_VERSION),
}

if __name__ == "__main__":
    sys.exit(run_adapter(__doc__.splitlines()[0], IMPLEMENTATION, OPS))
