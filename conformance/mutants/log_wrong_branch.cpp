// log at the branch cut: log(-1) = (0, 0, -pi) instead of the spec's (0, 0, pi).
#include "mutant.hpp"

namespace {
using namespace mutant;
struct Impl {
  using Scalar = float;
  MUTANT_META(log_wrong_branch, "wrong branch of log at pi")
  static Status log(const Q<float>& q, V<float>& out) {
    if (!valid(q)) return Status::domain_error;
    if (q[0] == 0 && q[1] == 0 && q[2] == 0 && q[3] < 0) {
      out = {0, 0, -std::numbers::pi_v<float>};  // BUG: +pi
      return Status::ok;
    }
    out = qlog(q);
    return Status::ok;
  }
};
}  // namespace
ROTORCERT_DEFINE_ENTRY(mutant_log_wrong_branch, Impl)
