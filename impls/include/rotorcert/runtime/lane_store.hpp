// A lane kernel's per-lane results written into its SoA output arrays (dq/dlb_lanes.hpp,
// motor_pga/motor_lanes.hpp).
#pragma once

#include <cstddef>
#include <utility>

namespace rotorcert::runtime {

/// u into lane l of out, out[c][l] = u[c], as N separate statements: a loop over c inside the
/// loop over lanes keeps GCC 12 from vectorising that loop.
template <class S, std::size_t N, std::size_t L>
[[gnu::always_inline]] inline void store_lane(const S (&u)[N], std::size_t l, S (&out)[N][L]) {
  [&]<std::size_t... c>(std::index_sequence<c...>) { ((out[c][l] = u[c]), ...); }(std::make_index_sequence<N>{});
}

}  // namespace rotorcert::runtime
