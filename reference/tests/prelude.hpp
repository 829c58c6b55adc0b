// What the reference's test files share: the reference's names, the generators and checks of
// rotorcert::testing, and short names for the reference's types over Real. For test files only
// (it opens namespaces into the file's anonymous namespace).
#pragma once

#include <rotorcert/reference/quaternion.hpp>
#include <rotorcert/reference/result.hpp>
#include <rotorcert/reference/rotation_ops.hpp>
#include <rotorcert/testing/clause.hpp>
#include <rotorcert/testing/generators.hpp>
#include <rotorcert/testing/near.hpp>
#include <rotorcert/testing/tolerance.hpp>

namespace {

using namespace rotorcert::ref;
using namespace rotorcert::ref::clause;
using rotorcert::testing::check_cases;
using rotorcert::testing::near;
using rotorcert::testing::quaternion;
using rotorcert::testing::real_in;
using rotorcert::testing::unit_quaternion;
using rotorcert::testing::vector3;
using Q = Quaternion<Real>;
using QD = Quaternion<double>;
using DQ = DualQuaternion<Real>;
using V3 = Vec3<Real>;

/// The spec's "ref" class (spec/clauses.json, tolerance_classes.ref: 1e-60).
[[maybe_unused]] const Real& ref_class_bar() { return rotorcert::testing::ref_class_bar(); }

}  // namespace
