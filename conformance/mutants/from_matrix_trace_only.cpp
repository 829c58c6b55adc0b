// from_matrix by the trace formula only (w = sqrt(1 + tr)/2, v from the skew part / 4w): no
// Shepperd pivot, so near half turns (w -> 0) the division by w amplifies the rounding.
#include "mutant.hpp"

namespace {
using namespace mutant;
struct Impl {
  using Scalar = float;
  MUTANT_META(from_matrix_trace_only, "from_matrix trace-only method")
  static Status from_matrix(const M<float>& m, Q<float>& out) {
    for (float x : m)
      if (!std::isfinite(x)) return Status::domain_error;
    auto at = [&](int r, int c) { return m[c * 3 + r]; };
    const float w = 0.5f * std::sqrt(std::max(0.0f, 1 + at(0, 0) + at(1, 1) + at(2, 2)));  // BUG: no pivot
    const float f = 0.25f / w;
    out = normalized(Q<float>{(at(2, 1) - at(1, 2)) * f, (at(0, 2) - at(2, 0)) * f, (at(1, 0) - at(0, 1)) * f, w});
    return valid(out) ? Status::ok : Status::domain_error;
  }
};
}  // namespace
ROTORCERT_DEFINE_ENTRY(mutant_from_matrix_trace_only, Impl)
