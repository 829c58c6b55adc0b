// Quaternion -> rotor map with one bivector sign flipped: R = w - x e23 - y e31 + z e12 (the
// e12 term has the wrong sign; the way back is the correct inverse map). Compose is then done in
// Cl(3,0) on the wrongly mapped rotors.
#include "mutant.hpp"
#include "rotor3.hpp"

namespace {
using namespace mutant;
namespace rr = rotorcert::rotor;
struct Impl {
  using Scalar = float;
  MUTANT_META(q2r_sign_flip, "rotor map with the e12 sign flipped")
  static rr::Rotor3<float> to_rotor(const Q<float>& q) { return {q[3], -q[0], -q[1], +q[2]}; }  // BUG: +z
  static Status compose(const Q<float>& a, const Q<float>& b, Q<float>& out) {
    if (!valid(a) || !valid(b)) return Status::domain_error;
    const rr::Rotor3<float> r = rr::gp(to_rotor(a), to_rotor(b));
    out = {-r.e23, -r.e31, -r.e12, r.s};
    return Status::ok;
  }
};
}  // namespace
ROTORCERT_DEFINE_ENTRY(mutant_q2r_sign_flip, Impl)
