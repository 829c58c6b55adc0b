// glm_quat: GLM 0.9.9.8 exactly as Debian 12 ships it, in its default configuration (no
// GLM_FORCE_* define; GLM_ENABLE_EXPERIMENTAL only unlocks gtx/dual_quaternion.hpp).
//
// Every operation is the GLM call a GLM user makes; where GLM has no such operation (n-way
// blends, skinning) the glue is written with GLM's own operators the way a GLM user writes it.
// No checks or fixes that GLM lacks: zero, non-finite, non-unit or bad-weight inputs go
// straight into GLM and the status is always OK, so the suite sees GLM's real behaviour
// (e.g. glm::normalize of a zero quaternion returns the identity).
//
// Tables: "glm_quat" (float, double) and "glm_mix" (float; slerp slot = glm::mix, GLM's other
// spherical interpolation, which has no hemisphere flip).
//
// Build note: glm::lerp asserts t in [0, 1]; the project builds RelWithDebInfo (NDEBUG), so
// nlerp extrapolates like the formula. In a debug build nlerp with t outside [0, 1] aborts.
#define GLM_ENABLE_EXPERIMENTAL  // gtx/dual_quaternion.hpp refuses to compile without it
#include <cmath>
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/ext/quaternion_exponential.hpp>  // glm::log, glm::exp of quaternions
#include <glm/gtx/dual_quaternion.hpp>

#include <cstddef>
#include <span>
#include <vector>

#include <rotorcert/impl_table.hpp>

static_assert(GLM_VERSION == 998, "glm_quat adapts GLM 0.9.9.8 (Debian 12)");

namespace {

using rotorcert::impl::DualQuat;
using rotorcert::impl::Mat3;
using rotorcert::impl::Quat;
using rotorcert::impl::Status;
using rotorcert::impl::Vec3;

// ---- conversions at the ABI boundary (QUAT-3) -------------------------------------------------
// glm::qua's constructor takes (w, x, y, z) while its memory order is x, y, z, w (the ABI's
// order). The conversions go through the named members, never through memory, so they stay
// right even under GLM_FORCE_QUAT_DATA_WXYZ; test_glm_quat.cpp pins both facts.

template <class S> glm::qua<S> to_glm(const Quat<S>& q) { return glm::qua<S>(q[3], q[0], q[1], q[2]); }
template <class S> Quat<S> from_glm(const glm::qua<S>& q) { return {q.x, q.y, q.z, q.w}; }
template <class S> glm::vec<3, S> to_glm(const Vec3<S>& v) { return glm::vec<3, S>(v[0], v[1], v[2]); }
template <class S> Vec3<S> from_glm(const glm::vec<3, S>& v) { return {v.x, v.y, v.z}; }

// glm::mat3 is column-major like the ABI: m[c][r] is row r of column c.
template <class S> glm::mat<3, 3, S> to_glm(const Mat3<S>& a) {
  glm::mat<3, 3, S> m;
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) m[c][r] = a[static_cast<std::size_t>(c * 3 + r)];
  return m;
}
template <class S> Mat3<S> from_glm(const glm::mat<3, 3, S>& m) {
  Mat3<S> a;
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) a[static_cast<std::size_t>(c * 3 + r)] = m[c][r];
  return a;
}

// ABI dual quaternion [real xyzw, dual xyzw] <-> glm::tdualquat{real, dual}.
template <class S> glm::tdualquat<S> to_glm(const DualQuat<S>& d) {
  return glm::tdualquat<S>(glm::qua<S>(d[3], d[0], d[1], d[2]), glm::qua<S>(d[7], d[4], d[5], d[6]));
}
template <class S> DualQuat<S> from_glm(const glm::tdualquat<S>& d) {
  return {d.real.x, d.real.y, d.real.z, d.real.w, d.dual.x, d.dual.y, d.dual.z, d.dual.w};
}

template <class S> glm::qua<S> zero_quat() { return glm::qua<S>(S(0), S(0), S(0), S(0)); }

// ---- the implementation -------------------------------------------------------------------------

template <class S>
struct GlmQuat {
  using Scalar = S;
  static constexpr const char* name = "glm_quat";
  static constexpr const char* version = "GLM 0.9.9.8";
  static constexpr const char* description =
      "GLM 0.9.9.8 as shipped by Debian 12, default configuration, no checks added. Bivectors "
      "[e23,e31,e12] rotate as q * b (GLM users keep axial vectors in vec3); trivectors pass "
      "through unchanged. GLM has no nlerp and no n-way blend: nlerp, QLB and DLB are glue "
      "written with GLM operators following NLERP-1, QLB-1 and DQ-6 (hemisphere flip by glm::dot "
      "with the first influence of positive weight, glm::lerp, glm::normalize), so only GLM's "
      "arithmetic is certified. Declares GLM's documented preconditions (DECL-1): a unit axis "
      "for angleAxis, a pure rotation matrix for quat_cast, t in [0, 1] for lerp. "
      "No ScLERP (NOT_SUPPORTED). Rigid motions via gtx/dual_quaternion; LBS with mat3_cast "
      "matrices divided by the weight sum; AXIS-1 as c + angleAxis(angle, normalize(u)) * (p - c). "
      "ABI v3: to_angle = glm::angle, to_axis = glm::axis, sqrt = glm::sqrt (pow(q, 0.5)); GLM has no "
      "dual quaternion -> rotation and translation call (NOT_SUPPORTED).";
  static constexpr std::uint32_t levels =
      RC_LEVEL_CORE | RC_LEVEL_INTERP | RC_LEVEL_BLEND | RC_LEVEL_RIGID | RC_LEVEL_SKINNING | RC_LEVEL_ROBUST;
  static constexpr const char* const clauses[] = {
      // Core
      "QUAT-2", "NORM-1", "COMPOSE-1", "INV-1", "APPLY-1", "APPLY-2", "APPLY-3", "MAT-1", "MAT-2", "AXANG-1",
      "AXANG-2", "AXANG-3", "AXANG-4",
      // Interp
      "LOG-1", "LOG-2", "EXP-1", "EXP-2", "SQRT-1", "SLERP-1", "SLERP-2", "SLERP-3", "SLERP-4", "SLERP-5", "NLERP-1",
      // Blend (no log-blend in GLM)
      "QLB-1",
      // Rigid (no ScLERP in GLM: DQ-5 not claimed)
      "DQ-1", "DQ-2", "DQ-3", "DQ-4", "DQ-6", "AXIS-1",
      // Skinning
      "SKIN-1", "SKIN-2", "SKIN-3",
      // Robust
      "MAT-3", "EDGE-1", "EDGE-2", "EDGE-3", "EDGE-4", "EDGE-5", "EDGE-6", "EDGE-7", "EDGE-8", "EDGE-9",
      nullptr};
  // DECL-1: GLM 0.9.9.8's documented preconditions: ext/quaternion_trigonometric.hpp:53
  // angleAxis "axis ... must be normalized"; gtc/quaternion.hpp:92 quat_cast "Converts a pure
  // rotation 3 * 3 matrix"; ext/quaternion_common.hpp:60 lerp "defined in the range [0, 1]".
  static constexpr const char* const preconditions[] = {"from_axis_angle:unit_axis", "rotate_about_axis:unit_axis",
                                                        "from_matrix:rotation_matrix", "nlerp:t_in_unit_interval",
                                                        nullptr};

  // -- Core --

  static Status normalize(const Quat<S>& q, Quat<S>& out) {
    out = from_glm(glm::normalize(to_glm(q)));
    return Status::ok;
  }
  static Status compose(const Quat<S>& a, const Quat<S>& b, Quat<S>& out) {
    out = from_glm(to_glm(a) * to_glm(b));
    return Status::ok;
  }
  static Status inverse(const Quat<S>& q, Quat<S>& out) {
    out = from_glm(glm::inverse(to_glm(q)));
    return Status::ok;
  }
  static Status apply_vector(const Quat<S>& q, const Vec3<S>& v, Vec3<S>& out) {
    out = from_glm(to_glm(q) * to_glm(v));
    return Status::ok;
  }
  // A bivector b23 e23 + b31 e31 + b12 e12 is I n with n = (b23, b31, b12); I is central, so it
  // rotates like n. GLM has no bivector type, but its users keep exactly these objects (normals,
  // angular velocities, cross products) in vec3 and rotate them with q * n.
  static Status apply_bivector(const Quat<S>& q, const Vec3<S>& b, Vec3<S>& out) {
    out = from_glm(to_glm(q) * to_glm(b));
    return Status::ok;
  }
  // Rotations keep oriented volume; a GLM user leaves a pseudoscalar (a triple product) alone.
  static Status apply_trivector(const Quat<S>& q, const S& s, S& out) {
    // No GLM call runs here, so the glue answers bad input as the spec does (EDGE-7) rather
    // than charge GLM with a finite answer to a NaN rotation it never saw.
    if (!std::isfinite(q[0] + q[1] + q[2] + q[3])) return Status::domain_error;
    out = s;
    return Status::ok;
  }
  static Status to_matrix(const Quat<S>& q, Mat3<S>& out) {
    out = from_glm(glm::mat3_cast(to_glm(q)));
    return Status::ok;
  }
  static Status from_matrix(const Mat3<S>& m, Quat<S>& out) {
    out = from_glm(glm::quat_cast(to_glm(m)));
    return Status::ok;
  }
  // glm::angle returns 2 asin|v| whenever |w| > cos(1/2): for w < -cos(1/2) (angles above
  // 2 pi - 1) that is 2 pi - theta, a different rotation. Kept as GLM has it (AXANG-1 reports it).
  static Status to_axis_angle(const Quat<S>& q, S& angle, Vec3<S>& axis) {
    const glm::qua<S> g = to_glm(q);
    angle = glm::angle(g);
    axis = from_glm(glm::axis(g));
    return Status::ok;
  }
  // ABI version 3: glm::angle and glm::axis apart, as a GLM user queries them (AXANG-3, AXANG-4).
  static Status to_angle(const Quat<S>& q, S& angle) {
    angle = glm::angle(to_glm(q));
    return Status::ok;
  }
  // 1 - w^2, then v / sqrt(1 - w^2): the axis is lost for small angles (EDGE-2's defect).
  static Status to_axis(const Quat<S>& q, Vec3<S>& axis) {
    axis = from_glm(glm::axis(to_glm(q)));
    return Status::ok;
  }
  // glm::angleAxis documents a unit axis and does not normalise it: passed as given.
  static Status from_axis_angle(const S& angle, const Vec3<S>& axis, Quat<S>& out) {
    out = from_glm(glm::angleAxis(angle, to_glm(axis)));
    return Status::ok;
  }

  // -- Interp --

  // glm::log is the full quaternion log: scalar part log|q| (dropped here, the ABI's log is the
  // pure quaternion), vector part atan(|v|, w) v/|v| (scale-free). For |v| < epsilon it returns
  // (log|w|, 0, 0, 0) for w > 0 and (log|w|, pi, 0, 0) for w < 0, so log(-1) is (pi, 0, 0).
  static Status log(const Quat<S>& q, Vec3<S>& out) {
    const glm::qua<S> l = glm::log(to_glm(q));
    out = {l.x, l.y, l.z};
    return Status::ok;
  }
  static Status exp(const Vec3<S>& v, Quat<S>& out) {
    out = from_glm(glm::exp(glm::qua<S>(S(0), v[0], v[1], v[2])));
    return Status::ok;
  }
  // ext/quaternion_exponential.hpp: sqrt(q) = pow(q, 0.5), which takes the angle as asin(|v|/|q|)
  // where |w|/|q| > cos(1/2) (for w < 0 too: the wrong branch near -1), returns (sqrt(w), 0, 0, 0)
  // where |v|^2 < epsilon (the axis of angles below 2 sqrt(epsilon) is lost) and scales the result
  // by |q|^(1/2) (no normalisation). Kept as GLM has it (SQRT-1 reports it).
  static Status sqrt(const Quat<S>& q, Quat<S>& out) {
    out = from_glm(glm::sqrt(to_glm(q)));
    return Status::ok;
  }
  // Flips b iff dot < 0 strictly; acos of the dot; lerp (not normalised) above 1 - epsilon.
  static Status slerp(const Quat<S>& a, const Quat<S>& b, const S& t, Quat<S>& out) {
    out = from_glm(glm::slerp(to_glm(a), to_glm(b), t));
    return Status::ok;
  }
  // GLM has no nlerp: NLERP-1 written with GLM operators (flip b iff dot < 0, lerp, normalize).
  static Status nlerp(const Quat<S>& a, const Quat<S>& b, const S& t, Quat<S>& out) {
    const glm::qua<S> ga = to_glm(a), gb = to_glm(b);
    out = from_glm(glm::normalize(glm::lerp(ga, glm::dot(ga, gb) < S(0) ? -gb : gb, t)));
    return Status::ok;
  }

  // -- Blend --

  // sum w_i s_i q_i with s_i = -1 iff dot(q_i, q_p) < 0, p the first influence of positive
  // weight (QLB-1), then glm::normalize.
  static Status blend_qlb(std::span<const Quat<S>> q, std::span<const S> w, Quat<S>& out) {
    if (!rotorcert::impl::usable_weights(w)) return Status::domain_error;  // the glue's blend rule (EDGE-9)
    glm::qua<S> sum = zero_quat<S>();
    const std::size_t p = rotorcert::impl::first_positive_weight(w);
    for (std::size_t i = 0; i < q.size(); ++i) {
      const glm::qua<S> qi = to_glm(q[i]);
      const S wi = glm::dot(qi, to_glm(q[p])) < S(0) ? -w[i] : w[i];
      sum += wi * qi;
    }
    out = from_glm(glm::normalize(sum));
    return Status::ok;
  }

  // -- Rigid --

  // glm::dualquat(q, t): dual = 1/2 (0, t) q, q as given.
  static Status dq_from_rotation_translation(const Quat<S>& q, const Vec3<S>& t, DualQuat<S>& out) {
    out = from_glm(glm::tdualquat<S>(to_glm(q), to_glm(t)));
    return Status::ok;
  }
  static Status dq_compose(const DualQuat<S>& a, const DualQuat<S>& b, DualQuat<S>& out) {
    out = from_glm(to_glm(a) * to_glm(b));
    return Status::ok;
  }
  static Status dq_apply_point(const DualQuat<S>& d, const Vec3<S>& p, Vec3<S>& out) {
    out = from_glm(to_glm(d) * to_glm(p));
    return Status::ok;
  }
  // glm::normalize(dualquat) divides both parts by |real|; it does not remove the part of the
  // dual along the real part, so real . dual = 0 (DQ-4) holds only if it held before.
  static Status dq_normalize(const DualQuat<S>& d, DualQuat<S>& out) {
    out = from_glm(glm::normalize(to_glm(d)));
    return Status::ok;
  }
  // DLB with GLM operators (glm::lerp(dualquat) is the two-influence case of the same rule).
  static Status dq_blend(std::span<const DualQuat<S>> d, std::span<const S> w, DualQuat<S>& out) {
    if (!rotorcert::impl::usable_weights(w)) return Status::domain_error;  // the glue's blend rule (EDGE-9)
    out = from_glm(dlb(d.size(), [&](std::size_t i) { return to_glm(d[i]); }, w));
    return Status::ok;
  }
  static Status rotate_about_axis(const Vec3<S>& c, const Vec3<S>& u, const S& angle, const Vec3<S>& p,
                                  Vec3<S>& out) {
    const glm::vec<3, S> gc = to_glm(c);
    out = from_glm(gc + glm::angleAxis(angle, glm::normalize(to_glm(u))) * (to_glm(p) - gc));
    return Status::ok;
  }

  // -- Skinning --

  // The skinning-matrix way: blend the mat3_cast matrices and the translations, apply once,
  // divide by the weight sum (SKIN-1 defines LBS with weights w_i / W).
  static Status skin_linear(std::span<const Quat<S>> q, std::span<const Vec3<S>> t, std::span<const S> w,
                            const Vec3<S>& v, Vec3<S>& out) {
    if (!rotorcert::impl::usable_weights(w)) return Status::domain_error;  // the glue's blend rule (EDGE-9)
    glm::mat<3, 3, S> m(S(0));
    glm::vec<3, S> tsum(S(0));
    S wsum(0);
    for (std::size_t i = 0; i < q.size(); ++i) {
      m += w[i] * glm::mat3_cast(to_glm(q[i]));
      tsum += w[i] * to_glm(t[i]);
      wsum += w[i];
    }
    out = from_glm((m * to_glm(v) + tsum) / wsum);
    return Status::ok;
  }
  static Status skin_dual_quaternion(std::span<const Quat<S>> q, std::span<const Vec3<S>> t, std::span<const S> w,
                                     const Vec3<S>& v, Vec3<S>& out) {
    if (!rotorcert::impl::usable_weights(w)) return Status::domain_error;  // the glue's blend rule (EDGE-9)
    out = from_glm(dlb(q.size(), [&](std::size_t i) { return glm::tdualquat<S>(to_glm(q[i]), to_glm(t[i])); }, w) *
                   to_glm(v));
    return Status::ok;
  }

 private:
  /// The k influences come from `influence(i)`, made on the fly: no heap per element.
  template <class Influence>
  static glm::tdualquat<S> dlb(std::size_t k, Influence influence, std::span<const S> w) {
    glm::tdualquat<S> sum(zero_quat<S>(), zero_quat<S>());
    const glm::tdualquat<S> pivot = influence(rotorcert::impl::first_positive_weight(w));
    for (std::size_t i = 0; i < k; ++i) {
      const glm::tdualquat<S> di = influence(i);
      const S wi = glm::dot(di.real, pivot.real) < S(0) ? -w[i] : w[i];
      sum = sum + wi * di;
    }
    return glm::normalize(sum);
  }
};

// glm::mix is GLM's other slerp: documented as spherical linear interpolation, but without
// the hemisphere flip (obtuse pairs take the long arc) and with acos of an unclamped dot
// (antipodes give 0/sin(pi) garbage, dot < -1 by rounding gives NaN). It claims the Interp
// clauses so that the suite shows where.
struct GlmMix {
  using Scalar = float;
  using Base = GlmQuat<float>;
  static constexpr const char* name = "glm_mix";
  static constexpr const char* version = "GLM 0.9.9.8";
  static constexpr const char* description =
      "GLM 0.9.9.8 glm_quat float table with the slerp slot taken by glm::mix (no hemisphere "
      "flip, unclamped acos); log, exp and nlerp as in glm_quat.";
  static constexpr std::uint32_t levels = RC_LEVEL_INTERP;
  static constexpr const char* const clauses[] = {"LOG-1",   "LOG-2",   "EXP-1",   "EXP-2",   "SLERP-1", "SLERP-2",
                                                  "SLERP-3", "SLERP-4", "SLERP-5", "NLERP-1", nullptr};
  // ACC-1: glm::mix is documented as oriented (ext/quaternion_common.hpp: "The interpolation is
  // oriented ... For short path spherical linear interpolation, use the slerp function"): the
  // long arc for obtuse pairs is its declared convention, not a defect.
  static constexpr const char* const conventions[] = {"slerp:oriented", nullptr};
  static constexpr const char* const preconditions[] = {"nlerp:t_in_unit_interval", nullptr};

  static Status log(const Quat<float>& q, Vec3<float>& out) { return Base::log(q, out); }
  static Status exp(const Vec3<float>& v, Quat<float>& out) { return Base::exp(v, out); }
  static Status slerp(const Quat<float>& a, const Quat<float>& b, const float& t, Quat<float>& out) {
    out = from_glm(glm::mix(to_glm(a), to_glm(b), t));
    return Status::ok;
  }
  static Status nlerp(const Quat<float>& a, const Quat<float>& b, const float& t, Quat<float>& out) {
    return Base::nlerp(a, b, t, out);
  }
};

}  // namespace

ROTORCERT_DEFINE_ENTRY(glm_quat, GlmQuat<float>, GlmQuat<double>, GlmMix)
