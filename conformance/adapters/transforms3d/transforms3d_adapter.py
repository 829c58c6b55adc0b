#!/usr/bin/env python3
"""rotorcert test-vector adapter for transforms3d (https://github.com/matthew-brett/transforms3d), binary64.

    python transforms3d_adapter.py --vectors DIR --out RESULTS.json

Runs the binary64 vectors of `rotorcert vectors export` through transforms3d.quaternions and writes
a results file for `rotorcert vectors check` (conformance/VECTORS.md). Reading, writing and the
status rule are the rotorcert_vectors package's (conformance/packages/python, installed into the
adapter's environment by scripts/setup-adapters): a Python exception raised inside transforms3d ->
DOMAIN_ERROR (every output NaN); every output component NaN -> DOMAIN_ERROR (transforms3d has no
status channel, RESULT-2); anything else -> OK with transforms3d's numbers as computed. The adapter
adds no domain checks, no rescaling, no hemisphere flips and no renormalisation that transforms3d
does not do itself.

Conventions (the mapping, nothing else):
  - Quaternions: transforms3d stores q = w + x i + y j + z k as the numpy array [w, x, y, z]
    (quaternions.py module docstring: "w is the real (scalar) part"); the ABI's [x, y, z, w] is
    reordered to [w, x, y, z] on the way in and back on the way out. qmult is the Hamilton product
    (quaternions.py:221, "Hamilton_product"), so compose(a, b) = qmult(a, b), b applied first.
  - Rotation: rotate_vector(v, q) is q (0, v) q* (quaternions.py:443), active and right-handed as
    the ABI's. quat2mat returns the 3x3 matrix that is applied on the left of column vectors
    (module docstring), M[r][c]; the ABI's column-major array is m[c*3 + r] = M[r][c], and the
    ABI's matrix input is reshaped and transposed into M the same way for mat2quat.
  - Angles are radians on both sides. quat2axangle returns (vector, theta) -- in that order -- and
    axangle2quat takes (vector, theta); the ABI's to_axis_angle returns (angle, axis).
  - Log and exp: the ABI's rotation log is the pure quaternion [x, y, z] = (theta/2) u (LOG-1);
    transforms3d's qlog(q) is the full quaternion log (log|q|, acos(w/|q|) v/|v|), whose vector part
    is exactly that, so log(q) = qlog(q)[1:] (its scalar part log|q| is the log of the norm, which
    the ABI's scale-free log has no slot for), and exp(v) = qexp([0, x, y, z]) (exp(0) = 1, so no
    factor). No factor of 2 is involved on either side.
  - Status: no status channel; the rotorcert_vectors rule (above). numpy's floating-point warnings
    (division by zero, invalid operation, overflow) are silenced with np.seterr(all="ignore"): that
    only stops the messages, numpy computes the same IEEE results under its default "warn".

Operations (what a transforms3d user calls):
  normalize        q / qnorm(q)                   transforms3d's own normalisation idiom: exactly what
                                                  rotate_vector(v, q, is_normalized=False) does
                                                  (quaternions.py:440); qnorm = sqrt(dot(q, q))
  compose          qmult(a, b)
  inverse          qinverse(q)                    conjugate / qnorm(q) (quaternions.py:300)
  apply_vector     rotate_vector(v, q, is_normalized=False)   transforms3d normalises q itself
  to_matrix        quat2mat(q)                    "allows quaternions that have not been normalized"
  from_matrix      mat2quat(M)                    Bar-Itzhack's eigenvector (numpy eigh), w >= 0; documented
                                                  for "3x3 rotation matrix" input (declared:
                                                  from_matrix:rotation_matrix; it has no determinant check)
  to_axis_angle    quat2axangle(q) -> (theta, vector)
  to_angle         quat2axangle(q)[1]             transforms3d has no angle-only or axis-only call:
  to_axis          quat2axangle(q)[0]             each is read from the one call a user gets it from
  from_axis_angle  axangle2quat(axis, angle)      is_normalized=False (its default): normalises the axis
  log              qlog(q)[1:]
  exp              qexp([0, x, y, z])
  rotate_about_axis  np.dot(axangles.axangle2aff(u, angle, c), [px, py, pz, 1])[:3]
                   axangle2aff returns the 4x4 affine of the rotation by angle about the line through
                   the point c with direction u (axangles.py:54), "to be multiplied on left of
                   coordinate column vector"; the product with the homogeneous point is that use
Not mapped (NOT_SUPPORTED): transforms3d 0.4.2 has no public slerp or nlerp (its private
_gohlketransforms module is not API), no square root (qpow is the general power), no blends, no
rotor/bivector/trivector objects, no dual quaternions and no skinning (adapter.json says why for each).
"""
import sys
from importlib.metadata import version as _dist_version

import numpy as np
from transforms3d import axangles as ta
from transforms3d import quaternions as tq
from rotorcert_vectors import Implementation, run_adapter

TRANSFORMS3D_VERSION = _dist_version("transforms3d")

np.seterr(all="ignore")  # messages only; the IEEE results are those of numpy's default "warn"


def wxyz(q):
    """ABI [x, y, z, w] -> transforms3d [w, x, y, z] (a float64 numpy array)."""
    x, y, z, w = q
    return np.array([w, x, y, z], dtype=np.float64)


def xyzw(q):
    """transforms3d [w, x, y, z] -> ABI [x, y, z, w]."""
    w, x, y, z = q
    return [x, y, z, w]


def matrix_in(m):
    """ABI column-major m[c*3 + r] -> the numpy matrix M[r][c] transforms3d takes."""
    return np.array(m, dtype=np.float64).reshape(3, 3).T


def matrix_out(M):
    """numpy M[r][c] -> ABI column-major m[c*3 + r]."""
    return [M[r][c] for c in range(3) for r in range(3)]


# --- Core ----------------------------------------------------------------------------------------

def normalize(q):
    Q = wxyz(q)
    return xyzw(Q / tq.qnorm(Q))


def compose(a, b):
    return xyzw(tq.qmult(wxyz(a), wxyz(b)))


def inverse(q):
    return xyzw(tq.qinverse(wxyz(q)))


def apply_vector(q, v):
    return tq.rotate_vector(np.array(v, dtype=np.float64), wxyz(q), is_normalized=False)


def to_matrix(q):
    return matrix_out(tq.quat2mat(wxyz(q)))


def from_matrix(m):
    return xyzw(tq.mat2quat(matrix_in(m)))


def to_axis_angle(q):
    vector, theta = tq.quat2axangle(wxyz(q))
    return theta, vector


def to_angle(q):
    return tq.quat2axangle(wxyz(q))[1]


def to_axis(q):
    return tq.quat2axangle(wxyz(q))[0]


def from_axis_angle(angle, axis):
    return xyzw(tq.axangle2quat(np.array(axis, dtype=np.float64), angle))


# --- Interp --------------------------------------------------------------------------------------

def log(q):
    return tq.qlog(wxyz(q))[1:]


def exp(v):
    x, y, z = v
    return xyzw(tq.qexp(np.array([0.0, x, y, z])))


# --- Rigid ---------------------------------------------------------------------------------------

def rotate_about_axis(c, u, angle, p):
    """axangle2aff's 4x4 affine, "to be multiplied on left of coordinate column vector", applied to (p, 1)."""
    A = ta.axangle2aff(np.array(u, dtype=np.float64), angle, np.array(c, dtype=np.float64))
    return np.dot(A, np.array([p[0], p[1], p[2], 1.0]))[:3]


OPS = {
    "normalize": normalize, "compose": compose, "inverse": inverse, "apply_vector": apply_vector,
    "to_matrix": to_matrix, "from_matrix": from_matrix, "to_axis_angle": to_axis_angle,
    "from_axis_angle": from_axis_angle, "log": log, "exp": exp, "rotate_about_axis": rotate_about_axis,
    "to_angle": to_angle, "to_axis": to_axis,
}

IMPLEMENTATION = Implementation(
    name="transforms3d",
    version=TRANSFORMS3D_VERSION,
    scalar="double",
    ops=OPS,
    description=(
        "transforms3d %s (PyPI) transforms3d.quaternions on float64 numpy arrays, [w, x, y, z] reordered "
        "to the ABI's [x, y, z, w]: qmult, qinverse, q / qnorm(q), rotate_vector(is_normalized=False), "
        "quat2mat, mat2quat, quat2axangle (whole, and its angle or axis alone), axangle2quat, qlog (vector part), qexp of a pure quaternion, "
        "axangles.axangle2aff applied to a homogeneous point. "
        "No status channel: a Python exception raised by transforms3d is graded DOMAIN_ERROR (outputs NaN), "
        "all outputs NaN is DOMAIN_ERROR, anything else OK as computed (rotorcert_vectors)" % TRANSFORMS3D_VERSION))

if __name__ == "__main__":
    sys.exit(run_adapter(__doc__.splitlines()[0], IMPLEMENTATION))
