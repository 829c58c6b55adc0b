#!/usr/bin/env python3
"""rotorcert test-vector adapter for pyquaternion (https://github.com/KieranWynn/pyquaternion), binary64.

    python pyquaternion_adapter.py --vectors DIR --out RESULTS.json

Runs the binary64 vectors of `rotorcert vectors export` through pyquaternion's Quaternion class and
writes a results file for `rotorcert vectors check` (conformance/VECTORS.md). Reading, writing and
the status rule are the rotorcert_vectors package's (conformance/packages/python, installed into the
adapter's environment by scripts/setup-adapters): a Python exception raised by pyquaternion ->
DOMAIN_ERROR (every output NaN); every output component NaN -> DOMAIN_ERROR (pyquaternion has no
status channel, RESULT-2); anything else -> OK with pyquaternion's numbers as computed. The adapter
adds no domain checks, no rescaling, no hemisphere flips and no renormalisation that pyquaternion
does not do itself.

Conventions (LAYOUT-1 <-> pyquaternion):
  - Quaternion(w, x, y, z) takes the scalar first and stores q.q = [w, x, y, z] (numpy float64): a
    spec quaternion [x, y, z, w] is Quaternion(w, x, y, z) and is read back as [q.x, q.y, q.z, q.w].
  - Hamilton product: Quaternion.__mul__ is q_matrix(a) . b with ij = k (checked once at start-up), so
    compose(a, b) = A * B, b applied first.
  - Active rotation: rotate(v) is q v q* (after normalising q), the spec's v' = q v q*.
  - rotation_matrix is a numpy 3x3 array M[row][col] acting on column vectors (M v = rotate(v)):
    stored column-major, m[c*3 + r] = M[r][c]; from_matrix gives pyquaternion the row-major array.
  - Angles in radians (Quaternion(axis=..., angle=...), .angle).
  - The log [x, y, z] of the spec (LOG-1) is the quaternion-view (theta/2) u; pyquaternion's
    Quaternion.log(q) is the full quaternion logarithm (log|q|, acos(w/|q|) v/|v|), whose vector part
    is that same (theta/2) u of q/|q| (no factor 2 between them): the adapter reads the vector part
    and leaves out the scalar log|q| (the spec's log is scale-free). exp(v) is Quaternion.exp of the
    pure quaternion (0, v) = (cos|v|, sin|v| v/|v|), EXP-1 itself.
  - to_axis_angle reads .angle (2 atan2(|v|, w) wrapped into (-pi, pi]: a signed angle, ACC-1
    angle_range) and get_axis(undefined=[0, 0, 1]): the documented parameter that names the axis of
    the null rotation (pyquaternion's default is [0, 0, 0]); the adapter passes the spec's (0, 0, 1).

Operations (what a pyquaternion user calls; Q = Quaternion(w, x, y, z), a fresh object per call,
because several properties normalise the object in place):
  normalize        Q.normalised
  compose          A * B
  inverse          Q.inverse
  apply_vector     Q.rotate(v)
  to_matrix        Q.rotation_matrix
  from_matrix      Quaternion(matrix=M)            (default rtol/atol of its orthogonality check;
                                                   declared precondition from_matrix:rotation_matrix)
  to_axis_angle    (Q.angle, Q.get_axis(undefined=[0, 0, 1]))
  from_axis_angle  Quaternion(axis=u, angle=theta)
  log              Quaternion.log(Q).vector
  exp              Quaternion.exp(Quaternion(vector=v))
  slerp            Quaternion.slerp(A, B, amount=t)  (amount clipped to [0, 1]: declared precondition
                                                   slerp:t_in_unit_interval)
  log_exp_round_trip   exp of what log returned (rotorcert_vectors.round_trip)
  to_angle         Q.angle                           (the same property as in to_axis_angle)
  to_axis          Q.get_axis(undefined=[0, 0, 1])   (the same call as in to_axis_angle)
Not mapped (NOT_SUPPORTED; adapter.json says why for each): apply_bivector, apply_trivector,
nlerp, blend_qlb, blend_log, sqrt (pyquaternion has none) and every dual-quaternion, rigid and
skinning op.
"""
import sys
import warnings
from importlib.metadata import version as _dist_version

import numpy as np
from pyquaternion import Quaternion
from rotorcert_vectors import round_trip, run_adapter, watch

PYQUATERNION_VERSION = _dist_version("pyquaternion")

# numpy's RuntimeWarnings (0/0, overflow inside pyquaternion's numpy arithmetic) only print;
# silencing them changes no value.
np.seterr(all="ignore")
warnings.simplefilter("ignore")


def _check_conventions():
    """Stops the adapter (not an assert, which -O removes) if pyquaternion's storage order or product
    rule is not the one the mapping above assumes."""
    i, j, k = Quaternion(0, 1, 0, 0), Quaternion(0, 0, 1, 0), Quaternion(0, 0, 0, 1)
    if list((i * j).q) != [0.0, 0.0, 0.0, 1.0] or list((i * j * k).q) != [-1.0, 0.0, 0.0, 0.0]:
        raise RuntimeError("pyquaternion's product is not Hamilton's with q = [w, x, y, z]")
    if [Quaternion(1, 2, 3, 4).w, Quaternion(1, 2, 3, 4).x] != [1.0, 2.0]:
        raise RuntimeError("pyquaternion's constructor is not scalar-first")


_check_conventions()
IDENTITY_AXIS = np.array([0.0, 0.0, 1.0])


def quat(q):
    """A spec quaternion [x, y, z, w] as pyquaternion's Quaternion(w, x, y, z), watched: a call that
    modifies it in place is reported (HYG-1), as the caller's own object would have been modified."""
    x, y, z, w = q
    return watch(Quaternion(w, x, y, z))


def xyzw(Q):
    return [Q.x, Q.y, Q.z, Q.w]


# --- Core ----------------------------------------------------------------------------------------

def normalize(q):
    return xyzw(quat(q).normalised)


def compose(a, b):
    return xyzw(quat(a) * quat(b))


def inverse(q):
    return xyzw(quat(q).inverse)


def apply_vector(q, v):
    return list(quat(q).rotate(list(v)))


def to_matrix(q):
    M = quat(q).rotation_matrix  # M[row][col]
    return [M[r][c] for c in range(3) for r in range(3)]  # column-major


def from_matrix(m):
    M = np.array([[m[c * 3 + r] for c in range(3)] for r in range(3)])  # column-major -> M[row][col]
    return xyzw(Quaternion(matrix=M))


def to_axis_angle(q):
    Q = quat(q)
    angle = Q.angle
    return angle, list(Q.get_axis(undefined=IDENTITY_AXIS))


def to_angle(q):
    return quat(q).angle


def to_axis(q):
    return list(quat(q).get_axis(undefined=IDENTITY_AXIS))


def from_axis_angle(angle, axis):
    return xyzw(Quaternion(axis=list(axis), angle=angle))


# --- Interp --------------------------------------------------------------------------------------

def log(q):
    return list(Quaternion.log(quat(q)).vector)


def exp(v):
    return xyzw(Quaternion.exp(Quaternion(vector=list(v))))


def slerp(a, b, t):
    return xyzw(Quaternion.slerp(quat(a), quat(b), amount=t))


OPS = {
    "normalize": normalize, "compose": compose, "inverse": inverse, "apply_vector": apply_vector,
    "to_matrix": to_matrix, "from_matrix": from_matrix,
    "to_axis_angle": to_axis_angle, "from_axis_angle": from_axis_angle,
    "log": log, "exp": exp, "slerp": slerp,
    "log_exp_round_trip": round_trip(log, exp),
    "to_angle": to_angle, "to_axis": to_axis,
}

IMPLEMENTATION = {
    "name": "pyquaternion",
    "version": PYQUATERNION_VERSION,
    "scalar": "double",
    "description": (
        "pyquaternion %s (PyPI) on numpy float64: Quaternion(w, x, y, z) read back as [x, y, z, w]; "
        "Hamilton product, normalised, inverse, rotate(), rotation_matrix, Quaternion(matrix=), .angle and "
        "get_axis() (together, and each alone), Quaternion(axis=, angle=), the vector part of Quaternion.log, "
        "Quaternion.exp of a pure quaternion, Quaternion.slerp. No status channel: an exception raised by "
        "pyquaternion is graded DOMAIN_ERROR (outputs NaN), all outputs NaN is DOMAIN_ERROR, anything else OK "
        "as computed (rotorcert_vectors)" % PYQUATERNION_VERSION),
}

if __name__ == "__main__":
    sys.exit(run_adapter(__doc__.splitlines()[0], IMPLEMENTATION, OPS))
