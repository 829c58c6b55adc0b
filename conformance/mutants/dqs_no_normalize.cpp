// Dual-quaternion skinning that blends sum w_i s_i sigma_i and applies it without normalising.
#include "mutant.hpp"

namespace {
using namespace mutant;
struct Impl {
  using Scalar = float;
  MUTANT_META(dqs_no_normalize, "DQS blending without normalisation")
  static Status skin_dual_quaternion(std::span<const Q<float>> q, std::span<const V<float>> t,
                                     std::span<const float> w, const V<float>& v, V<float>& out) {
    if (q.size() != w.size() || !valid_weights(w) || !finite(v)) return Status::domain_error;
    std::size_t p = 0;
    while (!(w[p] > 0)) ++p;
    D<float> sum{};
    for (std::size_t i = 0; i < q.size(); ++i) {
      if (!valid(q[i]) || !finite(t[i])) return Status::domain_error;
      const D<float> u = from_rt(normalized(q[i]), t[i]);
      const float f = dot(q[i], q[p]) < 0 ? -w[i] : w[i];
      for (int c = 0; c < 8; ++c) sum[c] += f * u[c];
    }
    out = apply_point(sum, v);  // BUG: apply_point(dnormalized(sum), v)
    return Status::ok;
  }
};
}  // namespace
ROTORCERT_DEFINE_ENTRY(mutant_dqs_no_normalize, Impl)
