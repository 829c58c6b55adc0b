// Slerp with the parameter reversed: weight t on a and 1 - t on b.
#include "mutant.hpp"

namespace {
using namespace mutant;
struct Impl {
  using Scalar = float;
  MUTANT_META(slerp_t_reversed, "slerp t reversed (1-t)")
  static Status slerp(const Q<float>& a, const Q<float>& b, const float& t, Q<float>& out) {
    if (!valid(a) || !valid(b) || !std::isfinite(t)) return Status::domain_error;
    out = slerp_unit(normalized(a), normalized(b), 1 - t, dot(a, b) < 0);  // BUG: t
    return Status::ok;
  }
};
}  // namespace
ROTORCERT_DEFINE_ENTRY(mutant_slerp_t_reversed, Impl)
