// from_axis_angle with the full angle where the half angle belongs: (cos theta, sin theta u).
#include "mutant.hpp"

namespace {
using namespace mutant;
struct Impl {
  using Scalar = double;
  MUTANT_META(axang_full_angle, "half angle and full angle mixed in from_axis_angle")
  static Status from_axis_angle(const double& angle, const V<double>& axis, Q<double>& out) {
    if (!std::isfinite(angle) || !finite(axis) || (axis[0] == 0 && axis[1] == 0 && axis[2] == 0))
      return Status::domain_error;
    const double n = std::hypot(axis[0], axis[1], axis[2]);
    const double s = std::sin(angle), c = std::cos(angle);  // BUG: angle / 2
    out = {s * axis[0] / n, s * axis[1] / n, s * axis[2] / n, c};
    return Status::ok;
  }
};
}  // namespace
ROTORCERT_DEFINE_ENTRY(mutant_axang_full_angle, Impl)
