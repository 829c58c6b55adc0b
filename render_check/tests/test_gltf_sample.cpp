// GLTF-2: sampling per glTF 2.0 Appendix C, checked against values derived by hand from the
// spec's formulas (written out next to each check), and the pose -> matrices chain.
#include <cmath>
#include <filesystem>

#include <gtest/gtest.h>

#include <rotorcert/render/gltf_load.hpp>
#include <rotorcert/render/sample.hpp>
#include <rotorcert/render/transform.hpp>
#include <rotorcert/testing/clause.hpp>

#include "gltf_test_doc.hpp"

namespace {

using namespace rotorcert::render;
using namespace rotorcert::render::test;

/// One-channel document on a single node, loaded.
Channel one_channel(const char* path, const char* interp, const std::vector<float>& times, const std::vector<float>& values) {
  Doc d;
  d.j["nodes"] = {{{"name", "n"}}};
  add_channel(d, 0, path, interp, times, values);
  const Scene s = d.load();
  EXPECT_EQ(s.clips.size(), 1u);
  return s.clips.at(0).channels.at(0);
}

template <std::size_t N>
void expect_exact(const std::array<double, 4>& got, const std::array<double, N>& want) {
  for (std::size_t i = 0; i < N; ++i) EXPECT_EQ(got[i], want[i]) << "component " << i;
}
template <std::size_t N>
void expect_near(const std::array<double, 4>& got, const std::array<double, N>& want, double tol) {
  for (std::size_t i = 0; i < N; ++i) EXPECT_NEAR(got[i], want[i], tol) << "component " << i;
}

TEST(GltfSample, StepHoldsTheValueUntilTheNextKeyframe) {
  RC_CLAUSE("GLTF-2");
  const Channel ch = one_channel("translation", "STEP", {0, 2, 3}, {1, 2, 3, 4, 5, 6, 7, 8, 9});
  expect_exact(sample_channel(ch, 1.999), std::array<double, 3>{1, 2, 3});
  expect_exact(sample_channel(ch, 2.0), std::array<double, 3>{4, 5, 6});
  expect_exact(sample_channel(ch, 2.5), std::array<double, 3>{4, 5, 6});
  expect_exact(sample_channel(ch, -1.0), std::array<double, 3>{1, 2, 3});  // before: first
  expect_exact(sample_channel(ch, 9.0), std::array<double, 3>{7, 8, 9});   // after: last
}

TEST(GltfSample, LinearTranslationIsLerp) {
  RC_CLAUSE("GLTF-2");
  // t = 0.5 in [0, 2]: s = 0.25, (1 - s) (0, 0, 0) + s (4, 8, -2) = (1, 2, -0.5), exact in binary64.
  const Channel ch = one_channel("translation", "LINEAR", {0, 2}, {0, 0, 0, 4, 8, -2});
  expect_exact(sample_channel(ch, 0.5), std::array<double, 3>{1, 2, -0.5});
}

TEST(GltfSample, LinearRotationIsShortestArcSlerp) {
  RC_CLAUSE("GLTF-2");
  // q0 = (0,0,0,1), q1 = -(1/2,1/2,1/2,1/2): q0.q1 = -1/2 < 0, so glTF's slerp goes to -q1, 60
  // degrees away on the 4-sphere; halfway both weights are sin(30)/sin(60) = 1/sqrt(3):
  // (q0 - q1)/sqrt(3) = (1/2, 1/2, 1/2, 3/2)/sqrt(3).
  const Channel ch = one_channel("rotation", "LINEAR", {0, 1}, {0, 0, 0, 1, -0.5f, -0.5f, -0.5f, -0.5f});
  const double r3 = std::sqrt(3.0);
  expect_near(sample_channel(ch, 0.5), std::array<double, 4>{0.5 / r3, 0.5 / r3, 0.5 / r3, 1.5 / r3}, class_tolerance("eps4", kEps64));
  // A third of the way: angles 20 and 40 degrees: sin(40)/sin(60) q0 + sin(20)/sin(60) (-q1).
  const double d = M_PI / 180, wa = std::sin(40 * d) / std::sin(60 * d), wb = std::sin(20 * d) / std::sin(60 * d);
  expect_near(sample_channel(ch, 1.0 / 3), std::array<double, 4>{wb / 2, wb / 2, wb / 2, wa + wb / 2}, class_tolerance("eps4", kEps64));
}

// SLERP-1 normalises its inputs: keyframes scaled by 2 and by 1/2 (a binary32 keyframe is only
// nearly unit; exact powers of two keep this check exact) interpolate to the same unit rotation
// as the unit keyframes. Computed by hand: 1 and the quarter turn about z, (0, 0, h, h) with
// h = sqrt(1/2), are 45 deg apart on the 4-sphere; halfway is the eighth turn about z,
// (0, 0, sin(22.5 deg), cos(22.5 deg)).
TEST(GltfSample, SlerpNormalisesItsInputs) {
  RC_CLAUSE("GLTF-2");
  const double h = std::sqrt(0.5);
  const Quat a{0, 0, 0, 1}, b{0, 0, h, h};
  const double tol = class_tolerance("eps4", kEps64);
  for (const Quat& got : {slerp(a, b, 0.5), slerp(Quat{0, 0, 0, 2}, Quat{0, 0, h / 2, h / 2}, 0.5)}) {
    expect_near(got, std::array<double, 4>{0, 0, std::sin(M_PI / 8), std::cos(M_PI / 8)}, tol);
    EXPECT_NEAR(std::hypot(got[2], got[3]), 1.0, tol);
  }
}

TEST(GltfSample, LinearRotationUsesThePluggedInterpolation) {
  RC_CLAUSE("GLTF-2");
  const Channel ch = one_channel("rotation", "LINEAR", {0, 1}, {0, 0, 0, 1, 0, 0, 1, 0});
  double seen_s = -1;
  const QuatInterpolation marker = [&](const Quat&, const Quat&, double s) {
    seen_s = s;
    return Quat{7, 7, 7, 7};
  };
  expect_exact(sample_channel(ch, 0.25, marker), std::array<double, 4>{7, 7, 7, 7});
  EXPECT_EQ(seen_s, 0.25);
}

TEST(GltfSample, CubicSplineTangentsAreScaledByTheInterval) {
  RC_CLAUSE("GLTF-2");
  // Keyframes t = 0, 2 (td = 2); x: v0 = 0, out-tangent b0 = 1, in-tangent a1 = 2, v1 = 1.
  // At t = 1, s = 1/2: p = (2s^3-3s^2+1) v0 + td (s^3-2s^2+s) b0 + (-2s^3+3s^2) v1 + td (s^3-s^2) a1
  //                      = 0.5*0 + 2*0.125*1 + 0.5*1 + 2*(-0.125)*2 = 0.25.
  const Channel ch = one_channel("translation", "CUBICSPLINE", {0, 2},
                                 {/*a0*/ 9, 9, 9, /*v0*/ 0, 0, 0, /*b0*/ 1, 0, 0, /*a1*/ 2, 0, 0, /*v1*/ 1, 0, 0, /*b1*/ 9, 9, 9});
  expect_exact(sample_channel(ch, 1.0), std::array<double, 3>{0.25, 0, 0});
  // At the keyframes: the values, never the tangents.
  expect_exact(sample_channel(ch, 0.0), std::array<double, 3>{0, 0, 0});
  expect_exact(sample_channel(ch, 2.0), std::array<double, 3>{1, 0, 0});
}

TEST(GltfSample, CubicSplineRotationIsNormalised) {
  RC_CLAUSE("GLTF-2");
  // Zero tangents, v0 = (0,0,0,1), v1 = (0,0,1,0): halfway the spline gives (0,0,1/2,1/2), which
  // normalised is (0, 0, 1/sqrt2, 1/sqrt2).
  const Channel ch = one_channel("rotation", "CUBICSPLINE", {0, 1}, {0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0});
  expect_near(sample_channel(ch, 0.5), std::array<double, 4>{0, 0, std::sqrt(0.5), std::sqrt(0.5)}, class_tolerance("eps4", kEps64));
}

TEST(GltfSample, InterpolationTestFileAgainstHandDerivedValues) {
  RC_CLAUSE("GLTF-2");
  if (!std::filesystem::is_directory(shared_dir())) GTEST_SKIP() << "../shared/data is absent: the sample files are optional";
  const Scene s = load_gltf_file(shared_dir() / "gltf" / "interpolation_test.gltf");
  auto clip = [&](const std::string& name) -> const Channel& {
    for (const auto& c : s.clips)
      if (c.name == name) return c.channels.at(0);
    throw std::runtime_error("no clip " + name);
  };
  // The keyframe data below are the file's binary32 values (interpolation_test.bin).
  const double t1 = 0.4166666567325592, t2 = 0.875;  // rotation and scale clips: keyframes 1 and 2
  // Step Scale: (0.5,0.5,0.5) on [t1, t2).
  expect_exact(sample_channel(clip("Step Scale"), (t1 + t2) / 2), std::array<double, 3>{0.5, 0.5, 0.5});
  // Step Rotation: keyframe 2 = (0, 0, -0.7071068286895752, 0.7071068286895752) on [0.875, 1.25).
  expect_exact(sample_channel(clip("Step Rotation"), 1.0), std::array<double, 4>{0, 0, -0.7071068286895752, 0.7071068286895752});
  // Linear Rotation: keyframes 1, 2 are z-rotations by -45 and -90 degrees; halfway is -67.5 degrees:
  // (0, 0, -sin(33.75 deg), cos(33.75 deg)), within the binary32 precision of the keyframes.
  const double h = 33.75 * M_PI / 180;
  expect_near(sample_channel(clip("Linear Rotation"), (t1 + t2) / 2), std::array<double, 4>{0, 0, -std::sin(h), std::cos(h)},
              class_tolerance("eps16", kEps32));
  // Linear Translation: keyframes 0 (t=0, y=6.621014595031738) and 1 (t=0.4166666567325592, y=10);
  // halfway y is their mean.
  expect_exact(sample_channel(clip("Linear Translation"), 0.4166666567325592 / 2),
               std::array<double, 3>{-3.2975807189941406, (6.621014595031738 + 10.0) / 2, 0});
  // CubicSpline Translation: zero tangents, keyframes 1 (t=0.4166666567325592, y=10) and
  // 2 (t=0.8333333134651184, y=6): at s = 1/2 both Hermite weights are 1/2: y = 8.
  expect_exact(sample_channel(clip("CubicSpline Translation"), (0.4166666567325592 + 0.8333333134651184) / 2),
               std::array<double, 3>{3.3051798343658447, 8.0, 0});
  // CubicSpline Rotation, keyframes 1 and 2 halfway: td = t2 - t1,
  // p = v1/2 + td/8 b1 + v2/2 - td/8 a2, normalised; z and w components from the file:
  const double td = t2 - t1;
  const double z = -0.3826834559440613 / 2 + td / 8 * -0.04789090156555176 + -0.7071068286895752 / 2 - td / 8 * -0.035464316606521606;
  const double w = 0.9238795638084412 / 2 + td / 8 * 0.9988526701927185 + 0.7071068286895752 / 2 - td / 8 * 0.9993709921836853;
  const double n = std::hypot(z, w);
  expect_near(sample_channel(clip("CubicSpline Rotation"), (t1 + t2) / 2), std::array<double, 4>{0, 0, z / n, w / n},
              class_tolerance("eps4", kEps64));
}

TEST(GltfSample, KeyframeTimesReturnTheKeyframeExactly) {
  RC_CLAUSE("GLTF-2");
  std::vector<Scene> scenes;
  scenes.push_back(skinned_doc().load());
  if (std::filesystem::is_directory(shared_dir()))
    for (const char* dir : {"gltf", "mocap"})
      for (const auto& e : std::filesystem::directory_iterator(shared_dir() / dir))
        if (e.path().extension() == ".gltf") scenes.push_back(load_gltf_file(e.path()));
  std::size_t checked = 0;
  for (const auto& s : scenes)
    for (const auto& c : s.clips)
      for (const auto& ch : c.channels)
        for (std::size_t k = 0; k < ch.times.size(); ++k) {
          // Equal successive times: the later keyframe holds from that time on.
          if (k + 1 < ch.times.size() && ch.times[k + 1] == ch.times[k]) continue;
          const std::size_t e = ch.interpolation == Interpolation::cubicspline ? 3 * k + 1 : k;
          const auto got = sample_channel(ch, ch.times[k]);
          for (std::size_t i = 0; i < ch.width(); ++i) ASSERT_EQ(got[i], ch.values[e * ch.width() + i]) << s.name << " " << c.name << " keyframe " << k;
          ++checked;
        }
  EXPECT_GT(checked, 0u);
}

TEST(GltfSample, PoseClampsTimeAndComposesTheHierarchy) {
  RC_CLAUSE("GLTF-2");
  // root: translation (1,0,0), rotation 180 degrees about z = (0,0,1,0); child: translation (0,2,0).
  // Child global position: (1,0,0) + Rz(180) (0,2,0) = (1,-2,0). Animated: child rotation.
  Doc d;
  d.j["nodes"] = {{{"children", {1}}, {"translation", {1, 0, 0}}, {"rotation", {0, 0, 1, 0}}}, {{"translation", {0, 2, 0}}}};
  add_channel(d, 1, "translation", "LINEAR", {1, 3}, {0, 2, 0, 0, 4, 0});
  const Scene s = d.load();
  const auto& clip = s.clips.at(0);
  EXPECT_EQ(clip.start, 1.0);
  EXPECT_EQ(clip.end, 3.0);
  auto child_position = [&](double t) {
    const auto g = global_matrices(s.skeleton, sample_pose(s.skeleton, clip, t));
    return Vec3{g[1][12], g[1][13], g[1][14]};
  };
  EXPECT_EQ(child_position(0.0), (Vec3{1, -2, 0}));   // clamped to the start
  EXPECT_EQ(child_position(2.0), (Vec3{1, -3, 0}));   // (0,3,0) rotated: (0,-3,0)
  EXPECT_EQ(child_position(10.0), (Vec3{1, -4, 0}));  // clamped to the end
  // No mesh: a skeleton-only document, whose inverse binds invert the rest globals (GLTF-4), so
  // at rest every skinning matrix = global * inverse bind is the identity (exact: small integers).
  ASSERT_TRUE(s.generated_skin);
  const auto g = global_matrices(s.skeleton, rest_pose(s.skeleton));
  EXPECT_EQ(skinning_matrices(s.skeleton, g)[1], identity_matrix());
}

TEST(GltfSample, SkinningMatricesAreGlobalTimesInverseBind) {
  RC_CLAUSE("GLTF-2");
  // skinned_doc: joint 1 ("tip") at rest is at (0,1,0) and its inverse bind translates by (0,-1,0):
  // at rest its skinning matrix is the identity. At t = 1 its rotation is (0,0,1,0) (180 about z):
  // skinning = T(0,1,0) Rz(180) T(0,-1,0), which maps the bind vertex (1,0,0) to (-1,2,0).
  const Scene s = skinned_doc().load();
  const auto rest = skinning_matrices(s.skeleton, global_matrices(s.skeleton, rest_pose(s.skeleton)));
  EXPECT_EQ(rest[1], identity_matrix());
  const auto posed = skinning_matrices(s.skeleton, global_matrices(s.skeleton, sample_pose(s.skeleton, s.clips[0], 1.0)));
  EXPECT_EQ(transform_point(posed[1], {1, 0, 0}), (Vec3{-1, 2, 0}));
}

}  // namespace
