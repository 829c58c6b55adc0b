#include <rotorcert/engine/abi_op.hpp>

#include <stdexcept>

#include <algorithm>
#include <span>

#include <rotorcert/reference/mat3_domain.hpp>
#include <rotorcert/reference/metrics.hpp>
#include <rotorcert/reference/rigid_ops.hpp>
#include <rotorcert/reference/rotation_ops.hpp>

#include "rigid_scales.hpp"

namespace rotorcert::engine {
namespace {

using Quat = ref::Quaternion<Real>;
using V3 = ref::Vec3<Real>;
using DQ = ref::DualQuaternion<Real>;
namespace clause = ref::clause;

// ---- ABI layout <-> reference types -------------------------------------------------------

Quat quat(const std::vector<Real>& a, std::size_t i = 0) { return {a[i * 4 + 3], a[i * 4], a[i * 4 + 1], a[i * 4 + 2]}; }
V3 vec3(const std::vector<Real>& a, std::size_t i = 0) { return {a[i * 3], a[i * 3 + 1], a[i * 3 + 2]}; }
DQ dq(const std::vector<Real>& a, std::size_t i = 0) {
  return {{a[i * 8 + 3], a[i * 8], a[i * 8 + 1], a[i * 8 + 2]}, {a[i * 8 + 7], a[i * 8 + 4], a[i * 8 + 5], a[i * 8 + 6]}};
}
ref::Mat3<Real> mat3(const std::vector<Real>& a) {
  ref::Mat3<Real> m;
  std::copy(a.begin(), a.begin() + 9, m.begin());
  return m;
}
std::vector<Quat> quats(const std::vector<Real>& a, std::size_t k) {
  std::vector<Quat> r;
  for (std::size_t i = 0; i < k; ++i) r.push_back(quat(a, i));
  return r;
}
std::vector<V3> vec3s(const std::vector<Real>& a, std::size_t k) {
  std::vector<V3> r;
  for (std::size_t i = 0; i < k; ++i) r.push_back(vec3(a, i));
  return r;
}
std::vector<DQ> dqs(const std::vector<Real>& a, std::size_t k) {
  std::vector<DQ> r;
  for (std::size_t i = 0; i < k; ++i) r.push_back(dq(a, i));
  return r;
}

std::vector<Real> flat(const Quat& q) { return {q.x, q.y, q.z, q.w}; }
std::vector<Real> flat(const V3& v) { return {v[0], v[1], v[2]}; }
std::vector<Real> flat(const DQ& d) {
  return {d.real.x, d.real.y, d.real.z, d.real.w, d.dual.x, d.dual.y, d.dual.z, d.dual.w};
}
std::vector<Real> flat(const ref::Mat3<Real>& m) { return {m.begin(), m.end()}; }
std::vector<Real> flat(const Real& s) { return {s}; }

template <class V>
ReferenceResult one(const ref::Result<V>& r) {
  return {r.status, {flat(r.value)}};
}

Real length(const V3& v) { return sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }
Real length_of(const std::vector<Real>& a, std::size_t i) { return length(vec3(a, i)); }

/// max(1, |p|, |t|) of a dual quaternion input and a point (DQ-3).
Real rigid_scale(const DQ& d, const V3& p) {
  Real s = std::max(Real(1), length(p));
  if (ref::finite(d) && !ref::is_zero(d.real)) s = std::max(s, length(ref::clause::dual_quaternion_translation(d)));
  return s;
}

Real unit_scale(const Values&, std::size_t) { return Real(1); }

std::vector<Real> join(std::vector<Real> a, const std::vector<Real>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}
ref::DualVector<Real> dual_vector(const std::vector<Real>& a) { return {vec3(a, 0), vec3(a, 1)}; }
ReferenceResult pair(const ref::Result<ref::RotationTranslation<Real>>& r) {
  return {r.status, {flat(r.value.q), flat(r.value.t)}};
}

Real dq_log_scale(const Values& in, std::size_t) { return rigid_scales::dq_log_scale(dq(in[0])); }

std::vector<AbiOp> build() {
  const Array q{"q", 4}, a{"a", 4}, b{"b", 4}, v{"v", 3}, t{"t", 1}, m{"m", 9}, da{"a", 8}, db{"b", 8}, d{"d", 8};
  auto out = [](const char* name, int stride, Measure measure) { return Array{name, stride, false, measure}; };
  auto influences = [](const char* name, int stride) { return Array{name, stride, true, Measure::scalar}; };
  std::vector<AbiOp> ops;
  // Rows in the op list's order: entry i describes OpId i, and its arrays are the list's.
  auto add = [&](AbiOp op) {
    const OpInfo& info = kOps.at(ops.size());
    if (op.name != info.name || op.inputs.size() != static_cast<std::size_t>(info.inputs) ||
        op.outputs.size() != static_cast<std::size_t>(info.outputs) || op.nway != (info.kind != OpKind::ELEM))
      throw std::logic_error("engine::abi_ops: entry " + std::to_string(ops.size()) + " (" + op.name +
                             ") does not match row " + std::string(info.name) + " of abi_op_list.h");
    op.id = static_cast<OpId>(ops.size());
    if (!op.scale) op.scale = unit_scale;
    ops.push_back(std::move(op));
  };

  add({"normalize", {q}, {out("out_q", 4, Measure::unit_rotation)}, false,
       [](const Values& in, std::size_t) { return one(clause::NORM_1_normalize(quat(in[0]))); }, {}});
  add({"compose", {a, b}, {out("out_q", 4, Measure::quaternion)}, false,
       [](const Values& in, std::size_t) { return one(clause::COMPOSE_1_compose(quat(in[0]), quat(in[1]))); }, {}});
  add({"inverse", {q}, {out("out_q", 4, Measure::quaternion)}, false,
       [](const Values& in, std::size_t) { return one(clause::INV_1_inverse(quat(in[0]))); }, {}});
  add({"apply_vector", {q, v}, {out("out_v", 3, Measure::vector)}, false,
       [](const Values& in, std::size_t) { return one(clause::APPLY_1_apply_vector(quat(in[0]), vec3(in[1]))); }, {}});
  add({"apply_bivector", {q, Array{"b", 3}}, {out("out_b", 3, Measure::vector)}, false,
       [](const Values& in, std::size_t) { return one(clause::APPLY_2_apply_bivector(quat(in[0]), vec3(in[1]))); }, {}});
  add({"apply_trivector", {q, Array{"s", 1}}, {out("out_s", 1, Measure::scalar)}, false,
       [](const Values& in, std::size_t) { return one(clause::APPLY_3_apply_trivector(quat(in[0]), in[1][0])); }, {}});
  add({"to_matrix", {q}, {out("out_m", 9, Measure::matrix)}, false,
       [](const Values& in, std::size_t) { return one(clause::MAT_1_to_matrix(quat(in[0]))); }, {}});
  add({"from_matrix", {m}, {out("out_q", 4, Measure::canonical_rotation)}, false,
       [](const Values& in, std::size_t) { return one(clause::MAT_2_from_matrix(mat3(in[0]))); }, {}});
  add({"to_axis_angle", {q}, {out("out_angle", 1, Measure::angle), out("out_axis", 3, Measure::vector)}, false,
       [](const Values& in, std::size_t) {
         const auto r = clause::AXANG_1_to_axis_angle(quat(in[0]));
         return ReferenceResult{r.status, {flat(r.value.angle), flat(r.value.axis)}};
       }, {}});
  add({"from_axis_angle", {Array{"angle", 1}, Array{"axis", 3}}, {out("out_q", 4, Measure::unit_rotation)}, false,
       [](const Values& in, std::size_t) { return one(clause::AXANG_2_from_axis_angle(in[0][0], vec3(in[1]))); }, {}});
  add({"log", {q}, {out("out_v", 3, Measure::bivector)}, false,
       [](const Values& in, std::size_t) { return one(clause::LOG_1_log(quat(in[0]))); }, {}});
  add({"exp", {v}, {out("out_q", 4, Measure::unit_rotation)}, false,
       [](const Values& in, std::size_t) { return one(clause::EXP_1_exp(vec3(in[0]))); }, {}});
  add({"slerp", {a, b, t}, {out("out_q", 4, Measure::unit_rotation)}, false,
       [](const Values& in, std::size_t) { return one(clause::SLERP_1_slerp(quat(in[0]), quat(in[1]), in[2][0])); }, {}});
  add({"nlerp", {a, b, t}, {out("out_q", 4, Measure::unit_rotation)}, false,
       [](const Values& in, std::size_t) { return one(clause::NLERP_1_nlerp(quat(in[0]), quat(in[1]), in[2][0])); }, {}});
  add({"blend_qlb", {influences("q", 4), influences("w", 1)}, {out("out_q", 4, Measure::unit_rotation)}, true,
       [](const Values& in, std::size_t k) {
         const auto qs = quats(in[0], k);
         return one(clause::QLB_1_blend(std::span<const Quat>(qs), std::span<const Real>(in[1])));
       }, {}});
  add({"blend_log", {influences("q", 4), influences("w", 1)}, {out("out_q", 4, Measure::unit_rotation)}, true,
       [](const Values& in, std::size_t k) {
         const auto qs = quats(in[0], k);
         return one(clause::LOGBLEND_1_blend(std::span<const Quat>(qs), std::span<const Real>(in[1])));
       }, {}});
  add({"dq_from_rotation_translation", {q, Array{"t", 3}}, {out("out_d", 8, Measure::unit_rigid)}, false,
       [](const Values& in, std::size_t) { return one(clause::DQ_1_from_rotation_translation(quat(in[0]), vec3(in[1]))); }, {}});
  add({"dq_compose", {da, db}, {out("out_d", 8, Measure::rigid)}, false,
       [](const Values& in, std::size_t) { return one(clause::DQ_2_compose(dq(in[0]), dq(in[1]))); }, {}});
  add({"dq_apply_point", {d, Array{"p", 3}}, {out("out_p", 3, Measure::point)}, false,
       [](const Values& in, std::size_t) { return one(clause::DQ_3_apply_point(dq(in[0]), vec3(in[1]))); },
       [](const Values& in, std::size_t) { return rigid_scale(dq(in[0]), vec3(in[1])); }});
  add({"dq_normalize", {d}, {out("out_d", 8, Measure::unit_rigid)}, false,
       [](const Values& in, std::size_t) { return one(clause::DQ_4_normalize(dq(in[0]))); }, {}});
  add({"dq_sclerp", {da, db, t}, {out("out_d", 8, Measure::unit_rigid)}, false,
       [](const Values& in, std::size_t) { return one(clause::DQ_5_sclerp(dq(in[0]), dq(in[1]), in[2][0])); }, {}});
  add({"dq_blend", {influences("d", 8), influences("w", 1)}, {out("out_d", 8, Measure::unit_rigid)}, true,
       [](const Values& in, std::size_t k) {
         const auto ds = dqs(in[0], k);
         return one(clause::DQ_6_dlb(std::span<const DQ>(ds), std::span<const Real>(in[1])));
       }, {}});
  add({"rotate_about_axis", {Array{"c", 3}, Array{"u", 3}, Array{"angle", 1}, Array{"p", 3}},
       {out("out_p", 3, Measure::point)}, false,
       [](const Values& in, std::size_t) {
         return one(clause::AXIS_1_rotate_about_line(vec3(in[0]), vec3(in[1]), in[2][0], vec3(in[3])));
       },
       [](const Values& in, std::size_t) {
         return std::max({Real(1), length_of(in[0], 0), length_of(in[3], 0)});
       }});
  auto skin_scale = [](const Values& in, std::size_t k) {
    Real s = std::max(Real(1), length_of(in[3], 0));
    for (std::size_t i = 0; i < k; ++i) s = std::max(s, length_of(in[1], i));
    return s;
  };
  add({"skin_linear", {influences("q", 4), influences("t", 3), influences("w", 1), Array{"v", 3}},
       {out("out_v", 3, Measure::point)}, true,
       [](const Values& in, std::size_t k) {
         const auto qs = quats(in[0], k);
         const auto ts = vec3s(in[1], k);
         return one(clause::SKIN_1_linear_blend(std::span<const Quat>(qs), std::span<const V3>(ts),
                                                std::span<const Real>(in[2]), vec3(in[3])));
       },
       skin_scale});
  add({"skin_dual_quaternion", {influences("q", 4), influences("t", 3), influences("w", 1), Array{"v", 3}},
       {out("out_v", 3, Measure::point)}, true,
       [](const Values& in, std::size_t k) {
         const auto qs = quats(in[0], k);
         const auto ts = vec3s(in[1], k);
         return one(clause::SKIN_2_dual_quaternion(std::span<const Quat>(qs), std::span<const V3>(ts),
                                                   std::span<const Real>(in[2]), vec3(in[3])));
       },
       skin_scale});
  // ---- ABI version 3 ----
  add({"to_angle", {q}, {out("out_angle", 1, Measure::angle)}, false,
       [](const Values& in, std::size_t) {
         const auto r = clause::AXANG_1_to_axis_angle(quat(in[0]));  // AXANG-3: AXANG-1's angle
         return ReferenceResult{r.status, {flat(r.value.angle)}};
       }, {}});
  add({"to_axis", {q}, {out("out_axis", 3, Measure::vector)}, false,
       [](const Values& in, std::size_t) {
         const auto r = clause::AXANG_1_to_axis_angle(quat(in[0]));  // AXANG-4: AXANG-1's axis
         return ReferenceResult{r.status, {flat(r.value.axis)}};
       }, {}});
  add({"sqrt", {q}, {out("out_q", 4, Measure::canonical_rotation)}, false,
       [](const Values& in, std::size_t) { return one(clause::SQRT_1_sqrt(quat(in[0]))); }, {}});
  add({"dq_to_rotation_translation", {d}, {out("out_q", 4, Measure::unit_rotation), out("out_t", 3, Measure::point)},
       false,
       [](const Values& in, std::size_t) { return pair(clause::DQ_7_to_rotation_translation(dq(in[0]))); },
       [](const Values& in, std::size_t) { return rigid_scales::dq_translation_scale(dq(in[0])); }});
  // ---- ABI version 4 ----
  const Array xi{"xi", 6}, rq{"q", 4}, rt{"t", 3};
  add({"dq_log", {d}, {out("out_xi", 6, Measure::point)}, false,
       [](const Values& in, std::size_t) {
         const auto r = clause::DQ_8_log(dq(in[0]));
         return ReferenceResult{r.status, {join(flat(r.value.real), flat(r.value.dual))}};
       },
       dq_log_scale});
  add({"dq_exp", {xi}, {out("out_d", 8, Measure::dual_parts)}, false,
       [](const Values& in, std::size_t) { return one(clause::DQ_9_exp(dual_vector(in[0]))); },
       // DQ-9: the dual part carries the rounding of xi_d, which near b = pi (sin b -> 0) can be
       // far larger than the output's translation.
       [](const Values& in, std::size_t) { return std::max(Real(1), length_of(in[0], 1)); }});
  add({"rigid_compose", {Array{"qa", 4}, Array{"ta", 3}, Array{"qb", 4}, Array{"tb", 3}},
       {out("out_q", 4, Measure::unit_rotation), out("out_t", 3, Measure::point)}, false,
       [](const Values& in, std::size_t) {
         return pair(clause::RIGID_1_compose(quat(in[0]), vec3(in[1]), quat(in[2]), vec3(in[3])));
       },
       [](const Values& in, std::size_t) { return std::max({Real(1), length_of(in[1], 0), length_of(in[3], 0)}); }});
  add({"rigid_apply", {rq, rt, Array{"p", 3}}, {out("out_p", 3, Measure::point)}, false,
       [](const Values& in, std::size_t) { return one(clause::RIGID_2_apply(quat(in[0]), vec3(in[1]), vec3(in[2]))); },
       [](const Values& in, std::size_t) { return std::max({Real(1), length_of(in[1], 0), length_of(in[2], 0)}); }});
  add({"rigid_inverse", {rq, rt}, {out("out_q", 4, Measure::unit_rotation), out("out_t", 3, Measure::point)}, false,
       [](const Values& in, std::size_t) { return pair(clause::RIGID_3_inverse(quat(in[0]), vec3(in[1]))); },
       [](const Values& in, std::size_t) { return std::max(Real(1), length_of(in[1], 0)); }});
  if (ops.size() != kOpCount) throw std::logic_error("engine::abi_ops: fewer entries than abi_op_list.h has rows");
  return ops;
}

// ---- calling a table --------------------------------------------------------------------

/// Calls op through the slot the op list (abi_op_list.h) gives it. An appended struct is read
/// only from a table whose abi_version is at least the one that added it (an older table's memory
/// ends before it): with_slot sees to that.
template <class S>
int dispatch(const rc_impl& table, const AbiOp& op, std::size_t n, std::size_t k, const std::vector<const void*>& in,
             const std::vector<void*>& out, std::uint8_t* status) {
  const OpInfo& info = op_info(op.id);
  if (in.size() != static_cast<std::size_t>(info.inputs) || out.size() != static_cast<std::size_t>(info.outputs))
    throw std::logic_error("engine::call: " + op.name + " takes " + std::to_string(info.inputs) + " input and " +
                           std::to_string(info.outputs) + " output arrays");
  std::vector<const S*> ins;
  std::vector<S*> outs;
  for (const void* p : in) ins.push_back(static_cast<const S*>(p));
  for (void* p : out) outs.push_back(static_cast<S*>(p));
  const SlotArgs<S> args{n, k, ins.data(), outs.data(), status};
  return with_slot<S>(table, op.id, [&](auto fn) { return fn == nullptr ? -1 : invoke_slot(fn, args); });
}

}  // namespace

const std::vector<AbiOp>& abi_ops() {
  static const std::vector<AbiOp> ops = build();
  return ops;
}

const AbiOp* find_abi_op(const std::string& name) {
  for (const AbiOp& op : abi_ops())
    if (op.name == name) return &op;
  return nullptr;
}

const AbiOp& judged_op(const std::string& clause, const std::string& op) {
  const AbiOp* d = find_abi_op(op);
  if (d == nullptr) throw std::logic_error("no ABI op " + op);
  if (clause == "SLERP-3" && op == "slerp") {
    // slerp(a, b, 0) = a and slerp(a, b, 1) = b', the hemisphere-aligned b: -b' is a FAIL.
    static const AbiOp endpoints = [d] {
      AbiOp o = *d;
      o.outputs[0].measure = Measure::signed_unit_rotation;
      return o;
    }();
    return endpoints;
  }
  return *d;
}

int call(const rc_impl& table, const std::string& op, std::size_t n, std::size_t k,
         const std::vector<const void*>& in, const std::vector<void*>& out, std::uint8_t* status) {
  const AbiOp* desc = find_abi_op(op);
  if (desc == nullptr) return -1;
  if (table.scalar == RC_SCALAR_FLOAT32) return dispatch<float>(table, *desc, n, k, in, out, status);
  if (table.scalar == RC_SCALAR_FLOAT64) return dispatch<double>(table, *desc, n, k, in, out, status);
  return -1;
}

Real block_norm(const std::vector<Real>& v, std::size_t from, std::size_t n) {
  Real s(0);
  for (std::size_t i = from; i < from + n && i < v.size(); ++i) s += v[i] * v[i];
  return sqrt(s);
}

bool is_axis_input(const AbiOp& op, const Array& a) {
  return (op.name == "from_axis_angle" && a.name == "axis") || (op.name == "rotate_about_axis" && a.name == "u");
}

Real orthogonality_defect(const std::vector<Real>& m) {
  ref::Mat3<Real> a;
  std::copy(m.begin(), m.begin() + 9, a.begin());
  return ref::clause::MAT_3_orthogonality_defect(a);
}

bool supports(const rc_impl& table, const std::string& op) {
  const AbiOp* desc = find_abi_op(op);
  return desc != nullptr && has_op(table, desc->id);  // reads the slot only: runs no plugin code
}

}  // namespace rotorcert::engine
