// DLB without the antipodality test against a pivot: sum w_i sigma_i, then DQ-4.
#include "mutant.hpp"

namespace {
using namespace mutant;
struct Impl {
  using Scalar = float;
  MUTANT_META(dlb_no_pivot, "DLB without antipodality pivot")
  static Status dq_blend(std::span<const D<float>> d, std::span<const float> w, D<float>& out) {
    if (d.size() != w.size() || !valid_weights(w)) return Status::domain_error;
    D<float> sum{};
    for (std::size_t i = 0; i < d.size(); ++i) {
      if (!valid(d[i])) return Status::domain_error;
      const D<float> u = dnormalized(d[i]);
      for (int c = 0; c < 8; ++c) sum[c] += w[i] * u[c];  // BUG: no sign s_i
    }
    out = dnormalized(sum);
    return Status::ok;
  }
};
}  // namespace
ROTORCERT_DEFINE_ENTRY(mutant_dlb_no_pivot, Impl)
