// Slerp with the angle from acos of the dot product (theta = acos(a.b)): the textbook formula.
// Near-identical inputs lose half their digits (acos is ill-conditioned at 1); the 0/0 at
// theta = 0 is guarded, so only the accuracy is wrong.
#include "mutant.hpp"

namespace {
using namespace mutant;
struct Impl {
  using Scalar = float;
  MUTANT_META(slerp_acos, "slerp angle by acos of a dot product")
  static Status slerp(const Q<float>& a_in, const Q<float>& b_in, const float& t, Q<float>& out) {
    if (!valid(a_in) || !valid(b_in) || !std::isfinite(t)) return Status::domain_error;
    const Q<float> a = normalized(a_in);
    Q<float> b = normalized(b_in);
    float d = dot(a, b);
    if (d < 0) b = neg(b), d = -d;
    const float theta = std::acos(std::min(d, 1.0f));  // BUG: acos, not atan2(|a - b|, |a + b|)
    if (theta == 0) {
      out = a;
      return Status::ok;
    }
    const float s = std::sin(theta);
    out = add(scale(std::sin((1 - t) * theta) / s, a), scale(std::sin(t * theta) / s, b));
    return Status::ok;
  }
};
}  // namespace
ROTORCERT_DEFINE_ENTRY(mutant_slerp_acos, Impl)
