// The Bullet table, written once for btScalar. Included by bullet_adapter.cpp (Debian's default
// build, bullet.pc: btScalar = float) and by bullet_adapter_float64.cpp (bullet-float64.pc:
// -DBT_USE_DOUBLE_PRECISION, btScalar = double). The two are compiled into two shared objects
// (CMakeLists.txt says why: the two builds' inline functions share their mangled names).
//
// Bullet 3.24 exactly as Debian 12 ships it (libbullet-dev 3.24+dfsg-2), LinearMath's btQuaternion,
// btMatrix3x3 and quatRotate. Every op is the Bullet call a Bullet user makes; conventions are
// mapped at this boundary and nothing else is done: no domain check, no rescaling, no
// renormalisation, no hemisphere flip the library does not do. Conventions (from the headers):
//   - storage: btQuaternion(x, y, z, w) (btQuaternion.h:82, btQuadWord m_floats[4] = x, y, z, w),
//     the ABI's order; conversions use the named accessors x(), y(), z(), w().
//   - product: operator*(q1, q2) (btQuaternion.h:633) is Hamilton's product q1 q2 (x = w1 x2 +
//     x1 w2 + y1 z2 - z1 y2), so compose(a, b) = a * b with no reordering.
//   - rotation: quatRotate(q, v) (btQuaternion.h:926) is (q * v) * q.inverse(), q v q* (active),
//     without division by |q|^2.
//   - matrix: btMatrix3x3 stores rows ("each vector is a row of the matrix", btMatrix3x3.h:51) and
//     its 9-scalar constructor is "row major formatting" (:69); setRotation(q) (:215) has
//     m[0][1] = xy - wz (scaled by 2/|q|^2), the spec's MAT-1: the ABI's column-major m[c*3 + r]
//     <-> row r, column c, i.e. (*this)[r][c].
//   - angles: radians (setRotation "The magnitude of the rotation in Radians", btQuaternion.h:107).
//     getAngle() returns the full rotation angle 2 acos(w) in [0, 2 pi] (:467) and getAxis() the
//     axis v / sqrt(1 - w^2), or (1, 0, 0) when 1 - w^2 < 10 SIMD_EPSILON (:486).
//   - slerp: slerp(q1, q2, t) = q1.slerp(q2, t) (:920), "t = 0 return q1, t=1 returns q2"; its own
//     hemisphere rule: sign = -1 when the normalised dot is < 0.
// Status (RESULT-2): Bullet has no status channel (its btAssert lines are compiled out in release
// builds, btScalar.h:295); an element whose outputs are all NaN is DOMAIN_ERROR, anything else OK.
#pragma once

#include <LinearMath/btMatrix3x3.h>
#include <LinearMath/btQuaternion.h>
#include <LinearMath/btScalar.h>
#include <LinearMath/btTransform.h>
#include <LinearMath/btVector3.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include <rotorcert/impl_table.hpp>

namespace {

using rotorcert::impl::Mat3;
using rotorcert::impl::Quat;
using rotorcert::impl::Status;
using rotorcert::impl::Vec3;
using S = btScalar;

// ---- conventions at the ABI boundary ------------------------------------------------------------

btQuaternion to_bt(const Quat<S>& q) { return btQuaternion(q[0], q[1], q[2], q[3]); }
Quat<S> from_bt(const btQuaternion& q) { return {q.x(), q.y(), q.z(), q.w()}; }
btVector3 to_bt(const Vec3<S>& v) { return btVector3(v[0], v[1], v[2]); }
Vec3<S> from_bt(const btVector3& v) { return {v.x(), v.y(), v.z()}; }
// Row-major btMatrix3x3 <-> column-major m[c*3 + r].
btMatrix3x3 to_bt(const Mat3<S>& m) {
  return btMatrix3x3(m[0], m[3], m[6],   // row 0: columns 0, 1, 2
                     m[1], m[4], m[7],   // row 1
                     m[2], m[5], m[8]);  // row 2
}
Mat3<S> from_bt(const btMatrix3x3& b) {
  Mat3<S> m{};
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) m[static_cast<std::size_t>(c * 3 + r)] = b[r][c];
  return m;
}

// ---- status rule (RESULT-2) -----------------------------------------------------------------------

bool all_nan(S x) { return std::isnan(x); }
template <std::size_t N>
bool all_nan(const std::array<S, N>& a) {
  for (S x : a)
    if (!std::isnan(x)) return false;
  return true;
}
template <class... Out>
Status status_of(const Out&... outputs) {
  return (all_nan(outputs) && ...) ? Status::domain_error : Status::ok;
}

struct BulletTable {
  using Scalar = S;
  static constexpr const char* name = "bullet";
  static constexpr const char* version = "Bullet 3.24 (Debian 12 libbullet-dev 3.24+dfsg-2)";
  static constexpr const char* description =
      sizeof(S) == 4
          ? "Bullet 3.24 LinearMath (Debian 12, default build bullet.pc: btScalar = float) with no checks added. "
            "btQuaternion(x,y,z,w) = ABI order; Hamilton operator*; inverse() (the conjugate); quatRotate q v q* "
            "(also for bivectors); btMatrix3x3 setRotation/getRotation row-major <-> column-major; getAngle/getAxis "
            "(together and apart); setRotation(axis, angle); slerp; btTransform (q, t) *, (), inverse(). "
            "Status: DOMAIN_ERROR iff every output is NaN."
          : "Bullet 3.24 LinearMath (Debian 12, bullet-float64.pc: -DBT_USE_DOUBLE_PRECISION, btScalar = double) with "
            "no checks added. btQuaternion(x,y,z,w) = ABI order; Hamilton operator*; inverse() (the conjugate); "
            "quatRotate q v q* (also for bivectors); btMatrix3x3 setRotation/getRotation row-major <-> column-major; "
            "getAngle/getAxis (together and apart); setRotation(axis, angle); slerp; btTransform (q, t) *, (), "
            "inverse(). Status: DOMAIN_ERROR iff every output is NaN.";
  static constexpr std::uint32_t levels = RC_LEVEL_CORE | RC_LEVEL_INTERP | RC_LEVEL_ROBUST;
  static constexpr const char* const clauses[] = {
      // Core (no APPLY-3: Bullet has no trivector)
      "QUAT-2", "NORM-1", "COMPOSE-1", "INV-1", "APPLY-1", "APPLY-2", "MAT-1", "MAT-2", "AXANG-1", "AXANG-2",
      // Extended (no SQRT-1: Bullet has no quaternion square root or power; no DQ-7, DQ-8, DQ-9: no dual
      // quaternions, no screw log/exp; RIGID-1..3: btTransform)
      "AXANG-3", "AXANG-4", "RIGID-1", "RIGID-2", "RIGID-3",
      // Interp (no LOG-*, EXP-*, NLERP-1: Bullet has none of them)
      "SLERP-1", "SLERP-2", "SLERP-3", "SLERP-4", "SLERP-5",
      // Robust (EDGE-9 judges weighted ops only; Bullet has none)
      "MAT-3", "EDGE-1", "EDGE-2", "EDGE-3", "EDGE-4", "EDGE-5", "EDGE-6", "EDGE-7", "EDGE-8", nullptr};
  // DECL-1, Bullet's documented preconditions: btMatrix3x3.h:46 "The btMatrix3x3 class implements a
  // 3x3 rotation matrix ... Make sure to only include a pure orthogonal matrix without scaling."
  // (getRotation, :418 "Get the matrix represented as a quaternion"). Nothing in btQuaternion.h
  // asks for unit quaternions or restricts t.
  static constexpr const char* const preconditions[] = {"from_matrix:rotation_matrix", nullptr};
  // Conventions Bullet chose (ACC-1): btMatrix3x3.h:494-517, getRotation takes w > 0 when the trace
  // is positive, else makes the component of the largest diagonal entry positive (s * 0.5) and
  // lets w take any sign; btQuaternion.h:490-491, getAxis returns (1, 0, 0) ("Arbitrary") where
  // 1 - w^2 < 10 SIMD_EPSILON, the identity's axis among them.
  static constexpr const char* const conventions[] = {"from_matrix:sign", "to_axis_angle:identity_axis",
                                                      "to_axis:identity_axis", nullptr};

  // -- Core --

  // btQuaternion.h:442: *this / length(), i.e. times 1/sqrt(x^2 + y^2 + z^2 + w^2) (normalize() is
  // the in-place twin, :385, the same arithmetic).
  static Status normalize(const Quat<S>& q, Quat<S>& out) {
    out = from_bt(to_bt(q).normalized());
    return status_of(out);
  }
  static Status compose(const Quat<S>& a, const Quat<S>& b, Quat<S>& out) {
    out = from_bt(to_bt(a) * to_bt(b));
    return status_of(out);
  }
  // btQuaternion.h:496 "Return the inverse of this quaternion": (-x, -y, -z, w).
  static Status inverse(const Quat<S>& q, Quat<S>& out) {
    out = from_bt(to_bt(q).inverse());
    return status_of(out);
  }
  static Status apply_vector(const Quat<S>& q, const Vec3<S>& v, Vec3<S>& out) {
    out = from_bt(quatRotate(to_bt(q), to_bt(v)));
    return status_of(out);
  }
  // [e23, e31, e12] rotate like a vector (APPLY-2); Bullet keeps a plane as its normal (axial)
  // vector (btStaticPlaneShape's normal, contact normals) and rotates it with the same call.
  static Status apply_bivector(const Quat<S>& q, const Vec3<S>& b, Vec3<S>& out) {
    out = from_bt(quatRotate(to_bt(q), to_bt(b)));
    return status_of(out);
  }
  // btMatrix3x3.h:215: s = 2 / |q|^2, the matrix of q/|q|.
  static Status to_matrix(const Quat<S>& q, Mat3<S>& out) {
    btMatrix3x3 m;
    m.setRotation(to_bt(q));
    out = from_bt(m);
    return status_of(out);
  }
  // btMatrix3x3.h:420: trace > 0: the w pivot, else the largest diagonal entry's pivot (positive).
  static Status from_matrix(const Mat3<S>& m, Quat<S>& out) {
    btQuaternion q;
    to_bt(m).getRotation(q);
    out = from_bt(q);
    return status_of(out);
  }
  static Status to_axis_angle(const Quat<S>& q, S& angle, Vec3<S>& axis) {
    const btQuaternion b = to_bt(q);
    angle = b.getAngle();
    axis = from_bt(b.getAxis());
    return status_of(angle, axis);
  }
  // ABI version 3: getAngle() and getAxis() apart, as a Bullet user queries them (AXANG-3, AXANG-4);
  // getAngleShortestPath() (:475) is the angle of the same rotation in [0, pi], a second to_angle
  // that a table has no slot for: getAngle, the one to_axis_angle uses, is mapped.
  static Status to_angle(const Quat<S>& q, S& angle) {
    angle = to_bt(q).getAngle();
    return status_of(angle);
  }
  static Status to_axis(const Quat<S>& q, Vec3<S>& axis) {
    axis = from_bt(to_bt(q).getAxis());
    return status_of(axis);
  }
  // btQuaternion.h:108: s = sin(angle/2) / |axis|, (s axis, cos(angle/2)).
  static Status from_axis_angle(const S& angle, const Vec3<S>& axis, Quat<S>& out) {
    btQuaternion q;
    q.setRotation(to_bt(axis), angle);
    out = from_bt(q);
    return status_of(out);
  }

  // ABI version 4: rigid transforms as a Bullet user holds them, btTransform (btTransform.h): built
  // with btTransform(q, c) (:43, m_basis(q): btMatrix3x3::setRotation, s = 2 / |q|^2, the rotation
  // of q/|q|; m_origin(c)), x -> m_basis x + m_origin (operator(), :91); composed with operator*
  // (:231, btTransform(m_basis * t.m_basis, (*this)(t.m_origin)): b applied first), applied with
  // operator() (:91), inverted with inverse() (:183, btTransform(R^T, R^T * -m_origin)); read back
  // with getRotation() (:119, btMatrix3x3::getRotation of the basis) and getOrigin().
  static btTransform to_bt_transform(const Quat<S>& q, const Vec3<S>& t) { return btTransform(to_bt(q), to_bt(t)); }
  static void from_bt_transform(const btTransform& m, Quat<S>& q, Vec3<S>& t) {
    q = from_bt(m.getRotation());
    t = from_bt(m.getOrigin());
  }
  static Status rigid_compose(const Quat<S>& qa, const Vec3<S>& ta, const Quat<S>& qb, const Vec3<S>& tb, Quat<S>& q,
                              Vec3<S>& t) {
    from_bt_transform(to_bt_transform(qa, ta) * to_bt_transform(qb, tb), q, t);
    return status_of(q, t);
  }
  static Status rigid_apply(const Quat<S>& q, const Vec3<S>& t, const Vec3<S>& p, Vec3<S>& out) {
    out = from_bt(to_bt_transform(q, t)(to_bt(p)));
    return status_of(out);
  }
  static Status rigid_inverse(const Quat<S>& q_in, const Vec3<S>& t_in, Quat<S>& q, Vec3<S>& t) {
    from_bt_transform(to_bt_transform(q_in, t_in).inverse(), q, t);
    return status_of(q, t);
  }

  // -- Interp --

  static Status slerp(const Quat<S>& a, const Quat<S>& b, const S& t, Quat<S>& out) {
    out = from_bt(::slerp(to_bt(a), to_bt(b), t));  // btQuaternion.h:920, q1.slerp(q2, t)
    return status_of(out);
  }
};

}  // namespace
