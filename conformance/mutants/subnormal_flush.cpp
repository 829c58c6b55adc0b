// normalize that flushes subnormal components to zero (FTZ/DAZ behaviour) before scaling.
#include "mutant.hpp"

namespace {
using namespace mutant;
struct Impl {
  using Scalar = float;
  MUTANT_META(subnormal_flush, "subnormal input flushed to zero")
  static Status normalize(const Q<float>& q_in, Q<float>& out) {
    Q<float> q = q_in;
    for (float& x : q)
      if (std::fpclassify(x) == FP_SUBNORMAL) x = std::copysign(0.0f, x);  // BUG: flush
    if (!valid(q)) return Status::domain_error;
    out = normalized(q);
    return Status::ok;
  }
};
}  // namespace
ROTORCERT_DEFINE_ENTRY(mutant_subnormal_flush, Impl)
