// nlerp as normalize(lerp(a, b, t)) without the hemisphere flip (GLM's mix-based nlerp).
#include "mutant.hpp"

namespace {
using namespace mutant;
struct Impl {
  using Scalar = double;
  MUTANT_META(nlerp_no_flip, "nlerp without hemisphere flip")
  static Status nlerp(const Q<double>& a_in, const Q<double>& b_in, const double& t, Q<double>& out) {
    if (!valid(a_in) || !valid(b_in) || !std::isfinite(t)) return Status::domain_error;
    const Q<double> s = add(scale(1 - t, normalized(a_in)), scale(t, normalized(b_in)));  // BUG: b' = -b iff a.b < 0
    if (!valid(s)) return Status::domain_error;
    out = normalized(s);
    return Status::ok;
  }
};
}  // namespace
ROTORCERT_DEFINE_ENTRY(mutant_nlerp_no_flip, Impl)
