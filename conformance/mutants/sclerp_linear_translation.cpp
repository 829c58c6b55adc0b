// "ScLERP" as slerp of the rotation and linear interpolation of the translation: not a screw motion.
#include "mutant.hpp"

namespace {
using namespace mutant;
struct Impl {
  using Scalar = double;
  MUTANT_META(sclerp_linear_translation, "ScLERP interpolating translation linearly")
  static Status dq_sclerp(const D<double>& a_in, const D<double>& b_in, const double& t, D<double>& out) {
    if (!valid(a_in) || !valid(b_in) || !std::isfinite(t)) return Status::domain_error;
    const D<double> a = dnormalized(a_in), b = dnormalized(b_in);
    const Q<double> r = slerp_unit(real(a), real(b), t, dot(real(a_in), real(b_in)) < 0);
    const V<double> ta = translation(a), tb = translation(b);
    const V<double> tt{ta[0] + t * (tb[0] - ta[0]), ta[1] + t * (tb[1] - ta[1]), ta[2] + t * (tb[2] - ta[2])};  // BUG
    out = from_rt(r, tt);
    return Status::ok;
  }
};
}  // namespace
ROTORCERT_DEFINE_ENTRY(mutant_sclerp_linear_translation, Impl)
