// Tolerances for tests, read from the spec's data (spec/clauses.json, "tolerance_classes"),
// so that no test carries an epsilon of its own.
#pragma once

#include <string>

#include <rotorcert/reference/scalar.hpp>
#include <rotorcert/reference/tolerance.hpp>

namespace rotorcert::testing {

/// The "ref" class: the bar for identities of the reference itself at >= 256 bits (NUM-2).
const ref::Real& ref_class_bar();

/// The strict and loose bars of an eps class ("eps4" ... "eps64"), in eps units.
ref::Bars eps_class_bars(const std::string& name);

}  // namespace rotorcert::testing
