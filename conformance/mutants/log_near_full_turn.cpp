// log with the vector part's length taken as sqrt(1 - w^2) for w < -0.9 (near a full turn): the
// cancellation of 1 - w^2 as w -> -1 scales the log by up to 1/sqrt(eps) wrong. Random rotations
// rarely come that close to 2 pi; the near-full-turn family (section 4a) always does.
#include "mutant.hpp"

#include <cmath>

namespace {
using namespace mutant;
struct Impl {
  using Scalar = float;
  MUTANT_META(log_near_full_turn, "log near a full turn: |v| from sqrt(1 - w^2)")
  static Status log(const Q<float>& q_in, V<float>& out) {
    if (!valid(q_in)) return Status::domain_error;
    const Q<float> q = normalized(q_in);
    const float n = std::hypot(q[0], q[1], q[2]);
    if (q[3] < -0.9f && n > 0) {
      const float s = std::sqrt(1.0f - q[3] * q[3]);  // BUG: cancels as w -> -1; use |v|
      const float f = std::acos(q[3]) / s;
      out = {f * q[0], f * q[1], f * q[2]};
      return Status::ok;
    }
    out = qlog(q);
    return Status::ok;
  }
};
}  // namespace
ROTORCERT_DEFINE_ENTRY(mutant_log_near_full_turn, Impl)
