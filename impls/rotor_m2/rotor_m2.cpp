// rotor_m2: the paper's Method 2 with the signs corrected (ERRATUM-2): quaternion -> rotor by
// the coefficient map Phi(q) = w - x e23 - y e31 - z e12 (Q2R-1), no trigonometry on the way in;
// every operation in Cl(3,0) (impls/rotor/rotor3.hpp) and the quaternion read back by Phi^-1.
// The same code as rotor_m1 except this conversion.
#include <rotorcert/impl_table.hpp>

#include "../rotor/rotor3.hpp"

namespace {

template <class S>
struct RotorM2 : rotorcert::rotor::RotorOps<S, rotorcert::rotor::Method2> {
  static constexpr const char* name = "rotor_m2";
  static constexpr const char* version = "1";
  static constexpr const char* description =
      "GA rotors, corrected Method 2: rotor = Phi(q) = w - x e23 - y e31 - z e12, ops in Cl(3,0)";
  static constexpr std::uint32_t levels = rotorcert::rotor::kRotorLevels;
  static constexpr const char* const* clauses = rotorcert::rotor::kRotorClauses;
};

}  // namespace

ROTORCERT_DEFINE_ENTRY(rotor_m2, RotorM2<float>, RotorM2<double>)
