// from_axis_angle reading its angle in degrees (GLM < 0.9.6 habit, ERRATUM-5), the ABI says radians.
#include "mutant.hpp"

namespace {
using namespace mutant;
struct Impl {
  using Scalar = float;
  MUTANT_META(axang_degrees, "degrees for radians in from_axis_angle")
  static Status from_axis_angle(const float& angle, const V<float>& axis, Q<float>& out) {
    if (!std::isfinite(angle) || !finite(axis) || (axis[0] == 0 && axis[1] == 0 && axis[2] == 0))
      return Status::domain_error;
    const float n = std::hypot(axis[0], axis[1], axis[2]);
    const float h = angle * std::numbers::pi_v<float> / 180 / 2;  // BUG: angle / 2
    const float s = std::sin(h);
    out = {s * axis[0] / n, s * axis[1] / n, s * axis[2] / n, std::cos(h)};
    return Status::ok;
  }
};
}  // namespace
ROTORCERT_DEFINE_ENTRY(mutant_axang_degrees, Impl)
