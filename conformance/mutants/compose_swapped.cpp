// compose(a, b) returns b a: the order of application swapped (b applied last instead of first).
#include "mutant.hpp"

namespace {
using namespace mutant;
struct Impl {
  using Scalar = double;
  MUTANT_META(compose_swapped, "compose order swapped")
  static Status compose(const Q<double>& a, const Q<double>& b, Q<double>& out) {
    if (!valid(a) || !valid(b)) return Status::domain_error;
    out = mul(b, a);  // BUG: a b
    return Status::ok;
  }
};
}  // namespace
ROTORCERT_DEFINE_ENTRY(mutant_compose_swapped, Impl)
