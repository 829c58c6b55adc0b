#!/usr/bin/env python3
"""rotorcert test-vector adapter for kingdon (https://github.com/tBuLi/kingdon), binary64.

    python kingdon_adapter.py --vectors DIR --out RESULTS.json

Runs the binary64 vectors of `rotorcert vectors export` through kingdon and writes a results file
for `rotorcert vectors check` (conformance/VECTORS.md). Reading, writing and the status rule are
the rotorcert_vectors package's (conformance/packages/python, installed into the adapter's
environment by scripts/setup-adapters): a Python exception raised inside kingdon -> DOMAIN_ERROR
(every output NaN); every output component NaN -> DOMAIN_ERROR (kingdon has no status channel,
RESULT-2); anything else -> OK with kingdon's numbers as computed. The adapter adds no domain checks, no
rescaling, no hemisphere flips and no renormalisation that kingdon does not do itself.

Algebras and coefficients. Multivectors hold Python floats (kingdon's default values_asarray=list),
so what is graded is kingdon's generated code on binary64 Python floats, where x/0.0 raises
ZeroDivisionError.
  - Rotations: Algebra(3, 0, 0). kingdon names the bivector blades e12, e13, e23 (bitmaps 3, 5, 6,
    the spec's own bitmaps); the spec's e31 is -e13. A quaternion [x, y, z, w] becomes the rotor
    Phi(q) = w - x e23 - y e31 - z e12 = w - z e12 + y e13 - x e23 (Q2R-1), created with
    alg.evenmv([w, -z, y, -x]) (even grades, keys in kingdon's order e, e12, e13, e23), and is read
    back as w = R.e, x = -R.e23, y = -R.e31 (= R.e13), z = -R.e12. A vector is alg.vector([x, y, z]);
    a bivector [b23, b31, b12] is alg.bivector([b12, -b31, b23]); a trivector a is alg.trivector([a])
    = a e123 (I = e123 as in the spec).
  - Rigid motions: Algebra(3, 0, 1) (kingdon puts e0 first: bitmaps e0 1, e1 2, e2 4, e3 8). A dual
    quaternion [rx, ry, rz, rw, dx, dy, dz, dw] becomes the motor of MOTOR-1,
    M = rw - rx e23 - ry e31 - rz e12 - dx e01 - dy e02 - dz e03 - dw e0123, created with
    alg.evenmv([rw, -dx, -dy, -dz, -rz, ry, -rx, -dw]) (keys e, e01, e02, e03, e12, e13, e23, e0123)
    and read back the same way. A point p is (e0 + x e1 + y e2 + z e3).dual(), kingdon's documented
    point (3DPGA example), i.e. x e032 + y e013 + z e021 + e123 (ALG-7), built as
    alg.vector([1, x, y, z]).dual(); a moved point is read as P.undual() divided by its e0 weight
    (the spec's readout, MOTOR-2; kingdon's generated sandwich returns that weight unchanged, 1.0).

Operations (what a kingdon user calls):
  normalize        Phi(q).normalized()                 R / sqrt(R ~R), kingdon's norm
  compose          Phi(a) * Phi(b)                     geometric product (a b: b applied first)
  inverse          Phi(q).inv()                        ~R / (R ~R)
  apply_vector     Phi(q) >> v                         kingdon's sandwich R v ~R (assumes R ~R = 1)
  apply_bivector   Phi(q) >> B
  apply_trivector  Phi(q) >> (a e123)
  to_matrix        Phi(q) >> alg.frame                 column c = the rotated frame vector e_c
  from_axis_angle  (alg.vector(u).normalized().dual() * (angle / 2)).exp()
                   dual() in Cl(3,0) is kingdon's polarity u I^-1 = -I u, so this is
                   exp(-I u angle/2), the right-handed rotor of the spec (AXANG-2)
  exp              alg.bivector(Phi(v)).exp()          kingdon's closed form for simple bivectors
  dq_compose       M_a * M_b                           geometric product of the motors (MOTOR-3)
  dq_apply_point   M >> P                              kingdon's sandwich (assumes M ~M = 1)
  dq_normalize     M.normalized()                      M / sqrt(M ~M), kingdon's Study-number sqrt
                                                       and inverse: equals DQ-4 under MOTOR-1
  sqrt             Phi(q).sqrt()                       kingdon's square root of a Study number a + bI
                                                       (operators.sqrt; R ** 0.5 calls it too)
Not mapped (NOT_SUPPORTED): kingdon 3.0.0 has no logarithm, no fractional power (** takes
integers and 0.5), no matrix-to-rotor, no slerp/nlerp/blends, no motor exponential for non-simple
bivectors (exp raises NotImplementedError), no translator/motor constructor and no angle, axis or
motor decomposition: from_matrix, to_axis_angle, to_angle, to_axis, log, slerp, nlerp, blend_qlb,
blend_log, dq_from_rotation_translation, dq_to_rotation_translation, dq_sclerp, dq_blend,
rotate_about_axis, skin_linear, skin_dual_quaternion (adapter.json says why for each).
"""
import sys
from importlib.metadata import version as _dist_version

from kingdon import Algebra
from rotorcert_vectors import run_adapter

KINGDON_VERSION = _dist_version("kingdon")

VGA = Algebra(3, 0, 0)
PGA = Algebra(3, 0, 1)

# The coefficient orders below are kingdon's key orders for these constructors; checked once
# here (not with assert, which -O removes) so that a kingdon with another order stops the adapter
# instead of mislabelling blades.
def _check_order(alg, mv, names):
    got = tuple(alg.bin2canon[k] for k in mv.keys())
    if got != names:
        raise RuntimeError("kingdon key order changed: %s, expected %s" % (got, names))


_check_order(VGA, VGA.evenmv([0.0] * 4), ("e", "e12", "e13", "e23"))
_check_order(VGA, VGA.bivector([0.0] * 3), ("e12", "e13", "e23"))
_check_order(VGA, VGA.vector([0.0] * 3), ("e1", "e2", "e3"))
_check_order(PGA, PGA.vector([0.0] * 4), ("e0", "e1", "e2", "e3"))
_check_order(PGA, PGA.evenmv([0.0] * 8), ("e", "e01", "e02", "e03", "e12", "e13", "e23", "e0123"))


def rotor(q):
    """Phi(q) = w - x e23 - y e31 - z e12 (Q2R-1); e31 = -e13 in kingdon's basis."""
    x, y, z, w = q
    return VGA.evenmv([w, -z, y, -x])


def quat(R):
    """Phi^-1: [x, y, z, w] = [-R_e23, -R_e31, -R_e12, <R>_0], read through kingdon's blade names."""
    return [-R.e23, -R.e31, -R.e12, R.e]


def motor(d):
    """MOTOR-1: M = rw - rx e23 - ry e31 - rz e12 - dx e01 - dy e02 - dz e03 - dw e0123."""
    rx, ry, rz, rw, dx, dy, dz, dw = d
    return PGA.evenmv([rw, -dx, -dy, -dz, -rz, ry, -rx, -dw])


def dual_quat(M):
    """MOTOR-1 inverted."""
    return [-M.e23, -M.e31, -M.e12, M.e, -M.e01, -M.e02, -M.e03, -M.e0123]


# --- Core ----------------------------------------------------------------------------------------

def normalize(q):
    return quat(rotor(q).normalized())


def compose(a, b):
    return quat(rotor(a) * rotor(b))


def inverse(q):
    return quat(rotor(q).inv())


def apply_vector(q, v):
    r = rotor(q) >> VGA.vector(v)
    return [r.e1, r.e2, r.e3]


def apply_bivector(q, b):
    b23, b31, b12 = b
    r = rotor(q) >> VGA.bivector([b12, -b31, b23])
    return [r.e23, r.e31, r.e12]


def apply_trivector(q, s):
    return (rotor(q) >> VGA.trivector([s])).e123


def to_matrix(q):
    columns = rotor(q) >> VGA.frame  # kingdon broadcasts an operator over a list
    return [c for col in columns for c in (col.e1, col.e2, col.e3)]  # column-major


def from_axis_angle(angle, axis):
    return quat((VGA.vector(axis).normalized().dual() * (angle / 2)).exp())


# --- Interp --------------------------------------------------------------------------------------

def exp(v):
    """The quaternion-view log v = [x, y, z] is the bivector Phi(v) = -x e23 - y e31 - z e12."""
    x, y, z = v
    return quat(VGA.bivector([-z, y, -x]).exp())


# --- Extended ------------------------------------------------------------------------------------

def sqrt(q):
    return quat(rotor(q).sqrt())


# --- Rigid (PGA motors through MOTOR-1) ----------------------------------------------------------

def dq_compose(a, b):
    return dual_quat(motor(a) * motor(b))


def dq_apply_point(d, p):
    x, y, z = p
    moved = (motor(d) >> PGA.vector([1.0, x, y, z]).dual()).undual()  # e0 + x e1 + y e2 + z e3
    weight = moved.e0
    return [moved.e1 / weight, moved.e2 / weight, moved.e3 / weight]


def dq_normalize(d):
    return dual_quat(motor(d).normalized())


OPS = {
    "normalize": normalize, "compose": compose, "inverse": inverse,
    "apply_vector": apply_vector, "apply_bivector": apply_bivector, "apply_trivector": apply_trivector,
    "to_matrix": to_matrix, "from_axis_angle": from_axis_angle,
    "exp": exp, "sqrt": sqrt,
    "dq_compose": dq_compose, "dq_apply_point": dq_apply_point, "dq_normalize": dq_normalize,
}

IMPLEMENTATION = {
    "name": "kingdon",
    "version": KINGDON_VERSION,
    "scalar": "double",
    "description": (
        "kingdon %s (PyPI) on Python floats: rotors of Algebra(3,0,0) with Phi(q) = w - x e23 - y e31 - z e12 "
        "(e31 = -e13 in kingdon's basis), motors of Algebra(3,0,1) by MOTOR-1; geometric product, "
        "normalized(), inv(), the >> sandwich, exp() of simple bivectors, sqrt(). No status channel: a Python "
        "exception raised by kingdon is graded DOMAIN_ERROR (outputs NaN), all outputs NaN is DOMAIN_ERROR, "
        "anything else OK as computed (rotorcert_vectors)" % KINGDON_VERSION),
}

if __name__ == "__main__":
    sys.exit(run_adapter(__doc__.splitlines()[0], IMPLEMENTATION, OPS))
