// Calling one op of a table on prepared arrays, through the slot the op list gives it
// (rotorcert/op_id.hpp: with_slot, invoke_slot).
#pragma once

#include <cstddef>
#include <cstdint>

#include <rotorcert/impl_abi.h>
#include <rotorcert/op_id.hpp>

#include "op_layout.hpp"

namespace rotorcert::bench {

/// One call's arrays, in the order of the op's OpSpec (inputs, outputs), of scalar S.
template <class S>
struct CallArgs {
  std::size_t n = 0, k = 0;
  const S* in[kMaxInputs] = {};
  S* out[kMaxOutputs] = {};
  std::uint8_t* status = nullptr;
};

/// Runs body(call) with a callable that makes one call of op `id` of the table (which must have
/// it) on a CallArgs<S> and returns the function's return value. The slot is looked up once, so
/// the timed loop inside body pays only the implementation's own call.
template <class S, class Body>
void with_call(const rc_impl& table, OpId id, Body&& body) {
  with_slot<S>(table, id, [&](auto fn) {
    body([fn](const CallArgs<S>& a) { return invoke_slot(fn, SlotArgs<S>{a.n, a.k, a.in, a.out, a.status}); });
    return 0;
  });
}

}  // namespace rotorcert::bench
