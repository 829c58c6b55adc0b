// The glam calls behind the ABI operations, for one scalar type: included by lib.rs into `mod f32`
// (S = f32, Q = glam::Quat, V = glam::Vec3, M = glam::Mat3) and `mod f64` (DQuat, DVec3, DMat3).
// Each op is the glam call a glam user makes, on the input as given; the only arithmetic here is
// the documented conversion between glam's rotation vector (angle * axis, to_scaled_axis /
// from_scaled_axis) and the ABI's quaternion-view log (angle/2 * axis), an exact scaling by 2.
// Conventions: adapter.json.

use crate::abi::{run, Answer, Ops, Ops3, Ops4, Panics, MAX_WIDTH};
use std::ffi::c_int;

const LIB: &str = "glam";
type Buf = [S; MAX_WIDTH];

/// The ABI's [x, y, z, w] is glam's from_xyzw / to_array order (glam stores x, y, z, w).
fn quat(a: &Buf) -> Q {
    Q::from_xyzw(a[0], a[1], a[2], a[3])
}
fn vec3(a: &Buf) -> V {
    V::new(a[0], a[1], a[2])
}
fn put(o: &mut Buf, xs: &[S]) {
    o[..xs.len()].copy_from_slice(xs);
}

// glam has no status channel and, built without its `glam-assert` feature, no panics on these
// paths; a panic would be a defect (Panics::Defect).

unsafe extern "C" fn normalize(n: usize, q: *const S, out: *mut S, st: *mut u8) -> c_int {
    run(LIB, "normalize", n, [(q, 4)], [(out, 4)], st, Panics::Defect, |i, o| {
        put(&mut o[0], &quat(&i[0]).normalize().to_array());
        Answer::Value
    })
}

// Quat * Quat is mul_quat, the Hamilton product self * rhs ("If they each represent a rotation,
// the result will represent the combined rotation"): compose(a, b) = a * b.
unsafe extern "C" fn compose(n: usize, a: *const S, b: *const S, out: *mut S, st: *mut u8) -> c_int {
    run(LIB, "compose", n, [(a, 4), (b, 4)], [(out, 4)], st, Panics::Defect, |i, o| {
        put(&mut o[0], &(quat(&i[0]) * quat(&i[1])).to_array());
        Answer::Value
    })
}

// inverse() is documented as "the inverse of a normalized quaternion": the conjugate.
unsafe extern "C" fn inverse(n: usize, q: *const S, out: *mut S, st: *mut u8) -> c_int {
    run(LIB, "inverse", n, [(q, 4)], [(out, 4)], st, Panics::Defect, |i, o| {
        put(&mut o[0], &quat(&i[0]).inverse().to_array());
        Answer::Value
    })
}

unsafe extern "C" fn apply_vector(n: usize, q: *const S, v: *const S, out: *mut S, st: *mut u8) -> c_int {
    run(LIB, "apply_vector", n, [(q, 4), (v, 3)], [(out, 3)], st, Panics::Defect, |i, o| {
        put(&mut o[0], &quat(&i[0]).mul_vec3(vec3(&i[1])).to_array());
        Answer::Value
    })
}

// Mat3 is column-major (x_axis, y_axis, z_axis are the columns): to_cols_array is the ABI's
// m[c*3 + r] as it is.
unsafe extern "C" fn to_matrix(n: usize, q: *const S, out: *mut S, st: *mut u8) -> c_int {
    run(LIB, "to_matrix", n, [(q, 4)], [(out, 9)], st, Panics::Defect, |i, o| {
        put(&mut o[0], &M::from_quat(quat(&i[0])).to_cols_array());
        Answer::Value
    })
}

unsafe extern "C" fn from_matrix(n: usize, m: *const S, out: *mut S, st: *mut u8) -> c_int {
    run(LIB, "from_matrix", n, [(m, 9)], [(out, 4)], st, Panics::Defect, |i, o| {
        put(&mut o[0], &Q::from_mat3(&M::from_cols_slice(&i[0][..9])).to_array());
        Answer::Value
    })
}

unsafe extern "C" fn to_axis_angle(n: usize, q: *const S, angle: *mut S, axis: *mut S, st: *mut u8) -> c_int {
    run(LIB, "to_axis_angle", n, [(q, 4)], [(angle, 1), (axis, 3)], st, Panics::Defect, |i, o| {
        let (u, theta) = quat(&i[0]).to_axis_angle();
        o[0][0] = theta;
        put(&mut o[1], &u.to_array());
        Answer::Value
    })
}

// ABI version 3. glam has no angle-only or axis-only query of a quaternion (Quat::angle_between is
// the angle between two rotations): to_axis_angle() is the call a glam user gets either from, so
// to_angle is its angle (`.1`) and to_axis its axis (`.0`), each from its own call.
unsafe extern "C" fn to_angle(n: usize, q: *const S, angle: *mut S, st: *mut u8) -> c_int {
    run(LIB, "to_angle", n, [(q, 4)], [(angle, 1)], st, Panics::Defect, |i, o| {
        o[0][0] = quat(&i[0]).to_axis_angle().1;
        Answer::Value
    })
}

unsafe extern "C" fn to_axis(n: usize, q: *const S, axis: *mut S, st: *mut u8) -> c_int {
    run(LIB, "to_axis", n, [(q, 4)], [(axis, 3)], st, Panics::Defect, |i, o| {
        put(&mut o[0], &quat(&i[0]).to_axis_angle().0.to_array());
        Answer::Value
    })
}

// The ABI passes the angle first, then the axis; glam takes (axis, angle).
unsafe extern "C" fn from_axis_angle(n: usize, angle: *const S, axis: *const S, out: *mut S, st: *mut u8) -> c_int {
    run(LIB, "from_axis_angle", n, [(angle, 1), (axis, 3)], [(out, 4)], st, Panics::Defect, |i, o| {
        put(&mut o[0], &Q::from_axis_angle(vec3(&i[1]), i[0][0]).to_array());
        Answer::Value
    })
}

// log q = (theta/2) u (LOG-1) = to_scaled_axis() / 2: glam's rotation vector is theta u.
unsafe extern "C" fn log(n: usize, q: *const S, out: *mut S, st: *mut u8) -> c_int {
    run(LIB, "log", n, [(q, 4)], [(out, 3)], st, Panics::Defect, |i, o| {
        put(&mut o[0], &(quat(&i[0]).to_scaled_axis() * 0.5).to_array());
        Answer::Value
    })
}

// exp v = the rotation by 2|v| about v/|v| (EXP-1) = from_scaled_axis(2 v).
unsafe extern "C" fn exp(n: usize, v: *const S, out: *mut S, st: *mut u8) -> c_int {
    run(LIB, "exp", n, [(v, 3)], [(out, 4)], st, Panics::Defect, |i, o| {
        put(&mut o[0], &Q::from_scaled_axis(vec3(&i[0]) * 2.0).to_array());
        Answer::Value
    })
}

unsafe extern "C" fn slerp(n: usize, a: *const S, b: *const S, t: *const S, out: *mut S, st: *mut u8) -> c_int {
    run(LIB, "slerp", n, [(a, 4), (b, 4), (t, 1)], [(out, 4)], st, Panics::Defect, |i, o| {
        put(&mut o[0], &quat(&i[0]).slerp(quat(&i[1]), i[2][0]).to_array());
        Answer::Value
    })
}

// Quat::lerp is glam's normalised lerp with the shorter-arc flip: "self * (1.0 - s) + end * s
// before normalizing", end negated when the dot is negative.
unsafe extern "C" fn nlerp(n: usize, a: *const S, b: *const S, t: *const S, out: *mut S, st: *mut u8) -> c_int {
    run(LIB, "nlerp", n, [(a, 4), (b, 4), (t, 1)], [(out, 4)], st, Panics::Defect, |i, o| {
        put(&mut o[0], &quat(&i[0]).lerp(quat(&i[1]), i[2][0]).to_array());
        Answer::Value
    })
}

pub static OPS: Ops<S> = Ops {
    normalize: Some(normalize),
    compose: Some(compose),
    inverse: Some(inverse),
    apply_vector: Some(apply_vector),
    to_matrix: Some(to_matrix),
    from_matrix: Some(from_matrix),
    to_axis_angle: Some(to_axis_angle),
    from_axis_angle: Some(from_axis_angle),
    log: Some(log),
    exp: Some(exp),
    slerp: Some(slerp),
    nlerp: Some(nlerp),
    ..Ops::NONE
};

/// The ABI version 3 operations glam has: the halves of to_axis_angle (no square root, no dual
/// quaternions).
pub static OPS3: Ops3<S> = Ops3 { to_angle: Some(to_angle), to_axis: Some(to_axis), ..Ops3::NONE };

// ABI version 4: rigid transforms as a glam user holds them, Affine3A / DAffine3 built with
// from_rotation_translation(rotation, translation) ("Creates an affine transform from the given
// `rotation` quaternion and `translation` vector", equivalent to from_translation(t) * from_quat(q):
// x -> R x + t; the rotation must be normalized, declared rigid_*:unit_quaternion); Affine * Affine
// composes (self * rhs applies rhs first); transform_point3 applies; inverse() inverts the 3x3 part
// and maps -t; to_scale_rotation_translation() reads the rotation (Quat::from_mat3 of the columns
// divided by their lengths) and translation back.
fn affine(q: &Buf, t: &Buf) -> A {
    A::from_rotation_translation(quat(q), vec3(t))
}
fn put_affine(oq: &mut Buf, ot: &mut Buf, m: &A) {
    let (_scale, r, t) = m.to_scale_rotation_translation();
    put(oq, &r.to_array());
    put(ot, &t.to_array());
}

unsafe extern "C" fn rigid_compose(
    n: usize,
    qa: *const S,
    ta: *const S,
    qb: *const S,
    tb: *const S,
    out_q: *mut S,
    out_t: *mut S,
    st: *mut u8,
) -> c_int {
    run(LIB, "rigid_compose", n, [(qa, 4), (ta, 3), (qb, 4), (tb, 3)], [(out_q, 4), (out_t, 3)], st, Panics::Defect, |i, o| {
        let m = affine(&i[0], &i[1]) * affine(&i[2], &i[3]);
        let (oq, ot) = o.split_at_mut(1);
        put_affine(&mut oq[0], &mut ot[0], &m);
        Answer::Value
    })
}

unsafe extern "C" fn rigid_apply(n: usize, q: *const S, t: *const S, p: *const S, out: *mut S, st: *mut u8) -> c_int {
    run(LIB, "rigid_apply", n, [(q, 4), (t, 3), (p, 3)], [(out, 3)], st, Panics::Defect, |i, o| {
        put(&mut o[0], &affine(&i[0], &i[1]).transform_point3(vec3(&i[2])).to_array());
        Answer::Value
    })
}

unsafe extern "C" fn rigid_inverse(n: usize, q: *const S, t: *const S, out_q: *mut S, out_t: *mut S, st: *mut u8) -> c_int {
    run(LIB, "rigid_inverse", n, [(q, 4), (t, 3)], [(out_q, 4), (out_t, 3)], st, Panics::Defect, |i, o| {
        let m = affine(&i[0], &i[1]).inverse();
        let (oq, ot) = o.split_at_mut(1);
        put_affine(&mut oq[0], &mut ot[0], &m);
        Answer::Value
    })
}

/// ABI version 4: glam has no dual quaternions and no screw log/exp (DQ-8, DQ-9).
pub static OPS4: Ops4<S> = Ops4 {
    rigid_compose: Some(rigid_compose),
    rigid_apply: Some(rigid_apply),
    rigid_inverse: Some(rigid_inverse),
    ..Ops4::NONE
};
