// rotor_m1: the paper's Method 1 (Table 1, Appendix A): quaternion -> angle and axis -> rotor
// R = exp(-I u theta/2) (eq. 5), then every operation in Cl(3,0) (impls/rotor/rotor3.hpp) and
// the quaternion read back by Phi^-1 (Q2R-1). Trigonometry on the way in is the cost this
// implementation measures against rotor_m2; the angle unit is radians (ERRATUM-5 corrected).
#include <cmath>
#include <numbers>

#include <rotorcert/impl_table.hpp>

#include "../rotor/rotor3.hpp"

namespace {

using rotorcert::impl::Quat;
using rotorcert::rotor::Rotor3;

struct Method1 : rotorcert::rotor::PhiReadout {
  /// theta/2 = atan2(|v|, w), u = v/|v| (AXANG-1, scale-free: q need not be unit), then
  /// exp(-I u theta/2) = cos(theta/2) - I u sin(theta/2). q is first rescaled by a power of two
  /// so that subnormal or huge components keep full accuracy (not needed where |q|^2 is
  /// ordinary, runtime/ordinary_range.hpp); |v| and u then come from v
  /// rescaled again by its own power of two (norm3, unit_vector): a subnormal v beside w = -1
  /// keeps its axis (EDGE-8). For w < 0 the angle is taken as pi - atan2(|v|, -w), through
  /// sin(pi - x) = sin x and cos(pi - x) = -cos x: sin of the rounded pi is -8.7e-8 in binary32,
  /// which would flip the axis of a rotation near 2 pi. v = 0 gives +-1 exactly (exp(0) = 1; the
  /// angle 2 pi for w < 0), w = 0 the exact half turn (cos(pi/2) rounded is not 0: in binary32
  /// it is -4.4e-8, which would move the hemisphere test of a tie).
  template <class S>
  static Rotor3<S> in(const Quat<S>& q) {
    const Quat<S> r = rotorcert::rotor::safely_rescaled(q);
    const S n = rotorcert::rotor::norm3(r[0], r[1], r[2]);
    if (n == 0) return {r[3] > 0 ? S(1) : S(-1), S(0), S(0), S(0)};
    S c = 0, s = 1;
    if (r[3] != 0) {
      const S half = std::atan2(n, std::abs(r[3]));
      c = std::copysign(std::cos(half), r[3]);
      s = std::sin(half);
    }
    const rotorcert::impl::Vec3<S> u = rotorcert::rotor::unit_vector(rotorcert::impl::Vec3<S>{r[0], r[1], r[2]});
    return {c, -s * u[0], -s * u[1], -s * u[2]};
  }
  /// |q| R (COMPOSE-1 and INV-1 keep the scale of their inputs).
  template <class S>
  static Rotor3<S> in_scaled(const Quat<S>& q) {
    const Rotor3<S> r = in(q);
    const S n = rotorcert::rotor::norm4(q);
    return {n * r.s, n * r.e23, n * r.e31, n * r.e12};
  }
};

template <class S>
struct RotorM1 : rotorcert::rotor::RotorOps<S, Method1> {
  static constexpr const char* name = "rotor_m1";
  static constexpr const char* version = "1";
  static constexpr const char* description =
      "GA rotors, paper's Method 1: quaternion -> angle/axis -> exp(-I u theta/2), ops in Cl(3,0)";
  static constexpr std::uint32_t levels = rotorcert::rotor::kRotorLevels;
  static constexpr const char* const* clauses = rotorcert::rotor::kRotorClauses;
};

}  // namespace

ROTORCERT_DEFINE_ENTRY(rotor_m1, RotorM1<float>, RotorM1<double>)
