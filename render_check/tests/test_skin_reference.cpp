// The reference pose and skin (reference_pose.hpp) against facts that do not depend on it: the
// bind pose of the built-in characters (CHAR-1), the rigid cases of SKIN-3 through the
// reference's own clause functions, and glTF's definition of skinning evaluated independently in
// binary64 with 4x4 matrices (GLTF-2, sample.hpp).
#include <cmath>
#include <cstdio>
#include <filesystem>

#include <gtest/gtest.h>

#include <rotorcert/reference/metrics.hpp>
#include <rotorcert/reference/rigid_ops.hpp>
#include <rotorcert/render/gltf_load.hpp>
#include <rotorcert/render/sample.hpp>
#include <rotorcert/render/transform.hpp>
#include <rotorcert/testing/clause.hpp>

#include "test_skin_support.hpp"

namespace {

using namespace rotorcert::render;
using namespace rotorcert::render::skin_test;
using rotorcert::ref::Real;
namespace clause = rotorcert::ref::clause;

constexpr double kEps32 = 0x1p-23;  // binary32 (NUM-1): the precision of the glTF FLOAT data
constexpr double kEps64 = 0x1p-52;

const std::array<Complexity, 3> kAll = {Complexity::simple, Complexity::medium, Complexity::full};

/// SKIN-1's scale for vertex v: max(1, |v|, max |t_k|) over its influences.
double skin_scale(const SkinnedMesh& m, std::size_t v, const std::vector<JointTransform>& skinning) {
  double s = std::max(1.0, std::hypot(m.positions[v][0], m.positions[v][1], m.positions[v][2]));
  for (std::size_t k = 0; k < 4; ++k) {
    const Vec3& t = skinning[m.joints[v][k]].translation;
    s = std::max(s, std::hypot(t[0], t[1], t[2]));
  }
  return s;
}

// At rest, global * inverse bind is the identity up to the binary32 rounding of the inverse bind
// matrices, so both reference deformations give back the bind positions and normals within one
// rounding: eps4 of binary32 (CHAR-1's bar for a single rounding).
TEST(SkinReference, RestPoseReproducesTheBindPose) {
  RC_CLAUSE("CHAR-1");
  const double bar = rotorcert::testing::eps_class_bars("eps4").strict * kEps32;
  for (Complexity c : kAll) {
    const Character& ch = character(c);
    const SkinnedMesh& mesh = ch.scene.meshes.at(0);
    const ReferencePose rp = reference_pose(ch.rig, PoseRequest{});
    const auto skinning = to_binary64(rp.skinning);
    for (std::size_t j : ch.rig.skeleton->skin_joints) {
      const Real d = rotorcert::ref::clause::METRIC_1_rotation_distance(rp.skinning[j].rotation,
                                                                        rotorcert::ref::Quaternion<Real>::identity());
      EXPECT_LE(d.toDouble(), bar) << to_string(c) << " joint " << ch.rig.skeleton->joints[j].name;
    }
    for (Technique k : {Technique::lbs, Technique::dqs}) {
      const SkinOutput out = reference_skin(rp, mesh, k);
      double worst = 0;
      for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        const Vec3 &p = out.positions[v], &b = mesh.positions[v];
        worst = std::max(worst, std::hypot(p[0] - b[0], p[1] - b[1], p[2] - b[2]) / skin_scale(mesh, v, skinning));
        const Vec3 &n = out.normals[v], &nb = mesh.normals[v];
        EXPECT_LE(std::hypot(n[0] - nb[0], n[1] - nb[1], n[2] - nb[2]), bar) << to_string(c) << " normal " << v;
      }
      std::printf("%s %s at rest: worst %.2f eps32 (bar %.0f)\n", to_string(c), to_string(k), worst / kEps32, bar / kEps32);
      EXPECT_LE(worst, bar) << to_string(c) << " " << to_string(k);
    }
  }
}

// A vertex with a single influence: LBS and DQS both give the rigid motion of that joint, and
// the reference skin agrees with the reference's clause functions SKIN_1 and SKIN_2 (on the
// stretched vertex K v), at the reference precision.
TEST(SkinReference, SingleInfluenceIsRigid) {
  RC_CLAUSE("SKIN-3");
  const Character& ch = character(Complexity::medium);
  const SkinnedMesh& mesh = ch.scene.meshes.at(0);
  const Real bar = rotorcert::testing::ref_class_bar();
  std::size_t checked = 0;
  for (const char* name : {"bend", "twist"}) {
    const Clip& clip = clip_named(ch.scene, name);
    PoseRequest req;
    req.a = {&clip, 0.77 * clip.end};
    const ReferencePose rp = reference_pose(ch.rig, req);
    for (std::size_t v = 0; v < mesh.positions.size(); v += 7) {  // every 7th vertex: the MPFR cost
      int influences = 0;
      std::size_t k1 = 0;
      for (std::size_t k = 0; k < 4; ++k)
        if (mesh.weights[v][k] > 0) {
          ++influences;
          k1 = k;
        }
      if (influences != 1) continue;
      const RefTransform& x = rp.skinning[mesh.joints[v][k1]];
      rotorcert::ref::Vec3<Real> p{Real(mesh.positions[v][0]), Real(mesh.positions[v][1]), Real(mesh.positions[v][2])};
      if (x.stretched) {
        rotorcert::ref::Vec3<Real> s{Real(0), Real(0), Real(0)};
        for (std::size_t r = 0; r < 3; ++r)
          for (std::size_t c = 0; c < 3; ++c) s[r] += x.stretch[3 * c + r] * p[c];
        p = s;
      }
      const std::array<rotorcert::ref::Quaternion<Real>, 1> q{x.rotation};
      const std::array<rotorcert::ref::Vec3<Real>, 1> t{x.translation};
      const std::array<Real, 1> w{Real(1)};
      const auto lbs = clause::SKIN_1_linear_blend<Real>(q, t, w, p);
      const auto dqs = clause::SKIN_2_dual_quaternion<Real>(q, t, w, p);
      ASSERT_EQ(lbs.status, rotorcert::ref::Status::ok);
      ASSERT_EQ(dqs.status, rotorcert::ref::Status::ok);
      const auto mine_lbs = reference_position(rp, mesh, v, Technique::lbs);
      const auto mine_dqs = reference_position(rp, mesh, v, Technique::dqs);
      for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_LE(abs(lbs.value[i] - dqs.value[i]), bar) << "vertex " << v;
        EXPECT_LE(abs(mine_lbs[i] - lbs.value[i]), bar) << "vertex " << v;
        EXPECT_LE(abs(mine_dqs[i] - dqs.value[i]), bar) << "vertex " << v;
      }
      ++checked;
    }
  }
  EXPECT_GT(checked, 10u);  // the medium character has many single-influence vertices
}

/// sample.hpp's binary64 slerp of the normalised keyframes. render::slerp normalises its inputs
/// too (SLERP-1); normalising here as well keeps this independent route explicit: binary32
/// keyframes are unit only to about 2^-24, and unnormalised they would differ from SLERP-1 (the
/// rotation of q/|q|, EDGE-5) by ~1e-8 rad, 1e5 eps64 at a fingertip.
Quat unit_slerp(const Quat& a, const Quat& b, double s) {
  auto unit = [](const Quat& q) {
    const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    return Quat{q[0] / n, q[1] / n, q[2] / n, q[3] / n};
  };
  return slerp(unit(a), unit(b), s);
}

/// glTF's skinning in binary64, independently of PoseJob and the reference: sample.hpp's pose
/// (with its binary64 slerp), 4x4 global and skinning matrices, sum (w/W) M p.
std::vector<Vec3> gltf_binary64_skin(const Scene& s, const SkinnedMesh& mesh, const PoseSample& ps) {
  const auto local = ps.clip != nullptr ? sample_pose(s.skeleton, *ps.clip, ps.time, unit_slerp) : rest_pose(s.skeleton);
  const auto skin = skinning_matrices(s.skeleton, global_matrices(s.skeleton, local));
  std::vector<Vec3> out(mesh.positions.size());
  for (std::size_t v = 0; v < out.size(); ++v) {
    double total = 0;
    for (std::size_t k = 0; k < 4; ++k) total += mesh.weights[v][k];
    Vec3 p{0, 0, 0};
    for (std::size_t k = 0; k < 4; ++k) {
      const Vec3 x = transform_point(skin[mesh.joints[v][k]], mesh.positions[v]);
      for (std::size_t i = 0; i < 3; ++i) p[i] += mesh.weights[v][k] / total * x[i];
    }
    out[v] = p;
  }
  return out;
}

/// Worst |reference LBS - glTF binary64 route| in eps64 units of the character's size, over the
/// frames of every clip, and the bound of a binary64 LBS chain.
void expect_matches_gltf(const std::string& what, const Scene& s, const Rig& rig) {
  const SkinnedMesh& mesh = s.meshes.at(0);
  const double bar = chain_bars(Technique::lbs, KeyInterpolation::slerp, chain_length(rig)).strict;
  for (const Clip& clip : s.clips)
    for (double t : frame_times(clip)) {
      PoseRequest req;
      req.a = {&clip, t};
      const SkinOutput ref = reference_skin(reference_pose(rig, req), mesh, Technique::lbs);
      const auto b64 = gltf_binary64_skin(s, mesh, req.a);
      double worst = 0;
      for (std::size_t v = 0; v < b64.size(); ++v) {
        const Vec3 &a = b64[v], &r = ref.positions[v];
        worst = std::max(worst, std::hypot(a[0] - r[0], a[1] - r[1], a[2] - r[2]));
      }
      const double e = worst / (kEps64 * size_scale(mesh, ref));
      std::printf("%s %s t=%.3f: glTF binary64 route vs reference LBS %.1f eps64 units (bar %.0f)\n", what.c_str(),
                  clip.name.c_str(), t, e, bar);
      EXPECT_LE(e, bar) << what << " " << clip.name << " t=" << t;
    }
}

// The pose model (stretch decompositions, hierarchy, inverse binds) is glTF's: the reference LBS
// equals glTF's matrix skinning up to the rounding of the binary64 route.
TEST(SkinReference, LbsIsGltfSkinning) {
  RC_CLAUSE("GLTF-2");
  for (Complexity c : kAll) expect_matches_gltf(to_string(c), character(c).scene, character(c).rig);
}

// The same on the Khronos samples, whose nodes carry matrices and (nearly unit, non-uniform)
// scales: the stretch path of pose_job.hpp.
TEST(SkinReference, LbsIsGltfSkinningOnSamples) {
  RC_CLAUSE("GLTF-2");
  if (!std::filesystem::is_directory(shared_data())) GTEST_SKIP() << "../shared/data is absent: the sample files are optional";
  for (const char* f : {"rigged_simple.gltf", "cesium_man.gltf"}) {
    const auto ch = make_rigged(load_gltf_file(shared_data() / "gltf" / f));
    expect_matches_gltf(f, ch->scene, ch->rig);
  }
}

}  // namespace
