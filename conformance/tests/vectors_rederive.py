#!/usr/bin/env python3
"""Re-derives exported test vectors from the formulas of spec/SPEC.md, independently of the C++ reference.

    vectors_rederive.py DIR [--ops OP,OP,...] [--digits N] [--quiet]

DIR is a directory written by `rotorcert vectors export` (binary64 and binary32 files alike).
For every vector of the ops below the expected status and output are computed again, from the
clause text alone, with mpmath at N decimal digits (default 80, at least 60), and compared with
what the export wrote. Exit 0 when every vector agrees, 1 on any disagreement (each one printed
with its vector id) or when an op of the set has no vector, 2 on a usage error, 77 (a skip for
ctest) when mpmath is not installed.

What "agrees" means. The status must be equal (RESULT-2; DOMAIN_ERROR by EDGE-6, EDGE-7,
EDGE-9, MAT-3, AXANG-2, AXIS-1, with every expected component NaN). For OK, every component x
(re-derived) of every output array is compared with both exported forms of the expected value
(conformance/VECTORS.md): `dec`, the 256-bit reference (NUM-2) rounded to 20 significant
digits, must lie within half a unit of its 20th digit of x; `hex`, the reference rounded to the
number format, within half an ulp of the format. Both bounds get an absolute slack of
2^-100 * s, s the largest |component| of the re-derived array: 20 digits are all that the
export keeps of the reference (about 2^-66 relative), and the slack only admits the reference's
own rounding residues (e.g. 1.2e-77 for an exact 0 beside components of order 1: NUM-2's
reference is checked to 1e-60, tolerance class `ref`). A formula that differs from the spec's by
one rounding of the format (eps/2, 2^-53 or 2^-24) is far outside these bounds.

Hemisphere and pivot decisions (EDGE-3, EDGE-8, QLB-1, DQ-5, DQ-6) and the sign of det M (MAT-3)
are taken exactly, in rational arithmetic on the inputs as given.
"""
import argparse
import json
import math
import os
import sys
from fractions import Fraction

try:
    import mpmath
    from mpmath import mp, mpf
except ImportError:
    print("python3-mpmath is not installed (scripts/bootstrap installs it)")
    sys.exit(77)

# ---- quaternions (w, x, y, z) ------------------------------------------------------------------
# LAYOUT-1 stores [x, y, z, w]; these helpers work on (w, x, y, z) tuples of mpf.


def quat(v, i=0):
    """The quaternion at element i of a flat [x, y, z, w, ...] array."""
    x, y, z, w = v[4 * i:4 * i + 4]
    return (w, x, y, z)


def flat_q(q):
    return [q[1], q[2], q[3], q[0]]


def qmul(a, b):
    """QUAT-1: the Hamilton product, ij = k."""
    aw, ax, ay, az = a
    bw, bx, by, bz = b
    return (aw * bw - ax * bx - ay * by - az * bz,
            aw * bx + ax * bw + ay * bz - az * by,
            aw * by - ax * bz + ay * bw + az * bx,
            aw * bz + ax * by - ay * bx + az * bw)


def qconj(q):
    return (q[0], -q[1], -q[2], -q[3])


def qadd(a, b):
    return tuple(p + r for p, r in zip(a, b))


def qsub(a, b):
    return tuple(p - r for p, r in zip(a, b))


def qscale(k, q):
    return tuple(k * c for c in q)


def qdot(a, b):
    return sum(p * r for p, r in zip(a, b))


def qnorm(q):
    return mp.sqrt(qdot(q, q))


def qunit(q):
    """NORM-1: q/|q| (mpmath's exponent range cannot overflow)."""
    n = qnorm(q)
    return tuple(c / n for c in q)


def pure(v):
    return (mpf(0), v[0], v[1], v[2])


def vec(q):
    return [q[1], q[2], q[3]]


def vnorm(v):
    return mp.sqrt(sum(c * c for c in v))


def rotate(q, v):
    """QUAT-2 / APPLY-1: the vector part of q v q* / |q|^2."""
    u = qunit(q)
    return vec(qmul(qmul(u, pure(v)), qconj(u)))


def is_zero(values):
    return all(c == 0 for c in values)


def finite(values):
    return all(mpmath.isfinite(c) for c in values)


def exact_sign_dot(a_flat, b_flat):
    """The sign of a.b computed exactly (EDGE-3: flip iff < 0 strictly; -0 counts as +0, EDGE-8)."""
    s = sum(Fraction(p) * Fraction(r) for p, r in zip(a_flat, b_flat))
    return (s > 0) - (s < 0)


class Domain(Exception):
    """The input is outside the op's domain: DOMAIN_ERROR with NaN outputs (RESULT-2)."""


def need(condition):
    if not condition:
        raise Domain()


# ---- the operations, from the clause text ---------------------------------------------------------
# Each takes the inputs (name -> list of exact values: `f` as Python floats, `m` as mpf) and the
# influence count k, and returns {output name: list of mpf}; raises Domain for DOMAIN_ERROR.


def rotation_input(f, m, name):
    """A quaternion input: finite (EDGE-7) and nonzero (EDGE-6)."""
    need(finite(m[name]) and not is_zero(m[name]))
    return quat(m[name])


def op_normalize(f, m, k):  # NORM-1
    return {"out_q": flat_q(qunit(rotation_input(f, m, "q")))}


def op_compose(f, m, k):  # COMPOSE-1: a b, no normalisation
    a, b = rotation_input(f, m, "a"), rotation_input(f, m, "b")
    return {"out_q": flat_q(qmul(a, b))}


def op_inverse(f, m, k):  # INV-1: q* / |q|^2
    q = rotation_input(f, m, "q")
    n2 = qdot(q, q)
    return {"out_q": flat_q(tuple(c / n2 for c in qconj(q)))}


def op_apply_vector(f, m, k):  # APPLY-1 = QUAT-2
    q = rotation_input(f, m, "q")
    need(finite(m["v"]))
    return {"out_v": rotate(q, m["v"])}


def op_apply_bivector(f, m, k):  # APPLY-2: (b23, b31, b12) rotate like (x, y, z)
    q = rotation_input(f, m, "q")
    need(finite(m["b"]))
    return {"out_b": rotate(q, m["b"])}


def op_apply_trivector(f, m, k):  # APPLY-3: a I is invariant
    rotation_input(f, m, "q")
    need(finite(m["s"]))
    return {"out_s": [m["s"][0]]}


def matrix_of(q):
    """MAT-1: rows of the rotation matrix of the unit q; returned column-major m[c*3 + r]."""
    w, x, y, z = qunit(q)
    rows = [[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
            [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
            [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]]
    return [rows[r][c] for c in range(3) for r in range(3)]


def op_to_matrix(f, m, k):  # MAT-1
    return {"out_m": matrix_of(rotation_input(f, m, "q"))}


def op_from_matrix(f, m, k):
    """MAT-2, MAT-3: the quaternion of the rotation nearest to M (Frobenius), the maximiser of
    trace(R(q)^T M) over unit q, with the sign rule w > 0, or w = 0 and the first nonzero of
    (x, y, z) positive. trace(R(q)^T M) is the quadratic form q^T K q with R(q) written
    homogeneously (1 = w^2 + x^2 + y^2 + z^2 in MAT-1's rows); K is read off by polarisation."""
    need(finite(m["m"]))
    mf = [[Fraction(f["m"][c * 3 + r]) for c in range(3)] for r in range(3)]
    det = (mf[0][0] * (mf[1][1] * mf[2][2] - mf[1][2] * mf[2][1]) - mf[0][1] * (mf[1][0] * mf[2][2] - mf[1][2] * mf[2][0])
           + mf[0][2] * (mf[1][0] * mf[2][1] - mf[1][1] * mf[2][0]))
    need(det > 0)  # det M <= 0 (the zero matrix included): DOMAIN_ERROR (MAT-3, EDGE-6)
    M = [[m["m"][c * 3 + r] for c in range(3)] for r in range(3)]
    # K's eigen gap is about twice M's two smaller singular values relative to the largest, so a
    # spread beyond the working precision leaves the eigenvector undetermined. M/|M| + C/|C|
    # with C = cof(M) = det(M) M^-T has M's singular vectors, hence the same polar factor, and
    # lifts the smallest singular value to about 1/sqrt(3) of the largest; twice lifts two.
    for _ in range(2):
        C = [[M[(r + 1) % 3][(c + 1) % 3] * M[(r + 2) % 3][(c + 2) % 3]
              - M[(r + 1) % 3][(c + 2) % 3] * M[(r + 2) % 3][(c + 1) % 3] for c in range(3)] for r in range(3)]
        nm = mpmath.sqrt(sum(x * x for row in M for x in row))
        nc = mpmath.sqrt(sum(x * x for row in C for x in row))
        M = [[M[r][c] / nm + C[r][c] / nc for c in range(3)] for r in range(3)]

    def form(q):  # trace(R(q)^T M), R homogeneous of degree 2 in q = (w, x, y, z)
        w, x, y, z = q
        R = [[w * w + x * x - y * y - z * z, 2 * (x * y - w * z), 2 * (x * z + w * y)],
             [2 * (x * y + w * z), w * w - x * x + y * y - z * z, 2 * (y * z - w * x)],
             [2 * (x * z - w * y), 2 * (y * z + w * x), w * w - x * x - y * y + z * z]]
        return sum(R[r][c] * M[r][c] for r in range(3) for c in range(3))

    e = [tuple(mpf(1) if j == i else mpf(0) for j in range(4)) for i in range(4)]
    K = mpmath.matrix(4, 4)
    for i in range(4):
        K[i, i] = form(e[i])
        for j in range(i + 1, 4):
            K[i, j] = K[j, i] = (form(qadd(e[i], e[j])) - form(e[i]) - form(e[j])) / 2
    values, vectors = mpmath.eigsy(K)
    best = max(range(4), key=lambda j: values[j])
    q = qunit(tuple(vectors[i, best] for i in range(4)))
    # Components that are zero in exact arithmetic come out of the eigensolver as O(10^-digits).
    zero = mpf(2) ** -200
    q = tuple(mpf(0) if abs(c) < zero else c for c in q)
    first = next((c for c in (q[0], q[1], q[2], q[3]) if c != 0), mpf(1))
    if first < 0:
        q = qscale(-1, q)
    return {"out_q": flat_q(q)}


def op_to_axis_angle(f, m, k):  # AXANG-1: theta = 2 atan2(|v|, w), u = v/|v| or (0, 0, 1)
    q = rotation_input(f, m, "q")
    s = vnorm(vec(q))
    theta = 2 * mpmath.atan2(s, q[0])  # atan2(0, w < 0) = pi: q = -1 gives 2 pi
    axis = [mpf(0), mpf(0), mpf(1)] if s == 0 else [c / s for c in vec(q)]
    return {"out_angle": [theta], "out_axis": axis}


def op_to_angle(f, m, k):  # AXANG-3: AXANG-1's theta alone
    return {"out_angle": op_to_axis_angle(f, m, k)["out_angle"]}


def op_to_axis(f, m, k):  # AXANG-4: AXANG-1's u alone (v/|v|, (0, 0, 1) for v = 0)
    return {"out_axis": op_to_axis_angle(f, m, k)["out_axis"]}


def op_sqrt(f, m, k):
    """SQRT-1: s = (1 + q^)/|1 + q^| with q^ = q/|q| (s^2 = q^, s.w > 0); q^ = -1: (0, 0, 1, 0)."""
    q = rotation_input(f, m, "q")
    if is_zero(vec(q)) and q[0] < 0:
        return {"out_q": [mpf(0), mpf(0), mpf(1), mpf(0)]}
    u = qunit(q)
    v2 = sum(c * c for c in vec(u))
    a = 1 + u[0] if u[0] >= 0 else v2 / (1 - u[0])  # 1 + w without cancellation
    return {"out_q": flat_q(qunit((a, u[1], u[2], u[3])))}


def op_from_axis_angle(f, m, k):  # AXANG-2
    need(finite(m["angle"]) and finite(m["axis"]) and not is_zero(m["axis"]))
    theta, u = m["angle"][0], m["axis"]
    n = vnorm(u)
    c, s = mpmath.cos(theta / 2), mpmath.sin(theta / 2)
    return {"out_q": flat_q((c, s * u[0] / n, s * u[1] / n, s * u[2] / n))}


def log_of(q):
    """LOG-1, LOG-2: atan2(|v|, w) v/|v| of q (scale-free); v = 0: 0 for w > 0, (0, 0, pi) for w < 0."""
    s = vnorm(vec(q))
    if s == 0:
        return [mpf(0), mpf(0), mp.pi if q[0] < 0 else mpf(0)]
    a = mpmath.atan2(s, q[0])
    return [a * c / s for c in vec(q)]


def exp_of(v):
    """EXP-1: (cos|v|, sin|v| v/|v|); exp(0) = 1."""
    n = vnorm(v)
    if n == 0:
        return (mpf(1), mpf(0), mpf(0), mpf(0))
    s = mpmath.sin(n)
    return (mpmath.cos(n), s * v[0] / n, s * v[1] / n, s * v[2] / n)


def op_log(f, m, k):
    return {"out_v": log_of(rotation_input(f, m, "q"))}


def op_exp(f, m, k):
    need(finite(m["v"]))
    return {"out_q": flat_q(exp_of(m["v"]))}


def op_log_exp_round_trip(f, m, k):  # EXP-2: exp(log q) through both ops
    return {"out_q": flat_q(exp_of(log_of(rotation_input(f, m, "q"))))}


def interp_inputs(f, m):
    """SLERP-1's preamble (also NLERP-1): a, b normalised, b' = -b iff a.b < 0 strictly."""
    a, b = rotation_input(f, m, "a"), rotation_input(f, m, "b")
    need(finite(m["t"]))
    a, b = qunit(a), qunit(b)
    if exact_sign_dot(f["a"], f["b"]) < 0:
        b = qscale(-1, b)
    return a, b, m["t"][0]


def op_slerp(f, m, k):
    """SLERP-1: (sin((1 - t) W) a + sin(t W) b') / sin W, W in [0, pi/2] the angle of a and b' on
    S^3 (2 atan2(|a - b'|, |a + b'|), the chord form of METRIC-1); W = 0 gives a."""
    a, b, t = interp_inputs(f, m)
    omega = 2 * mpmath.atan2(qnorm(qsub(a, b)), qnorm(qadd(a, b)))
    if omega == 0:
        return {"out_q": flat_q(a)}
    s = mpmath.sin(omega)
    return {"out_q": flat_q(qscale(1 / s, qadd(qscale(mpmath.sin((1 - t) * omega), a), qscale(mpmath.sin(t * omega), b))))}


def op_nlerp(f, m, k):  # NLERP-1: normalize((1 - t) a + t b')
    a, b, t = interp_inputs(f, m)
    return {"out_q": flat_q(qunit(qadd(qscale(1 - t, a), qscale(t, b))))}


def weights_of(f, m, k):
    """Common blend rules / EDGE-9: k >= 1 weights, finite, >= 0 (-0 counts as 0), sum > 0.
    Returns the weights and the pivot p, the first index with w_i > 0."""
    w = m["w"]
    need(k >= 1 and len(w) == k and finite(w) and all(x >= 0 for x in w) and sum(w) > 0)
    return w, next(i for i in range(k) if w[i] > 0)


def influences(f, m, name, k, stride):
    """The k influences of a per-influence array as flat lists (exact floats and mpf)."""
    return ([f[name][stride * i:stride * (i + 1)] for i in range(k)], [m[name][stride * i:stride * (i + 1)] for i in range(k)])


def op_blend_qlb(f, m, k):
    """QLB-1: normalize(sum w_i s_i q_i), q_i normalised (EDGE-5), s_i = -1 iff q_i . q_p < 0."""
    qf, qm = influences(f, m, "q", k, 4)
    for q in qm:  # a zero or non-finite quaternion anywhere is DOMAIN_ERROR, even with weight 0
        need(finite(q) and not is_zero(q))
    w, p = weights_of(f, m, k)
    total = (mpf(0),) * 4
    for i in range(k):
        s = -1 if exact_sign_dot(qf[i], qf[p]) < 0 else 1
        total = qadd(total, qscale(s * w[i], qunit(quat(qm[i]))))
    return {"out_q": flat_q(qunit(total))}


def op_blend_log(f, m, k):
    """LOGBLEND-1: q_p exp(sum (w_i/W) log(align(q_p^-1 q_i))), align(r) = -r iff r_w < 0."""
    qf, qm = influences(f, m, "q", k, 4)
    for q in qm:
        need(finite(q) and not is_zero(q))
    w, p = weights_of(f, m, k)
    W = sum(w)
    qp = qunit(quat(qm[p]))
    acc = [mpf(0)] * 3
    for i in range(k):
        r = qmul(qconj(qp), qunit(quat(qm[i])))  # r_w = q_p . q_i: its sign is decided exactly
        if exact_sign_dot(qf[p], qf[i]) < 0:
            r = qscale(-1, r)
        acc = [a + (w[i] / W) * c for a, c in zip(acc, log_of(r))]
    return {"out_q": flat_q(qmul(qp, exp_of(acc)))}


# ---- dual quaternions (w, x, y, z) pairs -------------------------------------------------------------


def dual(v, i=0):
    """The dual quaternion at element i of a flat [r x, y, z, w, d x, y, z, w, ...] array."""
    return (quat(v[8 * i:8 * i + 4]), quat(v[8 * i + 4:8 * i + 8]))


def flat_d(d):
    return flat_q(d[0]) + flat_q(d[1])


def dual_input(values):
    """A dual quaternion input: finite (EDGE-7) with a nonzero real part (EDGE-6)."""
    need(finite(values) and not is_zero(values[:4]))
    return dual(values)


def dmul(a, b):
    """DQ-2: (a_r + eps a_d)(b_r + eps b_d) = a_r b_r + eps (a_r b_d + a_d b_r)."""
    return (qmul(a[0], b[0]), qadd(qmul(a[0], b[1]), qmul(a[1], b[0])))


def dnormalize(d):
    """DQ-4: r' = r/|r|, d' = d/|r| - ((r . d)/|r|^3) r."""
    r, e = d
    n = qnorm(r)
    c = qdot(r, e) / n ** 3
    return (qscale(1 / n, r), qsub(qscale(1 / n, e), qscale(c, r)))


def translation(u):
    """DQ-1: t = 2 q_d q_r* of a unit dual quaternion."""
    return vec(qscale(2, qmul(u[1], qconj(u[0]))))


def apply_point(d, p):
    """DQ-3: p' = R p + t with R the rotation of q_r and t = 2 q_d q_r* of DQ-4(sigma)."""
    u = dnormalize(d)
    rp = rotate(u[0], p)
    return [a + b for a, b in zip(rp, translation(u))]


def from_rotation_translation(q, t):
    """DQ-1: q_r = q/|q|, q_d = 1/2 t q_r."""
    r = qunit(q)
    return (r, qscale(mpf(1) / 2, qmul(pure(t), r)))


def dlb(df, dm, w, p):
    """DQ-6 as amended: every influence DQ-4-normalised first (EDGE-5), s_i = -1 iff
    real_i . real_p < 0 strictly, DLB = DQ-4(sum w_i s_i DQ-4(sigma_i))."""
    total = ((mpf(0),) * 4, (mpf(0),) * 4)
    for i in range(len(dm)):
        s = -1 if exact_sign_dot(df[i][:4], df[p][:4]) < 0 else 1
        u = dnormalize(dual(dm[i]))
        total = (qadd(total[0], qscale(s * w[i], u[0])), qadd(total[1], qscale(s * w[i], u[1])))
    return dnormalize(total)


def op_dq_from_rotation_translation(f, m, k):  # DQ-1
    q = rotation_input(f, m, "q")
    need(finite(m["t"]))
    return {"out_d": flat_d(from_rotation_translation(q, m["t"]))}


def op_dq_to_rotation_translation(f, m, k):  # DQ-7: q = r/|r|, t = 2 d' r'* of DQ-4(sigma)
    u = dnormalize(dual_input(m["d"]))
    return {"out_q": flat_q(u[0]), "out_t": translation(u)}


def op_dq_log(f, m, k):
    """DQ-8: (r, d) = DQ-4(sigma), r = (cos b, sin b n), b = atan2(|r_v|, r_w) in [0, pi];
    xi_r = b n, xi_d = a n + (b / sin b) d_perp, a = (d_v . n) cos b - d_w sin b. r = 1: (0, d_v);
    r = -1: (pi t/|t|, t/2), t = the translation (DQ-1), (0, 0, pi, 0, 0, 0) for t = 0."""
    r, d = dnormalize(dual_input(m["d"]))
    rv, dv = vec(r), vec(d)
    s = vnorm(rv)
    if s == 0 and r[0] > 0:
        return {"out_xi": [mpf(0)] * 3 + dv}
    if s == 0:
        t = translation((r, d))
        n = vnorm(t)
        if n == 0:
            return {"out_xi": [mpf(0), mpf(0), mp.pi] + [mpf(0)] * 3}
        return {"out_xi": [mp.pi * c / n for c in t] + [c / 2 for c in t]}
    b = mpmath.atan2(s, r[0])
    n = [c / s for c in rv]
    along = sum(x * y for x, y in zip(dv, n))
    a = along * mpmath.cos(b) - d[0] * mpmath.sin(b)
    perp = [x - along * y for x, y in zip(dv, n)]
    return {"out_xi": [b * c for c in n] + [a * y + b / mpmath.sin(b) * x for x, y in zip(perp, n)]}


def op_dq_exp(f, m, k):
    """DQ-9: (cos b, sin b n) + eps (-a sin b, a cos b n + (sin b / b) xi_perp); b = 0: (1, (0, xi_d))."""
    xi = m["xi"]
    need(finite(xi))
    xr, xd = xi[:3], xi[3:]
    b = vnorm(xr)
    if b == 0:
        return {"out_d": flat_d(((mpf(1), mpf(0), mpf(0), mpf(0)), pure(xd)))}
    n = [c / b for c in xr]
    a = sum(x * y for x, y in zip(xd, n))
    c, sn = mpmath.cos(b), mpmath.sin(b)
    perp = [x - a * y for x, y in zip(xd, n)]
    dv = [a * c * y + sn / b * x for x, y in zip(perp, n)]
    return {"out_d": flat_d(((c, sn * n[0], sn * n[1], sn * n[2]), (-a * sn, dv[0], dv[1], dv[2])))}


def op_rigid_compose(f, m, k):
    """RIGID-1: (q^_a q^_b, R_a t_b + t_a)."""
    qa, qb = rotation_input(f, m, "qa"), rotation_input(f, m, "qb")
    need(finite(m["ta"]) and finite(m["tb"]))
    moved = rotate(qa, m["tb"])
    return {"out_q": flat_q(qmul(qunit(qa), qunit(qb))), "out_t": [x + y for x, y in zip(moved, m["ta"])]}


def op_rigid_apply(f, m, k):
    """RIGID-2: R p + t."""
    q = rotation_input(f, m, "q")
    need(finite(m["t"]) and finite(m["p"]))
    return {"out_p": [x + y for x, y in zip(rotate(q, m["p"]), m["t"])]}


def op_rigid_inverse(f, m, k):
    """RIGID-3: (q^*, -R^-1 t)."""
    q = rotation_input(f, m, "q")
    need(finite(m["t"]))
    inv = qconj(qunit(q))
    return {"out_q": flat_q(inv), "out_t": [-x for x in rotate(inv, m["t"])]}


def op_dq_compose(f, m, k):  # DQ-2: the product of the inputs as given, no normalisation
    return {"out_d": flat_d(dmul(dual_input(m["a"]), dual_input(m["b"])))}


def op_dq_apply_point(f, m, k):  # DQ-3
    d = dual_input(m["d"])
    need(finite(m["p"]))
    return {"out_p": apply_point(d, m["p"])}


def op_dq_normalize(f, m, k):  # DQ-4
    return {"out_d": flat_d(dnormalize(dual_input(m["d"])))}


def screw_power(u, t):
    """u^t = exp(t log u) for a unit dual quaternion u with real w >= 0, by its screw parameters
    (DQ-5): u = cos(th/2) + sin(th/2) n^ with dual angle th = theta + eps d and dual axis
    n^ = n + eps m; f(a + eps b) = f(a) + eps b f'(a). No rotation (v = 0): (1, t q_d)."""
    (w, vx, vy, vz), (dw, dx, dy, dz) = u
    v, dv = [vx, vy, vz], [dx, dy, dz]
    s = vnorm(v)
    if s == 0:
        return ((mpf(1), mpf(0), mpf(0), mpf(0)), qscale(t, u[1]))
    half = mpmath.atan2(s, w)  # theta / 2
    n = [c / s for c in v]
    d = -2 * dw / s  # dual part of cos(th/2) is -(d/2) sin(theta/2)
    mm = [(dv[i] - (d / 2) * w * n[i]) / s for i in range(3)]  # dual part of sin(th/2) n^
    c, sn, h = mpmath.cos(t * half), mpmath.sin(t * half), t * d / 2
    return ((c, sn * n[0], sn * n[1], sn * n[2]),
            (-h * sn, sn * mm[0] + h * c * n[0], sn * mm[1] + h * c * n[1], sn * mm[2] + h * c * n[2]))


def op_dq_sclerp(f, m, k):
    """DQ-5: a (a* b')^t of the DQ-4-normalised inputs, b' = -b (both parts) iff a_r . b_r < 0."""
    a, b = dual_input(m["a"]), dual_input(m["b"])
    need(finite(m["t"]))
    a, b = dnormalize(a), dnormalize(b)
    if exact_sign_dot(f["a"][:4], f["b"][:4]) < 0:
        b = (qscale(-1, b[0]), qscale(-1, b[1]))
    rel = dmul((qconj(a[0]), qconj(a[1])), b)
    return {"out_d": flat_d(dmul(a, screw_power(rel, m["t"][0])))}


def op_dq_blend(f, m, k):  # DQ-6
    df, dm = influences(f, m, "d", k, 8)
    for d in dm:
        need(finite(d) and not is_zero(d[:4]))
    w, p = weights_of(f, m, k)
    return {"out_d": flat_d(dlb(df, dm, w, p))}


def op_rotate_about_axis(f, m, k):
    """AXIS-1: x -> R (x - c) + c, R the rotation by the angle about u/|u| (zero u: DOMAIN_ERROR)."""
    need(finite(m["c"]) and finite(m["u"]) and finite(m["angle"]) and finite(m["p"]) and not is_zero(m["u"]))
    c, u, theta, p = m["c"], m["u"], m["angle"][0], m["p"]
    n = vnorm(u)
    h = mpmath.sin(theta / 2)
    q = (mpmath.cos(theta / 2), h * u[0] / n, h * u[1] / n, h * u[2] / n)
    moved = rotate(q, [p[i] - c[i] for i in range(3)])
    return {"out_p": [moved[i] + c[i] for i in range(3)]}


def skin_inputs(f, m, k):
    """Common skinning rules: k influences (q_i, t_i, w_i), EDGE-6/7/9 validation, vertex v."""
    qf, qm = influences(f, m, "q", k, 4)
    _, tm = influences(f, m, "t", k, 3)
    for q, t in zip(qm, tm):
        need(finite(q) and not is_zero(q) and finite(t))
    need(finite(m["v"]))
    w, p = weights_of(f, m, k)
    return qf, qm, tm, w, p, m["v"]


def op_skin_linear(f, m, k):  # SKIN-1: sum (w_i/W) (R_i v + t_i)
    qf, qm, tm, w, p, v = skin_inputs(f, m, k)
    W = sum(w)
    out = [mpf(0)] * 3
    for i in range(k):
        rv = rotate(quat(qm[i]), v)
        out = [out[j] + (w[i] / W) * (rv[j] + tm[i][j]) for j in range(3)]
    return {"out_v": out}


def op_skin_dual_quaternion(f, m, k):  # SKIN-2: DQ-3(DLB(DQ-1(q_i, t_i), w_i), v)
    qf, qm, tm, w, p, v = skin_inputs(f, m, k)
    sig = [flat_d(from_rotation_translation(quat(qm[i]), tm[i])) for i in range(k)]
    # The pivot's hemisphere test is on real_i = q_i/|q_i|: the sign of q_i . q_p, exactly.
    sigf = [list(qf[i]) + [0.0] * 4 for i in range(k)]
    return {"out_v": apply_point(dlb(sigf, sig, w, p), v)}


OPS = {
    "normalize": op_normalize,
    "compose": op_compose,
    "inverse": op_inverse,
    "apply_vector": op_apply_vector,
    "apply_bivector": op_apply_bivector,
    "apply_trivector": op_apply_trivector,
    "to_matrix": op_to_matrix,
    "from_matrix": op_from_matrix,
    "to_axis_angle": op_to_axis_angle,
    "from_axis_angle": op_from_axis_angle,
    "log": op_log,
    "exp": op_exp,
    "log_exp_round_trip": op_log_exp_round_trip,
    "slerp": op_slerp,
    "nlerp": op_nlerp,
    "blend_qlb": op_blend_qlb,
    "blend_log": op_blend_log,
    "dq_from_rotation_translation": op_dq_from_rotation_translation,
    "dq_compose": op_dq_compose,
    "dq_apply_point": op_dq_apply_point,
    "dq_normalize": op_dq_normalize,
    "dq_sclerp": op_dq_sclerp,
    "dq_blend": op_dq_blend,
    "rotate_about_axis": op_rotate_about_axis,
    "skin_linear": op_skin_linear,
    "skin_dual_quaternion": op_skin_dual_quaternion,
    # ABI version 3
    "to_angle": op_to_angle,
    "to_axis": op_to_axis,
    "sqrt": op_sqrt,
    "dq_to_rotation_translation": op_dq_to_rotation_translation,
    # ABI version 4
    "dq_log": op_dq_log,
    "dq_exp": op_dq_exp,
    "rigid_compose": op_rigid_compose,
    "rigid_apply": op_rigid_apply,
    "rigid_inverse": op_rigid_inverse,
}

# ---- comparison with the export ----------------------------------------------------------------------

FORMATS = {"binary64": (53, -1074, 1024), "binary32": (24, -149, 128)}  # precision, min subnormal exponent, emax + 1
DEC_DIGITS = 20  # conformance/VECTORS.md: expected "dec" = the 256-bit reference to 20 significant digits
SLACK = mpf(2) ** -100


def decode(text):
    """A value of the export: C99 hexfloat of the format, or nan / -nan / inf / -inf (exact)."""
    if text in ("nan", "-nan"):
        return float("nan")
    if text in ("inf", "-inf"):
        return float(text)
    return float.fromhex(text)


def half_ulp(h, fmt):
    """Half an ulp of the format at the exported value h (finite)."""
    p, emin, _ = FORMATS[fmt]
    if h == 0:
        return mpf(2) ** (emin - 1)
    _, e = math.frexp(h)  # |h| in [2^(e-1), 2^e)
    return mpf(2) ** (max(e - p, emin) - 1)


def component_disagreement(x, hex_text, dec_text, slack, fmt):
    """None if the exported component agrees with the re-derived x, else a short reason."""
    p, _, emax = FORMATS[fmt]
    h = decode(hex_text)
    if math.isnan(h) or dec_text in ("nan", "-nan"):
        return "expected NaN"
    if math.isinf(h):
        overflow = (2 - mpf(2) ** -p) * mpf(2) ** (emax - 1)  # rounds to infinity beyond this
        if not (abs(x) >= overflow and (x > 0) == (h > 0)):
            return "expected %s, re-derived finite" % hex_text
    elif abs(mpf(h) - x) > half_ulp(h, fmt) + slack:
        return "hex off by %s ulp" % mpmath.nstr(abs(mpf(h) - x) / (2 * half_ulp(h, fmt)), 3)
    d = mpf(dec_text)
    if d == 0:
        unit = mpf(0)
    else:
        unit = mpf(10) ** (int(mpmath.floor(mpmath.log10(abs(d)))) - (DEC_DIGITS - 1))
    if abs(d - x) > unit / 2 * (1 + mpf(2) ** -20) + slack:
        return "dec off by %s (relative %s)" % (mpmath.nstr(abs(d - x), 3), mpmath.nstr(abs(d - x) / max(abs(x), mpf(2) ** -1100), 3))
    return None


def check_vector(op, fmt, test):
    """Returns None if the vector agrees with the re-derivation, else a one-line description."""
    k = test["k"]
    f = {name: [decode(h) for h in val["hex"]] for name, val in test["in"].items()}
    m = {name: [mpf(x) for x in vals] for name, vals in f.items()}
    try:
        outs, status = OPS[op](f, m, k), "OK"
    except Domain:
        outs, status = None, "DOMAIN_ERROR"
    want = test["expected"]["status"]
    if want != status:
        return "status: expected %s, re-derived %s" % (want, status)
    expected = test["expected"]["out"]
    if status == "DOMAIN_ERROR":
        bad = [n for n, v in expected.items() if any(h not in ("nan", "-nan") for h in v["hex"])]
        return "DOMAIN_ERROR with non-NaN outputs %s" % bad if bad else None
    problems = []
    for name, xs in outs.items():
        if name not in expected:
            return "output %s missing from the export" % name
        ex = expected[name]
        if len(ex["hex"]) != len(xs):
            return "output %s has %d components, re-derived %d" % (name, len(ex["hex"]), len(xs))
        slack = SLACK * max(abs(x) for x in xs)
        for i, x in enumerate(xs):
            why = component_disagreement(x, ex["hex"][i], ex["dec"][i], slack, fmt)
            if why:
                problems.append("%s[%d] expected %s (dec %s), re-derived %s: %s" %
                                (name, i, ex["hex"][i], ex["dec"][i], mpmath.nstr(x, 22), why))
    return "; ".join(problems) if problems else None


REQUIRED = ["normalize", "compose", "inverse", "apply_vector", "to_matrix", "log", "exp", "slerp", "nlerp", "blend_qlb",
            "dq_from_rotation_translation", "dq_compose", "dq_apply_point", "dq_normalize", "dq_blend",
            "to_angle", "to_axis", "sqrt", "dq_to_rotation_translation"]


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("dir", help="a directory written by `rotorcert vectors export`")
    ap.add_argument("--ops", help="comma-separated ops to re-derive (default: every op this script knows)")
    ap.add_argument("--digits", type=int, default=80, help="mpmath working precision in decimal digits (>= 60)")
    ap.add_argument("--quiet", action="store_true", help="print only the summary and the disagreements")
    args = ap.parse_args(argv)
    if args.digits < 60:
        ap.error("--digits must be at least 60")
    mp.dps = args.digits
    ops = args.ops.split(",") if args.ops else list(OPS)
    unknown = [o for o in ops if o not in OPS]
    if unknown:
        ap.error("no re-derivation for op(s) %s" % ", ".join(unknown))
    try:
        with open(os.path.join(args.dir, "index.json")) as fh:
            index = json.load(fh)
    except (OSError, ValueError) as e:
        print("vectors_rederive: cannot read %s/index.json: %s" % (args.dir, e))
        return 2

    print("vectors_rederive: %s (spec %s, seed %s, %s cases per family), mpmath at %d digits" %
          (args.dir, index.get("spec_version"), index.get("seed"), index.get("cases_per_family"), mp.dps))
    counts = {}  # op -> [vectors, agreed]
    skipped = {}
    disagreements = []
    for entry in index["files"]:
        op, fmt = entry["op"], entry["number_format"]
        if op not in ops:
            skipped[op] = skipped.get(op, 0) + entry["numberOfTests"]
            continue
        with open(os.path.join(args.dir, entry["file"])) as fh:
            doc = json.load(fh)
        c = counts.setdefault(op, [0, 0])
        for test in doc["tests"]:
            c[0] += 1
            why = check_vector(op, fmt, test)
            if why is None:
                c[1] += 1
            else:
                disagreements.append("DISAGREE %s (%s): %s" % (test["id"], test["comment"], why))
        if not args.quiet:
            print("  %-36s %4d vectors" % (entry["file"], len(doc["tests"])))

    print("per op (binary64 and binary32 together):")
    for op in ops:
        n, ok = counts.get(op, [0, 0])
        print("  %-30s %5d of %5d agree%s" % (op, ok, n, "" if n else "   (no vectors in the export)"))
    if skipped:
        print("not re-derived: %s" % ", ".join("%s (%d)" % kv for kv in sorted(skipped.items())))
    for line in disagreements:
        print(line)
    missing = [o for o in REQUIRED if o in ops and not counts.get(o, [0])[0]]
    if missing:
        print("FAIL: no vectors of %s: export every clause (no --clause) to test them" % ", ".join(missing))
    total = sum(c[0] for c in counts.values())
    agreed = sum(c[1] for c in counts.values())
    print("%s: %d of %d vectors agree with the spec's formulas, %d disagree" %
          ("PASS" if agreed == total and not missing else "FAIL", agreed, total, total - agreed))
    return 0 if agreed == total and not missing else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
