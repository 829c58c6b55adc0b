// Comparisons of reference values with the spec's "ref" class, and property runs with a capped
// number of cases (MPFR at 256 bits is slow), shared by the reference's tests.
#pragma once

#include <algorithm>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <rapidcheck.h>

#include <rotorcert/reference/result.hpp>
#include <rotorcert/testing/tolerance.hpp>

namespace rotorcert::testing {

/// |got - want| <= ref class bar * max(1, |want|), per component.
inline bool near(const ref::Real& got, const ref::Real& want) {
  return abs(got - want) <= ref_class_bar() * std::max(ref::Real(1), ref::Real(abs(want)));
}
inline bool near(const ref::Vec3<ref::Real>& a, const ref::Vec3<ref::Real>& b) {
  return near(a[0], b[0]) && near(a[1], b[1]) && near(a[2], b[2]);
}
inline bool near(const ref::Quaternion<ref::Real>& a, const ref::Quaternion<ref::Real>& b) {
  return near(a.w, b.w) && near(a.x, b.x) && near(a.y, b.y) && near(a.z, b.z);
}
inline bool near(const ref::DualQuaternion<ref::Real>& a, const ref::DualQuaternion<ref::Real>& b) {
  return near(a.real, b.real) && near(a.dual, b.dual);
}

/// Runs a rapidcheck property inside the current gtest test with at most `cases` cases (and the
/// seed and other settings of RC_PARAMS); a counterexample is reported as a gtest failure.
template <class F>
void check_cases(int cases, F property) {
  rc::detail::TestParams params = rc::detail::configuration().testParams;
  params.maxSuccess = std::min(params.maxSuccess, cases);
  rc::detail::TestMetadata meta;
  meta.id = std::string(::testing::UnitTest::GetInstance()->current_test_info()->name());
  meta.description = meta.id;
  const auto result = rc::detail::checkTestable(property, meta, params);
  if (!result.template is<rc::detail::SuccessResult>()) {
    std::ostringstream ss;
    rc::detail::printResultMessage(result, ss);
    ADD_FAILURE() << ss.str();
  }
}

}  // namespace rotorcert::testing
