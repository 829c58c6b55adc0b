// GLTF-3: one defined outcome per kind of bad input. Errors: GltfError naming the file and the
// glTF object; repairs: normalised with a warning. Never a crash, never another exception.
#include <cmath>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include <rotorcert/render/gltf_load.hpp>
#include <rotorcert/testing/clause.hpp>

#include "gltf_test_doc.hpp"

namespace {

using namespace rotorcert::render;
using namespace rotorcert::render::test;

/// Loads d and expects a GltfError whose message starts with the file name and contains every
/// fragment given.
void expect_error(const Doc& d, std::initializer_list<std::string> fragments, const GltfLimits& limits = {}) {
  try {
    (void)d.load(limits, "bad.gltf");
    ADD_FAILURE() << "loaded without error; expected: " << *fragments.begin();
  } catch (const GltfError& e) {
    const std::string msg = e.what();
    EXPECT_EQ(msg.rfind("bad.gltf: ", 0), 0u) << msg;
    for (const auto& f : fragments) EXPECT_NE(msg.find(f), std::string::npos) << "message: " << msg << "\nmissing: " << f;
  }
}

/// Overwrites the float at accessor `acc`, element component `i` of the document's buffer.
void poke_float(Doc& d, int acc, std::size_t i, float v) {
  const auto& bv = d.j["bufferViews"][d.j["accessors"][acc]["bufferView"].get<std::size_t>()];
  std::memcpy(d.bin.data() + bv["byteOffset"].get<std::size_t>() + 4 * i, &v, 4);
}

/// The accessor of the output of sampler 0 (rotation keyframes of skinned_doc).
int rotation_output(const Doc& d) { return d.j["animations"][0]["samplers"][0]["output"].get<int>(); }

TEST(GltfMalformed, ValidDocumentLoads) {
  RC_CLAUSE("GLTF-3");
  EXPECT_NO_THROW((void)skinned_doc().load());
}

TEST(GltfMalformed, AccessorPastTheEndOfItsBufferView) {
  RC_CLAUSE("GLTF-3");
  Doc d = skinned_doc();
  d.j["accessors"][0]["count"] = 4;  // POSITION: 3 vertices of 12 bytes in a 36-byte view
  expect_error(d, {"accessor 0", "POSITION", "count 4", "exceeds buffer view 0 (36 bytes)"});
  Doc e = skinned_doc();
  e.j["accessors"][0]["byteOffset"] = 4;
  expect_error(e, {"accessor 0", "at offset 4", "exceeds buffer view 0"});
  Doc f = skinned_doc();
  f.j["bufferViews"][0]["byteLength"] = 100000;  // the view itself past the buffer
  expect_error(f, {"buffer view 0", "exceed buffer 0"});
  Doc g = skinned_doc();
  g.j["accessors"][0]["count"] = std::numeric_limits<std::uint64_t>::max() / 2;  // overflow bait
  expect_error(g, {"accessor 0", "exceeds buffer view 0"});
  Doc h = skinned_doc();
  h.j["accessors"][0]["bufferView"] = 42;
  expect_error(h, {"accessor 0", "buffer view 42 out of range"});
}

TEST(GltfMalformed, JointIndexOutOfRange) {
  RC_CLAUSE("GLTF-3");
  Doc d = skinned_doc();
  const auto& bv = d.j["bufferViews"][d.j["accessors"][2]["bufferView"].get<std::size_t>()];
  d.bin[bv["byteOffset"].get<std::size_t>() + 5] = 2;  // vertex 1, influence 1: joint 2 of a 2-joint skin
  expect_error(d, {"mesh 0 primitive 0", "vertex 1 joint index 2 out of range (2 joints in the skin)"});
  Doc e = skinned_doc();
  e.j["skins"][0]["joints"] = {0, 7};
  expect_error(e, {"skin 0", "node 7, out of range"});
  Doc f = skinned_doc();
  f.j["skins"][0]["joints"] = {0, 0};
  expect_error(f, {"skin 0", "listed twice"});
}

TEST(GltfMalformed, VertexIndexOutOfRange) {
  RC_CLAUSE("GLTF-3");
  Doc d = skinned_doc();
  const auto& bv = d.j["bufferViews"][d.j["accessors"][1]["bufferView"].get<std::size_t>()];
  d.bin[bv["byteOffset"].get<std::size_t>() + 4] = 3;  // index 2 = 3 with 3 vertices
  expect_error(d, {"mesh 0 primitive 0", "index 2 is 3, not below the vertex count 3"});
}

TEST(GltfMalformed, NodeIndicesAndCycles) {
  RC_CLAUSE("GLTF-3");
  Doc d = skinned_doc();
  d.j["nodes"][1]["children"] = {0};  // 0 -> 1 -> 0
  expect_error(d, {"cycle"});
  Doc e = skinned_doc();
  e.j["nodes"][1]["children"] = {1};
  expect_error(e, {"node 1 is its own child"});
  Doc f = skinned_doc();
  f.j["nodes"][2]["children"] = {1};  // node 1 has parents 0 and 2
  expect_error(f, {"node 1 has two parents"});
  Doc g = skinned_doc();
  g.j["nodes"][0]["children"] = {1, 9};
  expect_error(g, {"node 0: child 9 out of range"});
  Doc h = skinned_doc();
  h.j["animations"][0]["channels"][0]["target"]["node"] = 5;
  expect_error(h, {"animation 0 channel 0", "target node 5 out of range"});
  Doc i = skinned_doc();
  i.j["nodes"][2]["mesh"] = 3;
  expect_error(i, {"node 2: mesh 3 out of range"});
}

TEST(GltfMalformed, NanInfAndZeroRotationKeyframes) {
  RC_CLAUSE("GLTF-3");
  Doc d = skinned_doc();
  poke_float(d, rotation_output(d), 4 + 2, std::numeric_limits<float>::quiet_NaN());
  expect_error(d, {"animation 0 sampler 0: keyframe 1 rotation is NaN"});
  Doc e = skinned_doc();
  poke_float(e, rotation_output(e), 3, std::numeric_limits<float>::infinity());
  expect_error(e, {"animation 0 sampler 0: keyframe 0 rotation is infinite"});
  Doc f = skinned_doc();
  poke_float(f, rotation_output(f), 3, 0.0f);  // (0,0,0,0)
  expect_error(f, {"animation 0 sampler 0: keyframe 0 rotation is zero"});
  Doc g = skinned_doc();
  g.j["nodes"][1]["rotation"] = {0, 0, 0, 0};
  expect_error(g, {"node 1 rotation is zero"});
}

TEST(GltfMalformed, NonUnitRotationKeyframeIsNormalisedWithAWarning) {
  RC_CLAUSE("GLTF-3");
  Doc d = skinned_doc();
  const int out = rotation_output(d);
  poke_float(d, out, 6, 3.0f);  // keyframe 1 = (0,0,3,4): length 5
  poke_float(d, out, 7, 4.0f);
  const Scene s = d.load();
  EXPECT_EQ(s.warning_count, 1u);
  ASSERT_EQ(s.warnings.size(), 1u);
  EXPECT_NE(s.warnings[0].find("keyframe 1 rotation has length 5, normalised"), std::string::npos) << s.warnings[0];
  const auto& v = s.clips[0].channels[0].values;
  EXPECT_EQ(v[6], 0.6);  // 3/5 and 4/5, correctly rounded
  EXPECT_EQ(v[7], 0.8);
  // Within glTF-Validator's unit threshold: kept exactly as stored, no warning.
  Doc e = skinned_doc();
  poke_float(e, rotation_output(e), 6, 1.001f);  // keyframe 1: (0,0,1,0) -> (0,0,1.001,0)
  const Scene t = e.load();
  EXPECT_EQ(t.warning_count, 0u);
  EXPECT_EQ(t.clips[0].channels[0].values[6], static_cast<double>(1.001f));
}

TEST(GltfMalformed, KeyframeTimesMustBeFiniteAndNonDecreasing) {
  RC_CLAUSE("GLTF-3");
  Doc d;
  d.j["nodes"] = {{{"name", "n"}}};
  add_channel(d, 0, "translation", "LINEAR", {0, 2, 1}, {0, 0, 0, 1, 1, 1, 2, 2, 2});
  expect_error(d, {"animation 0 sampler 0: keyframe times decrease at keyframe 2"});
  Doc e;
  e.j["nodes"] = {{{"name", "n"}}};
  add_channel(e, 0, "translation", "LINEAR", {0, std::numeric_limits<float>::infinity()}, {0, 0, 0, 1, 1, 1});
  expect_error(e, {"keyframe 1 time is infinite"});
  Doc f;  // equal times are allowed (a jump)
  f.j["nodes"] = {{{"name", "n"}}};
  add_channel(f, 0, "translation", "LINEAR", {0, 1, 1}, {0, 0, 0, 1, 1, 1, 2, 2, 2});
  EXPECT_NO_THROW((void)f.load());
  Doc g;  // output count must match: CUBICSPLINE needs three elements per keyframe
  g.j["nodes"] = {{{"name", "n"}}};
  add_channel(g, 0, "translation", "CUBICSPLINE", {0, 1}, {0, 0, 0, 1, 1, 1});
  expect_error(g, {"output count 2 does not match 2 keyframes", "CUBICSPLINE"});
}

TEST(GltfMalformed, WrongComponentTypes) {
  RC_CLAUSE("GLTF-3");
  Doc d = skinned_doc();
  d.j["accessors"][2]["componentType"] = kFloat;  // JOINTS_0 as FLOAT (12 bytes -> too short too)
  expect_error(d, {"JOINTS_0", "component type FLOAT is not allowed here"});
  Doc e = skinned_doc();
  const int w8 = e.add_ints(std::vector<std::uint8_t>{255, 0, 0, 0, 255, 0, 0, 0, 255, 0, 0, 0}, kUByte, "VEC4", 4, false);
  e.j["meshes"][0]["primitives"][0]["attributes"]["WEIGHTS_0"] = w8;
  expect_error(e, {"WEIGHTS_0", "UNSIGNED_BYTE must be normalized"});
  e.j["accessors"][w8]["normalized"] = true;  // the same data normalised: 255 -> 1.0
  const Scene ok = e.load();
  EXPECT_EQ(ok.meshes[0].weights[1][0], 1.0);
  Doc f = skinned_doc();
  f.j["accessors"][0]["type"] = "VEC2";
  expect_error(f, {"POSITION", "type VEC2 is not allowed here"});
  Doc g = skinned_doc();
  g.j["accessors"][1]["componentType"] = 5130;  // DOUBLE: not glTF 2.0
  expect_error(g, {"accessor 1", "component type 5130 is not a glTF 2.0 component type"});
}

TEST(GltfMalformed, WeightsSummingToZeroOrNotToOne) {
  RC_CLAUSE("GLTF-3");
  Doc d = skinned_doc();
  const int wacc = d.j["meshes"][0]["primitives"][0]["attributes"]["WEIGHTS_0"].get<int>();
  poke_float(d, wacc, 4, 0.0f);  // vertex 1: (0,0,0,0)
  expect_error(d, {"vertex 1 weights sum to 0"});
  Doc e = skinned_doc();
  poke_float(e, wacc, 0, 0.25f);  // vertex 0: (0.25, 0.5): sum 0.75 -> (1/3, 2/3)
  const Scene s = e.load();
  EXPECT_EQ(s.warning_count, 1u);
  EXPECT_EQ(s.meshes[0].weights[0][0], 0.25 / 0.75);
  EXPECT_EQ(s.meshes[0].weights[0][1], 0.5 / 0.75);
  Doc f = skinned_doc();
  poke_float(f, wacc, 0, -0.5f);
  expect_error(f, {"vertex 0 weight 0 is negative"});
}

TEST(GltfMalformed, LimitsAreCheckedBeforeReading) {
  RC_CLAUSE("GLTF-3");
  const Doc d = skinned_doc();
  GltfLimits l;
  l.max_vertices = 2;
  expect_error(d, {"3 vertices exceed the limit of 2"}, l);
  l = {};
  l.max_joints = 2;
  expect_error(d, {"3 nodes exceed the limit of 2 joints"}, l);
  l = {};
  l.max_keyframes = 1;
  expect_error(d, {"2 keyframes exceed the limit of 1"}, l);
  l = {};
  l.max_triangles = 0;
  expect_error(d, {"exceed"}, l);
  l = {};
  l.max_file_bytes = 100;
  expect_error(d, {"bytes exceeds the limit of 100"}, l);
  Doc deep = skinned_doc();
  nlohmann::json x = 1;
  for (int i = 0; i < 100; ++i) x = nlohmann::json::array({x});
  deep.j["extras"] = x;
  expect_error(deep, {"JSON nesting deeper than 64"});
}

TEST(GltfMalformed, TruncatedJsonAndEveryPrefix) {
  RC_CLAUSE("GLTF-3");
  const std::string s = skinned_doc().str();
  try {
    (void)load_gltf_memory(reinterpret_cast<const std::uint8_t*>(s.data()), s.size() / 2, {}, "half.gltf");
    ADD_FAILURE() << "truncated JSON loaded";
  } catch (const GltfError& e) {
    EXPECT_NE(std::string(e.what()).find("half.gltf: invalid JSON"), std::string::npos) << e.what();
  }
  for (std::size_t n = 0; n < s.size(); n += 7)
    EXPECT_THROW((void)load_gltf_memory(reinterpret_cast<const std::uint8_t*>(s.data()), n, {}, "cut.gltf"), GltfError) << n;
}

TEST(GltfMalformed, ExternalFilesAreRefusedFromMemory) {
  RC_CLAUSE("GLTF-3");
  Doc d = skinned_doc();
  nlohmann::json j = d.j;
  j["buffers"] = {{{"byteLength", d.bin.size()}, {"uri", "../../../../etc/passwd"}}};
  const std::string s = j.dump();
  EXPECT_THROW((void)load_gltf_memory(reinterpret_cast<const std::uint8_t*>(s.data()), s.size(), {}, "ext.gltf"), GltfError);
}

TEST(GltfMalformed, AnimatedMatrixNodeAndDuplicateChannels) {
  RC_CLAUSE("GLTF-3");
  Doc d = skinned_doc();
  d.j["nodes"][1].erase("translation");
  d.j["nodes"][1]["matrix"] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 1, 0, 1};
  expect_error(d, {"animation 0 channel 0", "has a matrix"});
  Doc e = skinned_doc();
  add_channel(e, 1, "rotation", "STEP", {0}, {0, 0, 0, 1});
  expect_error(e, {"animation 0 channel 1", "channel 0 already targets node 1 rotation"});
}

TEST(GltfMalformed, RandomByteFlipsNeverCrash) {
  RC_CLAUSE("GLTF-3");
  // Deterministic mutations of a valid document: each either loads or throws GltfError.
  const std::string base = skinned_doc().str();
  std::mt19937 rng(20261122);
  int errors = 0, loaded = 0;
  for (int round = 0; round < 3000; ++round) {
    std::string s = base;
    const int flips = 1 + static_cast<int>(rng() % 4);
    for (int k = 0; k < flips; ++k) s[rng() % s.size()] = static_cast<char>("0123456789-.e,:[]{}\"x"[rng() % 21]);
    try {
      (void)load_gltf_memory(reinterpret_cast<const std::uint8_t*>(s.data()), s.size(), {}, "flip.gltf");
      ++loaded;
    } catch (const GltfError&) {
      ++errors;
    }
  }
  EXPECT_GT(errors, 0);
  EXPECT_EQ(errors + loaded, 3000);
}

}  // namespace
