// Linear blend skinning that assumes the weights sum to 1 (no division by the weight sum).
#include "mutant.hpp"

namespace {
using namespace mutant;
struct Impl {
  using Scalar = float;
  MUTANT_META(skin_linear_no_divide, "skin_linear without dividing by the weight sum")
  static Status skin_linear(std::span<const Q<float>> q, std::span<const V<float>> t, std::span<const float> w,
                            const V<float>& v, V<float>& out) {
    if (q.size() != w.size() || !valid_weights(w) || !finite(v)) return Status::domain_error;
    V<float> sum{0, 0, 0};
    for (std::size_t i = 0; i < q.size(); ++i) {
      if (!valid(q[i]) || !finite(t[i])) return Status::domain_error;
      const V<float> r = rotate(normalized(q[i]), v);
      for (int c = 0; c < 3; ++c) sum[c] += w[i] * (r[c] + t[i][c]);
    }
    out = sum;  // BUG: sum / sum(w)
    return Status::ok;
  }
};
}  // namespace
ROTORCERT_DEFINE_ENTRY(mutant_skin_linear_no_divide, Impl)
