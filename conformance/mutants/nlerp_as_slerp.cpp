// "slerp" that is really nlerp: normalize((1-t) a + t b'), not constant angular velocity.
#include "mutant.hpp"

namespace {
using namespace mutant;
struct Impl {
  using Scalar = float;
  MUTANT_META(nlerp_as_slerp, "nlerp sold as slerp")
  static Status slerp(const Q<float>& a_in, const Q<float>& b_in, const float& t, Q<float>& out) {
    if (!valid(a_in) || !valid(b_in) || !std::isfinite(t)) return Status::domain_error;
    const Q<float> a = normalized(a_in);
    Q<float> b = normalized(b_in);
    if (dot(a_in, b_in) < 0) b = neg(b);
    out = normalized(add(scale(1 - t, a), scale(t, b)));  // BUG: chord, not arc
    return Status::ok;
  }
};
}  // namespace
ROTORCERT_DEFINE_ENTRY(mutant_nlerp_as_slerp, Impl)
