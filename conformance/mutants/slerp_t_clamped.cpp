// Slerp clamping t to [0, 1] instead of extrapolating.
#include "mutant.hpp"

namespace {
using namespace mutant;
struct Impl {
  using Scalar = double;
  MUTANT_META(slerp_t_clamped, "t clamped to [0,1] in slerp")
  static Status slerp(const Q<double>& a, const Q<double>& b, const double& t, Q<double>& out) {
    if (!valid(a) || !valid(b) || !std::isfinite(t)) return Status::domain_error;
    out = slerp_unit(normalized(a), normalized(b), std::clamp(t, 0.0, 1.0), dot(a, b) < 0);  // BUG: clamp
    return Status::ok;
  }
};
}  // namespace
ROTORCERT_DEFINE_ENTRY(mutant_slerp_t_clamped, Impl)
