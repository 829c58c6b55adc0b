// Which technique a table supports, read from its ABI functions (method.hpp).
#include <rotorcert/render/method.hpp>

#include <algorithm>

namespace rotorcert::render {

namespace {

/// The non-NULL-ness of every op a method may call, for either scalar type.
struct Offered {
  bool normalize, compose, apply_vector, to_matrix, slerp, nlerp, blend_qlb;
  bool dq_from_rt, dq_compose, dq_apply_point, dq_normalize, dq_sclerp, dq_blend, skin_dq;
};

template <class Ops>
Offered offered_of(const Ops& o) {
  return {o.normalize != nullptr,  o.compose != nullptr,   o.apply_vector != nullptr,
          o.to_matrix != nullptr,  o.slerp != nullptr,     o.nlerp != nullptr,
          o.blend_qlb != nullptr,  o.dq_from_rotation_translation != nullptr,
          o.dq_compose != nullptr, o.dq_apply_point != nullptr, o.dq_normalize != nullptr,
          o.dq_sclerp != nullptr,  o.dq_blend != nullptr,  o.skin_dual_quaternion != nullptr};
}

Offered offered(const rc_impl& t) {
  if (t.scalar == RC_SCALAR_FLOAT32 && t.f32 != nullptr) return offered_of(*t.f32);
  if (t.scalar == RC_SCALAR_FLOAT64 && t.f64 != nullptr) return offered_of(*t.f64);
  return {};
}

void add_if(std::string& out, bool missing, const char* what) {
  if (!missing) return;
  if (!out.empty()) out += ", ";
  out += what;
}

}  // namespace

const char* to_string(Technique t) { return t == Technique::lbs ? "LBS" : "DQS"; }

const char* to_string(PoseBlend b) {
  switch (b) {
    case PoseBlend::none: return "none";
    case PoseBlend::qlb: return "blend_qlb";
    case PoseBlend::nlerp: return "nlerp";
    case PoseBlend::dlb: return "dq_blend";
    case PoseBlend::sclerp: return "dq_sclerp";
  }
  return "none";
}

std::string missing_ops(const rc_impl& table, Technique technique) {
  const Offered o = offered(table);
  std::string out;
  if (technique == Technique::lbs) {
    add_if(out, !o.slerp, "slerp");
    add_if(out, !o.compose, "compose");
    add_if(out, !o.apply_vector, "apply_vector");
    add_if(out, !o.to_matrix, "to_matrix");
  } else {
    add_if(out, !o.slerp && !o.dq_sclerp, "slerp or dq_sclerp");
    add_if(out, !o.dq_from_rt, "dq_from_rotation_translation");
    add_if(out, !o.dq_compose, "dq_compose");
    add_if(out, !o.skin_dq && !(o.dq_blend && o.dq_apply_point), "skin_dual_quaternion or dq_blend + dq_apply_point");
  }
  return out;
}

SkinningMethod make_method(const rc_impl& table, Technique technique) {
  const std::string missing = missing_ops(table, technique);
  if (!missing.empty())
    throw std::invalid_argument(std::string(table.name) + " cannot do " + to_string(technique) + ": no " + missing);
  return {&table, technique};
}

std::vector<SkinningMethod> skinning_methods(std::span<const rc_impl* const> tables) {
  std::vector<SkinningMethod> out;
  for (Technique t : {Technique::lbs, Technique::dqs})
    for (const rc_impl* table : tables)
      if (table != nullptr && missing_ops(*table, t).empty()) out.push_back({table, t});
  return out;
}

std::string SkinningMethod::name() const {
  return std::string(table->name) + (is_float() ? " float " : " double ") + to_string(technique);
}

double SkinningMethod::epsilon() const { return is_float() ? 0x1p-23 : 0x1p-52; }

KeyInterpolation SkinningMethod::key_interpolation() const {
  return offered(*table).slerp ? KeyInterpolation::slerp : KeyInterpolation::sclerp;
}

PoseBlend SkinningMethod::pose_blend() const {
  const Offered o = offered(*table);
  if (technique == Technique::lbs) return o.blend_qlb ? PoseBlend::qlb : o.nlerp ? PoseBlend::nlerp : PoseBlend::none;
  return o.dq_blend ? PoseBlend::dlb : o.dq_sclerp ? PoseBlend::sclerp : PoseBlend::none;
}

DqsRoute SkinningMethod::dqs_route() const {
  // The dual quaternions stay the method's own from pose to vertex; skin_dual_quaternion takes
  // (q, t) pairs, so it needs the translations read back from them first.
  const Offered o = offered(*table);
  return o.dq_blend && o.dq_apply_point ? DqsRoute::blend_and_apply : DqsRoute::skin_dual_quaternion;
}

std::vector<std::string> SkinningMethod::clauses() const {
  std::vector<std::string> c;
  c.push_back(key_interpolation() == KeyInterpolation::slerp ? "SLERP-1" : "DQ-5");
  // Keyframes are binary32 roundings of unit quaternions and no result is renormalised along
  // the chain, so every op receives quaternions of norm 1 +- a few eps: the rotation of q/|q|.
  c.push_back("EDGE-5");
  if (technique == Technique::lbs) {
    c.insert(c.end(), {"COMPOSE-1", "APPLY-1", "MAT-1"});  // the matrix blend is the suite's
  } else {
    c.insert(c.end(), {"DQ-1", "DQ-2"});
    if (dqs_route() == DqsRoute::blend_and_apply) c.insert(c.end(), {"DQ-6", "DQ-3"});
    else c.push_back("SKIN-2");
  }
  return c;
}

std::vector<std::string> SkinningMethod::unclaimed() const {
  std::vector<std::string> out;
  for (const std::string& c : clauses()) {
    bool claimed = false;
    for (const char* const* p = table->clauses; p != nullptr && *p != nullptr; ++p) claimed = claimed || c == *p;
    if (!claimed) out.push_back(c);
  }
  return out;
}

}  // namespace rotorcert::render
