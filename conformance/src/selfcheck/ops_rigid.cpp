// Rigid ops: dual quaternions (DQ-*), rigid transforms as rotation + translation (RIGID-*),
// motors (MOTOR-*), rotation about a line (AXIS-1) and skinning of one vertex (SKIN-*), from
// rigid_ops.hpp and motor.hpp.
#include <span>

#include <rotorcert/reference/motor.hpp>
#include <rotorcert/reference/rigid_ops.hpp>

#include "ops.hpp"

namespace rotorcert::conformance {

namespace clause = ref::clause;

namespace {

using DSpan = std::span<const DQ>;
using RSpan = std::span<const Real>;

Outputs dq_result(const ref::Result<DQ>& r) { return with_status(r).dq("d", r.value); }
Outputs point_result(const ref::Result<V3>& r) { return with_status(r).vec3("p", r.value); }

Outputs dq_from_rt(const Inputs& in) { return dq_result(clause::DQ_1_from_rotation_translation(in.quat("q"), in.vec3("t"))); }
Outputs dq_translation(const Inputs& in) {
  const auto r = clause::DQ_1_translation(in.dq("d"));
  return with_status(r).vec3("t", r.value);
}
Outputs dq_compose(const Inputs& in) { return dq_result(clause::DQ_2_compose(in.dq("a"), in.dq("b"))); }
Outputs dq_apply_point(const Inputs& in) { return point_result(clause::DQ_3_apply_point(in.dq("d"), in.vec3("p"))); }
Outputs dq_normalize(const Inputs& in) { return dq_result(clause::DQ_4_normalize(in.dq("d"))); }
Outputs dq_sclerp(const Inputs& in) { return dq_result(clause::DQ_5_sclerp(in.dq("a"), in.dq("b"), in.scalar("t"))); }

Outputs rotation_translation_result(const ref::Result<ref::RotationTranslation<Real>>& r) {
  return with_status(r).quat("q", r.value.q).vec3("t", r.value.t);
}
Outputs dq_to_rt(const Inputs& in) { return rotation_translation_result(clause::DQ_7_to_rotation_translation(in.dq("d"))); }

/// DQ-8, DQ-9: the dual vector xi = [xi_r, xi_d] (LAYOUT-1, 6 scalars).
Outputs dq_log(const Inputs& in) {
  const auto r = clause::DQ_8_log(in.dq("d"));
  const V3& a = r.value.real;
  const V3& b = r.value.dual;
  return with_status(r).array("xi", {a[0], a[1], a[2], b[0], b[1], b[2]});
}
Outputs dq_exp(const Inputs& in) {
  const std::vector<Real> xi = in.scalars("xi");
  if (xi.size() != 6) in.fail("xi", "a dual vector has 6 components [xi_r, xi_d]");
  return dq_result(clause::DQ_9_exp(ref::DualVector<Real>{{xi[0], xi[1], xi[2]}, {xi[3], xi[4], xi[5]}}));
}

Outputs rigid_compose(const Inputs& in) {
  return rotation_translation_result(clause::RIGID_1_compose(in.quat("qa"), in.vec3("ta"), in.quat("qb"), in.vec3("tb")));
}
Outputs rigid_apply(const Inputs& in) { return point_result(clause::RIGID_2_apply(in.quat("q"), in.vec3("t"), in.vec3("p"))); }
Outputs rigid_inverse(const Inputs& in) { return rotation_translation_result(clause::RIGID_3_inverse(in.quat("q"), in.vec3("t"))); }

template <class Blend>
Handler blend(Blend f) {
  return [f](const Inputs& in) {
    const std::vector<DQ> d = in.dqs("ds");
    const std::vector<Real> w = in.scalars("ws");
    return dq_result(f(DSpan(d), RSpan(w)));
  };
}

Outputs motor_from_dq(const Inputs& in) { return Outputs{}.pga("r", clause::MOTOR_1_from_dual_quaternion(in.dq("d"))); }
Outputs motor_apply_point(const Inputs& in) { return point_result(clause::MOTOR_2_apply_point(in.dq("d"), in.vec3("p"))); }
Outputs motor_compose(const Inputs& in) { return dq_result(clause::MOTOR_3_compose(in.dq("a"), in.dq("b"))); }
Outputs motor_interp(const Inputs& in) {
  return dq_result(clause::MOTOR_4_interpolate(in.dq("a"), in.dq("b"), in.scalar("t")));
}

Outputs axis_rotation(const Inputs& in) {
  return point_result(clause::AXIS_1_rotate_about_line(in.vec3("c"), in.vec3("u"), in.scalar("theta"), in.vec3("p")));
}

template <class Skin>
Handler skin(Skin f) {
  return [f](const Inputs& in) {
    const std::vector<Quat> q = in.quats("qs");
    const std::vector<V3> t = in.vec3s("ts");
    const std::vector<Real> w = in.scalars("ws");
    const auto r = f(std::span<const Quat>(q), std::span<const V3>(t), RSpan(w), in.vec3("v"));
    return with_status(r).vec3("v", r.value);
  };
}

}  // namespace

void register_rigid_ops(OpTable& table) {
  table["dq_from_rt"] = dq_from_rt;
  table["dq_translation"] = dq_translation;
  table["dq_compose"] = dq_compose;
  table["dq_apply_point"] = dq_apply_point;
  table["dq_normalize"] = dq_normalize;
  table["dq_sclerp"] = dq_sclerp;
  table["dq_to_rt"] = dq_to_rt;
  table["dq_log"] = dq_log;
  table["dq_exp"] = dq_exp;
  table["rigid_compose"] = rigid_compose;
  table["rigid_apply"] = rigid_apply;
  table["rigid_inverse"] = rigid_inverse;
  table["dq_dlb"] = blend([](DSpan d, RSpan w) { return clause::DQ_6_dlb<Real>(d, w); });
  table["motor_from_dq"] = motor_from_dq;
  table["motor_apply_point"] = motor_apply_point;
  table["motor_compose"] = motor_compose;
  table["motor_interp"] = motor_interp;
  table["motor_blend"] = blend([](DSpan d, RSpan w) { return clause::MOTOR_5_blend<Real>(d, w); });
  table["axis_rotation"] = axis_rotation;
  table["lbs_vertex"] = skin([](std::span<const Quat> q, std::span<const V3> t, RSpan w, const V3& v) {
    return clause::SKIN_1_linear_blend<Real>(q, t, w, v);
  });
  table["dqs_vertex"] = skin([](std::span<const Quat> q, std::span<const V3> t, RSpan w, const V3& v) {
    return clause::SKIN_2_dual_quaternion<Real>(q, t, w, v);
  });
}

}  // namespace rotorcert::conformance
