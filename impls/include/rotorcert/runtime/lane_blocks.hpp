// The batch driver of the SoA lane kernels (dq/dlb_lanes.hpp, motor_pga/motor_lanes.hpp): it
// cuts a batch of n elements into blocks for a kernel of Wide lanes, then the rest into blocks
// for a kernel of Narrow lanes, each padded with copies of the rest's last element, so that short
// batches (single elements, the fuzzers' 1..8) run the same lane code as long ones. Padding lanes
// compute a copy and are never read back.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>

#include <rotorcert/impl_abi.h>

namespace rotorcert::runtime {

/// Two input arrays of a batch: element e's scalars at a + a_stride e and b + b_stride e (the ABI
/// layouts), strides at most MaxStride. `run(kernel, a_block, b_block)` runs a kernel on the block
/// starting at those pointers; `finish(kernel, first, count)` takes the results of its first
/// `count` lanes for elements first .. first + count - 1.
template <std::size_t Wide, std::size_t Narrow, std::size_t MaxStride, class S, class WideKernel, class NarrowKernel,
          class Run, class Finish>
void in_lane_blocks(std::size_t n, const S* a, std::size_t a_stride, const S* b, std::size_t b_stride,
                    WideKernel& wide, NarrowKernel& narrow, Run run, Finish finish) {
  std::size_t i = 0;
  for (; i + Wide <= n; i += Wide) {
    run(wide, a + a_stride * i, b + b_stride * i);
    finish(wide, i, Wide);
  }
  S pad_a[Narrow * MaxStride], pad_b[Narrow * MaxStride];
  for (; i < n; i += Narrow) {
    const std::size_t m = std::min(Narrow, n - i);
    for (std::size_t l = 0; l < Narrow; ++l) {
      const std::size_t e = i + std::min(l, m - 1);
      std::copy(a + a_stride * e, a + a_stride * (e + 1), pad_a + a_stride * l);
      std::copy(b + b_stride * e, b + b_stride * (e + 1), pad_b + b_stride * l);
    }
    run(narrow, static_cast<const S*>(pad_a), static_cast<const S*>(pad_b));
    finish(narrow, i, m);
  }
}

/// in_lane_blocks() with Kernel<S, 16> and Kernel<S, 4>, kernels that flag each lane `ok` where
/// its cheap tests pass: `store(e, kernel, lane)` writes element e from an ok lane, `checked(e)`
/// computes element e on the checked path.
template <template <class, std::size_t> class Kernel, std::size_t MaxStride, class S, class Run, class Store,
          class Checked>
void in_lanes_or_checked(std::size_t n, const S* a, std::size_t a_stride, const S* b, std::size_t b_stride, Run run,
                         Store store, Checked checked) {
  Kernel<S, 16> wide;
  Kernel<S, 4> narrow;
  in_lane_blocks<16, 4, MaxStride>(n, a, a_stride, b, b_stride, wide, narrow, run,
                                   [&](const auto& lanes, std::size_t first, std::size_t count) {
                                     for (std::size_t l = 0; l < count; ++l) {
                                       if (lanes.ok[l]) [[likely]]
                                         store(first + l, lanes, l);
                                       else
                                         checked(first + l);
                                     }
                                   });
}

/// The store of in_lanes_or_checked() for kernels whose `out[c][lane]` holds the Out output
/// scalars as the ABI lays them out: element e's at out + Out e, status RC_OK.
template <std::size_t Out, class S>
auto copy_lane_outputs(S* out, std::uint8_t* status) {
  return [out, status](std::size_t e, const auto& lanes, std::size_t l) {
    for (std::size_t c = 0; c < Out; ++c) out[Out * e + c] = lanes.out[c][l];
    status[e] = RC_OK;
  };
}

}  // namespace rotorcert::runtime
