// GLTF-1: what the loader accepts and what it reads, on the shared sample files (counts from
// ../shared/data/gltf/README.md and ../shared/data/mocap/README.md) and on documents built here.
#include <algorithm>
#include <filesystem>
#include <map>

#include <gtest/gtest.h>

#include <rotorcert/render/gltf_load.hpp>
#include <rotorcert/testing/clause.hpp>

#include "gltf_test_doc.hpp"

namespace {

using namespace rotorcert::render;
using namespace rotorcert::render::test;

#define REQUIRE_SHARED()                                                                           \
  if (!std::filesystem::is_directory(shared_dir()))                                                \
  GTEST_SKIP() << "../shared/data is absent (" << shared_dir() << "): the sample files are optional"

/// Every joint's parent precedes it (the Skeleton invariant).
void expect_parents_first(const Skeleton& sk) {
  for (std::size_t j = 0; j < sk.joints.size(); ++j) EXPECT_LT(sk.joints[j].parent, static_cast<int>(j)) << "joint " << j;
}

/// Every vertex's joints are skeleton joints and its weights are >= 0 and sum to 1 within
/// binary32 precision (the data are FLOAT or normalised integers).
void expect_valid_skin(const Scene& s) {
  for (const auto& m : s.meshes) {
    ASSERT_EQ(m.joints.size(), m.positions.size());
    ASSERT_EQ(m.weights.size(), m.positions.size());
    ASSERT_EQ(m.normals.size(), m.positions.size());
    for (std::size_t v = 0; v < m.positions.size(); ++v) {
      double sum = 0;
      for (int k = 0; k < 4; ++k) {
        EXPECT_LT(m.joints[v][k], s.skeleton.joints.size());
        EXPECT_GE(m.weights[v][k], 0.0);
        sum += m.weights[v][k];
      }
      EXPECT_NEAR(sum, 1.0, class_tolerance("eps16", kEps32)) << m.name << " vertex " << v;
    }
    for (auto i : m.indices) EXPECT_LT(i, m.positions.size());
  }
}

TEST(GltfLoad, RiggedSimpleCountsFromReadme) {
  RC_CLAUSE("GLTF-1");
  REQUIRE_SHARED();
  const Scene s = load_gltf_file(shared_dir() / "gltf" / "rigged_simple.gltf");
  EXPECT_EQ(s.name, "rigged_simple.gltf");
  EXPECT_EQ(s.skeleton.skin_joints.size(), 2u);
  EXPECT_EQ(s.vertex_count(), 160u);
  EXPECT_EQ(s.triangle_count(), 188u);
  EXPECT_EQ(s.clips.size(), 1u);
  EXPECT_EQ(s.skeleton.joints.size(), 5u);  // every node: Z_UP, Armature, Cylinder, Bone, Bone.001
  EXPECT_FALSE(s.generated_skin);
  EXPECT_EQ(s.warning_count, 0u) << (s.warnings.empty() ? "" : s.warnings.front());
  expect_parents_first(s.skeleton);
  expect_valid_skin(s);
  // The skin's joints are the nodes "Bone" and "Bone.001"; the first is given by a matrix.
  const auto& j0 = s.skeleton.joints[s.skeleton.skin_joints[0]];
  const auto& j1 = s.skeleton.joints[s.skeleton.skin_joints[1]];
  EXPECT_EQ(j0.name, "Bone");
  EXPECT_EQ(j1.name, "Bone.001");
  EXPECT_TRUE(j0.matrix.has_value());
  EXPECT_EQ(s.skeleton.joints[static_cast<std::size_t>(j1.parent)].name, "Bone");
  // Animation: translation, rotation and scale of node 4 (Bone.001), LINEAR.
  ASSERT_EQ(s.clips[0].channels.size(), 3u);
  for (const auto& ch : s.clips[0].channels) {
    EXPECT_EQ(s.skeleton.joints[ch.joint].node, 4u);
    EXPECT_EQ(ch.interpolation, Interpolation::linear);
  }
}

TEST(GltfLoad, CesiumManCountsFromReadme) {
  RC_CLAUSE("GLTF-1");
  REQUIRE_SHARED();
  const Scene s = load_gltf_file(shared_dir() / "gltf" / "cesium_man.gltf");
  EXPECT_EQ(s.skeleton.skin_joints.size(), 19u);
  EXPECT_EQ(s.vertex_count(), 3273u);
  EXPECT_EQ(s.triangle_count(), 4672u);
  EXPECT_EQ(s.clips.size(), 1u);
  EXPECT_EQ(s.skeleton.joints.size(), 22u);
  // Warnings: its texture is not loaded (1), and 210 vertices whose weights sum to 1 +- more than
  // 0.0039216 are renormalised (counted from the file's WEIGHTS_0 independently, in Python).
  EXPECT_EQ(s.warning_count, 211u);
  expect_parents_first(s.skeleton);
  expect_valid_skin(s);
}

TEST(GltfLoad, InterpolationTestLoadsWithoutItsImage) {
  RC_CLAUSE("GLTF-1");
  REQUIRE_SHARED();
  // Its texture l.jpg is absent from ../shared (README): not an error.
  ASSERT_FALSE(std::filesystem::exists(shared_dir() / "gltf" / "l.jpg"));
  const Scene s = load_gltf_file(shared_dir() / "gltf" / "interpolation_test.gltf");
  EXPECT_EQ(s.clips.size(), 9u);
  EXPECT_TRUE(s.skeleton.skin_joints.empty());  // no skin: meshes bound rigidly to their nodes
  EXPECT_EQ(s.skeleton.joints.size(), 12u);
  std::map<Interpolation, int> modes;
  for (const auto& c : s.clips) {
    ASSERT_EQ(c.channels.size(), 1u) << c.name;
    ++modes[c.channels[0].interpolation];
  }
  EXPECT_EQ(modes[Interpolation::step], 3);
  EXPECT_EQ(modes[Interpolation::linear], 2);
  EXPECT_EQ(modes[Interpolation::cubicspline], 4);  // "Linear Scale" is CUBICSPLINE in the file
  for (const auto& m : s.meshes)
    for (std::size_t v = 0; v < m.positions.size(); ++v) {
      EXPECT_EQ(m.weights[v][0], 1.0);
      EXPECT_EQ(s.skeleton.joints[m.joints[v][0]].node, m.node);
    }
  expect_parents_first(s.skeleton);
}

TEST(GltfLoad, MocapClipsAreSkeletonsWithReadmeSampleCounts) {
  RC_CLAUSE("GLTF-1");
  REQUIRE_SHARED();
  const std::map<std::string, std::size_t> samples = {
      {"09_02.gltf", 26}, {"127_14.gltf", 31}, {"140_05.gltf", 6}, {"102_09.gltf", 10}, {"13_07.gltf", 291}};
  for (const auto& [file, n] : samples) {
    SCOPED_TRACE(file);
    const Scene s = load_gltf_file(shared_dir() / "mocap" / file);
    EXPECT_EQ(s.skeleton.joints.size(), 44u);
    EXPECT_EQ(s.skeleton.skin_joints.size(), 44u);
    ASSERT_EQ(s.clips.size(), 1u);
    EXPECT_TRUE(s.generated_skin);
    EXPECT_EQ(s.warning_count, 0u) << (s.warnings.empty() ? "" : s.warnings.front());
    for (const auto& ch : s.clips[0].channels) {
      EXPECT_EQ(ch.times.size(), n);
      EXPECT_EQ(ch.interpolation, Interpolation::linear);
      EXPECT_NE(ch.path, ChannelPath::scale);
    }
    expect_parents_first(s.skeleton);
    expect_valid_skin(s);
  }
}

TEST(GltfLoad, EveryFileOfSharedLoads) {
  RC_CLAUSE("GLTF-1");
  REQUIRE_SHARED();
  int files = 0;
  for (const char* dir : {"gltf", "mocap"})
    for (const auto& e : std::filesystem::directory_iterator(shared_dir() / dir)) {
      if (e.path().extension() != ".gltf" && e.path().extension() != ".glb") continue;
      SCOPED_TRACE(e.path().string());
      EXPECT_NO_THROW((void)load_gltf_file(e.path()));
      ++files;
    }
  EXPECT_EQ(files, 8);
}

TEST(GltfLoad, BuiltDocumentSkeletonMeshAndClip) {
  RC_CLAUSE("GLTF-1");
  const Scene s = skinned_doc().load();
  ASSERT_EQ(s.skeleton.joints.size(), 3u);
  EXPECT_EQ(s.skeleton.joints[0].name, "root");
  EXPECT_EQ(s.skeleton.joints[1].name, "tip");
  EXPECT_EQ(s.skeleton.joints[1].parent, 0);
  EXPECT_EQ(s.skeleton.joints[1].rest.translation, (Vec3{0, 1, 0}));
  EXPECT_EQ(s.skeleton.joints[2].name, "node 2");
  EXPECT_EQ(s.skeleton.skin_joints, (std::vector<std::size_t>{0, 1}));
  // Column-major inverse bind of joint 1: translation (0, -1, 0) in elements 12..14.
  EXPECT_EQ(s.skeleton.joints[1].inverse_bind[13], -1.0);
  ASSERT_EQ(s.meshes.size(), 1u);
  const auto& m = s.meshes[0];
  EXPECT_EQ(m.positions, (std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}));
  EXPECT_EQ(m.indices, (std::vector<std::uint32_t>{0, 1, 2}));
  EXPECT_EQ(m.joints[0], (std::array<std::uint32_t, 4>{0, 1, 0, 0}));
  EXPECT_EQ(m.weights[0], (std::array<double, 4>{0.5, 0.5, 0, 0}));
  // Normals absent: computed, the triangle lies in z = 0 and is counter-clockwise seen from +z.
  EXPECT_EQ(m.normals[0], (Vec3{0, 0, 1}));
  ASSERT_EQ(s.clips.size(), 1u);
  EXPECT_EQ(s.clips[0].name, "animation 0");
  EXPECT_EQ(s.clips[0].start, 0.0);
  EXPECT_EQ(s.clips[0].end, 1.0);
  EXPECT_EQ(s.warning_count, 0u);
}

TEST(GltfLoad, NodesAreOrderedParentsFirst) {
  RC_CLAUSE("GLTF-1");
  // Node 0 is a child of node 2: the skeleton must reorder (2, 0, then 1 a child of 0).
  Doc d;
  d.j["nodes"] = {{{"name", "a"}, {"children", {1}}}, {{"name", "b"}}, {{"name", "c"}, {"children", {0}}}};
  const Scene s = d.load();
  ASSERT_EQ(s.skeleton.joints.size(), 3u);
  EXPECT_EQ(s.skeleton.joints[0].name, "c");
  EXPECT_EQ(s.skeleton.joints[1].name, "a");
  EXPECT_EQ(s.skeleton.joints[2].name, "b");
  EXPECT_EQ(s.skeleton.joints[2].parent, 1);
  EXPECT_EQ(s.skeleton.joints[1].node, 0u);
}

TEST(GltfLoad, MissingExternalImageIsNotAnError) {
  RC_CLAUSE("GLTF-1");
  Doc d = skinned_doc();
  d.j["images"] = {{{"uri", "no_such_image.png"}}, {{"uri", "data:image/png;base64,AAAA"}}, {{"bufferView", 99}}};
  d.j["textures"] = {{{"source", 0}}};
  const Scene s = d.load();
  EXPECT_EQ(s.meshes.size(), 1u);
  EXPECT_EQ(s.warning_count, 1u);  // "3 image(s) not loaded"
}

TEST(GltfLoad, GlbContainerLoadsLikeTheJson) {
  RC_CLAUSE("GLTF-1");
  Doc d = skinned_doc();
  nlohmann::json j = d.j;
  j["buffers"] = {{{"byteLength", d.bin.size()}}};  // the GLB BIN chunk
  std::string json = j.dump();
  while (json.size() % 4) json += ' ';
  std::vector<std::uint8_t> bin = d.bin;
  while (bin.size() % 4) bin.push_back(0);
  std::vector<std::uint8_t> glb;
  auto u32 = [&](std::uint32_t v) {
    for (int i = 0; i < 4; ++i) glb.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
  };
  glb.insert(glb.end(), {'g', 'l', 'T', 'F'});
  u32(2);
  u32(static_cast<std::uint32_t>(12 + 8 + json.size() + 8 + bin.size()));
  u32(static_cast<std::uint32_t>(json.size()));
  u32(0x4E4F534Au);
  glb.insert(glb.end(), json.begin(), json.end());
  u32(static_cast<std::uint32_t>(bin.size()));
  u32(0x004E4942u);
  glb.insert(glb.end(), bin.begin(), bin.end());
  const Scene a = load_gltf_memory(glb.data(), glb.size(), {}, "doc.glb");
  const Scene b = d.load();
  ASSERT_EQ(a.meshes.size(), 1u);
  EXPECT_EQ(a.meshes[0].positions, b.meshes[0].positions);
  EXPECT_EQ(a.clips[0].channels[0].values, b.clips[0].channels[0].values);
  // Every truncation of the GLB is an error, never a crash or an out-of-bounds read.
  for (std::size_t n = 0; n < glb.size(); ++n) {
    std::vector<std::uint8_t> cut(glb.begin(), glb.begin() + static_cast<long>(n));
    EXPECT_THROW((void)load_gltf_memory(cut.data(), cut.size(), {}, "cut.glb"), GltfError) << n << " bytes";
  }
}

}  // namespace
