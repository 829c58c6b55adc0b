// GLTF-4: capsule skins for skeleton-only files: geometry around each bone, two-joint weights
// with a smooth falloff, outward winding, and the counts the options imply.
#include <cmath>
#include <filesystem>

#include <gtest/gtest.h>

#include <rotorcert/render/capsule.hpp>
#include <rotorcert/render/gltf_load.hpp>
#include <rotorcert/render/sample.hpp>
#include <rotorcert/render/transform.hpp>
#include <rotorcert/testing/clause.hpp>

#include "gltf_test_doc.hpp"

namespace {

using namespace rotorcert::render;
using namespace rotorcert::render::test;

/// A chain root (0,0,0) -> a (0,2,0) -> b (0,2,3) with rest-pose inverse binds.
Skeleton chain() {
  Skeleton s;
  const std::vector<Vec3> at = {{0, 0, 0}, {0, 2, 0}, {0, 2, 3}};
  for (std::size_t j = 0; j < 3; ++j) {
    Joint jt;
    jt.name = "j" + std::to_string(j);
    jt.parent = static_cast<int>(j) - 1;
    jt.skinned = true;
    jt.inverse_bind = identity_matrix();
    for (int k = 0; k < 3; ++k) jt.inverse_bind[12 + k] = -at[j][k];  // translation by -position
    s.joints.push_back(jt);
    s.skin_joints.push_back(j);
  }
  return s;
}

double distance_to_segment(const Vec3& p, const Vec3& a, const Vec3& b) {
  Vec3 d{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, ap{p[0] - a[0], p[1] - a[1], p[2] - a[2]};
  double t = (ap[0] * d[0] + ap[1] * d[1] + ap[2] * d[2]) / (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  t = std::clamp(t, 0.0, 1.0);
  const Vec3 q{a[0] + t * d[0] - p[0], a[1] + t * d[1] - p[1], a[2] + t * d[2] - p[2]};
  return std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
}

TEST(GltfCapsule, CountsFollowTheOptions) {
  RC_CLAUSE("GLTF-4");
  CapsuleOptions o;
  o.segments = 8;
  o.cap_rings = 2;
  o.body_rings = 3;
  const SkinnedMesh m = make_capsule_skin(chain(), o);
  // Per bone: rings = 2 caps * 2 + 3 = 7 rings of 8 vertices + 2 poles = 58 vertices;
  // triangles: 2 pole fans of 8 + 6 bands of 16 = 112. Two bones.
  EXPECT_EQ(m.positions.size(), 2u * 58u);
  EXPECT_EQ(m.triangle_count(), 2u * 112u);
}

TEST(GltfCapsule, SurfaceIsAtTheRadiusFromTheBone) {
  RC_CLAUSE("GLTF-4");
  const CapsuleOptions o;
  const SkinnedMesh m = make_capsule_skin(chain(), o);
  const std::vector<Vec3> at = {{0, 0, 0}, {0, 2, 0}, {0, 2, 3}};
  for (std::size_t v = 0; v < m.positions.size(); ++v) {
    const auto p = m.joints[v][0], c = m.joints[v][1];
    ASSERT_EQ(c, p + 1) << "a bone joins a joint to its child";
    const double len = p == 0 ? 2.0 : 3.0;
    EXPECT_NEAR(distance_to_segment(m.positions[v], at[p], at[c]), o.radius_fraction * len, class_tolerance("eps16", kEps64, len)) << v;
  }
}

TEST(GltfCapsule, WeightsFallOffSmoothlyAlongTheBone) {
  RC_CLAUSE("GLTF-4");
  const SkinnedMesh m = make_capsule_skin(chain());
  // Bone 0 runs along +y from 0 to 2: child weight smoothstep(y / 2) = 3u^2 - 2u^3, clamped.
  for (std::size_t v = 0; v < m.positions.size(); ++v) {
    if (m.joints[v][0] != 0) continue;
    const double u = std::clamp(m.positions[v][1] / 2.0, 0.0, 1.0);
    const double want = u * u * (3 - 2 * u);
    EXPECT_NEAR(m.weights[v][1], want, class_tolerance("eps16", kEps64)) << v;
    EXPECT_NEAR(m.weights[v][0] + m.weights[v][1], 1.0, class_tolerance("eps4", kEps64));
    EXPECT_EQ(m.weights[v][2], 0.0);
  }
}

TEST(GltfCapsule, TrianglesFaceOutwards) {
  RC_CLAUSE("GLTF-4");
  const SkinnedMesh m = make_capsule_skin(chain());
  for (std::size_t t = 0; t < m.indices.size(); t += 3) {
    const auto &a = m.positions[m.indices[t]], &b = m.positions[m.indices[t + 1]], &c = m.positions[m.indices[t + 2]];
    const Vec3 u{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, w{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const Vec3 f{u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
    const auto& n = m.normals[m.indices[t]];
    EXPECT_GT(f[0] * n[0] + f[1] * n[1] + f[2] * n[2], 0.0) << "triangle " << t / 3;
  }
}

TEST(GltfCapsule, ZeroLengthBonesGetNoCapsule) {
  RC_CLAUSE("GLTF-4");
  Skeleton s = chain();
  s.joints[2].inverse_bind = s.joints[1].inverse_bind;  // b placed on a
  const CapsuleOptions o;
  const SkinnedMesh m = make_capsule_skin(s, o);
  EXPECT_EQ(m.positions.size(), (2 * o.cap_rings + o.body_rings) * o.segments + 2);  // one bone
}

TEST(GltfCapsule, MocapSkinFollowsTheRestPose) {
  RC_CLAUSE("GLTF-4");
  if (!std::filesystem::is_directory(shared_dir())) GTEST_SKIP() << "../shared/data is absent: the mocap files are optional";
  const Scene s = load_gltf_file(shared_dir() / "mocap" / "140_05.gltf");
  ASSERT_TRUE(s.generated_skin);
  ASSERT_EQ(s.meshes.size(), 1u);
  const auto& m = s.meshes[0];
  EXPECT_GT(m.triangle_count(), 0u);
  // Every vertex is bound to a bone (parent, child) of the skeleton.
  for (std::size_t v = 0; v < m.positions.size(); ++v)
    ASSERT_EQ(s.skeleton.joints[m.joints[v][1]].parent, static_cast<int>(m.joints[v][0]));
  // In the rest pose (the bind pose of a skeleton-only file) skinning leaves the capsules where they
  // were built: the skinning matrices are global * inverse(global). Scale: the skeleton's size.
  const auto skin = skinning_matrices(s.skeleton, global_matrices(s.skeleton, rest_pose(s.skeleton)));
  double size = 0;
  for (const auto& p : m.positions) size = std::max({size, std::abs(p[0]), std::abs(p[1]), std::abs(p[2])});
  for (std::size_t v = 0; v < m.positions.size(); v += 17) {
    Vec3 q{0, 0, 0};
    for (int k = 0; k < 2; ++k) {
      const Vec3 r = transform_point(skin[m.joints[v][k]], m.positions[v]);
      for (int i = 0; i < 3; ++i) q[i] += m.weights[v][k] * r[i];
    }
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(q[i], m.positions[v][i], class_tolerance("eps64", kEps64, size)) << v;
  }
}

}  // namespace
