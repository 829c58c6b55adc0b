// rotate_about_axis rotating about the parallel axis through the origin (c ignored).
#include "mutant.hpp"

namespace {
using namespace mutant;
struct Impl {
  using Scalar = double;
  MUTANT_META(axis_about_origin, "rotate_about_axis rotating about the origin")
  static Status rotate_about_axis(const V<double>& c, const V<double>& u, const double& angle, const V<double>& p,
                                  V<double>& out) {
    if (!finite(c) || !finite(u) || !std::isfinite(angle) || !finite(p)) return Status::domain_error;
    if (u[0] == 0 && u[1] == 0 && u[2] == 0) return Status::domain_error;
    const double n = std::hypot(u[0], u[1], u[2]), s = std::sin(angle / 2);
    out = rotate(Q<double>{s * u[0] / n, s * u[1] / n, s * u[2] / n, std::cos(angle / 2)}, p);  // BUG: R(p - c) + c
    return Status::ok;
  }
};
}  // namespace
ROTORCERT_DEFINE_ENTRY(mutant_axis_about_origin, Impl)
