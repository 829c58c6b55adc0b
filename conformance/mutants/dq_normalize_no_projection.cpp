// dq_normalize dividing both parts by |r| without removing the dual part's component along r.
#include "mutant.hpp"

namespace {
using namespace mutant;
struct Impl {
  using Scalar = double;
  MUTANT_META(dq_normalize_no_projection, "dq_normalize without orthogonal projection")
  static Status dq_normalize(const D<double>& d, D<double>& out) {
    if (!valid(d)) return Status::domain_error;
    const double n = std::sqrt(dot(real(d), real(d)));
    out = make(scale(1 / n, real(d)), scale(1 / n, dual(d)));  // BUG: - (r.d/|r|^3) r missing
    return Status::ok;
  }
};
}  // namespace
ROTORCERT_DEFINE_ENTRY(mutant_dq_normalize_no_projection, Impl)
