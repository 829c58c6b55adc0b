// log returning the raw vector part below a threshold that is far too large (|v| < 1e-2):
// sin(h) u instead of h u, an error of h^3/6.
#include "mutant.hpp"

namespace {
using namespace mutant;
struct Impl {
  using Scalar = double;
  MUTANT_META(log_small_threshold, "log small-angle shortcut with too large a threshold")
  static Status log(const Q<double>& q_in, V<double>& out) {
    if (!valid(q_in)) return Status::domain_error;
    const Q<double> q = normalized(q_in);
    if (q[3] > 0 && std::hypot(q[0], q[1], q[2]) < 1e-2) {  // BUG: threshold 1e-2
      out = {q[0], q[1], q[2]};
      return Status::ok;
    }
    out = qlog(q);
    return Status::ok;
  }
};
}  // namespace
ROTORCERT_DEFINE_ENTRY(mutant_log_small_threshold, Impl)
