// ENGINE GAP (not built): survives INV-1 and EDGE-5, see gaps/README.md.
// inverse as the conjugate only, without dividing by |q|^2: right for unit q, wrong otherwise.
#include "mutant.hpp"

namespace {
using namespace mutant;
struct Impl {
  using Scalar = double;
  MUTANT_META(inv_conj_only, "inverse = conjugate on non-unit input")
  static Status inverse(const Q<double>& q, Q<double>& out) {
    if (!valid(q)) return Status::domain_error;
    out = conj(q);  // BUG: conj(q) / |q|^2
    return Status::ok;
  }
};
}  // namespace
ROTORCERT_DEFINE_ENTRY(mutant_inv_conj_only, Impl)
