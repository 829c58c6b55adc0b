#!/usr/bin/env python3
"""rotorcert test-vector adapter for SciPy's scipy.spatial.transform (https://scipy.org), binary64.

    python scipy_adapter.py --vectors DIR --out RESULTS.json

Runs the binary64 vectors of `rotorcert vectors export` through scipy.spatial.transform (Rotation,
Slerp, RigidTransform) and writes a results file for `rotorcert vectors check`
(conformance/VECTORS.md). Reading, writing and the status rule are the rotorcert_vectors package's
(conformance/packages/python, installed into the adapter's environment by scripts/setup-adapters): a
Python exception raised inside scipy (ValueError for a zero-norm quaternion, a non-positive
determinant or a time outside the keyframes) -> DOMAIN_ERROR (every output NaN); every output
component NaN -> DOMAIN_ERROR (scipy has no status channel, RESULT-2); anything else -> OK with
scipy's numbers as computed. The adapter adds no domain checks, no rescaling, no hemisphere flips and
no renormalisation that scipy does not do itself. Each call is one rotation (scipy is vectorised,
but the package calls one function per vector, so the status rule stays per vector).

Conventions (scipy's defaults are the ABI's, so nothing is reordered except the matrix):
  - quaternions: scipy's default scalar-last order (x, y, z, w) (from_quat / as_quat with
    scalar_first=False) is LAYOUT-1's [x, y, z, w]; as_quat(canonical=False), the default, returns
    the stored sign (no canonicalisation).
  - Rotation.from_quat normalises its input ("Each quaternion will be normalized to unit norm") and
    a Rotation is a rotation, not a quaternion: compose and inverse are of q/|q|, not of q itself
    (the manifest declares compose:unit_quaternion and inverse:unit_quaternion, DECL-1).
  - product: scipy's compose_quat is the Hamilton product; p * q is "q followed by p", i.e.
    compose(a, b) = from_quat(a) * from_quat(b) (b applied first), as the ABI.
  - rotation of vectors: Rotation.apply is active, "the same as self.as_matrix() @ vectors", so
    apply_vector(q, v) = from_quat(q).apply(v) = R v ~R.
  - matrices: as_matrix / from_matrix take row-major numpy arrays M[r][c]; the ABI's 3x3 matrix is
    column-major m[c*3 + r], so the adapter transposes at the boundary.
  - rotation vectors: scipy's rotvec is theta * u (radians); the ABI's log is the quaternion-view
    (theta/2) u, so log(q) = from_quat(q).as_rotvec() / 2 and exp(v) = from_rotvec(2 v).as_quat()
    (scalings by powers of two); from_axis_angle(theta, u) = from_rotvec(theta * u), scipy's own
    idiom (docstring example R.from_rotvec(np.pi/2 * np.array([0, 0, 1]))), meaningful for a unit u
    (declared from_axis_angle:unit_axis).
  - rigid transforms: RigidTransform's dual quaternion is scalar-last real part then dual part with
    q_d = 1/2 t q_r (as_dual_quat), LAYOUT-1's [rx, ry, rz, rw, dx, dy, dz, dw] and DQ-1's form;
    RigidTransform stores a 4x4 matrix, so every dual quaternion it returns comes back through
    from_matrix (Markley's method) with scipy's sign.

Operations (what a scipy user calls):
  normalize        Rotation.from_quat(q).as_quat()
  compose          (Rotation.from_quat(a) * Rotation.from_quat(b)).as_quat()
  inverse          Rotation.from_quat(q).inv().as_quat()
  apply_vector     Rotation.from_quat(q).apply(v)
  to_matrix        Rotation.from_quat(q).as_matrix(), transposed to column-major
  from_matrix      Rotation.from_matrix(M).as_quat()   (SVD polar factor if not orthogonal within
                                                        1e-12, then Markley's method)
  from_axis_angle  Rotation.from_rotvec(angle * axis).as_quat()
  log              Rotation.from_quat(q).as_rotvec() / 2
  exp              Rotation.from_rotvec(2 * v).as_quat()
  slerp            Slerp([0, 1], Rotation.from_quat([a, b]))(t).as_quat()
  dq_from_rotation_translation  RigidTransform.from_components(t, Rotation.from_quat(q)).as_dual_quat()
  dq_compose       (RigidTransform.from_dual_quat(a) * RigidTransform.from_dual_quat(b)).as_dual_quat()
  dq_apply_point   RigidTransform.from_dual_quat(d).apply(p)
  dq_normalize     RigidTransform.from_dual_quat(d).as_dual_quat()
  dq_sclerp        A * (A.inv() * B) ** t with A, B = RigidTransform.from_dual_quat(a), (b): the
                   documented ScLERP of RigidTransform.__pow__ from A towards B
  to_angle         Rotation.from_quat(q).magnitude()   (the angle in [0, pi])
  dq_to_rotation_translation   t, r = RigidTransform.from_dual_quat(d).as_components(): (r.as_quat(), t)
  rigid_compose    t, r = (T(qa, ta) * T(qb, tb)).as_components(): (r.as_quat(), t), with
                   T(q, t) = RigidTransform.from_components(t, Rotation.from_quat(q))
  rigid_apply      T(q, t).apply(p)
  rigid_inverse    t', r' = T(q, t).inv().as_components(): (r'.as_quat(), t')
  dq_log           RigidTransform.from_dual_quat(d).as_exp_coords() / 2: scipy's exponential
                   coordinates [r, v] are the twist tau with T = exp(tau) (from_exp_coords' doc), the
                   dual vector of DQ-8 is half of it (exp of the dual quaternion 1/2 (r + eps v) is the
                   dual quaternion of T, the scaling by 2 of log); its rotation part is as_rotvec's,
                   angle in [0, pi] (the log of -sigma where r_w < 0, ACC-1 shorter_arc)
Not mapped (NOT_SUPPORTED; adapter.json says why for each): apply_bivector, apply_trivector (scipy
has no bivectors or trivectors), to_axis_angle and to_axis (no axis call: magnitude() is the angle
only), sqrt (no square root: Rotation ** 0.5 is the documented principal root, half of the angle
in [0, pi], which for w < 0 is the square root of -q, not of q),
nlerp, blend_qlb and blend_log (Rotation.mean is the chordal L2 mean, another definition), dq_blend
(RigidTransform.mean: chordal mean plus mean translation), rotate_about_axis, skin_linear,
skin_dual_quaternion.

A call that never returns: Rotation.from_matrix hands a matrix with an infinite entry (whose
determinant is +inf or NaN, so its determinant check lets it through) to numpy.linalg.svd, and
LAPACK's SVD of some such matrices never returns (EDGE-7 vectors "-Inf in m[i]"). from_matrix calls
whose matrix has a non-finite entry therefore run in a forked child limited to HANG_CPU_S of CPU
time (SIGPROF ends it); a child that had to be stopped raises rotorcert_vectors.DidNotReturn, which
is reported with raw status byte 255 (a FAIL, conformance/VECTORS.md): neither OK nor a refusal.
What the child returned or raised is passed on unchanged. Finite matrices run in this process.
"""
import math
import os
import pickle
import signal
import sys
from importlib.metadata import version as _dist_version

import numpy as np
from scipy.spatial.transform import RigidTransform, Rotation, Slerp
from rotorcert_vectors import AdapterError, DidNotReturn, Implementation, run_adapter

SCIPY_VERSION = _dist_version("scipy")

# numpy reports overflow / invalid operations inside scipy as RuntimeWarnings on stderr; silence
# them (the values are unchanged: 'ignore' and 'warn' compute the same numbers).
np.seterr(all="ignore")

HANG_CPU_S = 2.0  # CPU seconds a forked call may use; a from_matrix call takes well under 1 ms


class ScipyRaised(Exception):
    """An exception scipy raised inside a forked call, re-raised here (the library's refusal)."""


def isolated(fn):
    """Runs fn in a forked child limited to HANG_CPU_S of CPU time when one of its arguments has a
    non-finite component (see the module docstring); returns or raises what the child did."""
    def call(*args):
        if all(math.isfinite(x) for a in args for x in (a if isinstance(a, (list, tuple)) else [a])):
            return fn(*args)
        r, w = os.pipe()
        pid = os.fork()
        if pid == 0:  # child
            os.close(r)
            signal.setitimer(signal.ITIMER_PROF, HANG_CPU_S)  # SIGPROF's default action ends it
            try:
                msg = ("ok", [float(c) for c in fn(*args)])
            except BaseException as e:  # noqa: B902 - every outcome goes back to the parent
                msg = ("raise", type(e).__name__, str(e))
            signal.setitimer(signal.ITIMER_PROF, 0)
            with os.fdopen(w, "wb") as f:
                f.write(pickle.dumps(msg))
            os._exit(0)
        os.close(w)
        chunks = []
        while True:
            chunk = os.read(r, 65536)
            if not chunk:
                break
            chunks.append(chunk)
        os.close(r)
        _, status = os.waitpid(pid, 0)
        if os.WIFSIGNALED(status):
            raise DidNotReturn("%s did not return within %.1f s CPU (signal %d)"
                               % (fn.__name__, HANG_CPU_S, os.WTERMSIG(status)))
        msg = pickle.loads(b"".join(chunks))
        if msg[0] == "ok":
            return msg[1]
        if msg[1] in ("NameError", "AttributeError", "ImportError", "KeyError"):  # a defect of this file
            raise AdapterError("adapter defect in %s: %s: %s" % ((fn.__name__,) + msg[1:]))
        raise ScipyRaised("%s: %s" % msg[1:])
    call.__name__ = fn.__name__
    return call


# --- Core ----------------------------------------------------------------------------------------

def normalize(q):
    return Rotation.from_quat(q).as_quat()


def compose(a, b):
    return (Rotation.from_quat(a) * Rotation.from_quat(b)).as_quat()


def inverse(q):
    return Rotation.from_quat(q).inv().as_quat()


def apply_vector(q, v):
    return Rotation.from_quat(q).apply(v)


def to_matrix(q):
    return Rotation.from_quat(q).as_matrix().T.ravel()  # rows M[r][c] -> column-major m[c*3 + r]


@isolated
def from_matrix(m):
    rows = np.asarray(m, dtype=float).reshape(3, 3).T  # column-major m[c*3 + r] -> M[r][c]
    return Rotation.from_matrix(rows).as_quat()


def from_axis_angle(angle, axis):
    return Rotation.from_rotvec(angle * np.asarray(axis, dtype=float)).as_quat()


# --- Interp --------------------------------------------------------------------------------------

def log(q):
    """scipy's rotation vector theta u is twice the quaternion-view log (theta/2) u."""
    return Rotation.from_quat(q).as_rotvec() / 2


def exp(v):
    return Rotation.from_rotvec(2 * np.asarray(v, dtype=float)).as_quat()


def slerp(a, b, t):
    return Slerp([0.0, 1.0], Rotation.from_quat([a, b]))(t).as_quat()


# --- Rigid (RigidTransform) ----------------------------------------------------------------------

def dq_from_rotation_translation(q, t):
    return RigidTransform.from_components(t, Rotation.from_quat(q)).as_dual_quat()


def dq_compose(a, b):
    return (RigidTransform.from_dual_quat(a) * RigidTransform.from_dual_quat(b)).as_dual_quat()


def dq_apply_point(d, p):
    return RigidTransform.from_dual_quat(d).apply(p)


def dq_normalize(d):
    return RigidTransform.from_dual_quat(d).as_dual_quat()


def dq_sclerp(a, b, t):
    ta, tb = RigidTransform.from_dual_quat(a), RigidTransform.from_dual_quat(b)
    return (ta * (ta.inv() * tb) ** t).as_dual_quat()


def dq_to_rotation_translation(d):
    t, r = RigidTransform.from_dual_quat(d).as_components()
    return r.as_quat(), t


# --- ABI version 3 (Extended) --------------------------------------------------------------------

def to_angle(q):
    return Rotation.from_quat(q).magnitude()


# --- ABI version 4 (Extended): rigid transforms as rotation + translation ------------------------
# RigidTransform.from_components(translation, rotation) ("the transform first rotates, then
# translates": x -> R x + t) with Rotation.from_quat (normalises q); * composes ("p * q: q followed
# by p"); apply, inv; as_components() -> (translation, rotation), the quaternion read with as_quat().

def dq_log(d):
    return RigidTransform.from_dual_quat(d).as_exp_coords() / 2


def rigid(q, t):
    return RigidTransform.from_components(t, Rotation.from_quat(q))


def rigid_compose(qa, ta, qb, tb):
    t, r = (rigid(qa, ta) * rigid(qb, tb)).as_components()
    return r.as_quat(), t


def rigid_apply(q, t, p):
    return rigid(q, t).apply(p)


def rigid_inverse(q, t):
    t2, r2 = rigid(q, t).inv().as_components()
    return r2.as_quat(), t2


OPS = {
    "normalize": normalize, "compose": compose, "inverse": inverse, "apply_vector": apply_vector,
    "to_matrix": to_matrix, "from_matrix": from_matrix, "from_axis_angle": from_axis_angle,
    "log": log, "exp": exp, "slerp": slerp,
    "dq_from_rotation_translation": dq_from_rotation_translation, "dq_compose": dq_compose,
    "dq_apply_point": dq_apply_point, "dq_normalize": dq_normalize, "dq_sclerp": dq_sclerp,
    "to_angle": to_angle, "dq_to_rotation_translation": dq_to_rotation_translation,
    "dq_log": dq_log, "rigid_compose": rigid_compose, "rigid_apply": rigid_apply, "rigid_inverse": rigid_inverse,
}

IMPLEMENTATION = Implementation(
    name="scipy", version=SCIPY_VERSION, scalar="double", ops=OPS,
    description=(
        "SciPy %s (PyPI) scipy.spatial.transform on numpy float64: Rotation (from_quat/as_quat "
        "scalar-last, *, inv, apply, as_matrix/from_matrix, as_rotvec/from_rotvec, magnitude), Slerp and "
        "RigidTransform (dual quaternions, *, apply, ** as ScLERP, as_components; from_components/as_components, *, apply, inv for rotation + translation; as_exp_coords / 2 as the dual-quaternion log). from_quat normalises its input. "
        "No status channel: a Python exception raised by scipy is graded DOMAIN_ERROR (outputs NaN), "
        "all outputs NaN is DOMAIN_ERROR, anything else OK as computed (rotorcert_vectors)" % SCIPY_VERSION))

if __name__ == "__main__":
    sys.exit(run_adapter(__doc__.splitlines()[0], IMPLEMENTATION))
