// normalize that answers a non-finite input with the identity: its guard against a bad input
// returns a plausible rotation with status OK, so the caller never sees the NaN. (A NaN carried
// into the result is ACC-1 nonfinite_propagation since spec 2.7.0; hiding it is the defect EDGE-7
// still catches.)
#include <cmath>

#include "mutant.hpp"

namespace {
using namespace mutant;
struct Impl {
  using Scalar = double;
  MUTANT_META(nan_not_reported, "NaN input answered with the identity")
  static Status normalize(const Q<double>& q, Q<double>& out) {
    if (q[0] == 0 && q[1] == 0 && q[2] == 0 && q[3] == 0) return Status::domain_error;
    if (!std::isfinite(q[0] + q[1] + q[2] + q[3])) {  // BUG: hides the NaN or Inf
      out = {0, 0, 0, 1};
      return Status::ok;
    }
    out = normalized(q);
    return Status::ok;
  }
};
}  // namespace
ROTORCERT_DEFINE_ENTRY(mutant_nan_not_reported, Impl)
