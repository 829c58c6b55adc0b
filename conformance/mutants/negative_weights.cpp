// QLB accepting negative weights (it only requires a positive sum).
#include "mutant.hpp"

namespace {
using namespace mutant;
struct Impl {
  using Scalar = float;
  MUTANT_META(negative_weights, "negative weights accepted")
  static Status blend_qlb(std::span<const Q<float>> q, std::span<const float> w, Q<float>& out) {
    if (q.empty() || q.size() != w.size()) return Status::domain_error;
    float total = 0;
    for (std::size_t i = 0; i < q.size(); ++i) {
      if (!valid(q[i]) || !std::isfinite(w[i])) return Status::domain_error;
      total += w[i];  // BUG: w[i] < 0 is outside the domain
    }
    if (!(total > 0)) return Status::domain_error;
    std::size_t p = 0;
    while (!(w[p] > 0)) ++p;
    Q<float> sum{0, 0, 0, 0};
    for (std::size_t i = 0; i < q.size(); ++i)
      sum = add(sum, scale(dot(q[i], q[p]) < 0 ? -w[i] : w[i], normalized(q[i])));
    if (!valid(sum)) return Status::domain_error;
    out = normalized(sum);
    return Status::ok;
  }
};
}  // namespace
ROTORCERT_DEFINE_ENTRY(mutant_negative_weights, Impl)
