// Flags of test vectors: a stable CamelCase vocabulary that says what a vector probes, derived
// from the label of the engine's case (cases.cpp) so that adapters in any language can select or
// explain vectors ("skip every Subnormal vector", "why did NearHalfTurn fail?"). Every flag is
// documented in the header of each vector file, as Wycheproof does.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace rotorcert::vectors {

/// The flags of a case label, in vocabulary order. Throws std::logic_error for a label the
/// vocabulary does not know (a new case family must be given flags here).
std::vector<std::string> flags_for_label(const std::string& label);

/// Every flag with its explanation (the file header's "flags" object lists those in use).
const std::map<std::string, std::string>& flag_docs();

}  // namespace rotorcert::vectors
