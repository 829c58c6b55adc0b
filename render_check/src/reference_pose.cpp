// The 256-bit reference pose and skin (reference_pose.hpp).
#include <rotorcert/render/reference_pose.hpp>

#include <algorithm>
#include <stdexcept>

#include <rotorcert/reference/rigid_ops.hpp>
#include <rotorcert/reference/rotation_ops.hpp>
#include <rotorcert/render/sample.hpp>

namespace rotorcert::render {

namespace {

using ref::Real;
using RQ = ref::Quaternion<Real>;
using RV = ref::Vec3<Real>;
using RM = ref::Mat3<Real>;
namespace clause = ref::clause;

RQ rq(const Quat& q) { return RQ::from_xyzw({Real(q[0]), Real(q[1]), Real(q[2]), Real(q[3])}); }
RV rv(const Vec3& v) { return {Real(v[0]), Real(v[1]), Real(v[2])}; }
RM rm(const Mat3& m) {
  RM r;
  for (std::size_t i = 0; i < 9; ++i) r[i] = Real(m[i]);
  return r;
}
RM identity() { return rm(identity3()); }

template <class V>
V value(const ref::Result<V>& r, const char* what) {
  if (r.status != ref::Status::ok) throw std::invalid_argument(std::string("reference pose: ") + what + " is outside its domain");
  return r.value;
}

RM mul(const RM& a, const RM& b) { return pose_math::mul3(a, b); }
RV mul(const RM& a, const RV& v) { return pose_math::mul3v(a, v); }
RM transpose(const RM& a) { return pose_math::transpose3(a); }
RV add(const RV& a, const RV& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }

struct Stretch {
  RM k = identity();
  bool stretched = false;
};

/// K_child = R(q)^T K_parent R(q) K_local, as PoseJob (pose_job.hpp) at the reference precision.
Stretch child_stretch(const Stretch& parent, const RQ& q, const Stretch& local) {
  if (!parent.stretched) return local;
  const RM r = value(clause::MAT_1_to_matrix(q), "a rotation");
  return {mul(mul(transpose(r), mul(parent.k, r)), local.k), true};
}

RV stretched(const Stretch& k, const RV& t) { return k.stretched ? mul(k.k, t) : t; }

/// A local transform read as PoseJob reads it (rotation by the reference, the rest in binary64).
struct Local {
  RQ q;
  Vec3 t{0.0, 0.0, 0.0};
  Vec3 s{1.0, 1.0, 1.0};
  const JointTransform* matrix = nullptr;
};

Stretch local_stretch(const Local& l) {
  if (l.matrix != nullptr) return {rm(l.matrix->stretch), l.matrix->stretched};
  return {rm({l.s[0], 0.0, 0.0, 0.0, l.s[1], 0.0, 0.0, 0.0, l.s[2]}), !(l.s[0] == 1.0 && l.s[1] == 1.0 && l.s[2] == 1.0)};
}

std::vector<Local> sample(const Rig& rig, const PoseSample& ps) {
  const Skeleton& sk = *rig.skeleton;
  const std::size_t n = sk.joints.size();
  std::vector<Local> out(n);
  for (std::size_t j = 0; j < n; ++j) {
    if (rig.matrix_local[j]) {
      out[j].matrix = &*rig.matrix_local[j];
      out[j].q = rq(out[j].matrix->rotation);
      out[j].t = out[j].matrix->translation;
    } else {
      out[j].q = rq(sk.joints[j].rest.rotation);
      out[j].t = sk.joints[j].rest.translation;
      out[j].s = sk.joints[j].rest.scale;
    }
  }
  if (ps.clip == nullptr) return out;
  const Clip& clip = *ps.clip;
  const double tc = std::clamp(ps.time, clip.start, std::max(clip.start, clip.end));
  for (const Channel& ch : clip.channels) {
    if (ch.joint >= n) continue;
    if (ch.path != ChannelPath::rotation) {
      const auto v = sample_channel(ch, tc);
      (ch.path == ChannelPath::translation ? out[ch.joint].t : out[ch.joint].s) = Vec3{v[0], v[1], v[2]};
      continue;
    }
    const pose_math::KeyLocation loc = pose_math::locate(ch, tc);
    switch (loc.kind) {
      case pose_math::KeyLocation::key: out[ch.joint].q = rq(pose_math::key_quat(ch, loc.k)); break;
      case pose_math::KeyLocation::linear:
        out[ch.joint].q = value(clause::SLERP_1_slerp(rq(pose_math::key_quat(ch, loc.k)),
                                                      rq(pose_math::key_quat(ch, loc.k + 1)), Real(loc.s)),
                                "slerp of keyframes");
        break;
      case pose_math::KeyLocation::cubic:
        out[ch.joint].q = value(clause::NORM_1_normalize(rq(pose_math::hermite_rotation(ch, loc))), "a Hermite sum");
        break;
    }
  }
  return out;
}

}  // namespace

ReferencePose reference_pose(const Rig& rig, const PoseRequest& request, PoseBlend blend) {
  if (mpfr::mpreal::get_default_prec() < ref::kReferenceBits)
    throw std::logic_error("reference_pose: call rotorcert::ref::use_reference_precision() first (NUM-2)");
  if (request.b && blend == PoseBlend::none) throw std::invalid_argument("reference_pose: a blend needs a rule");
  const Skeleton& sk = *rig.skeleton;
  const std::size_t n = sk.joints.size();
  std::vector<Local> a = sample(rig, request.a), b;
  const bool rigid_blend = request.b && (blend == PoseBlend::dlb || blend == PoseBlend::sclerp);
  if (request.b) {
    b = sample(rig, *request.b);
    const double al = request.alpha;
    for (std::size_t j = 0; j < n; ++j) {
      if (!rigid_blend) {
        const std::array<RQ, 2> q{a[j].q, b[j].q};
        const std::array<Real, 2> w{Real(1.0 - al), Real(al)};
        a[j].q = value(clause::QLB_1_blend<Real>(q, w), "the pose blend");
      }
      for (std::size_t i = 0; i < 3; ++i) {
        if (!rigid_blend) a[j].t[i] = (1.0 - al) * a[j].t[i] + al * b[j].t[i];  // binary64, as PoseJob
        a[j].s[i] = (1.0 - al) * a[j].s[i] + al * b[j].s[i];
      }
    }
  }
  ReferencePose pose;
  pose.globals.resize(n);
  std::vector<Stretch> gk(n);
  for (const auto& level : rig.levels)
    for (std::size_t j : level) {
      const int p = sk.joints[j].parent;
      const Stretch parent_k = p < 0 ? Stretch{} : gk[static_cast<std::size_t>(p)];
      RQ q = a[j].q;
      RV u = stretched(parent_k, rv(a[j].t));
      if (rigid_blend) {
        // The local rigid motions with their K_p-stretched translations, blended as DQS methods do.
        const auto da = value(clause::DQ_1_from_rotation_translation(a[j].q, u), "a local motion");
        const auto db = value(clause::DQ_1_from_rotation_translation(b[j].q, stretched(parent_k, rv(b[j].t))), "a local motion");
        ref::DualQuaternion<Real> d;
        if (blend == PoseBlend::dlb) {
          const std::array<ref::DualQuaternion<Real>, 2> ds{da, db};
          const std::array<Real, 2> w{Real(1.0 - request.alpha), Real(request.alpha)};
          d = value(clause::DQ_6_dlb<Real>(ds, w), "the pose blend");
        } else {
          d = value(clause::DQ_5_sclerp(da, db, Real(request.alpha)), "the pose blend");
        }
        q = d.real;
        u = value(clause::DQ_1_translation(d), "the pose blend");
      }
      RefTransform& g = pose.globals[j];
      gk[j] = child_stretch(parent_k, q, local_stretch(a[j]));
      if (p < 0) {
        g.rotation = q;
        g.translation = u;
      } else {
        const RefTransform& pg = pose.globals[static_cast<std::size_t>(p)];
        g.rotation = value(clause::COMPOSE_1_compose(pg.rotation, q), "compose");
        g.translation = add(pg.translation, value(clause::APPLY_1_apply_vector(pg.rotation, u), "apply_vector"));
      }
      g.stretch = gk[j].k;
      g.stretched = gk[j].stretched;
    }
  pose.skinning.resize(n);
  for (std::size_t j = 0; j < n; ++j) {
    const JointTransform& ib = rig.inverse_bind[j];
    const RefTransform& g = pose.globals[j];
    RefTransform& s = pose.skinning[j];
    const Stretch k = child_stretch({g.stretch, g.stretched}, rq(ib.rotation), {rm(ib.stretch), ib.stretched});
    s.rotation = value(clause::COMPOSE_1_compose(g.rotation, rq(ib.rotation)), "compose");
    s.translation = add(g.translation, value(clause::APPLY_1_apply_vector(g.rotation, stretched({g.stretch, g.stretched}, rv(ib.translation))), "apply_vector"));
    s.stretch = k.k;
    s.stretched = k.stretched;
  }
  return pose;
}

namespace {

/// Per-joint data of the reference skin, computed once per pose and technique.
struct JointSkin {
  RM a;                              // LBS: MAT_1(q) K
  ref::DualQuaternion<Real> motion;  // DQS: DQ_1(q, t)
};

std::vector<JointSkin> joint_skin(const ReferencePose& pose, Technique technique) {
  std::vector<JointSkin> out(pose.skinning.size());
  for (std::size_t j = 0; j < out.size(); ++j) {
    const RefTransform& x = pose.skinning[j];
    if (technique == Technique::lbs) {
      const RM r = value(clause::MAT_1_to_matrix(x.rotation), "to_matrix");
      out[j].a = x.stretched ? mul(r, x.stretch) : r;
    } else {
      out[j].motion = value(clause::DQ_1_from_rotation_translation(x.rotation, x.translation), "a skinning motion");
    }
  }
  return out;
}

std::array<Real, 4> unit_weights(const SkinnedMesh& mesh, std::size_t v) {
  std::array<Real, 4> w;
  Real total(0);
  for (std::size_t k = 0; k < 4; ++k) total += w[k] = Real(mesh.weights[v][k]);
  for (auto& x : w) x /= total;
  return w;
}

RV stretched_vertex(const ReferencePose& pose, const SkinnedMesh& mesh, std::size_t v, const std::array<Real, 4>& w,
                    const RV& x) {
  RV r{Real(0), Real(0), Real(0)};
  for (std::size_t k = 0; k < 4; ++k) {
    const RefTransform& xj = pose.skinning[mesh.joints[v][k]];
    const RV y = stretched({xj.stretch, xj.stretched}, x);
    for (std::size_t i = 0; i < 3; ++i) r[i] += w[k] * y[i];
  }
  return r;
}

/// Position and normal of vertex v (normal not yet unit).
std::pair<RV, RV> skin_vertex(const ReferencePose& pose, const std::vector<JointSkin>& js, const SkinnedMesh& mesh,
                              std::size_t v, Technique technique) {
  const auto w = unit_weights(mesh, v);
  const RV p = rv(mesh.positions[v]), nrm = rv(mesh.normals[v]);
  if (technique == Technique::lbs) {
    RV pos{Real(0), Real(0), Real(0)}, nor{Real(0), Real(0), Real(0)};
    for (std::size_t k = 0; k < 4; ++k) {
      const std::size_t j = mesh.joints[v][k];
      const RV ap = mul(js[j].a, p), an = mul(js[j].a, nrm);
      for (std::size_t i = 0; i < 3; ++i) {
        pos[i] += w[k] * (ap[i] + pose.skinning[j].translation[i]);
        nor[i] += w[k] * an[i];
      }
    }
    return {pos, nor};
  }
  std::array<ref::DualQuaternion<Real>, 4> d;
  for (std::size_t k = 0; k < 4; ++k) d[k] = js[mesh.joints[v][k]].motion;
  const auto blended = value(clause::DQ_6_dlb<Real>(d, w), "the vertex blend");
  const RV pos = value(clause::DQ_3_apply_point(blended, stretched_vertex(pose, mesh, v, w, p)), "dq_apply_point");
  const RV nor = value(clause::APPLY_1_apply_vector(blended.real, stretched_vertex(pose, mesh, v, w, nrm)), "apply_vector");
  return {pos, nor};
}

}  // namespace

ref::Vec3<Real> reference_position(const ReferencePose& pose, const SkinnedMesh& mesh, std::size_t v, Technique technique) {
  return skin_vertex(pose, joint_skin(pose, technique), mesh, v, technique).first;
}

SkinOutput reference_skin(const ReferencePose& pose, const SkinnedMesh& mesh, Technique technique) {
  const std::vector<JointSkin> js = joint_skin(pose, technique);
  SkinOutput out;
  const std::size_t nv = mesh.positions.size();
  out.positions.resize(nv);
  out.normals.resize(nv);
  for (std::size_t v = 0; v < nv; ++v) {
    const auto [p, nrm] = skin_vertex(pose, js, mesh, v, technique);
    const Real len = sqrt(nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2]);
    for (std::size_t i = 0; i < 3; ++i) {
      out.positions[v][i] = p[i].toDouble();
      out.normals[v][i] = (nrm[i] / len).toDouble();
    }
  }
  return out;
}

std::vector<Vec3> reference_virtual_vertices(const ReferencePose& pose, std::span<const std::size_t> joints, double offset) {
  std::vector<Vec3> out;
  out.reserve(3 * joints.size());
  for (std::size_t j : joints) {
    const RefTransform& g = pose.globals.at(j);
    const RM r = value(clause::MAT_1_to_matrix(g.rotation), "to_matrix");
    const RM a = g.stretched ? mul(r, g.stretch) : r;
    for (std::size_t axis = 0; axis < 3; ++axis) {
      RV e{Real(0), Real(0), Real(0)};
      e[axis] = Real(offset);
      const RV x = add(mul(a, e), g.translation);
      out.push_back({x[0].toDouble(), x[1].toDouble(), x[2].toDouble()});
    }
  }
  return out;
}

std::vector<JointTransform> to_binary64(const std::vector<RefTransform>& transforms) {
  std::vector<JointTransform> out(transforms.size());
  for (std::size_t j = 0; j < out.size(); ++j) {
    const RefTransform& x = transforms[j];
    const auto q = x.rotation.xyzw();
    for (std::size_t i = 0; i < 4; ++i) out[j].rotation[i] = q[i].toDouble();
    for (std::size_t i = 0; i < 3; ++i) out[j].translation[i] = x.translation[i].toDouble();
    for (std::size_t i = 0; i < 9; ++i) out[j].stretch[i] = x.stretch[i].toDouble();
    out[j].stretched = x.stretched;
  }
  return out;
}

}  // namespace rotorcert::render
