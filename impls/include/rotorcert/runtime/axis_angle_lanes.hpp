// AXIS-1's inputs for L elements at once, the common first half of dq's and motor_pga's
// rotate_about_axis lanes (dq/dlb_lanes.hpp, motor_pga/motor_lanes.hpp): the ABI's centres,
// axes, angles and points in SoA lanes, the cheap tests, u/|u| and sin, cos of angle/2. Data:
// element e's centre at c + 3 e, axis at u + 3 e, angle at angle + e, point at p + 3 e.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>

#include <rotorcert/runtime/ordinary_range.hpp>

namespace rotorcert::runtime {

template <class S, std::size_t L>
struct AxisAngleLanes {
  using Flag = std::int32_t;

  S centre[3][L], point[3][L];
  S axis[3][L];  // u/|u|, divided component by component
  S sin_half[L], cos_half[L];
  Flag ok[L];    // centre, angle and point finite, |u|^2 ordinary (so u finite and nonzero)

  void load(const S* c, const S* u, const S* angle, const S* p) {
    constexpr S kMax = std::numeric_limits<S>::max();
    // Copied into lane arrays first: read in place, the next loop does not vectorise (GCC 12).
    S uu[3][L], ang[L], half[L];
    for (std::size_t l = 0; l < L; ++l) {
      for (std::size_t j = 0; j < 3; ++j) uu[j][l] = u[3 * l + j], centre[j][l] = c[3 * l + j], point[j][l] = p[3 * l + j];
      ang[l] = angle[l];
    }
    for (std::size_t l = 0; l < L; ++l) {
      const S ux = uu[0][l], uy = uu[1][l], uz = uu[2][l], a = ang[l];
      // |u|^2 as both element paths take it, the norm of the quaternion (u, 0).
      const S n2 = ux * ux + uy * uy + uz * uz + S(0) * S(0);
      const bool ordinary = is_ordinary_square_lane(n2);
      const bool finite_c = finite3_lane(centre[0][l], centre[1][l], centre[2][l]);
      const bool finite_p = finite3_lane(point[0][l], point[1][l], point[2][l]);
      const bool finite_a = (a <= kMax) & (a >= -kMax);
      ok[l] = Flag(ordinary & finite_c & finite_p & finite_a);
      const S n = std::sqrt(n2);
      axis[0][l] = ux / n;
      axis[1][l] = uy / n;
      axis[2][l] = uz / n;
      half[l] = a / S(2);
    }
    // The element functions' own libm calls, lane by lane (no vector sin or cos gives their bits),
    // on 0 where the lane is not ok, so that they see no Inf or NaN (no errno, no FE_INVALID); the
    // select sits here, as a select on a lane flag in the loop above keeps it from vectorising.
    for (std::size_t l = 0; l < L; ++l) {
      const S h = ok[l] != 0 ? half[l] : S(0);
      sin_half[l] = std::sin(h), cos_half[l] = std::cos(h);
    }
  }
};

}  // namespace rotorcert::runtime
