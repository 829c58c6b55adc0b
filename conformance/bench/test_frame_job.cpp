// FrameJob (the frame benchmarks' pipeline, frame_job.hpp) must pose and skin the render check's
// frame: for every skinning method of the built-in tables, on the built-in simple and medium
// characters, its vertices agree with PoseJob + SkinJob's within VIS-1's strict bars (the spec's
// classes vis-mm and vis-rad), at frames between keyframes and on the clip's ends.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <rotorcert/registry.hpp>
#include <rotorcert/render/character.hpp>
#include <rotorcert/render/method.hpp>
#include <rotorcert/render/pose_job.hpp>
#include <rotorcert/testing/clause.hpp>

#include "bench/frame_job.hpp"

namespace {

namespace r = rotorcert::render;
using rotorcert::bench::FrameAgreement;
using rotorcert::bench::FrameJob;

/// The strict bar of a tolerance class of spec/clauses.json.
double strict_bar(const std::string& cls) {
  std::ifstream in(std::string(ROTORCERT_SPEC_DIR) + "/clauses.json");
  const nlohmann::json spec = nlohmann::json::parse(in);
  return std::stod(spec.at("tolerance_classes").at(cls).at("strict").get<std::string>());
}

struct Character {
  r::Scene scene;
  r::Rig rig;
};

void check_character(r::Complexity c, const std::vector<r::SkinningMethod>& methods,
                     const std::function<void(r::Scene&)>& edit = {}) {
  Character ch;
  ch.scene = r::make_character(c);
  if (edit) edit(ch.scene);
  ch.rig = r::prepare_rig(ch.scene.skeleton);
  ASSERT_GE(ch.scene.clips.size(), 2u);
  const r::Clip& a = ch.scene.clips[0];
  const r::Clip& b = ch.scene.clips[1];
  // Between keyframes (the method's slerp), on a keyframe, before the start and after the end
  // (clamped), and A and B at different times.
  const std::vector<std::pair<double, double>> times = {
      {a.start + 0.27 * a.duration(), b.start + 0.61 * b.duration()},
      {a.start + 0.5 * a.duration(), b.start + 0.13 * b.duration()},
      {a.start - 1.0, b.end + 1.0},
      {a.end, b.start + 0.77 * b.duration()}};
  const double mm = strict_bar("vis-mm"), rad = strict_bar("vis-rad");
  ASSERT_FALSE(methods.empty());
  for (const r::SkinningMethod& m : methods) {
    SCOPED_TRACE(std::string(r::to_string(c)) + " " + m.name());
    FrameJob job;
    job.method = m;
    job.scene = &ch.scene;
    job.rig = &ch.rig;
    job.clip_a = &a;
    job.clip_b = &b;
    job.alpha = 0.25;
    ASSERT_TRUE(job.prepare()) << job.message;
    EXPECT_EQ(job.vertex_count(), ch.scene.vertex_count());
    const FrameAgreement ag = rotorcert::bench::compare_with_render_check(job, times, 1.0);
    ASSERT_TRUE(ag.failure.empty()) << ag.failure;
    EXPECT_LE(ag.max_mm, mm) << "worst: " << ag.worst;
    EXPECT_LE(ag.max_normal_rad, rad) << "worst: " << ag.worst;
    std::printf("%-8s %-28s max %.3g mm, normals %.3g rad\n", r::to_string(c), m.name().c_str(), ag.max_mm,
                ag.max_normal_rad);
  }
}

std::vector<r::SkinningMethod> builtin_methods() { return r::skinning_methods(rotorcert::impl::builtin_tables()); }

TEST(FrameJob, IsTheRenderCheckFrameSimple) {
  RC_CLAUSE("VIS-1");
  RC_CLAUSE("REPORT-2");  // the frame's vertex loops (vertex_kernels.hpp)
  check_character(r::Complexity::simple, builtin_methods());
}

TEST(FrameJob, IsTheRenderCheckFrameMedium) {
  RC_CLAUSE("VIS-1");
  RC_CLAUSE("REPORT-2");  // the frame's vertex loops (vertex_kernels.hpp)
  check_character(r::Complexity::medium, builtin_methods());
}

// The built-in characters give no vertex more than three influences of weight > 0, so the fourth
// lane of the vertex loops' gathers would go unchecked: here every vertex has four distinct
// joints, weighted 0.7, 0.1, 0.1, 0.1 (so that DQS's |b_r| >= 0.4 whatever the signs).
TEST(FrameJob, IsTheRenderCheckFrameWithFourInfluencesPerVertex) {
  RC_CLAUSE("VIS-1");
  RC_CLAUSE("REPORT-2");  // the frame's vertex loops (vertex_kernels.hpp)
  check_character(r::Complexity::medium, builtin_methods(), [](r::Scene& scene) {
    const std::size_t n = scene.skeleton.joints.size();
    ASSERT_GE(n, 4u);
    for (r::SkinnedMesh& mesh : scene.meshes)
      for (std::size_t v = 0; v < mesh.joints.size(); ++v) {
        const std::uint32_t j = mesh.joints[v][0];
        for (std::uint32_t k = 1; k < 4; ++k) mesh.joints[v][k] = static_cast<std::uint32_t>((j + k * (v % 5 + 1)) % n);
        mesh.weights[v] = {0.7, 0.1, 0.1, 0.1};
      }
  });
}

// The routes no built-in table takes (method.hpp's fallbacks), on tables with ops removed:
// keys by dq_sclerp of [q, 0], the DQS pose blend by dq_sclerp, and the render check's
// vertices by skin_dual_quaternion (dq without slerp, dq_blend, dq_apply_point; FrameJob's own
// vertex loop is the same on every route); the LBS pose blend by
// nlerp (glm_quat without blend_qlb).
TEST(FrameJob, IsTheRenderCheckFrameOnFallbackRoutes) {
  RC_CLAUSE("VIS-1");
  const rc_impl* dq = rotorcert::impl::find_builtin("dq", RC_SCALAR_FLOAT64);
  const rc_impl* glm = rotorcert::impl::find_builtin("glm_quat", RC_SCALAR_FLOAT32);
  ASSERT_NE(dq, nullptr);
  ASSERT_NE(glm, nullptr);
  rc_ops_f64 dq_ops = *dq->f64;
  dq_ops.slerp = nullptr;
  dq_ops.dq_blend = nullptr;
  dq_ops.dq_apply_point = nullptr;
  rc_impl dq_table = *dq;
  dq_table.f64 = &dq_ops;
  rc_ops_f32 glm_ops = *glm->f32;
  glm_ops.blend_qlb = nullptr;
  rc_impl glm_table = *glm;
  glm_table.f32 = &glm_ops;
  const r::SkinningMethod dqs = r::make_method(dq_table, r::Technique::dqs);
  const r::SkinningMethod lbs = r::make_method(glm_table, r::Technique::lbs);
  ASSERT_EQ(dqs.key_interpolation(), r::KeyInterpolation::sclerp);
  ASSERT_EQ(dqs.pose_blend(), r::PoseBlend::sclerp);
  ASSERT_EQ(dqs.dqs_route(), r::DqsRoute::skin_dual_quaternion);
  ASSERT_EQ(lbs.pose_blend(), r::PoseBlend::nlerp);
  check_character(r::Complexity::simple, {dqs, lbs});
  check_character(r::Complexity::medium, {dqs, lbs});
}

// A table may answer either sign of a dual quaternion (the same rigid motion; DQ-2 compares up to
// sign): dq's dq_compose wrapped to negate every other element's output, so the skinning palette
// holds both hemispheres, and the frame's vertex loop must sign each influence against the pivot
// (DQ-6) as the table's dq_blend does for the render check. Without that, vertices whose
// influences disagree in sign land far off.
int (*g_dq_compose)(std::size_t, const double*, const double*, double*, std::uint8_t*) = nullptr;
int dq_compose_alternating_sign(std::size_t n, const double* a, const double* b, double* out, std::uint8_t* st) {
  const int rc = g_dq_compose(n, a, b, out, st);
  for (std::size_t e = 1; e < n; e += 2)
    for (std::size_t c = 0; c < 8; ++c) out[8 * e + c] = -out[8 * e + c];
  return rc;
}

TEST(FrameJob, IsTheRenderCheckFrameWhenTheTableAnswersEitherSign) {
  RC_CLAUSE("DQ-6");
  RC_CLAUSE("VIS-1");
  const rc_impl* dq = rotorcert::impl::find_builtin("dq", RC_SCALAR_FLOAT64);
  ASSERT_NE(dq, nullptr);
  rc_ops_f64 ops = *dq->f64;
  g_dq_compose = ops.dq_compose;
  ops.dq_compose = &dq_compose_alternating_sign;
  rc_impl table = *dq;
  table.f64 = &ops;
  const r::SkinningMethod dqs = r::make_method(table, r::Technique::dqs);
  check_character(r::Complexity::simple, {dqs});
  check_character(r::Complexity::medium, {dqs});
}

// A job that cannot be the render check's frame says so instead of running.
TEST(FrameJob, RefusesWhatItCannotPose) {
  RC_CLAUSE("VIS-1");
  Character ch;
  ch.scene = r::make_character(r::Complexity::simple);
  ch.scene.skeleton.joints[0].rest.scale = {2.0, 2.0, 2.0};
  ch.rig = r::prepare_rig(ch.scene.skeleton);
  FrameJob job;
  job.method = r::skinning_methods(rotorcert::impl::builtin_tables()).at(0);
  job.scene = &ch.scene;
  job.rig = &ch.rig;
  job.clip_a = job.clip_b = &ch.scene.clips.at(0);
  EXPECT_FALSE(job.prepare());
  EXPECT_NE(job.message.find("rigid"), std::string::npos) << job.message;
  EXPECT_FALSE(job.run());
}

}  // namespace
