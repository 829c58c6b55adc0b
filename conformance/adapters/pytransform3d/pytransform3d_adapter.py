#!/usr/bin/env python3
"""rotorcert test-vector adapter for pytransform3d (https://github.com/dfki-ric/pytransform3d), binary64.

    python pytransform3d_adapter.py --vectors DIR --out RESULTS.json

Runs the binary64 vectors of `rotorcert vectors export` through pytransform3d.rotations and
pytransform3d.transformations and writes a results file for `rotorcert vectors check`
(conformance/VECTORS.md). Reading, writing and the status rule are the rotorcert_vectors package's
(conformance/packages/python, installed into the adapter's environment by scripts/setup-adapters):
a Python exception raised inside pytransform3d (its ValueError input checks) -> DOMAIN_ERROR (every
output NaN); every output component NaN -> DOMAIN_ERROR (pytransform3d has no status channel,
RESULT-2); anything else -> OK with pytransform3d's numbers as computed. The adapter adds no domain
checks, no rescaling, no hemisphere flips and no renormalisation that pytransform3d does not do
itself (its functions normalise quaternion inputs themselves, through check_quaternion).

Conventions (the mapping, nothing else):
  - Quaternions: pytransform3d stores q = w + x i + y j + z k as [w, x, y, z] ("Quaternion to
    represent rotation: (w, x, y, z)"); the ABI's [x, y, z, w] is reordered on the way in and back.
    concatenate_quaternions(q1, q2) is Hamilton's product q1 q2 (its docstring), so
    compose(a, b) = concatenate_quaternions(a, b), b applied first. q_prod_vector(q, v) is
    q (0, v) q*: active and right-handed as the ABI's; matrix_from_quaternion returns the active
    matrix M[r][c] that multiplies column vectors, stored column-major as m[c*3 + r] = M[r][c], and
    the ABI's matrix input is reshaped and transposed into M the same way.
  - Axis-angle: pytransform3d's axis-angle is the array (x, y, z, angle) and its compact axis-angle
    (rotation vector) is angle * (x, y, z), angles in radians. The ABI's rotation log is the pure
    quaternion (angle/2) u (LOG-1): log(q) = compact_axis_angle_from_quaternion(q) / 2 and
    exp(v) = quaternion_from_compact_axis_angle(2 v) -- pytransform3d calls these the logarithmic
    and exponential map; the factor 2 (rotation angle vs. S^3 angle) is a power of two and exact.
  - Dual quaternions: pytransform3d stores sigma = p + eps q as (pw, px, py, pz, qw, qx, qy, qz), with
    the translation t carried as q = 0.5 t p (dual_quaternion_from_pq; the translation is read back
    as 2 q p*, pq_from_dual_quaternion) -- the spec's DQ-1 convention. The ABI's
    [rx, ry, rz, rw, dx, dy, dz, dw] is reordered to [rw, rx, ry, rz, dw, dx, dy, dz] and back; no
    sign or factor changes. concatenate_dual_quaternions(dq1, dq2) is dq1 dq2 (b applied first: the
    warning in its docstring says the argument order differs from concat's, whose first argument is
    applied first); dq_prod_vector applies rotation then translation (R p + t). dual_quaternion_from_pq
    takes (x, y, z, qw, qx, qy, qz): position first, then the quaternion.
  - Rotation about a line: dual_quaternion_from_screw_parameters(q, s_axis, h, theta) is the screw
    through the point q with direction s_axis, pitch h and angle theta; pitch 0 is a pure rotation
    about that line, so rotate_about_axis(c, u, angle, p) = dq_prod_vector(
    dual_quaternion_from_screw_parameters(c, u, 0.0, angle), p).
  - Status: no status channel; the rotorcert_vectors rule (above). numpy's floating-point warnings
    are silenced with np.seterr(all="ignore") (messages only: the IEEE results are those of numpy's
    default "warn"); pytransform3d's own warnings are untouched.

Operations (what a pytransform3d user calls):
  normalize        pr.norm_vector(q)                     q / np.linalg.norm(q), the zero vector kept
  compose          pr.concatenate_quaternions(a, b)
  inverse          pr.q_conj(q)                          "The conjugate of a unit quaternion inverts
                                                          the rotation"; pytransform3d has no other
                                                          inverse, so adapter.json declares the
                                                          precondition inverse:unit_quaternion
  apply_vector     pr.q_prod_vector(q, v)                normalises q (check_quaternion)
  to_matrix        pr.matrix_from_quaternion(q)          normalises q
  from_matrix      pr.quaternion_from_matrix(M)          strict_check=True (its default): ValueError
                                                          unless M is a rotation within 1e-6
                                                          (declared: from_matrix:rotation_matrix)
  to_axis_angle    pr.axis_angle_from_quaternion(q) -> (a[3], a[:3])   angle in [0, pi)
  to_angle         pr.axis_angle_from_quaternion(q)[3]   pytransform3d has no angle-only or axis-only
  to_axis          pr.axis_angle_from_quaternion(q)[:3]  call: each is read from the one call that gives it
  from_axis_angle  pr.quaternion_from_axis_angle([ux, uy, uz, angle])
  log              pr.compact_axis_angle_from_quaternion(q) / 2
  exp              pr.quaternion_from_compact_axis_angle(2 v)
  slerp            pr.quaternion_slerp(a, b, t, shortest_path=True)   the library's shorter-arc option
  dq_from_rotation_translation   pt.dual_quaternion_from_pq([tx, ty, tz, w, x, y, z])
  dq_compose       pt.concatenate_dual_quaternions(a, b)              unit=True (its default)
  dq_apply_point   pt.dq_prod_vector(d, p)
  dq_normalize     pt.norm_dual_quaternion(d)
  dq_sclerp        pt.dual_quaternion_sclerp(a, b, t)
  dq_to_rotation_translation   pt.pq_from_dual_quaternion(d) -> (pq[3:] as [x, y, z, w], pq[:3])
  rotate_about_axis pt.dq_prod_vector(pt.dual_quaternion_from_screw_parameters(c, u, 0.0, angle), p)
  rigid_compose    pt.pq_from_transform(pt.concat(T(qb, tb), T(qa, ta)))  concat(A2B, B2C) = B2C A2B: its
                                                          first argument is applied first (its docstring),
                                                          so b goes first; T(q, t) = pt.transform_from_pq
                                                          ([tx, ty, tz, w, x, y, z]) (normalises q)
  rigid_apply      pt.transform(T(q, t), pt.vector_to_point(p))[:3]   the homogeneous point's x, y, z
  rigid_inverse    pt.pq_from_transform(pt.invert_transform(T(q, t)))
  dq_log           pt.exponential_coordinates_from_transform(pt.transform_from_dual_quaternion(d)) / 2
                   the exponential coordinates S theta = (omega theta, v theta) are the twist of
                   T = exp([S] theta); DQ-8's dual vector is half of them (the dual quaternion of
                   exp([S] theta) is the dual-quaternion exponential of 1/2 (omega + eps v) theta)
                   (Log(R) is compact_axis_angle_from_matrix, angle in [0, pi]: where r_w < 0 this
                   is the log of -sigma, the same motion, declared dq_log:shorter_arc)
Not mapped (NOT_SUPPORTED): pytransform3d 3.17.0 has no dual-quaternion exponential (dq_exp, see
adapter.json), no quaternion square root, no nlerp, no n-way quaternion or dual-quaternion
blend, no skinning, and no bivector or trivector sandwich (its "rotors" are quaternions relabelled
(a, b_yz, b_zx, b_xy) and act on vectors only): adapter.json says why for each.
"""
import sys
from importlib.metadata import version as _dist_version

import numpy as np
import pytransform3d.rotations as pr
import pytransform3d.transformations as pt
from rotorcert_vectors import Implementation, run_adapter

PYTRANSFORM3D_VERSION = _dist_version("pytransform3d")

np.seterr(all="ignore")  # messages only; the IEEE results are those of numpy's default "warn"


def wxyz(q):
    """ABI [x, y, z, w] -> pytransform3d (w, x, y, z), a float64 numpy array."""
    x, y, z, w = q
    return np.array([w, x, y, z], dtype=np.float64)


def xyzw(q):
    """pytransform3d (w, x, y, z) -> ABI [x, y, z, w]."""
    w, x, y, z = q
    return [x, y, z, w]


def dq_in(d):
    """ABI [rx, ry, rz, rw, dx, dy, dz, dw] -> pytransform3d (pw, px, py, pz, qw, qx, qy, qz)."""
    rx, ry, rz, rw, dx, dy, dz, dw = d
    return np.array([rw, rx, ry, rz, dw, dx, dy, dz], dtype=np.float64)


def dq_out(s):
    """pytransform3d (pw, px, py, pz, qw, qx, qy, qz) -> ABI [rx, ry, rz, rw, dx, dy, dz, dw]."""
    pw, px, py, pz, qw, qx, qy, qz = s
    return [px, py, pz, pw, qx, qy, qz, qw]


def vec(v):
    return np.array(v, dtype=np.float64)


def matrix_in(m):
    """ABI column-major m[c*3 + r] -> numpy M[r][c]."""
    return np.array(m, dtype=np.float64).reshape(3, 3).T


def matrix_out(M):
    """numpy M[r][c] -> ABI column-major m[c*3 + r]."""
    return [M[r][c] for c in range(3) for r in range(3)]


# --- Core ----------------------------------------------------------------------------------------

def normalize(q):
    return xyzw(pr.norm_vector(wxyz(q)))


def compose(a, b):
    return xyzw(pr.concatenate_quaternions(wxyz(a), wxyz(b)))


def inverse(q):
    return xyzw(pr.q_conj(wxyz(q)))


def apply_vector(q, v):
    return pr.q_prod_vector(wxyz(q), vec(v))


def to_matrix(q):
    return matrix_out(pr.matrix_from_quaternion(wxyz(q)))


def from_matrix(m):
    return xyzw(pr.quaternion_from_matrix(matrix_in(m)))


def to_axis_angle(q):
    a = pr.axis_angle_from_quaternion(wxyz(q))
    return a[3], a[:3]


def to_angle(q):
    return pr.axis_angle_from_quaternion(wxyz(q))[3]


def to_axis(q):
    return pr.axis_angle_from_quaternion(wxyz(q))[:3]


def from_axis_angle(angle, axis):
    ux, uy, uz = axis
    return xyzw(pr.quaternion_from_axis_angle(np.array([ux, uy, uz, angle], dtype=np.float64)))


# --- Interp --------------------------------------------------------------------------------------

def log(q):
    return pr.compact_axis_angle_from_quaternion(wxyz(q)) / 2.0


def exp(v):
    return xyzw(pr.quaternion_from_compact_axis_angle(2.0 * vec(v)))


def slerp(a, b, t):
    return xyzw(pr.quaternion_slerp(wxyz(a), wxyz(b), t, shortest_path=True))


# --- Rigid ---------------------------------------------------------------------------------------

def dq_from_rotation_translation(q, t):
    x, y, z, w = q
    tx, ty, tz = t
    return dq_out(pt.dual_quaternion_from_pq(np.array([tx, ty, tz, w, x, y, z], dtype=np.float64)))


def dq_compose(a, b):
    return dq_out(pt.concatenate_dual_quaternions(dq_in(a), dq_in(b)))


def dq_apply_point(d, p):
    return pt.dq_prod_vector(dq_in(d), vec(p))


def dq_normalize(d):
    return dq_out(pt.norm_dual_quaternion(dq_in(d)))


def dq_sclerp(a, b, t):
    return dq_out(pt.dual_quaternion_sclerp(dq_in(a), dq_in(b), t))


def dq_to_rotation_translation(d):
    pq = pt.pq_from_dual_quaternion(dq_in(d))  # (x, y, z, qw, qx, qy, qz)
    return xyzw(pq[3:]), pq[:3]


def rotate_about_axis(c, u, angle, p):
    return pt.dq_prod_vector(pt.dual_quaternion_from_screw_parameters(vec(c), vec(u), 0.0, angle), vec(p))


# --- ABI version 4 (Extended): rigid transforms as rotation + translation ------------------------
# pytransform3d holds them as 4x4 matrices A2B built from a position and quaternion (pq, (x, y, z,
# qw, qx, qy, qz)); transform_from_pq normalises the quaternion (matrix_from_quaternion).

def transform_pq(q, t):
    x, y, z, w = q
    tx, ty, tz = t
    return pt.transform_from_pq(np.array([tx, ty, tz, w, x, y, z], dtype=np.float64))


def pq_out(pq):
    return xyzw(pq[3:]), pq[:3]


def rigid_compose(qa, ta, qb, tb):
    return pq_out(pt.pq_from_transform(pt.concat(transform_pq(qb, tb), transform_pq(qa, ta))))


def rigid_apply(q, t, p):
    return pt.transform(transform_pq(q, t), pt.vector_to_point(vec(p)))[:3]


def rigid_inverse(q, t):
    return pq_out(pt.pq_from_transform(pt.invert_transform(transform_pq(q, t))))


def dq_log(d):
    return pt.exponential_coordinates_from_transform(pt.transform_from_dual_quaternion(dq_in(d))) / 2


OPS = {
    "normalize": normalize, "compose": compose, "inverse": inverse, "apply_vector": apply_vector,
    "to_matrix": to_matrix, "from_matrix": from_matrix, "to_axis_angle": to_axis_angle,
    "from_axis_angle": from_axis_angle,
    "log": log, "exp": exp, "slerp": slerp,
    "dq_from_rotation_translation": dq_from_rotation_translation, "dq_compose": dq_compose,
    "dq_apply_point": dq_apply_point, "dq_normalize": dq_normalize, "dq_sclerp": dq_sclerp,
    "rotate_about_axis": rotate_about_axis,
    "to_angle": to_angle, "to_axis": to_axis, "dq_to_rotation_translation": dq_to_rotation_translation,
    "rigid_compose": rigid_compose, "rigid_apply": rigid_apply, "rigid_inverse": rigid_inverse,
    "dq_log": dq_log,
}

IMPLEMENTATION = Implementation(
    name="pytransform3d",
    version=PYTRANSFORM3D_VERSION,
    scalar="double",
    ops=OPS,
    description=(
        "pytransform3d %s (PyPI) on float64 numpy arrays: quaternions (w, x, y, z) of pytransform3d.rotations "
        "and dual quaternions (pw, px, py, pz, qw, qx, qy, qz) of pytransform3d.transformations, reordered to the "
        "ABI's [x, y, z, w] / [real xyzw, dual xyzw]; log/exp through the compact axis-angle (rotation vector / 2); "
        "slerp with shortest_path=True; rigid transforms as transform_from_pq matrices (concat, transform, invert_transform, pq_from_transform). No status channel: a Python exception raised by pytransform3d is graded "
        "DOMAIN_ERROR (outputs NaN), all outputs NaN is DOMAIN_ERROR, anything else OK as computed "
        "(rotorcert_vectors)" % PYTRANSFORM3D_VERSION))

if __name__ == "__main__":
    sys.exit(run_adapter(__doc__.splitlines()[0], IMPLEMENTATION))
