// CHAR-1: the built-in characters (make_character) and their glTF form (write_gltf, read back by
// the GLTF-1 loader). Expected counts, angles and clip timing are those CHAR-1 of spec/SPEC.md
// states; geometric expectations are derived here from the loaded rest data, not from the
// generator.
#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <map>
#include <numeric>
#include <set>

#include <gtest/gtest.h>

#include <rotorcert/render/character.hpp>
#include <rotorcert/render/gltf_load.hpp>
#include <rotorcert/render/gltf_write.hpp>
#include <rotorcert/render/sample.hpp>
#include <rotorcert/render/transform.hpp>
#include <rotorcert/testing/clause.hpp>

#include "gltf_test_doc.hpp"

namespace {

using namespace rotorcert::render;
using namespace rotorcert::render::test;

constexpr double kPi = 3.14159265358979323846;
const std::array<Complexity, 3> kAll = {Complexity::simple, Complexity::medium, Complexity::full};

Scene load_string(const std::string& doc, const std::string& name) {
  return load_gltf_memory(reinterpret_cast<const std::uint8_t*>(doc.data()), doc.size(), {}, name);
}

std::size_t joint_named(const Scene& s, const std::string& name) {
  for (std::size_t j = 0; j < s.skeleton.joints.size(); ++j)
    if (s.skeleton.joints[j].name == name) return j;
  ADD_FAILURE() << "no joint " << name;
  return 0;
}

const Clip& clip_named(const Scene& s, const std::string& name) {
  for (const auto& c : s.clips)
    if (c.name == name) return c;
  throw std::runtime_error("no clip " + name);
}

Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3 cross(const Vec3& a, const Vec3& b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }
double norm(const Vec3& a) { return std::sqrt(dot(a, a)); }
Vec3 position(const Mat4& m) { return {m[12], m[13], m[14]}; }
/// The angle between two vectors, accurate at every angle.
double angle_between(const Vec3& a, const Vec3& b) { return std::atan2(norm(cross(a, b)), dot(a, b)); }

Quat qmul(const Quat& a, const Quat& b) {
  return {a[3] * b[0] + a[0] * b[3] + a[1] * b[2] - a[2] * b[1], a[3] * b[1] - a[0] * b[2] + a[1] * b[3] + a[2] * b[0],
          a[3] * b[2] + a[0] * b[1] - a[1] * b[0] + a[2] * b[3], a[3] * b[3] - a[0] * b[0] - a[1] * b[1] - a[2] * b[2]};
}
/// The rotation by `angle` about the direction of v: (sin(angle/2) v/|v|, cos(angle/2)).
Quat about(const Vec3& v, double angle) {
  const double n = norm(v), s = std::sin(angle / 2);
  return {s * v[0] / n, s * v[1] / n, s * v[2] / n, std::cos(angle / 2)};
}
/// max |a_i - b_i| over the closer of b and -b (q and -q are the same rotation).
double quat_distance(const Quat& a, const Quat& b) {
  double plus = 0, minus = 0;
  for (std::size_t i = 0; i < 4; ++i) {
    plus = std::max(plus, std::abs(a[i] - b[i]));
    minus = std::max(minus, std::abs(a[i] + b[i]));
  }
  return std::min(plus, minus);
}

/// The joints whose twist/bend CHAR-1 states: (twisted or bent joint, its parent's parent) per side.
std::vector<std::string> sides(Complexity c) { return c == Complexity::simple ? std::vector<std::string>{""} : std::vector<std::string>{"_L", "_R"}; }
std::string wrist(Complexity c, const std::string& side) { return c == Complexity::simple ? "tip" : "hand" + side; }
std::string elbow(Complexity c, const std::string& side) { return c == Complexity::simple ? "mid" : "forearm" + side; }
std::string shoulder(Complexity c, const std::string& side) { return c == Complexity::simple ? "root" : "upper_arm" + side; }

// ---------------------------------------------------------------------------------------------

TEST(Character, JointAndTriangleCountsPerComplexity) {
  RC_CLAUSE("CHAR-1");
  struct Want {
    Complexity c;
    std::size_t joints, min_triangles, max_triangles;
  };
  // CHAR-1: 3 joints / 6 vertices / 4 triangles; 21 joints / 2,000-5,000; 42 joints / 28,500-31,500.
  for (const Want& w : {Want{Complexity::simple, 3, 4, 4}, Want{Complexity::medium, 21, 2000, 5000},
                        Want{Complexity::full, 42, 28500, 31500}}) {
    SCOPED_TRACE(to_string(w.c));
    const Scene s = make_character(w.c);
    EXPECT_EQ(s.name, std::string("rotorcert_") + to_string(w.c));
    EXPECT_EQ(s.skeleton.skin_joints.size(), w.joints);
    EXPECT_EQ(s.skeleton.joints.size(), w.joints + 1) << "the skin joints and the mesh node";
    ASSERT_EQ(s.meshes.size(), 1u);
    EXPECT_EQ(s.skeleton.joints[s.meshes[0].node].name, "body");
    EXPECT_FALSE(s.skeleton.joints[s.meshes[0].node].skinned);
    EXPECT_GE(s.triangle_count(), w.min_triangles);
    EXPECT_LE(s.triangle_count(), w.max_triangles);
    if (w.c == Complexity::simple) {
      EXPECT_EQ(s.vertex_count(), 6u);
    }
    for (std::size_t j = 0; j < s.skeleton.joints.size(); ++j) EXPECT_LT(s.skeleton.joints[j].parent, static_cast<int>(j));
  }
}

TEST(Character, EveryVertexHasOneToFourValidInfluencesSummingToOne) {
  RC_CLAUSE("CHAR-1");
  for (Complexity c : kAll) {
    SCOPED_TRACE(to_string(c));
    const Scene s = make_character(c);
    const std::set<std::size_t> skin(s.skeleton.skin_joints.begin(), s.skeleton.skin_joints.end());
    std::set<std::size_t> used;
    std::size_t four = 0;
    for (const auto& m : s.meshes)
      for (std::size_t v = 0; v < m.positions.size(); ++v) {
        std::set<std::uint32_t> joints;
        double sum64 = 0;
        float sum32 = 0;
        for (std::size_t k = 0; k < 4; ++k) {
          const double w = m.weights[v][k];
          ASSERT_GE(w, 0.0) << v;
          ASSERT_EQ(std::round(w * 65536.0), w * 65536.0) << "vertex " << v << ": not a multiple of 2^-16";
          sum64 += w;
          sum32 += static_cast<float>(w);
          if (w > 0) {
            ASSERT_TRUE(skin.count(m.joints[v][k])) << "vertex " << v << " weighted to a joint outside the skin";
            ASSERT_TRUE(joints.insert(m.joints[v][k]).second) << "vertex " << v << ": joint " << m.joints[v][k] << " twice";
            used.insert(m.joints[v][k]);
          }
        }
        ASSERT_GE(joints.size(), 1u) << v;
        four += joints.size() == 4;
        ASSERT_EQ(sum64, 1.0) << "vertex " << v;
        ASSERT_EQ(sum32, 1.0f) << "vertex " << v;
      }
    EXPECT_EQ(used, skin) << "every skin joint moves some vertex";
    if (c == Complexity::full) {
      EXPECT_GT(four, 0u) << "the full character has vertices with four influences";
    }
  }
}

/// Connected parts of a mesh (vertices joined by triangles).
std::vector<std::size_t> components(const SkinnedMesh& m) {
  std::vector<std::size_t> up(m.positions.size());
  std::iota(up.begin(), up.end(), 0);
  auto find = [&](std::size_t x) {
    while (up[x] != x) x = up[x] = up[up[x]];
    return x;
  };
  for (std::size_t t = 0; t < m.indices.size(); t += 3)
    for (std::size_t k = 1; k < 3; ++k) up[find(m.indices[t + k])] = find(m.indices[t]);
  std::vector<std::size_t> part(m.positions.size());
  for (std::size_t v = 0; v < part.size(); ++v) part[v] = find(v);
  return part;
}

TEST(Character, NormalsAreUnitAndPartsAreClosedAndFaceOutwards) {
  RC_CLAUSE("CHAR-1");
  for (Complexity c : kAll) {
    SCOPED_TRACE(to_string(c));
    const Scene s = make_character(c);
    const SkinnedMesh& m = s.meshes.at(0);
    ASSERT_EQ(m.normals.size(), m.positions.size());
    // One binary32 rounding per component of a unit vector.
    for (std::size_t v = 0; v < m.normals.size(); ++v) ASSERT_NEAR(norm(m.normals[v]), 1.0, class_tolerance("eps4", kEps32)) << v;
    if (c == Complexity::simple) {
      // The strip lies in the XZ plane facing +Y.
      for (std::size_t t = 0; t < m.indices.size(); t += 3) {
        const Vec3& a = m.positions[m.indices[t]];
        const Vec3 f = cross(sub(m.positions[m.indices[t + 1]], a), sub(m.positions[m.indices[t + 2]], a));
        EXPECT_EQ(f[0], 0.0);
        EXPECT_GT(f[1], 0.0);
        EXPECT_EQ(f[2], 0.0);
      }
      for (const auto& n : m.normals) EXPECT_EQ(n, (Vec3{0.0, 1.0, 0.0}));
      continue;
    }
    // Closed tubes: every edge is shared by exactly two triangles, in opposite directions, and
    // the volume each part encloses (divergence theorem) is positive: triangles face outwards.
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
    for (std::size_t t = 0; t < m.indices.size(); t += 3)
      for (std::size_t k = 0; k < 3; ++k) ++edges[{m.indices[t + k], m.indices[t + (k + 1) % 3]}];
    for (const auto& [e, n] : edges) {
      ASSERT_EQ(n, 1) << "edge " << e.first << "-" << e.second << " used twice in one direction";
      ASSERT_EQ(edges.count({e.second, e.first}), 1u) << "open edge " << e.first << "-" << e.second;
    }
    const auto part = components(m);
    std::map<std::size_t, double> volume;
    for (std::size_t t = 0; t < m.indices.size(); t += 3) {
      const Vec3 &a = m.positions[m.indices[t]], &b = m.positions[m.indices[t + 1]], &d = m.positions[m.indices[t + 2]];
      volume[part[m.indices[t]]] += dot(a, cross(b, d)) / 6.0;
      // A vertex normal lies on the outer side of each triangle around it.
      const Vec3 f = cross(sub(b, a), sub(d, a));
      for (std::size_t k = 0; k < 3; ++k) ASSERT_GT(dot(f, m.normals[m.indices[t + k]]), 0.0) << "triangle " << t / 3;
    }
    EXPECT_GE(volume.size(), c == Complexity::full ? 17u : 7u) << "torso, arms, fingers (and legs, feet)";
    for (const auto& [p, vol] : volume) EXPECT_GT(vol, 0.0) << "part of vertex " << p;
  }
}

TEST(Character, InverseBindMatricesInvertTheRestGlobalMatrices) {
  RC_CLAUSE("CHAR-1");
  for (Complexity c : kAll) {
    SCOPED_TRACE(to_string(c));
    const Scene s = make_character(c);
    const auto global = global_matrices(s.skeleton, rest_pose(s.skeleton));
    for (std::size_t j : s.skeleton.skin_joints) {
      const auto inv = inverse(global[j]);
      ASSERT_TRUE(inv.has_value());
      double scale = 1.0;
      for (double x : *inv) scale = std::max(scale, std::abs(x));
      // Each element is one binary32 rounding of the inverse.
      for (std::size_t e = 0; e < 16; ++e)
        EXPECT_NEAR(s.skeleton.joints[j].inverse_bind[e], (*inv)[e], class_tolerance("eps4", kEps32, scale))
            << s.skeleton.joints[j].name << " element " << e;
    }
    const Joint& body = s.skeleton.joints.back();
    EXPECT_EQ(body.inverse_bind, identity_matrix());
  }
}

TEST(Character, ClipsAreTwoSecondsOf61LinearKeyframes) {
  RC_CLAUSE("CHAR-1");
  const std::map<Complexity, std::vector<std::string>> names = {
      {Complexity::simple, {"bend", "twist"}}, {Complexity::medium, {"bend", "twist"}}, {Complexity::full, {"walk", "bend", "twist"}}};
  for (Complexity c : kAll) {
    SCOPED_TRACE(to_string(c));
    const Scene s = make_character(c);
    std::vector<std::string> got;
    for (const auto& clip : s.clips) got.push_back(clip.name);
    EXPECT_EQ(got, names.at(c));
    for (const auto& clip : s.clips) {
      SCOPED_TRACE(clip.name);
      EXPECT_EQ(clip.start, 0.0);
      EXPECT_EQ(clip.end, 2.0);
      for (const auto& ch : clip.channels) {
        EXPECT_EQ(ch.interpolation, Interpolation::linear);
        ASSERT_EQ(ch.times.size(), 61u);
        for (std::size_t k = 0; k < 61; ++k) EXPECT_EQ(ch.times[k], static_cast<double>(static_cast<float>(k / 30.0)));
        ASSERT_EQ(ch.values.size(), 61u * ch.width());
        if (ch.path == ChannelPath::translation) {
          EXPECT_EQ(clip.name, "walk") << "translation only in the walk";
          EXPECT_EQ(s.skeleton.joints[ch.joint].name, "hips");
        }
        EXPECT_NE(ch.path, ChannelPath::scale);
        if (ch.path != ChannelPath::rotation) continue;
        for (std::size_t k = 0; k < 61; ++k) {
          const double* q = &ch.values[4 * k];
          EXPECT_NEAR(std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]), 1.0, class_tolerance("eps4", kEps32)) << k;
          if (k > 0) {
            EXPECT_GE(q[0] * q[-4] + q[1] * q[-3] + q[2] * q[-2] + q[3] * q[-1], 0.0) << "keys " << k - 1 << ", " << k;
          }
        }
      }
      if (clip.name == "walk") {  // one cycle: the last keyframe is the first again
        for (const auto& ch : clip.channels)
          for (std::size_t i = 0; i < ch.width(); ++i)
            EXPECT_NEAR(ch.values[60 * ch.width() + i], ch.values[i], class_tolerance("eps4", kEps32)) << s.skeleton.joints[ch.joint].name;
      }
    }
  }
}

TEST(Character, TwistTurnsTheWristAboutTheForearmAxis) {
  RC_CLAUSE("CHAR-1");
  for (Complexity c : kAll) {
    SCOPED_TRACE(to_string(c));
    const Scene s = make_character(c);
    const Clip& twist = clip_named(s, "twist");
    std::set<std::size_t> wrists;
    for (const auto& side : sides(c)) {
      const std::size_t w = joint_named(s, wrist(c, side));
      wrists.insert(w);
      const Joint& jt = s.skeleton.joints[w];
      ASSERT_EQ(jt.parent, static_cast<int>(joint_named(s, elbow(c, side))));
      // The forearm axis in the forearm's frame is the direction of the wrist's rest translation;
      // smoothstep easing: half the angle at half time, 180 degrees at the end.
      for (const auto& [t, angle] : {std::pair{1.0, kPi / 2}, std::pair{2.0, kPi}}) {
        const auto pose = sample_pose(s.skeleton, twist, t);
        const Quat want = qmul(about(jt.rest.translation, angle), jt.rest.rotation);
        EXPECT_LE(quat_distance(pose[w].rotation, want), class_tolerance("eps4", kEps32)) << jt.name << " at " << t << " s";
      }
    }
    std::set<std::size_t> animated;
    for (const auto& ch : twist.channels) animated.insert(ch.joint);
    EXPECT_EQ(animated, wrists) << "only the wrists turn";
  }
}

TEST(Character, TwistCollapsesHalfWeightedVerticesUnderLinearBlending) {
  RC_CLAUSE("CHAR-1");
  // The candy-wrapper case: a vertex weighted w to the wrist and 1 - w to the forearm, at radial
  // offset r from the forearm axis, is blended by linear blend skinning to (1 - w) r - w r after
  // half a turn: its distance from the axis becomes |1 - 2w| r.
  for (Complexity c : kAll) {
    SCOPED_TRACE(to_string(c));
    const Scene s = make_character(c);
    const std::string side = sides(c).front();
    const std::size_t w = joint_named(s, wrist(c, side)), e = joint_named(s, elbow(c, side));
    const auto rest = global_matrices(s.skeleton, rest_pose(s.skeleton));
    const auto global = global_matrices(s.skeleton, sample_pose(s.skeleton, clip_named(s, "twist"), 2.0));
    const auto skin = skinning_matrices(s.skeleton, global);
    const Vec3 o = position(rest[e]), axis = sub(position(rest[w]), o);
    auto radial = [&](const Vec3& p) { return norm(cross(sub(p, o), axis)) / norm(axis); };
    std::size_t checked = 0;
    const SkinnedMesh& m = s.meshes.at(0);
    for (std::size_t v = 0; v < m.positions.size(); ++v) {
      double ww = 0, we = 0, other = 0;
      for (std::size_t k = 0; k < 4; ++k) (m.joints[v][k] == w ? ww : m.joints[v][k] == e ? we : other) += m.weights[v][k];
      if (other > 0 || ww < 0.25 || we < 0.25) continue;
      Vec3 p{0, 0, 0};
      for (std::size_t k = 0; k < 4; ++k) {
        const Vec3 q = transform_point(skin[m.joints[v][k]], m.positions[v]);
        for (std::size_t i = 0; i < 3; ++i) p[i] += m.weights[v][k] * q[i];
      }
      const double r = radial(m.positions[v]);
      EXPECT_NEAR(radial(p), std::abs(1 - 2 * ww) * r, class_tolerance("eps16", kEps32, norm(m.positions[v]))) << "vertex " << v;
      ++checked;
    }
    EXPECT_GT(checked, 0u) << "vertices blended between forearm and wrist";
  }
}

TEST(Character, BendFoldsTheElbowForwards) {
  RC_CLAUSE("CHAR-1");
  for (Complexity c : kAll) {
    SCOPED_TRACE(to_string(c));
    const Scene s = make_character(c);
    const auto global = global_matrices(s.skeleton, sample_pose(s.skeleton, clip_named(s, "bend"), 2.0));
    const double want = c == Complexity::simple ? kPi / 2 : 135.0 * kPi / 180.0;  // CHAR-1
    for (const auto& side : sides(c)) {
      const Vec3 sh = position(global[joint_named(s, shoulder(c, side))]), el = position(global[joint_named(s, elbow(c, side))]),
                 wr = position(global[joint_named(s, wrist(c, side))]);
      EXPECT_NEAR(angle_between(sub(el, sh), sub(wr, el)), want, class_tolerance("eps16", kEps32)) << side;
      // Forwards (+Z) for the arms; up (+Y) for the strip.
      if (c == Complexity::simple) {
        EXPECT_GT(wr[1], el[1]);
      } else {
        EXPECT_GT(wr[2], el[2]) << side;
      }
    }
  }
}

void expect_same_scene(const Scene& a, const Scene& b) {
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(b.warning_count, 0u) << (b.warnings.empty() ? "" : b.warnings.front());
  EXPECT_EQ(a.generated_skin, b.generated_skin);
  ASSERT_EQ(a.skeleton.joints.size(), b.skeleton.joints.size());
  for (std::size_t j = 0; j < a.skeleton.joints.size(); ++j) {
    const Joint &x = a.skeleton.joints[j], &y = b.skeleton.joints[j];
    SCOPED_TRACE("joint " + x.name);
    EXPECT_EQ(x.name, y.name);
    EXPECT_EQ(x.parent, y.parent);
    EXPECT_EQ(x.node, y.node);
    EXPECT_EQ(x.rest.translation, y.rest.translation);
    EXPECT_EQ(x.rest.rotation, y.rest.rotation);
    EXPECT_EQ(x.rest.scale, y.rest.scale);
    EXPECT_EQ(x.matrix.has_value(), y.matrix.has_value());
    EXPECT_EQ(x.inverse_bind, y.inverse_bind);
    EXPECT_EQ(x.skinned, y.skinned);
  }
  EXPECT_EQ(a.skeleton.skin_joints, b.skeleton.skin_joints);
  ASSERT_EQ(a.meshes.size(), b.meshes.size());
  for (std::size_t i = 0; i < a.meshes.size(); ++i) {
    const SkinnedMesh &x = a.meshes[i], &y = b.meshes[i];
    EXPECT_EQ(x.name, y.name);
    EXPECT_EQ(x.node, y.node);
    EXPECT_EQ(x.positions, y.positions);
    EXPECT_EQ(x.normals, y.normals);
    EXPECT_EQ(x.joints, y.joints);
    EXPECT_EQ(x.weights, y.weights);
    EXPECT_EQ(x.indices, y.indices);
  }
  ASSERT_EQ(a.clips.size(), b.clips.size());
  for (std::size_t i = 0; i < a.clips.size(); ++i) {
    const Clip &x = a.clips[i], &y = b.clips[i];
    SCOPED_TRACE("clip " + x.name);
    EXPECT_EQ(x.name, y.name);
    EXPECT_EQ(x.start, y.start);
    EXPECT_EQ(x.end, y.end);
    ASSERT_EQ(x.channels.size(), y.channels.size());
    for (std::size_t k = 0; k < x.channels.size(); ++k) {
      EXPECT_EQ(x.channels[k].joint, y.channels[k].joint);
      EXPECT_EQ(x.channels[k].path, y.channels[k].path);
      EXPECT_EQ(x.channels[k].interpolation, y.channels[k].interpolation);
      EXPECT_EQ(x.channels[k].times, y.channels[k].times);
      EXPECT_EQ(x.channels[k].values, y.channels[k].values);
    }
  }
}

TEST(Character, WrittenGltfLoadsBackAsTheSameScene) {
  RC_CLAUSE("GLTF-1");
  RC_CLAUSE("CHAR-1");
  for (Complexity c : kAll) {
    SCOPED_TRACE(to_string(c));
    const Scene s = make_character(c);
    const std::string doc = write_gltf(s);
    expect_same_scene(s, load_string(doc, s.name));
  }
}

TEST(Character, OutputIsByteIdenticalOnEveryCall) {
  RC_CLAUSE("CHAR-1");
  const auto dir = std::filesystem::path(::testing::TempDir()) / "rotorcert_character_test";
  std::filesystem::create_directories(dir);
  for (Complexity c : kAll) {
    SCOPED_TRACE(to_string(c));
    const std::string first = write_gltf(make_character(c));
    EXPECT_TRUE(first == write_gltf(make_character(c))) << "two calls differ";
    // Loading and writing again gives the same bytes: nothing is lost or reordered.
    EXPECT_TRUE(first == write_gltf(load_string(first, std::string("rotorcert_") + to_string(c)))) << "round trip differs";
    const auto file = dir / (std::string(to_string(c)) + ".gltf");
    write_gltf_file(make_character(c), file);
    EXPECT_EQ(std::filesystem::file_size(file), first.size());
    const Scene from_file = load_gltf_file(file);
    EXPECT_EQ(from_file.triangle_count(), make_character(c).triangle_count());
  }
  std::filesystem::remove_all(dir);
}

TEST(GltfWrite, RefusesWhatItCannotWrite) {
  RC_CLAUSE("CHAR-1");
  {
    Scene s = make_character(Complexity::simple);
    s.skeleton.joints[1].rest.translation[0] = std::nan("");
    EXPECT_THROW(write_gltf(s), GltfWriteError);
  }
  {
    Scene s = make_character(Complexity::simple);
    s.meshes[0].positions[0][0] = 1e39;  // beyond binary32
    EXPECT_THROW(write_gltf(s), GltfWriteError);
  }
  {
    Scene s = make_character(Complexity::simple);
    s.meshes[0].joints[0][0] = static_cast<std::uint32_t>(s.meshes[0].node);  // "body" is outside the skin
    EXPECT_THROW(write_gltf(s), GltfWriteError);
  }
  {
    Scene s = make_character(Complexity::simple);
    s.skeleton.joints[0].parent = 2;  // a parent after its child
    EXPECT_THROW(write_gltf(s), GltfWriteError);
  }
  {
    Scene s = make_character(Complexity::simple);
    s.clips[0].channels[0].values.pop_back();
    EXPECT_THROW(write_gltf(s), GltfWriteError);
  }
}

}  // namespace
