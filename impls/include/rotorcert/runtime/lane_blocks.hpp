// The batch driver of the SoA lane kernels (dq/dlb_lanes.hpp, motor_pga/motor_lanes.hpp,
// rotor/rotor_lanes.hpp): it cuts a batch of n elements into blocks for a kernel of Wide lanes,
// then the rest into blocks for a kernel of Narrow lanes, and hands the last n mod Narrow elements
// to a per-element function. Those are not padded into a lane block: a block reads its inputs
// back as vectors right after storing them lane by lane, and for one element that store-to-load
// forwarding stall cost several times the element's arithmetic (dq_blend of one element: 340 ns
// in a padded block of 4).
#pragma once

#include <cstddef>
#include <cstdint>

#include <rotorcert/impl_abi.h>

namespace rotorcert::runtime {

/// Two input arrays of a batch: element e's scalars at a + a_stride e and b + b_stride e (the ABI
/// layouts). `run(kernel, a_block, b_block)` runs a kernel on the block starting at those
/// pointers; `finish(kernel, first, count)` takes the results of its `count` lanes for elements
/// first .. first + count - 1; `single(e)` computes element e alone.
template <std::size_t Wide, std::size_t Narrow, class S, class WideKernel, class NarrowKernel, class Run, class Finish,
          class Single>
void in_lane_blocks(std::size_t n, const S* a, std::size_t a_stride, const S* b, std::size_t b_stride,
                    WideKernel& wide, NarrowKernel& narrow, Run run, Finish finish, Single single) {
  std::size_t i = 0;
  for (; i + Wide <= n; i += Wide) {
    run(wide, a + a_stride * i, b + b_stride * i);
    finish(wide, i, Wide);
  }
  for (; i + Narrow <= n; i += Narrow) {
    run(narrow, a + a_stride * i, b + b_stride * i);
    finish(narrow, i, Narrow);
  }
  for (; i < n; ++i) single(i);
}

/// in_lane_blocks() with Kernel<S, 16> and Kernel<S, 4>, kernels that flag each lane `ok` where
/// its cheap tests pass: `store(e, kernel, lane)` writes element e from an ok lane, `checked(e)`
/// computes element e on the checked path, `single(e)` an element after the last block (its
/// scalar fast path, or `checked`).
template <template <class, std::size_t> class Kernel, class S, class Run, class Store, class Checked, class Single>
void in_lanes_or_checked(std::size_t n, const S* a, std::size_t a_stride, const S* b, std::size_t b_stride, Run run,
                         Store store, Checked checked, Single single) {
  Kernel<S, 16> wide;
  Kernel<S, 4> narrow;
  in_lane_blocks<16, 4>(n, a, a_stride, b, b_stride, wide, narrow, run,
                        [&](const auto& lanes, std::size_t first, std::size_t count) {
                          for (std::size_t l = 0; l < count; ++l) {
                            if (lanes.ok[l]) [[likely]]
                              store(first + l, lanes, l);
                            else
                              checked(first + l);
                          }
                        },
                        single);
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
