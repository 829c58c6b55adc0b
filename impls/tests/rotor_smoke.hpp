// The smoke property of the rotor group's tables (rotor_m1, rotor_m2, rotor_gen): smoke() of
// rotor/rotor_test_support.hpp, one random input per op against the reference, in binary32 and
// binary64, with the clauses it checks named once here for every table that runs it. Call it
// from a rapidcheck property body: RC_GTEST_PROP(Suite, SmokeAgainstReference, ()) { ... }.
#pragma once

#include <rotorcert/testing/clause.hpp>

#include "../rotor/rotor_test_support.hpp"

namespace rotor_test {

inline void smoke_against_reference(const Ops<float>& f32, const Ops<double>& f64) {
  RC_CLAUSE("NORM-1");
  RC_CLAUSE("COMPOSE-1");
  RC_CLAUSE("INV-1");
  RC_CLAUSE("APPLY-1");
  RC_CLAUSE("APPLY-2");
  RC_CLAUSE("MAT-1");
  RC_CLAUSE("MAT-2");
  RC_CLAUSE("AXANG-1");
  RC_CLAUSE("AXANG-2");
  RC_CLAUSE("LOG-1");
  RC_CLAUSE("EXP-1");
  RC_CLAUSE("SLERP-1");
  RC_CLAUSE("NLERP-1");
  RC_CLAUSE("QLB-1");
  RC_CLAUSE("LOGBLEND-1");
  RC_CLAUSE("SKIN-1");
  smoke<float>(f32);
  smoke<double>(f64);
}

}  // namespace rotor_test
