// normalize that never checks for NaN or Inf: non-finite input gives status OK.
#include "mutant.hpp"

namespace {
using namespace mutant;
struct Impl {
  using Scalar = double;
  MUTANT_META(nan_not_reported, "NaN input not reported")
  static Status normalize(const Q<double>& q, Q<double>& out) {
    if (q[0] == 0 && q[1] == 0 && q[2] == 0 && q[3] == 0) return Status::domain_error;  // BUG: no finiteness check
    out = normalized(q);
    return Status::ok;
  }
};
}  // namespace
ROTORCERT_DEFINE_ENTRY(mutant_nan_not_reported, Impl)
