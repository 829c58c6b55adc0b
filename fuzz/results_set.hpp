// The fixed vectors the results-file harness grades against, and the seed generator answers:
// a few clauses covering the value kinds of a results file (quaternions, an n-way blend, a
// matrix, a dual quaternion, a round trip), 2 cases per family, seed 1.
#pragma once

#include <rotorcert/vectors/vector_set.hpp>

#include "oracle.hpp"

namespace rotorcert::fuzz {

inline const vectors::VectorSet& results_vector_set(ref::Format f) {
  auto build = [](ref::Format format) {
    vectors::BuildOptions o;
    o.seed = 1;
    o.cases_per_family = 2;
    o.formats = {format};
    o.clauses = {"NORM-1", "MAT-2", "EXP-2", "SLERP-3", "QLB-1", "DQ-3", "EDGE-9"};
    vectors::VectorSet set;
    set.index = "<fuzz vectors>/index.json";
    set.seed = o.seed;
    set.cases_per_family = o.cases_per_family;
    set.files = vectors::build_vector_files(embedded_spec(), o);
    return set;
  };
  static const vectors::VectorSet f32 = build(ref::Format::binary32), f64 = build(ref::Format::binary64);
  return f == ref::Format::binary32 ? f32 : f64;
}

}  // namespace rotorcert::fuzz
