// The nalgebra calls behind the ABI operations, for one scalar type: included by lib.rs into
// `mod f32` (S = f32) and `mod f64` (S = f64). Each op is the nalgebra call a nalgebra user makes,
// on the input as given; nothing is computed here. Inputs that nalgebra types as unit
// (UnitQuaternion, UnitDualQuaternion, Unit<Vector3>) are made with nalgebra's own documented
// constructors from a raw value: UnitQuaternion::from_quaternion ("The input quaternion will be
// normalized"), Unit::new_normalize (the idiom of the from_axis_angle docs) and
// UnitDualQuaternion::new_normalize. Conventions: adapter.json.

use crate::abi::{run, Answer, Ops, Ops3, Ops4, Panics, MAX_WIDTH};
use nalgebra::{
    DualQuaternion, Isometry3, Matrix3, Point3, Quaternion, Rotation3, Translation3, Unit, UnitDualQuaternion,
    UnitQuaternion, Vector3,
};
use std::ffi::c_int;

const LIB: &str = "nalgebra";
type Buf = [S; MAX_WIDTH];

/// Quaternion::new(w, i, j, k) from the ABI's [x, y, z, w]; `coords` is [i, j, k, w] ("[ x, y, z, w ]
/// storage order", quaternion.rs), the ABI's order, on the way out.
fn quat(a: &Buf) -> Quaternion<S> {
    Quaternion::new(a[3], a[0], a[1], a[2])
}
fn unit(a: &Buf) -> UnitQuaternion<S> {
    UnitQuaternion::from_quaternion(quat(a))
}
fn vec3(a: &Buf) -> Vector3<S> {
    Vector3::new(a[0], a[1], a[2])
}
/// The ABI's [real xyzw, dual xyzw]; nalgebra's DualQuaternion "stored as [..real, ..dual]", both
/// in i, j, k, w order.
fn dual(a: &Buf) -> DualQuaternion<S> {
    DualQuaternion::from_real_and_dual(
        Quaternion::new(a[3], a[0], a[1], a[2]),
        Quaternion::new(a[7], a[4], a[5], a[6]),
    )
}
fn put(o: &mut Buf, xs: &[S]) {
    o[..xs.len()].copy_from_slice(xs);
}
fn put_quat(o: &mut Buf, q: &Quaternion<S>) {
    put(o, q.coords.as_slice());
}
fn put_dual(o: &mut Buf, d: &DualQuaternion<S>) {
    o[..4].copy_from_slice(d.real.coords.as_slice());
    o[4..8].copy_from_slice(d.dual.coords.as_slice());
}

unsafe extern "C" fn normalize(n: usize, q: *const S, out: *mut S, st: *mut u8) -> c_int {
    run(LIB, "normalize", n, [(q, 4)], [(out, 4)], st, Panics::Defect, |i, o| {
        put_quat(&mut o[0], &quat(&i[0]).normalize());
        Answer::Value
    })
}

// Quaternion * Quaternion: Hamilton's product (quaternion_ops.rs), compose(a, b) = a * b.
unsafe extern "C" fn compose(n: usize, a: *const S, b: *const S, out: *mut S, st: *mut u8) -> c_int {
    run(LIB, "compose", n, [(a, 4), (b, 4)], [(out, 4)], st, Panics::Defect, |i, o| {
        put_quat(&mut o[0], &(quat(&i[0]) * quat(&i[1])));
        Answer::Value
    })
}

// Quaternion::try_inverse: "Inverts this quaternion if it is not zero"; None is its refusal.
unsafe extern "C" fn inverse(n: usize, q: *const S, out: *mut S, st: *mut u8) -> c_int {
    run(LIB, "inverse", n, [(q, 4)], [(out, 4)], st, Panics::Defect, |i, o| match quat(&i[0]).try_inverse() {
        Some(r) => {
            put_quat(&mut o[0], &r);
            Answer::Value
        }
        None => Answer::Refused,
    })
}

unsafe extern "C" fn apply_vector(n: usize, q: *const S, v: *const S, out: *mut S, st: *mut u8) -> c_int {
    run(LIB, "apply_vector", n, [(q, 4), (v, 3)], [(out, 3)], st, Panics::Defect, |i, o| {
        put(&mut o[0], (unit(&i[0]) * vec3(&i[1])).as_slice());
        Answer::Value
    })
}

// nalgebra matrices are stored column-major: as_slice() is the ABI's m[c*3 + r] as it is.
unsafe extern "C" fn to_matrix(n: usize, q: *const S, out: *mut S, st: *mut u8) -> c_int {
    run(LIB, "to_matrix", n, [(q, 4)], [(out, 9)], st, Panics::Defect, |i, o| {
        put(&mut o[0], unit(&i[0]).to_rotation_matrix().matrix().as_slice());
        Answer::Value
    })
}

unsafe extern "C" fn from_matrix(n: usize, m: *const S, out: *mut S, st: *mut u8) -> c_int {
    run(LIB, "from_matrix", n, [(m, 9)], [(out, 4)], st, Panics::Defect, |i, o| {
        let r = Rotation3::from_matrix_unchecked(Matrix3::from_column_slice(&i[0][..9]));
        put_quat(&mut o[0], UnitQuaternion::from_rotation_matrix(&r).quaternion());
        Answer::Value
    })
}

// axis_angle(): "The rotation axis and angle in (0, pi] ... Returns None if the angle is zero".
// None is documented as "the angle is zero" (nalgebra then has no axis to give); the ABI has no
// "no axis", and for a zero angle every unit axis is right (ACC-1 identity_axis), so None is
// written as that documented answer: angle 0 about (0, 0, 1), the spec's own axis for it. The
// adapter does not look at the input: whatever nalgebra answers None for (a NaN quaternion
// too) reads as nalgebra's documented "the angle is zero".
unsafe extern "C" fn to_axis_angle(n: usize, q: *const S, angle: *mut S, axis: *mut S, st: *mut u8) -> c_int {
    run(LIB, "to_axis_angle", n, [(q, 4)], [(angle, 1), (axis, 3)], st, Panics::Defect, |i, o| {
        match unit(&i[0]).axis_angle() {
            Some((u, theta)) => {
                o[0][0] = theta;
                put(&mut o[1], u.as_slice());
            }
            None => {
                o[0][0] = 0.0;
                put(&mut o[1], &[0.0, 0.0, 1.0]);
            }
        }
        Answer::Value
    })
}

// ABI version 3: UnitQuaternion::angle(), "The rotation angle in [0; pi] of this unit quaternion"
// (2 atan2(|v|, |w|)), the angle of the same rotation about -u where w < 0 (ACC-1 angle_range).
unsafe extern "C" fn to_angle(n: usize, q: *const S, angle: *mut S, st: *mut u8) -> c_int {
    run(LIB, "to_angle", n, [(q, 4)], [(angle, 1)], st, Panics::Defect, |i, o| {
        o[0][0] = unit(&i[0]).angle();
        Answer::Value
    })
}

// UnitQuaternion::axis(), "The rotation axis of this unit quaternion or None if the rotation is
// zero": v/|v| for w >= 0, -v/|v| for w < 0 (the axis of angle(), ACC-1 angle_range). None is
// written as nalgebra documents it, the zero rotation, whose axis is any unit axis (ACC-1
// identity_axis): (0, 0, 1), as to_axis_angle writes it.
unsafe extern "C" fn to_axis(n: usize, q: *const S, axis: *mut S, st: *mut u8) -> c_int {
    run(LIB, "to_axis", n, [(q, 4)], [(axis, 3)], st, Panics::Defect, |i, o| {
        match unit(&i[0]).axis() {
            Some(u) => put(&mut o[0], u.as_slice()),
            None => put(&mut o[0], &[0.0, 0.0, 1.0]),
        }
        Answer::Value
    })
}

// Quaternion::sqrt(), "Calculates square root", of the rotation UnitQuaternion::from_quaternion(q)
// (nalgebra has no UnitQuaternion::sqrt; the unit quaternion is a Quaternion through Deref):
// powf(0.5) = (ln() * 0.5).exp(), with Quaternion::ln = (ln|q|, v.normalize() * acos(w / |q|)).
unsafe extern "C" fn sqrt(n: usize, q: *const S, out: *mut S, st: *mut u8) -> c_int {
    run(LIB, "sqrt", n, [(q, 4)], [(out, 4)], st, Panics::Defect, |i, o| {
        put_quat(&mut o[0], &unit(&i[0]).quaternion().sqrt());
        Answer::Value
    })
}

// The ABI passes the angle first, then the axis.
unsafe extern "C" fn from_axis_angle(n: usize, angle: *const S, axis: *const S, out: *mut S, st: *mut u8) -> c_int {
    run(LIB, "from_axis_angle", n, [(angle, 1), (axis, 3)], [(out, 4)], st, Panics::Defect, |i, o| {
        let q = UnitQuaternion::from_axis_angle(&Unit::new_normalize(vec3(&i[1])), i[0][0]);
        put_quat(&mut o[0], q.quaternion());
        Answer::Value
    })
}

// UnitQuaternion::ln(): the vector part is the ABI's log slot, as nalgebra returns it.
unsafe extern "C" fn log(n: usize, q: *const S, out: *mut S, st: *mut u8) -> c_int {
    run(LIB, "log", n, [(q, 4)], [(out, 3)], st, Panics::Defect, |i, o| {
        put(&mut o[0], unit(&i[0]).ln().imag().as_slice());
        Answer::Value
    })
}

// The quaternion exponential of the pure quaternion (0, v): Quaternion::from_imag(v).exp().
unsafe extern "C" fn exp(n: usize, v: *const S, out: *mut S, st: *mut u8) -> c_int {
    run(LIB, "exp", n, [(v, 3)], [(out, 4)], st, Panics::Defect, |i, o| {
        put_quat(&mut o[0], &Quaternion::from_imag(vec3(&i[0])).exp());
        Answer::Value
    })
}

// UnitQuaternion::slerp: "Panics if the angle between both quaternion is 180 degrees (in which
// case the interpolation is not well-defined)": that documented panic is its refusal.
unsafe extern "C" fn slerp(n: usize, a: *const S, b: *const S, t: *const S, out: *mut S, st: *mut u8) -> c_int {
    run(LIB, "slerp", n, [(a, 4), (b, 4), (t, 1)], [(out, 4)], st, Panics::Refusal, |i, o| {
        put_quat(&mut o[0], unit(&i[0]).slerp(&unit(&i[1]), i[2][0]).quaternion());
        Answer::Value
    })
}

unsafe extern "C" fn nlerp(n: usize, a: *const S, b: *const S, t: *const S, out: *mut S, st: *mut u8) -> c_int {
    run(LIB, "nlerp", n, [(a, 4), (b, 4), (t, 1)], [(out, 4)], st, Panics::Defect, |i, o| {
        put_quat(&mut o[0], unit(&i[0]).nlerp(&unit(&i[1]), i[2][0]).quaternion());
        Answer::Value
    })
}

// UnitDualQuaternion::from_parts(translation, rotation): real = rotation, dual = 1/2 (0, t) rotation.
unsafe extern "C" fn dq_from_rotation_translation(n: usize, q: *const S, t: *const S, out: *mut S, st: *mut u8) -> c_int {
    run(LIB, "dq_from_rotation_translation", n, [(q, 4), (t, 3)], [(out, 8)], st, Panics::Defect, |i, o| {
        let d = UnitDualQuaternion::from_parts(Translation3::from(vec3(&i[1])), unit(&i[0]));
        put_dual(&mut o[0], d.dual_quaternion());
        Answer::Value
    })
}

// UnitDualQuaternion::rotation() ("Return the rotation part of this unit dual quaternion": the
// real part) and translation() (vector part of 2 dual real*) of new_normalize(d), as dq_apply_point.
unsafe extern "C" fn dq_to_rotation_translation(n: usize, d: *const S, q: *mut S, t: *mut S, st: *mut u8) -> c_int {
    run(LIB, "dq_to_rotation_translation", n, [(d, 8)], [(q, 4), (t, 3)], st, Panics::Defect, |i, o| {
        let u = UnitDualQuaternion::new_normalize(dual(&i[0]));
        put_quat(&mut o[0], u.rotation().quaternion());
        put(&mut o[1], u.translation().vector.as_slice());
        Answer::Value
    })
}

// DualQuaternion * DualQuaternion: the product of the inputs as given (DQ-2).
unsafe extern "C" fn dq_compose(n: usize, a: *const S, b: *const S, out: *mut S, st: *mut u8) -> c_int {
    run(LIB, "dq_compose", n, [(a, 8), (b, 8)], [(out, 8)], st, Panics::Defect, |i, o| {
        put_dual(&mut o[0], &(dual(&i[0]) * dual(&i[1])));
        Answer::Value
    })
}

unsafe extern "C" fn dq_apply_point(n: usize, d: *const S, p: *const S, out: *mut S, st: *mut u8) -> c_int {
    run(LIB, "dq_apply_point", n, [(d, 8), (p, 3)], [(out, 3)], st, Panics::Defect, |i, o| {
        let u = UnitDualQuaternion::new_normalize(dual(&i[0]));
        put(&mut o[0], u.transform_point(&Point3::from(vec3(&i[1]))).coords.as_slice());
        Answer::Value
    })
}

unsafe extern "C" fn dq_normalize(n: usize, d: *const S, out: *mut S, st: *mut u8) -> c_int {
    run(LIB, "dq_normalize", n, [(d, 8)], [(out, 8)], st, Panics::Defect, |i, o| {
        put_dual(&mut o[0], &dual(&i[0]).normalize());
        Answer::Value
    })
}

// UnitDualQuaternion::sclerp: "Panics if the angle between both quaternion is 180 degrees (in
// which case the interpolation is not well-defined)": that documented panic is its refusal.
unsafe extern "C" fn dq_sclerp(n: usize, a: *const S, b: *const S, t: *const S, out: *mut S, st: *mut u8) -> c_int {
    run(LIB, "dq_sclerp", n, [(a, 8), (b, 8), (t, 1)], [(out, 8)], st, Panics::Refusal, |i, o| {
        let ua = UnitDualQuaternion::new_normalize(dual(&i[0]));
        let ub = UnitDualQuaternion::new_normalize(dual(&i[1]));
        put_dual(&mut o[0], ua.sclerp(&ub, i[2][0]).dual_quaternion());
        Answer::Value
    })
}

// Isometry3::rotation_wrt_point(r, c): "The isometry that applies the rotation r with its axis
// passing through the point p", r = UnitQuaternion::from_axis_angle; applied with transform_point.
unsafe extern "C" fn rotate_about_axis(
    n: usize,
    c: *const S,
    u: *const S,
    angle: *const S,
    p: *const S,
    out: *mut S,
    st: *mut u8,
) -> c_int {
    run(LIB, "rotate_about_axis", n, [(c, 3), (u, 3), (angle, 1), (p, 3)], [(out, 3)], st, Panics::Defect, |i, o| {
        let r = UnitQuaternion::from_axis_angle(&Unit::new_normalize(vec3(&i[1])), i[2][0]);
        let iso = Isometry3::rotation_wrt_point(r, Point3::from(vec3(&i[0])));
        put(&mut o[0], iso.transform_point(&Point3::from(vec3(&i[3]))).coords.as_slice());
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
    dq_from_rotation_translation: Some(dq_from_rotation_translation),
    dq_compose: Some(dq_compose),
    dq_apply_point: Some(dq_apply_point),
    dq_normalize: Some(dq_normalize),
    dq_sclerp: Some(dq_sclerp),
    rotate_about_axis: Some(rotate_about_axis),
    ..Ops::NONE
};

pub static OPS3: Ops3<S> = Ops3 {
    to_angle: Some(to_angle),
    to_axis: Some(to_axis),
    sqrt: Some(sqrt),
    dq_to_rotation_translation: Some(dq_to_rotation_translation),
};

/// Isometry3::from_parts(Translation3::from(t), UnitQuaternion::from_quaternion(q)): the isometry
/// x -> R x + t ("the translation is applied after the rotation", Isometry docs), as a nalgebra user
/// builds one from a quaternion and a translation.
fn iso(q: &Buf, t: &Buf) -> Isometry3<S> {
    Isometry3::from_parts(Translation3::from(vec3(t)), unit(q))
}
fn put_iso(oq: &mut Buf, ot: &mut Buf, m: &Isometry3<S>) {
    put(oq, m.rotation.coords.as_slice());
    put(ot, m.translation.vector.as_slice());
}

// Isometry3 * Isometry3 (isometry_ops.rs: rotation a.r * b.r, translation a.t + a.r * b.t):
// rigid_compose(a, b) = a * b, b applied first.
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
        let m = iso(&i[0], &i[1]) * iso(&i[2], &i[3]);
        let (oq, ot) = o.split_at_mut(1);
        put_iso(&mut oq[0], &mut ot[0], &m);
        Answer::Value
    })
}

// Isometry3::transform_point: "Transform the given point by this isometry".
unsafe extern "C" fn rigid_apply(n: usize, q: *const S, t: *const S, p: *const S, out: *mut S, st: *mut u8) -> c_int {
    run(LIB, "rigid_apply", n, [(q, 4), (t, 3), (p, 3)], [(out, 3)], st, Panics::Defect, |i, o| {
        put(&mut o[0], iso(&i[0], &i[1]).transform_point(&Point3::from(vec3(&i[2]))).coords.as_slice());
        Answer::Value
    })
}

// Isometry3::inverse: "Inverts self" (rotation r^-1, translation -(r^-1 t)).
unsafe extern "C" fn rigid_inverse(n: usize, q: *const S, t: *const S, out_q: *mut S, out_t: *mut S, st: *mut u8) -> c_int {
    run(LIB, "rigid_inverse", n, [(q, 4), (t, 3)], [(out_q, 4), (out_t, 3)], st, Panics::Defect, |i, o| {
        let m = iso(&i[0], &i[1]).inverse();
        let (oq, ot) = o.split_at_mut(1);
        put_iso(&mut oq[0], &mut ot[0], &m);
        Answer::Value
    })
}

/// ABI version 4: nalgebra has no dual-quaternion or isometry logarithm / exponential (DQ-8, DQ-9).
pub static OPS4: Ops4<S> = Ops4 {
    rigid_compose: Some(rigid_compose),
    rigid_apply: Some(rigid_apply),
    rigid_inverse: Some(rigid_inverse),
    ..Ops4::NONE
};
