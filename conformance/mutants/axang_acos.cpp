// to_axis_angle with theta = 2 acos(w): half the digits lost near the identity.
#include "mutant.hpp"

namespace {
using namespace mutant;
struct Impl {
  using Scalar = float;
  MUTANT_META(axang_acos, "to_axis_angle angle by acos(w)")
  static Status to_axis_angle(const Q<float>& q_in, float& angle, V<float>& axis) {
    if (!valid(q_in)) return Status::domain_error;
    const Q<float> q = normalized(q_in);
    const float n = std::hypot(q[0], q[1], q[2]);
    angle = 2 * std::acos(std::clamp(q[3], -1.0f, 1.0f));  // BUG: 2 atan2(|v|, w)
    axis = n == 0 ? V<float>{0, 0, 1} : V<float>{q[0] / n, q[1] / n, q[2] / n};
    return Status::ok;
  }
};
}  // namespace
ROTORCERT_DEFINE_ENTRY(mutant_axang_acos, Impl)
