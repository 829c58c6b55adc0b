// dq_apply_point rotating by r/|r| but reading the translation 2 d r* off the raw input: right
// for unit dual quaternions, scaled by |r|^2 otherwise.
#include "mutant.hpp"

namespace {
using namespace mutant;
struct Impl {
  using Scalar = double;
  MUTANT_META(dq_translation_unnormalized, "DQ translation extracted without normalising")
  static Status dq_apply_point(const D<double>& d, const V<double>& p, V<double>& out) {
    if (!valid(d) || !finite(p)) return Status::domain_error;
    const V<double> r = rotate(normalized(real(d)), p);
    const V<double> t = translation(d);  // BUG: translation(d / |r|)
    out = {r[0] + t[0], r[1] + t[1], r[2] + t[2]};
    return Status::ok;
  }
};
}  // namespace
ROTORCERT_DEFINE_ENTRY(mutant_dq_translation_unnormalized, Impl)
