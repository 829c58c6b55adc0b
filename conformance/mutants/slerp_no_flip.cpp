// Slerp without the hemisphere flip: obtuse pairs interpolate along the longer arc.
#include "mutant.hpp"

namespace {
using namespace mutant;
struct Impl {
  using Scalar = float;
  MUTANT_META(slerp_no_flip, "slerp without hemisphere flip")
  static Status slerp(const Q<float>& a, const Q<float>& b, const float& t, Q<float>& out) {
    if (!valid(a) || !valid(b) || !std::isfinite(t)) return Status::domain_error;
    out = slerp_unit(normalized(a), normalized(b), t, false);  // BUG: flip iff a.b < 0
    return Status::ok;
  }
};
}  // namespace
ROTORCERT_DEFINE_ENTRY(mutant_slerp_no_flip, Impl)
