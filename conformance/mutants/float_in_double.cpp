// A double table that normalises in float (an accumulator declared float in a templated path).
#include "mutant.hpp"

namespace {
using namespace mutant;
struct Impl {
  using Scalar = double;
  MUTANT_META(float_in_double, "float accumulation in a double path")
  static Status normalize(const Q<double>& q, Q<double>& out) {
    if (!valid(q)) return Status::domain_error;
    const Q<float> f{float(q[0]), float(q[1]), float(q[2]), float(q[3])};  // BUG: binary32 inside
    const Q<float> n = normalized(f);
    out = {n[0], n[1], n[2], n[3]};
    return Status::ok;
  }
};
}  // namespace
ROTORCERT_DEFINE_ENTRY(mutant_float_in_double, Impl)
