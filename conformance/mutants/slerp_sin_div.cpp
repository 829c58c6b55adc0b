// Slerp dividing by sin(theta) with no small-angle fallback: 0/0 = NaN at (and near) identity.
#include "mutant.hpp"

namespace {
using namespace mutant;
struct Impl {
  using Scalar = float;
  MUTANT_META(slerp_sin_div, "slerp without small-angle fallback")
  static Status slerp(const Q<float>& a_in, const Q<float>& b_in, const float& t, Q<float>& out) {
    if (!valid(a_in) || !valid(b_in) || !std::isfinite(t)) return Status::domain_error;
    const Q<float> a = normalized(a_in);
    Q<float> b = normalized(b_in);
    if (dot(a_in, b_in) < 0) b = neg(b);
    const Q<float> dif = add(a, neg(b)), sum = add(a, b);
    const float theta = 2 * std::atan2(std::sqrt(dot(dif, dif)), std::sqrt(dot(sum, sum)));
    const float s = std::sin(theta);  // BUG: no fallback when s -> 0
    out = add(scale(std::sin((1 - t) * theta) / s, a), scale(std::sin(t * theta) / s, b));
    return Status::ok;
  }
};
}  // namespace
ROTORCERT_DEFINE_ENTRY(mutant_slerp_sin_div, Impl)
