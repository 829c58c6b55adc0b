// normalize(0) = identity with status OK (GLM's choice) instead of DOMAIN_ERROR.
#include "mutant.hpp"

namespace {
using namespace mutant;
struct Impl {
  using Scalar = float;
  MUTANT_META(zero_to_identity, "zero quaternion normalised to identity")
  static Status normalize(const Q<float>& q, Q<float>& out) {
    if (!finite(q)) return Status::domain_error;
    if (!valid(q)) {
      out = {0, 0, 0, 1};  // BUG: DOMAIN_ERROR
      return Status::ok;
    }
    out = normalized(q);
    return Status::ok;
  }
};
}  // namespace
ROTORCERT_DEFINE_ENTRY(mutant_zero_to_identity, Impl)
