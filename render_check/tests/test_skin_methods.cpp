// Posing and skinning the built-in characters with every implementation (PoseJob, SkinJob) and
// comparing with the MPFR reference of the same technique (SKIN-1, SKIN-2; keyframes by the
// implementation's slerp, GLTF-2). Bounds come from the spec classes of the ops each method
// chains (test_skin_support.hpp, chain_bars); which methods must meet them is read from the
// tables' claims and impls/*/expected_failures.json.
#include <cstdio>
#include <memory>
#include <set>

#include <gtest/gtest.h>

#include <rotorcert/registry.hpp>
#include <rotorcert/render/skin_job.hpp>
#include <rotorcert/render/transform.hpp>
#include <rotorcert/testing/clause.hpp>

#include "test_skin_support.hpp"

namespace {

using namespace rotorcert::render;
using namespace rotorcert::render::skin_test;
using rotorcert::ref::Bars;

/// A copy of a built-in double table with some ops removed, to steer the method's choices
/// through the ABI alone.
struct EditedTable {
  rc_impl table{};
  rc_ops_f64 ops{};
};
template <class Edit>
std::unique_ptr<EditedTable> edited(const char* name, Edit edit) {
  const rc_impl* base = rotorcert::impl::find_builtin(name, RC_SCALAR_FLOAT64);
  if (base == nullptr) throw std::runtime_error(std::string("no built-in double table ") + name);
  auto t = std::make_unique<EditedTable>();
  t->table = *base;
  t->ops = *base->f64;
  edit(t->ops);
  t->table.f64 = &t->ops;
  return t;
}

const rc_impl& builtin(const char* name, std::uint32_t scalar) {
  const rc_impl* t = rotorcert::impl::find_builtin(name, scalar);
  if (t == nullptr) throw std::runtime_error(std::string("no built-in table ") + name);
  return *t;
}

bool supports(const rc_impl& t, Technique k) { return missing_ops(t, k).empty(); }

TEST(SkinMethods, CapabilitiesFollowTheAbi) {
  // Facts about the built-in tables (their ops are listed by `rotorcert list`).
  EXPECT_TRUE(supports(builtin("rotor_m2", RC_SCALAR_FLOAT64), Technique::lbs));
  EXPECT_FALSE(supports(builtin("rotor_m2", RC_SCALAR_FLOAT64), Technique::dqs));
  EXPECT_FALSE(supports(builtin("motor_pga", RC_SCALAR_FLOAT64), Technique::lbs));
  EXPECT_TRUE(supports(builtin("motor_pga", RC_SCALAR_FLOAT64), Technique::dqs));
  EXPECT_EQ(missing_ops(builtin("dq", RC_SCALAR_FLOAT64), Technique::lbs), "slerp, to_matrix");
  EXPECT_TRUE(supports(builtin("glm_quat", RC_SCALAR_FLOAT32), Technique::lbs));
  EXPECT_TRUE(supports(builtin("glm_quat", RC_SCALAR_FLOAT32), Technique::dqs));
  EXPECT_EQ(missing_ops(builtin("glm_mix", RC_SCALAR_FLOAT32), Technique::lbs), "compose, apply_vector, to_matrix");
  EXPECT_THROW(make_method(builtin("glm_mix", RC_SCALAR_FLOAT32), Technique::lbs), std::invalid_argument);

  // The report's list: every method the brief names is there.
  std::set<std::string> names;
  for (const auto& m : builtin_methods()) names.insert(m.name());
  for (const char* n : {"glm_quat float LBS", "eigen_quat double LBS", "dq double DQS", "motor_pga float DQS",
                        "rotor_m1 double LBS", "rotor_m2 float LBS", "rotor_simd float LBS", "rotor_gen float LBS",
                        "rotor_gen double LBS", "paper_literal float LBS"})
    EXPECT_EQ(names.count(n), 1u) << n;
  EXPECT_EQ(names.count("glm_mix float LBS") + names.count("glm_mix float DQS"), 0u);

  // The same table with an op removed: only the pointers decide, the name stays.
  const auto no_matrix = edited("rotor_m2", [](rc_ops_f64& o) { o.to_matrix = nullptr; });
  EXPECT_EQ(missing_ops(no_matrix->table, Technique::lbs), "to_matrix");
  const auto dq = make_method(builtin("dq", RC_SCALAR_FLOAT64), Technique::dqs);
  EXPECT_EQ(dq.key_interpolation(), KeyInterpolation::sclerp);  // dq has no slerp
  EXPECT_EQ(dq.dqs_route(), DqsRoute::blend_and_apply);
  EXPECT_EQ(dq.pose_blend(), PoseBlend::dlb);
  const auto no_blend = edited("dq", [](rc_ops_f64& o) { o.dq_blend = nullptr; });
  const auto dq2 = make_method(no_blend->table, Technique::dqs);
  EXPECT_EQ(dq2.dqs_route(), DqsRoute::skin_dual_quaternion);
  EXPECT_EQ(dq2.pose_blend(), PoseBlend::sclerp);
  const auto glm = make_method(builtin("glm_quat", RC_SCALAR_FLOAT64), Technique::dqs);
  EXPECT_EQ(glm.key_interpolation(), KeyInterpolation::slerp);
  // Clauses used, and the claim check: rotor_simd claims every clause its LBS uses.
  const auto simd = make_method(builtin("rotor_simd", RC_SCALAR_FLOAT32), Technique::lbs);
  EXPECT_EQ(simd.clauses(), (std::vector<std::string>{"SLERP-1", "EDGE-5", "COMPOSE-1", "APPLY-1", "MAT-1"}));
  EXPECT_TRUE(simd.unclaimed().empty());
}

TEST(SkinMethods, ConformanceIsReadFromClaimsAndExpectedFailures) {
  // The brief's conforming implementations conform; paper_literal, and GLM's and Eigen's
  // tables (EDGE-5: their matrices and slerp assume unit input), do not.
  std::set<std::string> conf;
  for (const auto& m : builtin_methods())
    if (conforming(m)) conf.insert(m.name());
  for (const char* n : {"rotor_m1 float LBS", "rotor_m1 double LBS", "rotor_m2 float LBS", "rotor_m2 double LBS",
                        "rotor_simd float LBS", "rotor_gen float LBS", "rotor_gen double LBS", "dq float DQS",
                        "dq double DQS", "motor_pga float DQS", "motor_pga double DQS"})
    EXPECT_EQ(conf.count(n), 1u) << n;
  for (const char* n : {"paper_literal float LBS", "glm_quat double LBS", "glm_quat float DQS", "eigen_quat double LBS"})
    EXPECT_EQ(conf.count(n), 0u) << n;
}

class SkinCharacters : public ::testing::TestWithParam<Complexity> {};

// Every clip of the character at four frames, every method; the conforming ones must PASS the
// chained strict bar, both for the skinned vertices and for the virtual vertices of the pose.
TEST_P(SkinCharacters, ConformingMethodsWithinSpecBound) {
  RC_CLAUSE("SKIN-1");
  RC_CLAUSE("SKIN-2");
  RC_CLAUSE("GLTF-2");
  const Character& c = character(GetParam());
  const auto methods = builtin_methods();
  const int chain = chain_length(c.rig);
  std::size_t checked_lbs = 0, checked_dqs = 0;
  std::printf("| character | clip | method ((nc): not conforming) | max mm | mean mm | virtual mm (joint, axis, frame) | eps units | volume %% at end |\n");
  for (const Clip& clip : c.scene.clips) {
    const ClipResult r = measure_clip(methods, c.rig, c.scene.meshes[0], clip, frame_times(clip));
    print_table(to_string(GetParam()), clip.name, r, c.rig);
    for (const Row& row : r.rows) {
      if (!conforming(row.method)) continue;
      const Bars bars = chain_bars(row.method, chain);
      ASSERT_TRUE(row.failure.empty()) << row.method.name() << ": " << row.failure;
      const auto verdict = rotorcert::ref::clause::TOL_1_verdict(row.eps_units, bars);
      EXPECT_EQ(verdict, rotorcert::ref::Verdict::pass)
          << row.method.name() << " " << clip.name << ": " << row.eps_units << " eps units (bars " << bars.strict
          << " / " << bars.loose << "), worst " << row.summary.max_mm << " mm at " << row.summary.worst_frame;
      EXPECT_LE(row.virtual_eps_units, bars.strict) << row.method.name() << " " << clip.name << " virtual vertices";
      (row.method.technique == Technique::lbs ? checked_lbs : checked_dqs) += 1;
    }
  }
  // Not vacuous: conforming methods of both techniques were measured.
  EXPECT_GE(checked_lbs, 3 * c.scene.clips.size());
  EXPECT_GE(checked_dqs, 2 * c.scene.clips.size());
}

INSTANTIATE_TEST_SUITE_P(Builtin, SkinCharacters,
                         ::testing::Values(Complexity::simple, Complexity::medium, Complexity::full),
                         [](const auto& p) { return std::string(to_string(p.param)); });

// The paper as printed (ERRATUM-2, ERRATUM-3) poses the character visibly wrong: its compose
// reverses the order and its sandwich and matrix turn the inverse way.
TEST(SkinMethods, PaperLiteralIsVisiblyWrong) {
  RC_CLAUSE("SKIN-1");
  RC_CLAUSE("ERRATUM-2");
  RC_CLAUSE("ERRATUM-3");
  const Character& c = character(Complexity::medium);
  const auto paper = make_method(builtin("paper_literal", RC_SCALAR_FLOAT32), Technique::lbs);
  ASSERT_FALSE(conforming(paper));
  const Clip& clip = clip_named(c.scene, "bend");
  const ClipResult r = measure_clip({paper}, c.rig, c.scene.meshes[0], clip, frame_times(clip));
  print_table("medium", clip.name, r, c.rig);
  const Row& row = r.rows.at(0);
  ASSERT_TRUE(row.failure.empty()) << row.failure;
  const Bars bars = chain_bars(paper, chain_length(c.rig));
  EXPECT_EQ(rotorcert::ref::clause::TOL_1_verdict(row.eps_units, bars), rotorcert::ref::Verdict::fail);
  // "Visible": above the 1 mm that the proposed visual-equivalence clause calls a failure (a
  // pixel of a 1,080-pixel view of a 2 m character is about 2 mm). It is in fact metres.
  EXPECT_GT(row.summary.max_mm, 1.0);
  EXPECT_GT(row.summary.virtual_max_mm, 1.0);
}

// The other DQS route: skin_dual_quaternion fed with (real part, translation) of each skinning
// motion, and keyframes by dq_sclerp; with dq_blend removed from dq's table.
TEST(SkinMethods, SkinDualQuaternionRouteWithinSpecBound) {
  RC_CLAUSE("SKIN-2");
  const Character& c = character(Complexity::medium);
  const auto t = edited("dq", [](rc_ops_f64& o) { o.dq_blend = nullptr; });
  const auto m = make_method(t->table, Technique::dqs);
  ASSERT_EQ(m.dqs_route(), DqsRoute::skin_dual_quaternion);
  const Clip& clip = clip_named(c.scene, "twist");
  const ClipResult r = measure_clip({m}, c.rig, c.scene.meshes[0], clip, frame_times(clip));
  print_table("medium", clip.name, r, c.rig);
  ASSERT_TRUE(r.rows[0].failure.empty()) << r.rows[0].failure;
  EXPECT_LE(r.rows[0].eps_units, chain_bars(m, chain_length(c.rig)).strict);
}

// Two clips blended (bend at 0.6 s with weight 0.7, twist at 1.3 s with weight 0.3), with each
// blend rule: blend_qlb and dq_blend of the conforming tables, and nlerp and dq_sclerp through
// tables without blend_qlb / dq_blend. Each is compared with the reference of the same rule.
TEST(SkinMethods, PoseBlendWithinSpecBound) {
  RC_CLAUSE("QLB-1");
  RC_CLAUSE("NLERP-1");
  RC_CLAUSE("DQ-6");
  RC_CLAUSE("DQ-5");
  const Character& c = character(Complexity::medium);
  const SkinnedMesh& mesh = c.scene.meshes[0];
  PoseRequest req;
  req.a = {&clip_named(c.scene, "bend"), 0.6};
  req.b = PoseSample{&clip_named(c.scene, "twist"), 1.3};
  req.alpha = 0.3;
  const auto no_qlb = edited("rotor_m2", [](rc_ops_f64& o) { o.blend_qlb = nullptr; });
  const auto no_dlb = edited("motor_pga", [](rc_ops_f64& o) { o.dq_blend = nullptr; });
  std::vector<SkinningMethod> methods;
  for (const auto& m : builtin_methods())
    if (conforming(m)) methods.push_back(m);
  methods.push_back(make_method(no_qlb->table, Technique::lbs));
  methods.push_back(make_method(no_dlb->table, Technique::dqs));
  std::set<PoseBlend> rules;
  const auto& joints = c.rig.skeleton->skin_joints;
  for (const auto& m : methods) {
    rules.insert(m.pose_blend());
    const ReferencePose rp = reference_pose(c.rig, req, m.pose_blend());
    const SkinOutput ref = reference_skin(rp, mesh, m.technique);
    const auto vv = reference_virtual_vertices(rp, joints, kVirtualVertexMetres);
    const FrameResult fr = measure_frame(m, c.rig, mesh, req, ref, vv, joints);
    const double e = fr.vertex.max_mm / (1000.0 * m.epsilon() * size_scale(mesh, ref));
    const Bars bars = chain_bars(m, chain_length(c.rig), m.pose_blend());
    std::printf("blend %-26s rule %-10s max %.3e mm, virtual %.3e mm, %.1f eps units (strict bar %.0f)\n",
                m.name().c_str(), to_string(m.pose_blend()), fr.vertex.max_mm, fr.virtual_vertex.max_mm, e, bars.strict);
    EXPECT_LE(e, bars.strict) << m.name();
  }
  EXPECT_EQ(rules, (std::set<PoseBlend>{PoseBlend::qlb, PoseBlend::nlerp, PoseBlend::dlb, PoseBlend::sclerp}));
}

TEST(SkinJobs, ValidateSaysWhatIsMissing) {
  const Character& c = character(Complexity::simple);
  const auto lbs = make_method(builtin("rotor_m2", RC_SCALAR_FLOAT64), Technique::lbs);
  std::vector<JointTransform> globals, skinning;
  PoseJob job{lbs, &c.rig, {}, nullptr, &skinning, {}};
  EXPECT_NE(job.validate().find("no output"), std::string::npos) << job.validate();
  EXPECT_FALSE(job.run());

  // No op to blend with: blend_qlb and nlerp removed.
  const auto t = edited("rotor_m2", [](rc_ops_f64& o) { o.blend_qlb = nullptr; o.nlerp = nullptr; });
  PoseJob blend{make_method(t->table, Technique::lbs), &c.rig, {}, &globals, &skinning, {}};
  blend.request.b = PoseSample{};
  EXPECT_NE(blend.validate().find("blend"), std::string::npos) << blend.validate();

  // A table that cannot do the technique at all.
  PoseJob mix{SkinningMethod{&builtin("glm_mix", RC_SCALAR_FLOAT32), Technique::lbs}, &c.rig, {}, &globals, &skinning, {}};
  EXPECT_NE(mix.validate().find("compose"), std::string::npos) << mix.validate();

  // DQS skinning needs the dual quaternions of a DQS pose.
  job.globals = &globals;
  ASSERT_TRUE(job.run()) << job.message;
  SkinOutput out;
  SkinJob skin{make_method(builtin("dq", RC_SCALAR_FLOAT64), Technique::dqs), &c.scene.meshes[0], &skinning, &out, {}};
  EXPECT_NE(skin.validate().find("dual quaternions"), std::string::npos) << skin.validate();
  EXPECT_FALSE(skin.run());
}

// A zero rest rotation is outside every op's domain (EDGE-6): the job stops and names the op.
TEST(SkinJobs, DomainErrorStopsTheJob) {
  RC_CLAUSE("EDGE-6");
  Skeleton sk;
  sk.joints.resize(2);
  sk.joints[0].rest.rotation = {0.0, 0.0, 0.0, 0.0};
  sk.joints[1].parent = 0;
  sk.joints[1].rest.translation = {0.0, 1.0, 0.0};
  for (auto& j : sk.joints) j.inverse_bind = identity_matrix();
  sk.skin_joints = {0, 1};
  const Rig rig = prepare_rig(sk);
  std::vector<JointTransform> globals;
  for (Technique k : {Technique::lbs, Technique::dqs}) {
    const auto m = make_method(builtin(k == Technique::lbs ? "rotor_m2" : "motor_pga", RC_SCALAR_FLOAT64), k);
    PoseJob job{m, &rig, {}, &globals, nullptr, {}};
    EXPECT_FALSE(job.run()) << m.name();
    EXPECT_NE(job.message.find("DOMAIN_ERROR"), std::string::npos) << job.message;
  }
}

}  // namespace
