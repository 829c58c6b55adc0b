// EDGE-9's rules on a blend's weights for L elements at once, the prologue of the SIMD-lane blend
// and skinning kernels (dq/dlb_lanes.hpp, motor_pga/motor_lanes.hpp, rotor/rotor_lanes.hpp): the
// lane form of impl.hpp's ordinary_weights(). Data: element e's k weights at w + k e (the ABI's
// array). No branch depends on a lane, so the loops vectorise.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>

namespace rotorcert::runtime {

template <class S, std::size_t L>
struct LaneWeights {
  using Flag = std::int32_t;

  S w_max[L];      // the largest weight, by which the kernels divide (the blends are scale-free in w)
  Flag pivot[L];   // the first weight > 0, the hemisphere reference; k where there is none
  Flag ok[L];      // every weight in [0, max] (-0 is 0; NaN, < 0 and +Inf fail) and some > 0

  void scan(std::size_t k, const S* w) {
    constexpr S kMax = std::numeric_limits<S>::max();
    for (std::size_t l = 0; l < L; ++l) {
      ok[l] = 1;
      w_max[l] = 0;
      pivot[l] = Flag(k);
    }
    for (std::size_t i = 0; i < k; ++i)
      for (std::size_t l = 0; l < L; ++l) {
        const S wi = w[k * l + i];
        ok[l] = ok[l] & Flag((wi >= 0) & (wi <= kMax));
        w_max[l] = wi > w_max[l] ? wi : w_max[l];  // std::max's value; a select, so that it vectorises
        pivot[l] = ((pivot[l] == Flag(k)) & (wi > 0)) ? Flag(i) : pivot[l];
      }
    for (std::size_t l = 0; l < L; ++l) ok[l] = ok[l] & Flag(pivot[l] != Flag(k));
  }

  /// Where element l's pivot influence starts in an array of `width` scalars per influence
  /// (influence 0's where there is no pivot: that lane is not ok).
  std::size_t pivot_offset(std::size_t k, std::size_t width, std::size_t l) const {
    return width * k * l + width * (pivot[l] == Flag(k) ? 0 : std::size_t(pivot[l]));
  }
};

}  // namespace rotorcert::runtime
