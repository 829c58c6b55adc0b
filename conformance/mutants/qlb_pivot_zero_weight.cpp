// ENGINE GAP (not built): survives QLB-1, see gaps/README.md.
// QLB with the pivot always the first influence, even when its weight is 0.
#include "mutant.hpp"

namespace {
using namespace mutant;
struct Impl {
  using Scalar = float;
  MUTANT_META(qlb_pivot_zero_weight, "QLB pivot = first influence even with weight 0")
  static Status blend_qlb(std::span<const Q<float>> q, std::span<const float> w, Q<float>& out) {
    if (q.size() != w.size() || !valid_weights(w)) return Status::domain_error;
    for (const auto& x : q)
      if (!valid(x)) return Status::domain_error;
    const std::size_t p = 0;  // BUG: first influence with positive weight
    Q<float> sum{0, 0, 0, 0};
    for (std::size_t i = 0; i < q.size(); ++i)
      sum = add(sum, scale(dot(q[i], q[p]) < 0 ? -w[i] : w[i], normalized(q[i])));
    if (!valid(sum)) return Status::domain_error;
    out = normalized(sum);
    return Status::ok;
  }
};
}  // namespace
ROTORCERT_DEFINE_ENTRY(mutant_qlb_pivot_zero_weight, Impl)
