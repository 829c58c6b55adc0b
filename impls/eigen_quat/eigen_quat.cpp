// eigen_quat: Eigen 3.4 exactly as Debian 12 ships it (libeigen3-dev), Eigen::Quaternion and
// Eigen::AngleAxis in their default configuration.
//
// Every operation is the Eigen call an Eigen user makes; nlerp and the n-way blend, which Eigen
// lacks, are written with Eigen operations the way an Eigen user writes them. No checks or fixes
// that Eigen lacks: zero, non-finite, non-unit or bad-weight inputs go straight into Eigen and
// the status is always OK, so the suite sees Eigen's real behaviour (e.g. normalized() of a zero
// quaternion returns it unchanged). Eigen has no quaternion log/exp and no dual quaternions:
// those slots stay NULL (NOT_SUPPORTED).
#include <cmath>
#include <Eigen/Geometry>

#include <cstddef>
#include <span>

#include <rotorcert/impl_table.hpp>

static_assert(EIGEN_WORLD_VERSION == 3 && EIGEN_MAJOR_VERSION == 4, "eigen_quat adapts Eigen 3.4 (Debian 12)");

namespace {

using rotorcert::impl::Mat3;
using rotorcert::impl::Quat;
using rotorcert::impl::Status;
using rotorcert::impl::Vec3;

// ---- conversions at the ABI boundary (QUAT-3) -------------------------------------------------
// Eigen::Quaternion's constructor takes (w, x, y, z) while coeffs() and its memory hold
// x, y, z, w. The conversions use the named accessors, never memory; test_eigen_quat.cpp pins
// both facts.

template <class S> using EQuat = Eigen::Quaternion<S>;
template <class S> using EVec3 = Eigen::Matrix<S, 3, 1>;
template <class S> using EMat3 = Eigen::Matrix<S, 3, 3>;  // column-major (Eigen's default)

template <class S> EQuat<S> to_eigen(const Quat<S>& q) { return EQuat<S>(q[3], q[0], q[1], q[2]); }
template <class S> Quat<S> from_eigen(const EQuat<S>& q) { return {q.x(), q.y(), q.z(), q.w()}; }
template <class S> EVec3<S> to_eigen(const Vec3<S>& v) { return EVec3<S>(v[0], v[1], v[2]); }
template <class S> Vec3<S> from_eigen(const EVec3<S>& v) { return {v.x(), v.y(), v.z()}; }
template <class S> EMat3<S> to_eigen(const Mat3<S>& a) {
  EMat3<S> m;
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) m(r, c) = a[static_cast<std::size_t>(c * 3 + r)];
  return m;
}
template <class S> Mat3<S> from_eigen(const EMat3<S>& m) {
  Mat3<S> a;
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) a[static_cast<std::size_t>(c * 3 + r)] = m(r, c);
  return a;
}

template <class S>
struct EigenQuat {
  using Scalar = S;
  static constexpr const char* name = "eigen_quat";
  static constexpr const char* version = "Eigen 3.4.0";
  static constexpr const char* description =
      "Eigen 3.4 as shipped by Debian 12 (Quaternion, AngleAxis), no checks added. Bivectors "
      "[e23,e31,e12] rotate as q._transformVector(b); trivectors pass through unchanged. nlerp "
      "= (coeffs lerp).normalized() with the dot-sign flip of Eigen's own slerp (the rule an "
      "Eigen user copies). Eigen has no n-way blend: QLB is glue written with Eigen operations "
      "following QLB-1's rules (weighted sum of coeffs, sign flip by the dot with the first "
      "influence of positive weight, normalized()), so only Eigen's arithmetic is certified. No "
      "log/exp, no log-blend, no dual quaternions (NOT_SUPPORTED). Rigid transforms as Isometry3 "
      "(Translation3 * Quaternion). Declares Eigen's documented "
      "preconditions (DECL-1): unit quaternions for the rotation operations, t in [0, 1] for "
      "slerp, a rotation matrix for Quaternion(Matrix3), a unit axis for AngleAxis.";
  static constexpr std::uint32_t levels = RC_LEVEL_CORE | RC_LEVEL_INTERP | RC_LEVEL_BLEND | RC_LEVEL_ROBUST;
  static constexpr const char* const clauses[] = {
      // Core
      "QUAT-2", "NORM-1", "COMPOSE-1", "INV-1", "APPLY-1", "APPLY-2", "APPLY-3", "MAT-1", "MAT-2", "AXANG-1",
      "AXANG-2", "AXANG-3", "AXANG-4",
      // Extended: rigid transforms as Eigen::Isometry3 (Translation * Quaternion)
      "RIGID-1", "RIGID-2", "RIGID-3",
      // Interp: the ops Eigen has (no LOG-*, EXP-*)
      "SLERP-1", "SLERP-2", "SLERP-3", "SLERP-4", "SLERP-5", "NLERP-1",
      // Blend: QLB only
      "QLB-1",
      // Robust
      "MAT-3", "EDGE-1", "EDGE-2", "EDGE-3", "EDGE-4", "EDGE-5", "EDGE-6", "EDGE-7", "EDGE-8", "EDGE-9", nullptr};
  // DECL-1: Eigen's documented preconditions (Eigen 3.4, Geometry/):
  //   Quaternion.h:253 "Operations interpreting the quaternion as rotation have undefined behavior
  //     if the quaternion is not normalized"; :587 toRotationMatrix "The quaternion is required to
  //     be normalized"; :774 slerp "at the parameter t in [0;1]"; :573 Quaternion(Matrix3) "xpr
  //     is assumed to be rotation matrix"; AngleAxis.h:23 "the axis vector must be normalized";
  //     AngleAxis.h:162 AngleAxis = quaternion "Set *this from a unit quaternion" (angle() and axis()
  //     read from it), one of the operations :253 speaks of.
  //   Core/Dot.h:113-116 normalized() "If the input vector is too small (i.e., this->norm()==0),
  //     then this function returns a copy of the input", and :153-158 stableNormalized() "while
  //     avoiding underflow and overflow": normalize's squared norm must not under- or overflow.
  static constexpr const char* const preconditions[] = {
      "normalize:norm_in_range", "apply_vector:unit_quaternion", "apply_bivector:unit_quaternion", "to_matrix:unit_quaternion",
      "slerp:unit_quaternion", "slerp:t_in_unit_interval", "from_matrix:rotation_matrix", "from_axis_angle:unit_axis",
      "to_axis_angle:unit_quaternion", "to_angle:unit_quaternion", "to_axis:unit_quaternion",
      // nlerp and QLB are glue with Eigen's operations (Eigen has neither); they take the
      // contract of the interpolation they copy, QuaternionBase::slerp (unit quaternions), so
      // that no FAIL of the glue on a zero or non-unit input is charged to Eigen.
      "nlerp:unit_quaternion", "blend_qlb:unit_quaternion",
      // Translation * Quaternion converts the quaternion with toRotationMatrix (normalized required).
      "rigid_compose:unit_quaternion", "rigid_apply:unit_quaternion", "rigid_inverse:unit_quaternion", nullptr};

  // -- Core --

  // MatrixBase::normalized(): divides by the norm if squaredNorm() > 0, else returns the
  // input unchanged (zero stays zero; all-subnormal input, whose squared norm underflows,
  // also comes back unchanged and not unit).
  static Status normalize(const Quat<S>& q, Quat<S>& out) {
    out = from_eigen(to_eigen(q).normalized());
    return Status::ok;
  }
  static Status compose(const Quat<S>& a, const Quat<S>& b, Quat<S>& out) {
    out = from_eigen(EQuat<S>(to_eigen(a) * to_eigen(b)));
    return Status::ok;
  }
  // conjugate / squaredNorm; a zero quaternion gives zero.
  static Status inverse(const Quat<S>& q, Quat<S>& out) {
    out = from_eigen(to_eigen(q).inverse());
    return Status::ok;
  }
  // What q * v calls for a 3-vector; assumes unit q.
  static Status apply_vector(const Quat<S>& q, const Vec3<S>& v, Vec3<S>& out) {
    out = from_eigen(EVec3<S>(to_eigen(q)._transformVector(to_eigen(v))));
    return Status::ok;
  }
  // I n rotates like n (I central): Eigen users keep axial vectors as Vector3 and rotate them
  // the same way.
  static Status apply_bivector(const Quat<S>& q, const Vec3<S>& b, Vec3<S>& out) {
    out = from_eigen(EVec3<S>(to_eigen(q)._transformVector(to_eigen(b))));
    return Status::ok;
  }
  static Status apply_trivector(const Quat<S>& q, const S& s, S& out) {
    // No Eigen call runs here, so the glue answers bad input as the spec does (EDGE-7) rather
    // than charge Eigen with a finite answer to a NaN rotation it never saw.
    if (!std::isfinite(q[0] + q[1] + q[2] + q[3])) return Status::domain_error;
    out = s;
    return Status::ok;
  }
  static Status to_matrix(const Quat<S>& q, Mat3<S>& out) {
    out = from_eigen(EMat3<S>(to_eigen(q).toRotationMatrix()));
    return Status::ok;
  }
  // Shoemake's method (trace > 0, else the largest diagonal); no sign canonicalisation.
  static Status from_matrix(const Mat3<S>& m, Quat<S>& out) {
    out = from_eigen(EQuat<S>(to_eigen(m)));
    return Status::ok;
  }
  // AngleAxis(q): angle = 2 atan2(|v|, |w|) in [0, pi] with the axis negated for w < 0, and
  // axis (1, 0, 0) for v = 0. AXANG-1 does not canonicalise (theta in [0, 2 pi], u = v/|v|,
  // (0, 0, 1) for v = 0): the suite reports the difference.
  static Status to_axis_angle(const Quat<S>& q, S& angle, Vec3<S>& axis) {
    const Eigen::AngleAxis<S> aa(to_eigen(q));
    angle = aa.angle();
    axis = from_eigen(EVec3<S>(aa.axis()));
    return Status::ok;
  }
  // ABI version 3: AngleAxis(q).angle() and .axis() apart, as an Eigen user queries them (AXANG-3,
  // AXANG-4): the angle in [0, pi] and the axis that goes with it (-u for w < 0), ACC-1
  // angle_range. AngleAxis(q) "implicitly normalizes the quaternion" (AngleAxis.h). Eigen has no
  // quaternion square root (sqrt stays NULL).
  static Status to_angle(const Quat<S>& q, S& angle) {
    angle = Eigen::AngleAxis<S>(to_eigen(q)).angle();
    return Status::ok;
  }
  static Status to_axis(const Quat<S>& q, Vec3<S>& axis) {
    axis = from_eigen(EVec3<S>(Eigen::AngleAxis<S>(to_eigen(q)).axis()));
    return Status::ok;
  }
  // ABI version 4: rigid transforms as an Eigen user holds them, Isometry3 = Translation3 *
  // Quaternion (Transform<S, 3, Isometry>): composed with operator*, applied to a point with
  // operator*, inverted with inverse() (which uses the Isometry mode: R^T, -R^T t), and read back
  // with Quaternion(T.rotation()) (Isometry mode: the linear part itself) and T.translation().
  using Isometry = Eigen::Transform<S, 3, Eigen::Isometry>;
  static Isometry isometry(const Quat<S>& q, const Vec3<S>& t) {
    return Isometry(Eigen::Translation<S, 3>(to_eigen(t)) * to_eigen(q));
  }
  static void split(const Isometry& m, Quat<S>& q, Vec3<S>& t) {
    q = from_eigen(EQuat<S>(EMat3<S>(m.rotation())));
    t = from_eigen(EVec3<S>(m.translation()));
  }
  static Status rigid_compose(const Quat<S>& qa, const Vec3<S>& ta, const Quat<S>& qb, const Vec3<S>& tb, Quat<S>& q,
                              Vec3<S>& t) {
    split(isometry(qa, ta) * isometry(qb, tb), q, t);
    return Status::ok;
  }
  static Status rigid_apply(const Quat<S>& q, const Vec3<S>& t, const Vec3<S>& p, Vec3<S>& out) {
    out = from_eigen(EVec3<S>(isometry(q, t) * to_eigen(p)));
    return Status::ok;
  }
  static Status rigid_inverse(const Quat<S>& q_in, const Vec3<S>& t_in, Quat<S>& q, Vec3<S>& t) {
    split(isometry(q_in, t_in).inverse(), q, t);
    return Status::ok;
  }
  // Quaternion(AngleAxis): Eigen documents a unit axis and uses it as given.
  static Status from_axis_angle(const S& angle, const Vec3<S>& axis, Quat<S>& out) {
    out = from_eigen(EQuat<S>(Eigen::AngleAxis<S>(angle, to_eigen(axis))));
    return Status::ok;
  }

  // -- Interp --

  // Flips iff dot < 0 strictly, acos(|dot|), plain lerp weights when |dot| >= 1 - epsilon.
  static Status slerp(const Quat<S>& a, const Quat<S>& b, const S& t, Quat<S>& out) {
    out = from_eigen(to_eigen(a).slerp(t, to_eigen(b)));
    return Status::ok;
  }
  static Status nlerp(const Quat<S>& a, const Quat<S>& b, const S& t, Quat<S>& out) {
    const EQuat<S> qa = to_eigen(a), qb = to_eigen(b);
    const S tb = qa.dot(qb) < S(0) ? -t : t;
    out = from_eigen(EQuat<S>((qa.coeffs() * (S(1) - t) + qb.coeffs() * tb).normalized()));
    return Status::ok;
  }

  // -- Blend --

  static Status blend_qlb(std::span<const Quat<S>> q, std::span<const S> w, Quat<S>& out) {
    if (!rotorcert::impl::usable_weights(w)) return Status::domain_error;  // the glue's blend rule (EDGE-9)
    Eigen::Matrix<S, 4, 1> sum = Eigen::Matrix<S, 4, 1>::Zero();
    const std::size_t pivot = rotorcert::impl::first_positive_weight(w);  // QLB-1
    for (std::size_t i = 0; i < q.size(); ++i) {
      const EQuat<S> qi = to_eigen(q[i]);
      sum += (qi.dot(to_eigen(q[pivot])) < S(0) ? -w[i] : w[i]) * qi.coeffs();
    }
    out = from_eigen(EQuat<S>(sum.normalized()));  // Quaternion(Vector4) reads x, y, z, w
    return Status::ok;
  }
};

}  // namespace

ROTORCERT_DEFINE_ENTRY(eigen_quat, EigenQuat<float>, EigenQuat<double>)
