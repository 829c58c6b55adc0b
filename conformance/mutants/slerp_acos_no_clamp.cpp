// Slerp with Omega = acos(d) of the flipped dot product and no clamp: when the rounded dot of a
// (near-)antipodal pair is below -1, d = -dot is above 1 and acos gives NaN. Exactly parallel
// inputs (d == 1) are guarded, so identities and random pairs pass; the antipodes whose rounded dot
// is below -1 (section 4a's near-antipodal family) do not.
#include "mutant.hpp"

#include <cmath>

namespace {
using namespace mutant;
struct Impl {
  using Scalar = float;
  MUTANT_META(slerp_acos_no_clamp, "slerp: acos of a rounded dot above 1 is NaN")
  static Status slerp(const Q<float>& a, const Q<float>& b_in, const float& t, Q<float>& out) {
    if (!valid(a) || !valid(b_in) || !std::isfinite(t)) return Status::domain_error;
    Q<float> b = b_in;
    float d = dot(a, b);
    if (d < 0) b = neg(b), d = -d;
    if (d == 1.0f) {
      out = normalized(a);
      return Status::ok;
    }
    const float omega = std::acos(d);  // BUG: NaN for d > 1 (no clamp)
    const float s = std::sin(omega);
    out = normalized(add(scale(std::sin((1 - t) * omega) / s, a), scale(std::sin(t * omega) / s, b)));
    return Status::ok;
  }
};
}  // namespace
ROTORCERT_DEFINE_ENTRY(mutant_slerp_acos_no_clamp, Impl)
