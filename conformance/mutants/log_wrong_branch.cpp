// log for w < 0 on the wrong branch: atan2(|v|, |w|) v/|v|, the angle of -q with the axis of q (the
// classic "atan2 of |w|" without negating the vector part). exp of it is neither q nor -q, so no
// convention explains it (ACC-1 accepts the log of -q, whose axis is negated). At a negative real
// q it returns 0, the log of -q: acceptable there (LOG-2's minus_one_axis / shorter_arc).
#include "mutant.hpp"

#include <cmath>

namespace {
using namespace mutant;
struct Impl {
  using Scalar = float;
  MUTANT_META(log_wrong_branch, "wrong branch of log for w < 0")
  static Status log(const Q<float>& q, V<float>& out) {
    if (!valid(q)) return Status::domain_error;
    if (q[3] < 0) {
      const float n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
      const float s = n > 0 ? std::atan2(n, -q[3]) / n : 0.0f;  // BUG: -q's angle, q's axis
      out = {s * q[0], s * q[1], s * q[2]};
      return Status::ok;
    }
    out = qlog(q);
    return Status::ok;
  }
};
}  // namespace
ROTORCERT_DEFINE_ENTRY(mutant_log_wrong_branch, Impl)
