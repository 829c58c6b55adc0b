// rotor_m2: the paper's Method 2 with the signs corrected (ERRATUM-2): quaternion -> rotor by
// the coefficient map Phi(q) = w - x e23 - y e31 - z e12 (Q2R-1), no trigonometry on the way in;
// every operation in Cl(3,0) (impls/rotor/rotor3.hpp) and the quaternion read back by Phi^-1.
// The same code as rotor_m1 except this conversion.
//
// normalize, compose and apply_vector batches run their ordinary elements in SIMD lanes
// (rotor/rotor_lanes.hpp: RotorOps' operations in RotorOps' order, so the same bits) and every
// other element, and the last n mod 4, through RotorOps, which scales only where it must.
#include <cstddef>
#include <cstdint>

#include <rotorcert/impl_table.hpp>
#include <rotorcert/runtime/lane_blocks.hpp>
#include <rotorcert/runtime/target_clones.hpp>

#include "../rotor/rotor3.hpp"
#include "../rotor/rotor_lanes.hpp"

namespace {

namespace rci = rotorcert::impl;
namespace runtime = rotorcert::runtime;
namespace lanes = rotorcert::rotor::lanes;

template <class S>
struct RotorM2 : rotorcert::rotor::RotorOps<S, rotorcert::rotor::Method2> {
  using Base = rotorcert::rotor::RotorOps<S, rotorcert::rotor::Method2>;
  static constexpr const char* name = "rotor_m2";
  static constexpr const char* version = "1";
  static constexpr const char* description =
      "GA rotors, corrected Method 2: rotor = Phi(q) = w - x e23 - y e31 - z e12, ops in Cl(3,0)";
  static constexpr std::uint32_t levels = rotorcert::rotor::kRotorLevels;
  static constexpr const char* const* clauses = rotorcert::rotor::kRotorClauses;

  /// NORM-1 batch: lanes for ordinary |q|^2, RotorOps::normalize otherwise.
  ROTORCERT_TARGET_CLONES_FLAT static int normalize_batch(std::size_t n, const S* q, S* out, std::uint8_t* status) {
    using Checked = rci::detail::Elementwise<&Base::normalize, decltype(&Base::normalize)>;
    const auto checked = [&](std::size_t e) { Checked::run(1, q + 4 * e, out + 4 * e, status + e); };
    runtime::in_lanes_or_checked<lanes::NormalizeLanes>(
        n, q, 4, q, 0, [](auto& k, const S* a, const S* b) { k.run(a, b); }, runtime::copy_lane_outputs<4>(out, status),
        checked, checked);
    return 0;
  }

  /// COMPOSE-1 batch: lanes for ordinary |a|^2 and |b|^2, RotorOps::compose otherwise.
  ROTORCERT_TARGET_CLONES_FLAT static int compose_batch(std::size_t n, const S* a, const S* b, S* out,
                                                       std::uint8_t* status) {
    using Checked = rci::detail::Elementwise<&Base::compose, decltype(&Base::compose)>;
    const auto checked = [&](std::size_t e) { Checked::run(1, a + 4 * e, b + 4 * e, out + 4 * e, status + e); };
    runtime::in_lanes_or_checked<lanes::ComposeLanes>(
        n, a, 4, b, 4, [](auto& k, const S* x, const S* y) { k.run(x, y); }, runtime::copy_lane_outputs<4>(out, status),
        checked, checked);
    return 0;
  }

  /// APPLY-1 batch: lanes for ordinary |q|^2 and finite v, RotorOps::apply_vector otherwise.
  ROTORCERT_TARGET_CLONES_FLAT static int apply_vector_batch(std::size_t n, const S* q, const S* v, S* out,
                                                            std::uint8_t* status) {
    using Checked = rci::detail::Elementwise<&Base::apply_vector, decltype(&Base::apply_vector)>;
    const auto checked = [&](std::size_t e) { Checked::run(1, q + 4 * e, v + 3 * e, out + 3 * e, status + e); };
    runtime::in_lanes_or_checked<lanes::ApplyVectorLanes>(
        n, q, 4, v, 3, [](auto& k, const S* x, const S* y) { k.run(x, y); }, runtime::copy_lane_outputs<3>(out, status),
        checked, checked);
    return 0;
  }
};

}  // namespace

ROTORCERT_DEFINE_ENTRY(rotor_m2, RotorM2<float>, RotorM2<double>)
