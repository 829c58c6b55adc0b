// to_matrix written row-major into a column-major array: the transpose (the inverse rotation).
#include "mutant.hpp"

namespace {
using namespace mutant;
struct Impl {
  using Scalar = double;
  MUTANT_META(to_matrix_transposed, "to_matrix transposed")
  static Status to_matrix(const Q<double>& q, M<double>& out) {
    if (!valid(q)) return Status::domain_error;
    const M<double> m = mutant::to_matrix(normalized(q));
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) out[r * 3 + c] = m[c * 3 + r];  // BUG: transposed
    return Status::ok;
  }
};
}  // namespace
ROTORCERT_DEFINE_ENTRY(mutant_to_matrix_transposed, Impl)
