// rotor_m2: the paper's Method 2 with the signs corrected (ERRATUM-2): quaternion -> rotor by
// the coefficient map Phi(q) = w - x e23 - y e31 - z e12 (Q2R-1), no trigonometry on the way in;
// every operation in Cl(3,0) (impls/rotor/rotor3.hpp) and the quaternion read back by Phi^-1.
// The same code as rotor_m1 except this conversion.
#include <rotorcert/impl_table.hpp>

#include "../rotor/rotor3.hpp"

namespace {

using rotorcert::impl::Quat;
using rotorcert::rotor::Rotor3;

struct Method2 : rotorcert::rotor::PhiReadout {
  /// Phi(q/|q|): a normalisation (EDGE-5) and a move of coefficients with sign changes.
  template <class S>
  static Rotor3<S> in(const Quat<S>& q) {
    const Quat<S> n = rotorcert::rotor::normalized(q);
    return {n[3], -n[0], -n[1], -n[2]};
  }
  /// Phi(q), exact (COMPOSE-1 and INV-1 keep the scale of their inputs).
  template <class S>
  static Rotor3<S> in_scaled(const Quat<S>& q) { return {q[3], -q[0], -q[1], -q[2]}; }
};

constexpr const char* kClauses[] = {
    // Core
    "QUAT-2", "AXANG-1", "AXANG-2", "AXANG-3", "AXANG-4", "NORM-1", "COMPOSE-1", "INV-1", "APPLY-1", "APPLY-2",
    "APPLY-3", "MAT-1", "MAT-2",
    // Interp
    "LOG-1", "LOG-2", "EXP-1", "EXP-2", "SQRT-1", "SLERP-1", "SLERP-2", "SLERP-3", "SLERP-4", "SLERP-5", "NLERP-1",
    // Blend
    "QLB-1", "LOGBLEND-1",
    // Skinning (linear blend skinning only)
    "SKIN-1",
    // Robust
    "MAT-3", "EDGE-1", "EDGE-2", "EDGE-3", "EDGE-4", "EDGE-5", "EDGE-6", "EDGE-7", "EDGE-8", "EDGE-9", nullptr};

template <class S>
struct RotorM2 : rotorcert::rotor::RotorOps<S, Method2> {
  static constexpr const char* name = "rotor_m2";
  static constexpr const char* version = "1";
  static constexpr const char* description =
      "GA rotors, corrected Method 2: rotor = Phi(q) = w - x e23 - y e31 - z e12, ops in Cl(3,0)";
  static constexpr std::uint32_t levels =
      RC_LEVEL_CORE | RC_LEVEL_INTERP | RC_LEVEL_BLEND | RC_LEVEL_SKINNING | RC_LEVEL_ROBUST;
  static constexpr const char* const* clauses = kClauses;
};

}  // namespace

ROTORCERT_DEFINE_ENTRY(rotor_m2, RotorM2<float>, RotorM2<double>)
