// normalize(0) = a half turn about x with status OK: a finite rotation made up for an input that has
// none, neither DOMAIN_ERROR nor a sentinel of ACC-1 (all zero, or the identity: zero_sentinel).
#include "mutant.hpp"

namespace {
using namespace mutant;
struct Impl {
  using Scalar = float;
  MUTANT_META(zero_to_half_turn, "zero quaternion normalised to a half turn about x")
  static Status normalize(const Q<float>& q, Q<float>& out) {
    if (!finite(q)) return Status::domain_error;
    if (!valid(q)) {
      out = {1, 0, 0, 0};  // BUG: DOMAIN_ERROR, or a sentinel (0 or the identity)
      return Status::ok;
    }
    out = normalized(q);
    return Status::ok;
  }
};
}  // namespace
ROTORCERT_DEFINE_ENTRY(mutant_zero_to_half_turn, Impl)
