// cqrlib_adapter: H. J. Bernstein's CQRlib 1.1.4 exactly as Debian 12 ships it (libcqrlib-dev
// 1.1.4-3: /usr/include/cqrlib.h, libCQRlib.so), certified through the C ABI (route "abi") as the
// dlopen plugin rotorcert_adapter_cqrlib.so with one binary64 table named "cqrlib" (CQRlib is
// double only).
//
// Every op is the CQRlib call a CQRlib user makes; conventions are mapped at this boundary and
// nothing else is done: no domain checks, no rescaling, no renormalisation, no hemisphere flips
// the library does not do. Conventions of CQRlib, each checked by experiment on the installed
// library (the lead's report lists the probes):
//   - storage: CQRQuaternion is {w, x, y, z}; the ABI is [x, y, z, w]. to_cqr / from_cqr copy by
//     field name, never by memory.
//   - product: CQRMultiply(q1, q2) is the Hamilton product q1 q2 (i j = +k), so compose(a, b) =
//     CQRMultiply(a, b) with no reordering.
//   - rotation: CQRRotateByQuaternion(w, q, v) computes w = q v q* (active; the header says so),
//     with no division by |q|^2.
//   - matrix: CQRQuaternion2Matrix / CQRMatrix2Quaternion use double R[3][3] with R[row][col]
//     (R[0][1] = 2(xy - wz)) in the same active convention as the spec's MAT-1; the ABI is
//     column-major, so m[c*3 + r] <-> R[r][c].
//   - angles: radians. CQRGetQuaternionAngle returns the angle of the polar form
//     q = |q| (cos phi + u sin phi), phi = atan2(|v|, w) in [0, pi], i.e. HALF the rotation angle:
//     to_axis_angle's theta = 2 phi (exact in binary). CQRAxis2Quaternion takes the full angle.
//   - log: CQRLog(q) = (log|q|, phi u), the full quaternion log; the ABI's rotation log is its
//     vector part [x, y, z] = (theta/2) u, and the scalar log|q| (the log of the scale, which the
//     ABI's scale-free log has no slot for) is dropped.
//   - exp: the ABI's v is the pure quaternion (0, v) handed to CQRExp.
//   - slerp: CQRHLERP(out, q1, q2, w1, w2), the library's slerp "for use with quaternions
//     representing rotations", takes the weight w1 of q1 and w2 of q2 (t_lib = w1/(w1+w2) is the
//     weight of q1): slerp(a, b, t) = CQRHLERP(a, b, 1 - t, t). CQRSLERP is the library's
//     full-sphere variant that "is not appropriate for quaternions representing rotations".
//   - normalize: the C API has none; the same header's C++ template (compiled here from
//     cqrlib.h) has CPPQR::UnitQ(), "Get a unit quaternion from a general one": q/sqrt(Normsq()),
//     or DBL_MAX in all four components for a zero q.
// Status (RESULT-2): DOMAIN_ERROR, every output a quiet NaN, when a CQRlib call returns anything
// but CQR_SUCCESS or when every output component comes out NaN; otherwise OK with what it computed
// (DBL_MAX sentinels included). One library quirk is pinned here because the ABI forces a
// choice: CQRGetQuaternionAngle returns CQR_SUCCESS WITHOUT writing the angle when |v| <= DBL_MIN;
// the adapter's variable starts at 0, the value the header's own CPPQR::GetAngle() returns there.
//
// Not supported (no CQRlib function): nlerp, QLB and log-blends, dual quaternions, skinning, the
// trivector (CQRlib has no pseudoscalar; an identity written here would certify the adapter).
#include <cqrlib.h>

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

// ---- conventions at the ABI boundary ------------------------------------------------------------

CQRQuaternion to_cqr(const Quat<double>& q) {
  CQRQuaternion c;
  c.w = q[3];
  c.x = q[0];
  c.y = q[1];
  c.z = q[2];
  return c;
}
Quat<double> from_cqr(const CQRQuaternion& c) { return {c.x, c.y, c.z, c.w}; }

// CQRlib's R[row][col] from / to the ABI's column-major m[c*3 + r].
void to_rows(const Mat3<double>& m, double r[3][3]) {
  for (std::size_t row = 0; row < 3; ++row)
    for (std::size_t col = 0; col < 3; ++col) r[row][col] = m[col * 3 + row];
}
Mat3<double> from_rows(const double r[3][3]) {
  Mat3<double> m{};
  for (std::size_t row = 0; row < 3; ++row)
    for (std::size_t col = 0; col < 3; ++col) m[col * 3 + row] = r[row][col];
  return m;
}

// ---- status rule (RESULT-2) -----------------------------------------------------------------------

bool all_nan(double x) { return std::isnan(x); }
template <std::size_t N>
bool all_nan(const std::array<double, N>& a) {
  for (double x : a)
    if (!std::isnan(x)) return false;
  return true;
}
/// DOMAIN_ERROR iff the library reported an error or every output is NaN (the batch loop of
/// impl.hpp then sets every output to a quiet NaN).
template <class... Out>
Status status_of(int rc, const Out&... outputs) {
  if (rc != CQR_SUCCESS) return Status::domain_error;
  if ((all_nan(outputs) && ...)) return Status::domain_error;
  return Status::ok;
}

struct CQRlibTable {
  using Scalar = double;
  static constexpr const char* name = "cqrlib";
  static constexpr const char* version = "CQRlib 1.1.4 (Debian 12 libcqrlib-dev 1.1.4-3)";
  static constexpr const char* description =
      "CQRlib 1.1.4 (H. J. Bernstein, C, Debian 12) through its C API, no checks added. "
      "{w,x,y,z} <-> [x,y,z,w]; Hamilton CQRMultiply; CQRRotateByQuaternion q v q* (also for "
      "bivectors); R[row][col] <-> column-major; to_axis_angle 2*CQRGetQuaternionAngle (half "
      "angle) and CQRGetQuaternionAxis, together and apart (to_angle, to_axis); log = vector part of CQRLog; exp = CQRExp of (0,v); slerp "
      "= CQRHLERP(a,b,1-t,t); normalize = CPPQR::UnitQ of the same header. Status: DOMAIN_ERROR iff "
      "a call returns non-CQR_SUCCESS or every output is NaN.";
  static constexpr std::uint32_t levels = RC_LEVEL_CORE | RC_LEVEL_INTERP | RC_LEVEL_ROBUST;
  static constexpr const char* const clauses[] = {
      // Core (APPLY-3 not claimed: no trivector in CQRlib)
      "QUAT-2", "NORM-1", "COMPOSE-1", "INV-1", "APPLY-1", "APPLY-2", "MAT-1", "MAT-2", "AXANG-1", "AXANG-2",
      // Extended (no SQRT-1: CQRlib has no square root, only CQRDoublePower; no DQ-7: no dual quaternions)
      "AXANG-3", "AXANG-4",
      // Interp (no NLERP-1: CQRlib has no nlerp)
      "LOG-1", "LOG-2", "EXP-1", "EXP-2", "SLERP-1", "SLERP-2", "SLERP-3", "SLERP-4", "SLERP-5",
      // Robust (EDGE-9 judges weighted ops only; CQRlib has none)
      "MAT-3", "EDGE-1", "EDGE-2", "EDGE-3", "EDGE-4", "EDGE-5", "EDGE-6", "EDGE-7", "EDGE-8", nullptr};
  // DECL-1, CQRlib's documented preconditions (cqrlib.h): :1457 CQRMatrix2Quaternion "Form the
  // quaternion from a 3x3 rotation matrix R"; :1449 CQRRotateByQuaternion "w = qvq*" (a rotation
  // only for a unit q: it does not divide by |q|^2); :1492 HLERP interpolates "quaternions
  // representing rotations" linearly "between the radii" (unit inputs give the rotation).
  static constexpr const char* const preconditions[] = {"from_matrix:rotation_matrix", "apply_vector:unit_quaternion",
                                                        "apply_bivector:unit_quaternion", "slerp:unit_quaternion", nullptr};

  // -- Core --

  // CPPQR<double>::UnitQ(): q / sqrt(Normsq()); Normsq() == 0 gives DBL_MAX x 4 (no error code).
  static Status normalize(const Quat<double>& q, Quat<double>& out) {
    const CPPQR<double> u = CPPQR<double>(q[3], q[0], q[1], q[2]).UnitQ();
    out = {u.GetX(), u.GetY(), u.GetZ(), u.GetW()};
    return status_of(CQR_SUCCESS, out);
  }
  static Status compose(const Quat<double>& a, const Quat<double>& b, Quat<double>& out) {
    CQRQuaternion ca = to_cqr(a), cb = to_cqr(b), r{};
    const int rc = CQRMultiply(&r, &ca, &cb);
    out = from_cqr(r);
    return status_of(rc, out);
  }
  // conjugate / normsq; CQR_BAD_ARGUMENT when normsq is not > 0.
  static Status inverse(const Quat<double>& q, Quat<double>& out) {
    CQRQuaternion cq = to_cqr(q), r{};
    const int rc = CQRInverse(&r, &cq);
    out = from_cqr(r);
    return status_of(rc, out);
  }
  static Status apply_vector(const Quat<double>& q, const Vec3<double>& v, Vec3<double>& out) {
    CQRQuaternion cq = to_cqr(q);
    double in[3] = {v[0], v[1], v[2]}, w[3] = {0, 0, 0};
    const int rc = CQRRotateByQuaternion(w, &cq, in);
    out = {w[0], w[1], w[2]};
    return status_of(rc, out);
  }
  // [e23, e31, e12] rotate like a vector (APPLY-2); a quaternion library keeps a plane as its
  // normal (axial) vector and rotates it with the same call.
  static Status apply_bivector(const Quat<double>& q, const Vec3<double>& b, Vec3<double>& out) {
    return apply_vector(q, b, out);
  }
  static Status to_matrix(const Quat<double>& q, Mat3<double>& out) {
    CQRQuaternion cq = to_cqr(q);
    double r[3][3] = {};
    const int rc = CQRQuaternion2Matrix(r, &cq);
    out = from_rows(r);
    return status_of(rc, out);
  }
  // Trace > -0.75: w = sqrt(1 + trace)/2 pivot, else the x, y, z pivots (>= 1/4); none of them:
  // CQR_BAD_ARGUMENT. No det or orthogonality check.
  static Status from_matrix(const Mat3<double>& m, Quat<double>& out) {
    double r[3][3];
    to_rows(m, r);
    CQRQuaternion q{};
    const int rc = CQRMatrix2Quaternion(&q, r);
    out = from_cqr(q);
    return status_of(rc, out);
  }
  static Status to_axis_angle(const Quat<double>& q, double& angle, Vec3<double>& axis) {
    CQRQuaternion cq = to_cqr(q), ax{};
    double half = 0.0;  // left unwritten by CQRlib when |v| <= DBL_MIN (see the header comment)
    const int rc_angle = CQRGetQuaternionAngle(&half, &cq);
    const int rc_axis = CQRGetQuaternionAxis(&ax, &cq);
    angle = 2.0 * half;  // polar-form angle phi is half the rotation angle
    axis = {ax.x, ax.y, ax.z};
    return status_of(rc_angle != CQR_SUCCESS ? rc_angle : rc_axis, angle, axis);
  }
  // ABI version 3: the same two calls apart. to_angle = 2 * CQRGetQuaternionAngle (the polar
  // half angle, doubled exactly as in to_axis_angle), to_axis = CQRGetQuaternionAxis.
  static Status to_angle(const Quat<double>& q, double& angle) {
    CQRQuaternion cq = to_cqr(q);
    double half = 0.0;  // left unwritten by CQRlib when |v| <= DBL_MIN (see the header comment)
    const int rc = CQRGetQuaternionAngle(&half, &cq);
    angle = 2.0 * half;
    return status_of(rc, angle);
  }
  static Status to_axis(const Quat<double>& q, Vec3<double>& axis) {
    CQRQuaternion cq = to_cqr(q), ax{};
    const int rc = CQRGetQuaternionAxis(&ax, &cq);
    axis = {ax.x, ax.y, ax.z};
    return status_of(rc, axis);
  }
  // Radians, full angle; the axis is divided by its norm unless normsq == 1 exactly;
  // CQR_BAD_ARGUMENT for normsq == 0.
  static Status from_axis_angle(const double& angle, const Vec3<double>& axis, Quat<double>& out) {
    double u[3] = {axis[0], axis[1], axis[2]};
    CQRQuaternion q{};
    const int rc = CQRAxis2Quaternion(&q, u, angle);
    out = from_cqr(q);
    return status_of(rc, out);
  }

  // -- Interp --

  static Status log(const Quat<double>& q, Vec3<double>& out) {
    CQRQuaternion cq = to_cqr(q), l{};
    const int rc = CQRLog(&l, &cq);
    out = {l.x, l.y, l.z};  // l.w = log|q| has no ABI slot (the ABI log is scale-free)
    return status_of(rc, out);
  }
  static Status exp(const Vec3<double>& v, Quat<double>& out) {
    CQRQuaternion pv{}, e{};
    pv.w = 0.0;
    pv.x = v[0];
    pv.y = v[1];
    pv.z = v[2];
    const int rc = CQRExp(&e, &pv);
    out = from_cqr(e);
    return status_of(rc, out);
  }
  // w1 = 1 - t is the weight of a, w2 = t of b (CQRlib's t_lib = w1/(w1 + w2) weighs q1).
  static Status slerp(const Quat<double>& a, const Quat<double>& b, const double& t, Quat<double>& out) {
    CQRQuaternion ca = to_cqr(a), cb = to_cqr(b), r{};
    const int rc = CQRHLERP(&r, &ca, &cb, 1.0 - t, t);
    out = from_cqr(r);
    return status_of(rc, out);
  }
};

}  // namespace

extern "C" __attribute__((visibility("default"))) const rc_impl* rotorcert_impl_entry(std::uint32_t abi_version,
                                                                                     std::uint32_t index) {
  return rotorcert::impl::entry<CQRlibTable>(abi_version, index);
}
