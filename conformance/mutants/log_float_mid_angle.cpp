// A float log whose small-angle branch starts too early: for |v| < 0.25 it uses the first term of
// the series, atan2(|v|, w)/|v| ~ 1/w, whose error |v|^3/3 rad is 4e-5 (350 eps in binary32) at
// |v| = 0.05. EDGE-2's angles (below 1e-3) are too small to see it, random rotations rarely that
// small; the logarithmic angle sweep (section 4a) sees every decade.
#include "mutant.hpp"

#include <cmath>

namespace {
using namespace mutant;
struct Impl {
  using Scalar = float;
  MUTANT_META(log_float_mid_angle, "float log: first-order series up to |v| = 0.25")
  static Status log(const Q<float>& q_in, V<float>& out) {
    if (!valid(q_in)) return Status::domain_error;
    const Q<float> q = normalized(q_in);
    const float n = std::hypot(q[0], q[1], q[2]);
    if (n > 0 && n < 0.25f && q[3] > 0) {
      const float f = 1.0f / q[3];  // BUG: one term of atan2(n, w)/n = (1/w)(1 - n^2/(3 w^2) + ...)
      out = {f * q[0], f * q[1], f * q[2]};
      return Status::ok;
    }
    out = qlog(q);
    return Status::ok;
  }
};
}  // namespace
ROTORCERT_DEFINE_ENTRY(mutant_log_float_mid_angle, Impl)
