// Rotation ops (rotation_ops.hpp), the quaternion <-> rotor map (Q2R-*) and the paper's printed
// forms (paper.hpp, ERRATUM-*).
#include <span>

#include <rotorcert/reference/paper.hpp>
#include <rotorcert/reference/rotation_ops.hpp>

#include "ops.hpp"

namespace rotorcert::conformance {

namespace clause = ref::clause;
namespace paper = ref::paper;

namespace {

using QSpan = std::span<const Quat>;
using RSpan = std::span<const Real>;

Outputs quat_result(const ref::Result<Quat>& r) { return with_status(r).quat("q", r.value); }
Outputs vec3_result(const std::string& name, const ref::Result<V3>& r) { return with_status(r).vec3(name, r.value); }

// ---- quaternion <-> rotor (Q2R-*) -----------------------------------------------------------

Outputs q2r(const Inputs& in) { return Outputs{}.cl3("r", clause::Q2R_1_rotor_from_quaternion(in.quat("q"))); }
Outputs r2q(const Inputs& in) { return Outputs{}.quat("q", clause::Q2R_1_quaternion_from_rotor(in.cl3("r"))); }

/// Q2R-2: size of the violation of Phi(ab) = Phi(a)Phi(b) and Phi(a*) = ~Phi(a).
Outputs q2r_homomorphism(const Inputs& in) {
  using clause::Q2R_1_rotor_from_quaternion;
  const Quat a = in.quat("a"), b = in.quat("b");
  const CL3 pa = Q2R_1_rotor_from_quaternion(a), pb = Q2R_1_rotor_from_quaternion(b);
  const Real product = ref::coefficient_norm(Q2R_1_rotor_from_quaternion(a * b) - ref::gp(pa, pb));
  const Real conjugate = ref::coefficient_norm(Q2R_1_rotor_from_quaternion(ref::conj(a)) - ref::reverse(pa));
  return Outputs{}.scalar("residual", mpfr::max(product, conjugate));
}

/// Q2R-3: size of the violation of Phi(q) v ~Phi(q) = q v q* (both unnormalised: both scale by |q|^2).
Outputs q2r_rotation(const Inputs& in) {
  const Quat q = in.quat("q");
  const V3 v = in.vec3("v");
  const CL3 r = clause::Q2R_1_rotor_from_quaternion(q);
  const CL3 rotated = ref::gp(ref::gp(r, ref::cl3::vector(v)), ref::reverse(r));
  const Quat hamilton = q * Quat{Real(0), v[0], v[1], v[2]} * ref::conj(q);
  const CL3 difference = rotated - ref::cl3::vector<Real>({hamilton.x, hamilton.y, hamilton.z});
  return Outputs{}.scalar("residual", ref::coefficient_norm(difference));
}

Outputs method1(const Inputs& in) {
  const auto r = clause::Q2R_4_method1(in.scalar("theta"), in.vec3("axis"));
  return with_status(r).cl3("r", r.value);
}

Outputs q2r_uniqueness(const Inputs&) { return Outputs{}.scalar("count", Real(clause::Q2R_5_count_valid_maps())); }

// ---- the paper as printed (ERRATUM-*) --------------------------------------------------------

Outputs paper_ijk(const Inputs&) { return Outputs{}.cl3("r", paper::ERRATUM_1_ijk_product<Real>()); }
Outputs paper_method2(const Inputs& in) { return Outputs{}.cl3("r", paper::ERRATUM_2_method2_as_printed(in.quat("q"))); }
Outputs paper_alt_rotor(const Inputs& in) {
  return Outputs{}.cl3("r", paper::ERRATUM_4_alternative_rotor_as_printed(in.quat("q")));
}
Outputs paper_method1_degrees(const Inputs& in) {
  return Outputs{}.cl3("r", paper::ERRATUM_5_method1_as_printed(in.quat("q")));
}
Outputs paper_interp(const Inputs& in) {
  return Outputs{}.quat("q", paper::ERRATUM_3_interpolation_as_printed(in.quat("a"), in.quat("b"), in.scalar("t")));
}

// ---- rotation ops ------------------------------------------------------------------------

Outputs normalize(const Inputs& in) { return quat_result(clause::NORM_1_normalize(in.quat("q"))); }
Outputs compose(const Inputs& in) { return quat_result(clause::COMPOSE_1_compose(in.quat("a"), in.quat("b"))); }
Outputs inverse(const Inputs& in) { return quat_result(clause::INV_1_inverse(in.quat("q"))); }
Outputs apply_vector(const Inputs& in) { return vec3_result("v", clause::APPLY_1_apply_vector(in.quat("q"), in.vec3("v"))); }
Outputs apply_bivector(const Inputs& in) {
  return vec3_result("b", clause::APPLY_2_apply_bivector(in.quat("q"), in.vec3("b")));
}
Outputs apply_trivector(const Inputs& in) {
  const auto r = clause::APPLY_3_apply_trivector(in.quat("q"), in.scalar("s"));
  return with_status(r).scalar("s", r.value);
}
Outputs to_matrix(const Inputs& in) {
  const auto r = clause::MAT_1_to_matrix(in.quat("q"));
  return with_status(r).mat3("m", r.value);
}
Outputs from_matrix(const Inputs& in) { return quat_result(clause::MAT_2_from_matrix(in.mat3("m"))); }
Outputs to_axis_angle(const Inputs& in) {
  const auto r = clause::AXANG_1_to_axis_angle(in.quat("q"));
  return with_status(r).scalar("theta", r.value.angle).vec3("axis", r.value.axis);
}
/// AXANG-3 and AXANG-4: AXANG-1's angle alone, its axis alone.
Outputs to_angle(const Inputs& in) {
  const auto r = clause::AXANG_1_to_axis_angle(in.quat("q"));
  return with_status(r).scalar("theta", r.value.angle);
}
Outputs to_axis(const Inputs& in) {
  const auto r = clause::AXANG_1_to_axis_angle(in.quat("q"));
  return with_status(r).vec3("axis", r.value.axis);
}
Outputs sqrt(const Inputs& in) { return quat_result(clause::SQRT_1_sqrt(in.quat("q"))); }
Outputs from_axis_angle(const Inputs& in) {
  return quat_result(clause::AXANG_2_from_axis_angle(in.scalar("theta"), in.vec3("axis")));
}
Outputs log(const Inputs& in) { return vec3_result("v", clause::LOG_1_log(in.quat("q"))); }
Outputs exp(const Inputs& in) { return quat_result(clause::EXP_1_exp(in.vec3("v"))); }

/// EXP-2: |exp(log q) - q/|q|| (Euclidean norm of the coefficient difference).
Outputs exp_log(const Inputs& in) {
  const Quat q = in.quat("q");
  const auto l = clause::LOG_1_log(q);
  const auto unit = clause::NORM_1_normalize(q);
  if (l.status != ref::Status::ok || unit.status != ref::Status::ok)
    return with_status(ref::domain_error<Real>()).scalar("residual", ref::ScalarTraits<Real>::nan());
  const auto e = clause::EXP_1_exp(l.value);
  return with_status(e).scalar("residual", ref::norm(e.value - unit.value));
}

Outputs slerp(const Inputs& in) { return quat_result(clause::SLERP_1_slerp(in.quat("a"), in.quat("b"), in.scalar("t"))); }
Outputs rotor_interp(const Inputs& in) {
  return quat_result(clause::SLERP_2_rotor_interpolation(in.quat("a"), in.quat("b"), in.scalar("t")));
}
Outputs nlerp(const Inputs& in) { return quat_result(clause::NLERP_1_nlerp(in.quat("a"), in.quat("b"), in.scalar("t"))); }

template <class Blend>
Handler blend(Blend f) {
  return [f](const Inputs& in) {
    const std::vector<Quat> q = in.quats("qs");
    const std::vector<Real> w = in.scalars("ws");
    return quat_result(f(QSpan(q), RSpan(w)));
  };
}

Outputs blend_deviation(const Inputs& in) {
  const std::vector<Quat> q = in.quats("qs");
  const std::vector<Real> w = in.scalars("ws");
  const std::string m = in.text("method");
  clause::BlendMethod method = clause::BlendMethod::qlb;
  if (m == "log_blend") method = clause::BlendMethod::log_blend;
  else if (m != "qlb") in.fail("method", "expected \"qlb\" or \"log_blend\", found \"" + m + "\"");
  const auto r = clause::BLENDQ_1_deviation(QSpan(q), RSpan(w), method);
  return with_status(r).scalar("theta", r.value);
}

}  // namespace

void register_rotation_ops(OpTable& table) {
  table["q2r"] = q2r;
  table["r2q"] = r2q;
  table["q2r_homomorphism"] = q2r_homomorphism;
  table["q2r_rotation"] = q2r_rotation;
  table["method1"] = method1;
  table["q2r_uniqueness"] = q2r_uniqueness;
  table["paper_ijk"] = paper_ijk;
  table["paper_method2"] = paper_method2;
  table["paper_alt_rotor"] = paper_alt_rotor;
  table["paper_method1_degrees"] = paper_method1_degrees;
  table["paper_interp"] = paper_interp;
  table["normalize"] = normalize;
  table["compose"] = compose;
  table["inverse"] = inverse;
  table["apply_vector"] = apply_vector;
  table["apply_bivector"] = apply_bivector;
  table["apply_trivector"] = apply_trivector;
  table["to_matrix"] = to_matrix;
  table["from_matrix"] = from_matrix;
  table["to_axis_angle"] = to_axis_angle;
  table["to_angle"] = to_angle;
  table["to_axis"] = to_axis;
  table["sqrt"] = sqrt;
  table["from_axis_angle"] = from_axis_angle;
  table["log"] = log;
  table["exp"] = exp;
  table["exp_log"] = exp_log;
  table["slerp"] = slerp;
  table["rotor_interp"] = rotor_interp;
  table["nlerp"] = nlerp;
  table["qlb"] = blend([](QSpan q, RSpan w) { return clause::QLB_1_blend<Real>(q, w); });
  table["log_blend"] = blend([](QSpan q, RSpan w) { return clause::LOGBLEND_1_blend<Real>(q, w); });
  table["karcher_mean"] = blend([](QSpan q, RSpan w) { return clause::KARCHER_1_mean<Real>(q, w); });
  table["blend_deviation"] = blend_deviation;
}

}  // namespace rotorcert::conformance
