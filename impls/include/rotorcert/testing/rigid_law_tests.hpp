// The rigid-motion laws of rigid_laws.hpp as a typed gtest suite, written once for every built-in
// table that offers the dual-quaternion ops: each test names its clauses, and a test file runs the
// whole suite on its own tables with one line,
//
//   struct DqTables : rotorcert::testing::rigid_laws::AbiTables<&rotorcert_impl_entry_dq> {};
//   namespace rotorcert::testing::rigid_laws {
//   INSTANTIATE_TYPED_TEST_SUITE_P(Dq, RigidLaws, DqTables);
//   }
//
// which names tests Dq/RigidLaws/0.<law> (ctest: Dq.<law><DqTables>).
// dq and motor_pga run it (impls/dq/test_dq.cpp, impls/motor_pga/test_motor_pga.cpp); what is
// specific to one implementation stays in its file. Tolerances are the spec's eps class bars.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>

#include <gtest/gtest.h>

#include <rotorcert/impl.hpp>
#include <rotorcert/impl_abi.h>
#include <rotorcert/testing/abi_values.hpp>
#include <rotorcert/testing/clause.hpp>
#include <rotorcert/testing/rigid_laws.hpp>

namespace rotorcert::testing::rigid_laws {

/// The tables of a built-in entry point that numbers its binary32 table 0 and its binary64 table 1
/// (dq, motor_pga).
template <rc_impl_entry_fn entry> struct AbiTables {
  static const Ops<float>& f32() { return *entry(RC_ABI_VERSION, 0)->f32; }
  static const Ops<double>& f64() { return *entry(RC_ABI_VERSION, 1)->f64; }
  static const impl::Ops4<float>& f32_v4() { return *entry(RC_ABI_VERSION, 0)->f32_v4; }
  static const impl::Ops4<double>& f64_v4() { return *entry(RC_ABI_VERSION, 1)->f64_v4; }
};

/// SKIN-2, candy wrapper: a vertex at radius 1.5 around the bone axis x, two influences that twist
/// by +theta and -theta about the bone with equal weights. DQS blends the rigid motions: it keeps
/// the radius and the position along the bone.
template <class S> void dqs_keeps_the_radius_of_a_twisted_vertex(const Ops<S>& ops) {
  for (int k = 1; k < 16; ++k) {
    const double theta = k * 3.14159265358979323846 / 16;
    const S sn = S(std::sin(theta / 2)), cs = S(std::cos(theta / 2));
    const std::array<Q<S>, 2> q{Q<S>{sn, 0, 0, cs}, Q<S>{-sn, 0, 0, cs}};
    const std::array<V<S>, 2> t{V<S>{0, 0, 0}, V<S>{0, 0, 0}};
    const std::array<S, 2> w{S(0.5), S(0.5)};
    const V<S> v{S(0.75), S(1.5), S(0)};
    V<S> out;
    std::uint8_t st = 9;
    ops.skin_dual_quaternion(1, 2, q.front().data(), t.front().data(), w.data(), v.data(), out.data(), &st);
    ASSERT_EQ(st, RC_OK);
    const Real scale = max(Real(1), norm3(rv(v)));
    const Real radius = sqrt(Real(out[1]) * Real(out[1]) + Real(out[2]) * Real(out[2]));
    EXPECT_LE((abs(radius - Real(v[1])) / scale / eps<S>()).toDouble(), strict("eps64")) << theta;
    EXPECT_LE((abs(Real(out[0]) - Real(v[0])) / scale / eps<S>()).toDouble(), strict("eps64")) << theta;
  }
}

/// The suite; Tables is an AbiTables (or anything with its four functions).
template <class Tables> class RigidLaws : public ::testing::Test {};
TYPED_TEST_SUITE_P(RigidLaws);

TYPED_TEST_P(RigidLaws, NormaliseMakesRealUnitAndDualOrthogonal) {
  RC_CLAUSE("DQ-4");
  RC_CLAUSE("EDGE-5");
  normalise_makes_real_unit_and_dual_orthogonal<float>(TypeParam::f32());
  normalise_removes_a_large_parallel_part<float>(TypeParam::f32());
  normalise_makes_real_unit_and_dual_orthogonal<double>(TypeParam::f64());
  normalise_removes_a_large_parallel_part<double>(TypeParam::f64());
}

TYPED_TEST_P(RigidLaws, LogAndExpKeepASubnormalRotation) {
  RC_CLAUSE("DQ-8");
  RC_CLAUSE("DQ-9");
  RC_CLAUSE("EDGE-1");
  log_exp_keep_a_subnormal_rotation<float>(TypeParam::f32_v4());
  log_exp_keep_a_subnormal_rotation<double>(TypeParam::f64_v4());
}

TYPED_TEST_P(RigidLaws, LogNearTheCutKeepsTheScrew) {
  RC_CLAUSE("DQ-8");
  log_near_the_cut_keeps_the_screw<float>(TypeParam::f32_v4());
  log_near_the_cut_keeps_the_screw<double>(TypeParam::f64_v4());
}

TYPED_TEST_P(RigidLaws, SclerpOfPureTranslationIsLinearInT) {
  RC_CLAUSE("DQ-5");
  sclerp_of_pure_translation_is_linear_in_t<float>(TypeParam::f32());
  sclerp_of_pure_translation_is_linear_in_t<double>(TypeParam::f64());
}

TYPED_TEST_P(RigidLaws, DqsKeepsTheRadiusOfATwistedVertex) {
  RC_CLAUSE("SKIN-2");
  dqs_keeps_the_radius_of_a_twisted_vertex<float>(TypeParam::f32());
  dqs_keeps_the_radius_of_a_twisted_vertex<double>(TypeParam::f64());
}

TYPED_TEST_P(RigidLaws, IdentityInIdentityOut) {
  RC_CLAUSE("EDGE-1");
  identity_in_identity_out<float>(TypeParam::f32());
  identity_in_identity_out<double>(TypeParam::f64());
}

TYPED_TEST_P(RigidLaws, OutsideTheDomainIsDomainErrorWithNaN) {
  RC_CLAUSE("EDGE-6");
  RC_CLAUSE("EDGE-7");
  RC_CLAUSE("EDGE-9");
  outside_the_domain_is_domain_error_with_nan<float>(TypeParam::f32());
  outside_the_domain_is_domain_error_with_nan<double>(TypeParam::f64());
}

TYPED_TEST_P(RigidLaws, BlendDoesNotFlipOnExactlyZeroDot) {
  RC_CLAUSE("EDGE-3");
  RC_CLAUSE("DQ-6");
  blend_does_not_flip_on_exactly_zero_dot<float>(TypeParam::f32());
  blend_does_not_flip_on_exactly_zero_dot<double>(TypeParam::f64());
}

TYPED_TEST_P(RigidLaws, ApplyPointFastAndCheckedPathsAgree) {
  RC_CLAUSE("DQ-3");
  RC_CLAUSE("EDGE-5");
  RC_CLAUSE("EDGE-7");
  apply_point_fast_and_checked_paths_agree<float>(TypeParam::f32());
  apply_point_fast_and_checked_paths_agree<double>(TypeParam::f64());
}

TYPED_TEST_P(RigidLaws, BlendFastAndCheckedPathsAgree) {
  RC_CLAUSE("DQ-6");
  RC_CLAUSE("EDGE-5");
  blend_fast_and_checked_paths_agree<float>(TypeParam::f32());
  blend_fast_and_checked_paths_agree<double>(TypeParam::f64());
}

TYPED_TEST_P(RigidLaws, DqBatchesGiveTheElementBits) {
  RC_CLAUSE("DQ-1");
  RC_CLAUSE("DQ-2");
  RC_CLAUSE("DQ-4");
  RC_CLAUSE("EDGE-5");
  RC_CLAUSE("EDGE-6");
  RC_CLAUSE("EDGE-7");
  dq_batches_give_the_element_bits<float>(TypeParam::f32());
  dq_batches_give_the_element_bits<double>(TypeParam::f64());
}

TYPED_TEST_P(RigidLaws, SkinBatchesGiveTheElementBits) {
  RC_CLAUSE("SKIN-1");
  RC_CLAUSE("SKIN-2");
  RC_CLAUSE("EDGE-3");
  RC_CLAUSE("EDGE-5");
  RC_CLAUSE("EDGE-6");
  RC_CLAUSE("EDGE-7");
  RC_CLAUSE("EDGE-9");
  skin_batches_give_the_element_bits<float>(TypeParam::f32());
  skin_batches_give_the_element_bits<double>(TypeParam::f64());
}

TYPED_TEST_P(RigidLaws, AxisBatchGivesTheElementBits) {
  RC_CLAUSE("AXIS-1");
  RC_CLAUSE("EDGE-6");
  RC_CLAUSE("EDGE-7");
  axis_batch_gives_the_element_bits<float>(TypeParam::f32());
  axis_batch_gives_the_element_bits<double>(TypeParam::f64());
}

/// The rigid ops against the reference (a smoke check: the systematic run is the suite's). A table
/// that blends otherwise (motor_pga: MOTOR-5) names that clause in its own file's test.
TYPED_TEST_P(RigidLaws, SmokeAgainstReference) {
  RC_CLAUSE("DQ-1");
  RC_CLAUSE("DQ-2");
  RC_CLAUSE("DQ-3");
  RC_CLAUSE("DQ-5");
  RC_CLAUSE("DQ-6");
  RC_CLAUSE("AXIS-1");
  rigid_smoke_against_reference<float>(TypeParam::f32());
  rigid_smoke_against_reference<double>(TypeParam::f64());
}

REGISTER_TYPED_TEST_SUITE_P(RigidLaws, NormaliseMakesRealUnitAndDualOrthogonal, LogAndExpKeepASubnormalRotation,
                            LogNearTheCutKeepsTheScrew, SclerpOfPureTranslationIsLinearInT,
                            DqsKeepsTheRadiusOfATwistedVertex, IdentityInIdentityOut, OutsideTheDomainIsDomainErrorWithNaN,
                            BlendDoesNotFlipOnExactlyZeroDot, ApplyPointFastAndCheckedPathsAgree,
                            BlendFastAndCheckedPathsAgree, DqBatchesGiveTheElementBits,
                            SkinBatchesGiveTheElementBits, AxisBatchGivesTheElementBits, SmokeAgainstReference);

}  // namespace rotorcert::testing::rigid_laws
