// Slerp flipping the hemisphere on a.b <= 0 instead of < 0: the tie (dot exactly 0) flips.
#include "mutant.hpp"

namespace {
using namespace mutant;
struct Impl {
  using Scalar = float;
  MUTANT_META(tie_flip_le, "hemisphere flip on dot <= 0")
  static Status slerp(const Q<float>& a, const Q<float>& b, const float& t, Q<float>& out) {
    if (!valid(a) || !valid(b) || !std::isfinite(t)) return Status::domain_error;
    out = slerp_unit(normalized(a), normalized(b), t, dot(a, b) <= 0);  // BUG: < 0
    return Status::ok;
  }
};
}  // namespace
ROTORCERT_DEFINE_ENTRY(mutant_tie_flip_le, Impl)
