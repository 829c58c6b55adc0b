// apply_vector as ~R x R (q* v q): the inverse rotation.
#include "mutant.hpp"

namespace {
using namespace mutant;
struct Impl {
  using Scalar = float;
  MUTANT_META(apply_reversed, "apply_vector with ~R x R")
  static Status apply_vector(const Q<float>& q, const V<float>& v, V<float>& out) {
    if (!valid(q) || !finite(v)) return Status::domain_error;
    out = rotate(conj(normalized(q)), v);  // BUG: q, not q*
    return Status::ok;
  }
};
}  // namespace
ROTORCERT_DEFINE_ENTRY(mutant_apply_reversed, Impl)
