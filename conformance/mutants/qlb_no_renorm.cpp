// QLB without the final renormalisation: sum w_i s_i q_i returned as is.
#include "mutant.hpp"

namespace {
using namespace mutant;
struct Impl {
  using Scalar = float;
  MUTANT_META(qlb_no_renorm, "no renormalisation after QLB blending")
  static Status blend_qlb(std::span<const Q<float>> q, std::span<const float> w, Q<float>& out) {
    if (q.size() != w.size() || !valid_weights(w)) return Status::domain_error;
    for (const auto& x : q)
      if (!valid(x)) return Status::domain_error;
    std::size_t p = 0;
    while (!(w[p] > 0)) ++p;
    Q<float> sum{0, 0, 0, 0};
    for (std::size_t i = 0; i < q.size(); ++i)
      sum = add(sum, scale(dot(q[i], q[p]) < 0 ? -w[i] : w[i], normalized(q[i])));
    out = sum;  // BUG: normalized(sum)
    return Status::ok;
  }
};
}  // namespace
ROTORCERT_DEFINE_ENTRY(mutant_qlb_no_renorm, Impl)
