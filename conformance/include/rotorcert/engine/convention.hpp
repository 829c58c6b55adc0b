// Conventions: consistent ways of doing rotations that differ from the spec's (LAYOUT-1, Q2R-1,
// COMPOSE-1, APPLY-1, AXANG-2). An implementation that follows one of them fails the clauses
// concerned, rightly; the certificate then also says which convention explains the failure, so
// the reader can tell a convention mismatch at the boundary from a numerical defect.
//
// A convention is a hypothesis about what the implementation computes, written as two maps:
// the spec's function evaluated on mapped inputs, with the reference outputs mapped back into
// the implementation's convention. A failing clause whose every case passes under a hypothesis
// is "consistent with" it.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <rotorcert/engine/abi_op.hpp>

namespace rotorcert::engine {

struct Convention {
  std::string id;           // stable: "reverse_map", "inverse_sandwich", "wxyz_order", ...
  std::string description;  // one line for the certificate
  /// Whether the hypothesis changes anything for this op (otherwise it is not tried on it).
  std::function<bool(const AbiOp& op)> applies;
  /// The inputs on which the spec's function reproduces the implementation's result.
  std::function<Values(const AbiOp& op, const Values& inputs)> map_inputs;
  /// The reference outputs expressed in the implementation's convention.
  std::function<Values(const AbiOp& op, const Values& outputs)> map_outputs;
};

/// Every convention the suite can detect, in the order they are reported.
const std::vector<Convention>& conventions();
/// The convention with that id, or nullptr.
const Convention* find_convention(const std::string& id);

}  // namespace rotorcert::engine
