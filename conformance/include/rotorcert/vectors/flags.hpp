// Flags of test vectors: a stable CamelCase vocabulary that says what a vector probes, set as data
// where the engine makes the case (engine::Case::flags, cases.cpp; never parsed from its label), so
// that adapters in any language can select or explain vectors ("skip every Subnormal vector", "why
// did NearHalfTurn fail?"). Every flag is documented in the header of each vector file, as
// Wycheproof does.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace rotorcert::vectors {

/// A case's flags in vocabulary order, each once. Throws std::logic_error for no flags (a case
/// family that sets none) or a flag the vocabulary does not know (a new flag must be documented).
std::vector<std::string> sorted_flags(std::vector<std::string> flags);

/// Every flag with its explanation (the file header's "flags" object lists those in use).
const std::map<std::string, std::string>& flag_docs();

}  // namespace rotorcert::vectors
