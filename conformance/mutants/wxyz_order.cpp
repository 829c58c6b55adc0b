// The ABI's [x, y, z, w] read as [w, x, y, z] (the GLM/Eigen constructor order, QUAT-3).
#include "mutant.hpp"

namespace {
using namespace mutant;
struct Impl {
  using Scalar = double;
  MUTANT_META(wxyz_order, "w-first order read as xyzw")
  static Status apply_vector(const Q<double>& q, const V<double>& v, V<double>& out) {
    if (!valid(q) || !finite(v)) return Status::domain_error;
    const Q<double> r{q[1], q[2], q[3], q[0]};  // BUG: q[0] is x, not w
    out = rotate(normalized(r), v);
    return Status::ok;
  }
};
}  // namespace
ROTORCERT_DEFINE_ENTRY(mutant_wxyz_order, Impl)
