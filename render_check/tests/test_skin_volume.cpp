// Volume of closed meshes (vertex_error.hpp, mesh_volume) and the candy-wrapper effect of the
// twist clip: linear blend skinning collapses a joint twisted by 180 degrees (SKIN-1's stated
// property), dual-quaternion skinning stays rigid (SKIN-2's).
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include <rotorcert/render/skin_job.hpp>
#include <rotorcert/testing/clause.hpp>

#include "test_skin_support.hpp"

namespace {

using namespace rotorcert::render;
using namespace rotorcert::render::skin_test;

/// The unit cube [0,1]^3 as 12 outward (counter-clockwise seen from outside) triangles, shifted by o.
void add_cube(std::vector<Vec3>& p, std::vector<std::uint32_t>& idx, const Vec3& o) {
  const auto base = static_cast<std::uint32_t>(p.size());
  for (int i = 0; i < 8; ++i) p.push_back({o[0] + (i & 1), o[1] + ((i >> 1) & 1), o[2] + ((i >> 2) & 1)});
  // Faces as quads (a, b, c, d) counter-clockwise from outside, two triangles each.
  const std::uint32_t quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads)
    for (std::uint32_t t : {q[0], q[1], q[2], q[0], q[2], q[3]}) idx.push_back(base + t);
}

TEST(SkinVolume, FormulaOnKnownSolids) {
  std::vector<Vec3> p;
  std::vector<std::uint32_t> idx;
  add_cube(p, idx, {0, 0, 0});
  MeshVolume v = mesh_volume(p, idx);
  EXPECT_TRUE(v.closed);
  EXPECT_EQ(v.total, 1.0);  // small integers: every product and sum is exact
  // Closed: the origin does not matter. Two parts, listed separately.
  add_cube(p, idx, {10, -3, 7});
  v = mesh_volume(p, idx);
  EXPECT_TRUE(v.closed);
  EXPECT_EQ(v.total, 2.0);
  EXPECT_EQ(v.parts, (std::vector<double>{1.0, 1.0}));
  // Inward-facing triangles give the negative volume.
  std::vector<std::uint32_t> flipped = idx;
  for (std::size_t t = 0; t < flipped.size(); t += 3) std::swap(flipped[t + 1], flipped[t + 2]);
  EXPECT_EQ(mesh_volume(p, flipped).total, -2.0);
  // One triangle missing: open, its three edges have no partner.
  idx.resize(idx.size() - 3);
  v = mesh_volume(p, idx);
  EXPECT_FALSE(v.closed);
  EXPECT_EQ(v.open_edges, 3u);
}

// The volume is meaningful only for closed meshes: CHAR-1's tubes are closed, the strip of
// `simple` is not.
TEST(SkinVolume, BuiltinCharactersClosedExceptTheStrip) {
  RC_CLAUSE("CHAR-1");
  const SkinnedMesh& strip = character(Complexity::simple).scene.meshes.at(0);
  EXPECT_FALSE(mesh_volume(strip.positions, strip.indices).closed);
  for (Complexity c : {Complexity::medium, Complexity::full}) {
    const SkinnedMesh& m = character(c).scene.meshes.at(0);
    const MeshVolume v = mesh_volume(m.positions, m.indices);
    EXPECT_TRUE(v.closed) << to_string(c) << ": " << v.open_edges << " open edges";
    EXPECT_GT(v.parts.size(), 1u) << to_string(c);
    for (double x : v.parts) EXPECT_GT(x, 0.0) << to_string(c) << ": triangles face outwards";
  }
}

/// Relative volume change of each part, in percent.
std::vector<double> part_change(const SkinnedMesh& mesh, const std::vector<Vec3>& posed) {
  const MeshVolume rest = mesh_volume(mesh.positions, mesh.indices), now = mesh_volume(posed, mesh.indices);
  std::vector<double> r;
  for (std::size_t i = 0; i < rest.parts.size(); ++i) r.push_back(100.0 * (now.parts[i] - rest.parts[i]) / rest.parts[i]);
  return r;
}

class CandyWrapper : public ::testing::TestWithParam<Complexity> {};

// At the end of `twist` the wrists have turned 180 degrees. In the part that LBS shrinks most
// (an arm), LBS must lose volume and DQS change it by clearly less (at most half as much), for the
// reference of each technique and for every conforming method.
TEST_P(CandyWrapper, LbsLosesVolumeDqsKeepsIt) {
  RC_CLAUSE("SKIN-1");
  RC_CLAUSE("SKIN-2");
  const Character& c = character(GetParam());
  const SkinnedMesh& mesh = c.scene.meshes.at(0);
  const Clip& twist = clip_named(c.scene, "twist");
  PoseRequest req;
  req.a = {&twist, twist.end};
  const ReferencePose rp = reference_pose(c.rig, req);
  const auto lbs = part_change(mesh, reference_skin(rp, mesh, Technique::lbs).positions);
  const auto dqs = part_change(mesh, reference_skin(rp, mesh, Technique::dqs).positions);
  std::size_t worst = 0;
  for (std::size_t i = 0; i < lbs.size(); ++i)
    if (lbs[i] < lbs[worst]) worst = i;
  const MeshVolume rest = mesh_volume(mesh.positions, mesh.indices);
  std::printf("%s twist at %.2f s, part %zu of %zu (rest volume %.6f m^3): reference LBS %+.3f %%, DQS %+.3f %%\n",
              to_string(GetParam()), twist.end, worst, lbs.size(), rest.parts[worst], lbs[worst], dqs[worst]);
  EXPECT_LT(lbs[worst], 0.0);
  EXPECT_LT(2.0 * std::abs(dqs[worst]), -lbs[worst]);

  const auto& joints = c.rig.skeleton->skin_joints;
  const auto vv = reference_virtual_vertices(rp, joints, kVirtualVertexMetres);
  const SkinOutput ref[2] = {reference_skin(rp, mesh, Technique::lbs), reference_skin(rp, mesh, Technique::dqs)};
  for (const auto& m : builtin_methods()) {
    if (!conforming(m)) continue;
    const FrameResult fr = measure_frame(m, c.rig, mesh, req, ref[m.technique == Technique::lbs ? 0 : 1], vv, joints);
    const double change = part_change(mesh, fr.skin.positions)[worst];
    std::printf("  %-24s %+.3f %%\n", m.name().c_str(), change);
    if (m.technique == Technique::lbs) EXPECT_LT(2.0 * std::abs(dqs[worst]), -change) << m.name();
    else EXPECT_LT(2.0 * std::abs(change), -lbs[worst]) << m.name();
  }
}

INSTANTIATE_TEST_SUITE_P(Builtin, CandyWrapper, ::testing::Values(Complexity::medium, Complexity::full),
                         [](const auto& p) { return std::string(to_string(p.param)); });

}  // namespace
