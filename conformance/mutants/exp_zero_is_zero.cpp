// exp with a small-angle shortcut that drops the scalar part (w = 0 instead of cos|v| ~ 1):
// exp(0) returns the zero quaternion, GLM 0.9.9.8's slip.
#include "mutant.hpp"

namespace {
using namespace mutant;
struct Impl {
  using Scalar = float;
  MUTANT_META(exp_zero_is_zero, "exp(0) returns the zero quaternion")
  static Status exp(const V<float>& v, Q<float>& out) {
    if (!finite(v)) return Status::domain_error;
    const float n = std::hypot(v[0], v[1], v[2]);
    if (n < 1e-6f) {
      out = {v[0], v[1], v[2], 0};  // BUG: w = cos|v| ~ 1
      return Status::ok;
    }
    out = qexp(v);
    return Status::ok;
  }
};
}  // namespace
ROTORCERT_DEFINE_ENTRY(mutant_exp_zero_is_zero, Impl)
