"""A small quaternion library in plain Python floats (binary64): the library a maintainer certifies
in this example. Quaternions are [x, y, z, w] lists, vectors [x, y, z] (the ABI's layouts, LAYOUT-1),
Hamilton product, compose(a, b) = a b applies b first, active rotation v' = q v q*.

Every function refuses what is not a rotation (a zero, NaN or infinite quaternion, a non-finite
vector or t) with ValueError: rotorcert grades that as DOMAIN_ERROR (RESULT-2, EDGE-6, EDGE-7).

ROTORCERT_EXAMPLE_DEFECT plants a defect, for the test that the certificate catches it:
  compose_reversed   compose returns b a (the JPL order): COMPOSE-1 must FAIL
  typo               compose calls a function that does not exist: the item of COMPOSE-1 must fail
                     naming the vector and its input
"""
import math
import os

__version__ = "1.0"

DEFECT = os.environ.get("ROTORCERT_EXAMPLE_DEFECT", "")


def _finite(xs):
    return all(math.isfinite(x) for x in xs)


def _check_rotation(q):
    if not _finite(q) or not any(q):
        raise ValueError("not a rotation: %r" % (q,))


def _scaled(q):
    """q * 2^-e with 2^e near max |q_i|, and e: |q|^2 then neither overflows nor underflows (NORM-1)."""
    e = math.frexp(max(abs(c) for c in q))[1]
    return [math.ldexp(c, -e) for c in q], e


def normalize(q):
    """q / |q| (NORM-1)."""
    _check_rotation(q)
    s, _ = _scaled(q)
    n = math.sqrt(sum(c * c for c in s))
    return [c / n for c in s]


def _hamilton(a, b):
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return [aw * bx + ax * bw + ay * bz - az * by,
            aw * by - ax * bz + ay * bw + az * bx,
            aw * bz + ax * by - ay * bx + az * bw,
            aw * bw - ax * bx - ay * by - az * bz]


def compose(a, b):
    """a b: b is applied first (COMPOSE-1); not normalised."""
    _check_rotation(a)
    _check_rotation(b)
    if DEFECT == "compose_reversed":
        return _hamilton(b, a)
    if DEFECT == "typo":
        return hamiltonian(a, b)  # noqa: F821 - the planted defect: no such function
    return _hamilton(a, b)


def inverse(q):
    """q* / |q|^2 (INV-1), scaled so that |q|^2 stays in range."""
    _check_rotation(q)
    s, e = _scaled(q)
    n2 = sum(c * c for c in s)
    return [math.ldexp(c / n2, -e) for c in (-s[0], -s[1], -s[2], s[3])]


def _cross(u, v):
    return [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]


def apply_vector(q, v):
    """q v q* of the normalised q (APPLY-1): v + 2w (u x v) + 2 u x (u x v)."""
    _check_rotation(q)
    if not _finite(v):
        raise ValueError("not a vector: %r" % (v,))
    x, y, z, w = normalize(q)
    u = [x, y, z]
    t = [2.0 * c for c in _cross(u, v)]
    ut = _cross(u, t)
    return [v[i] + w * t[i] + ut[i] for i in range(3)]


def slerp(a, b, t):
    """a (a^-1 b')^t with b' = -b when a.b < 0 (SLERP-1), for unit a and b:
    sin((1-t) theta)/sin(theta) a + sin(t theta)/sin(theta) b', theta the angle between a and b'
    as 4-vectors, taken as 2 atan2(|a - b'|, |a + b'|), which stays accurate for nearly equal and
    nearly opposite pairs where acos(a.b) does not."""
    _check_rotation(a)
    _check_rotation(b)
    if not math.isfinite(t):
        raise ValueError("t is not finite: %r" % (t,))
    if sum(p * q for p, q in zip(a, b)) < 0.0:  # the hemisphere rule: flip iff a.b < 0 strictly
        b = [-c for c in b]
    diff = math.sqrt(sum((p - q) ** 2 for p, q in zip(a, b)))
    total = math.sqrt(sum((p + q) ** 2 for p, q in zip(a, b)))
    theta = 2.0 * math.atan2(diff, total)
    if theta == 0.0:
        wa, wb = 1.0 - t, t
    else:
        s = math.sin(theta)
        wa, wb = math.sin((1.0 - t) * theta) / s, math.sin(t * theta) / s
    return [wa * p + wb * q for p, q in zip(a, b)]
