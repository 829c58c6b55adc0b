// `rotorcert vectors run`: runs an implementation table (built-in or plugin, through the C ABI)
// on exported vectors and writes the results file an adapter in another language would write.
// It is the C++ example for adapter authors, and lets the tests check that the results-file
// route and `certify` give the same verdicts.
#pragma once

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include <rotorcert/impl_abi.h>
#include <rotorcert/vectors/vector_set.hpp>

namespace rotorcert::vectors {

/// The results file (format "rotorcert-results") of `table` on every vector of its format in
/// `set`. Operations the table lacks are listed in unsupported_ops. `results_file` is where the
/// file will be written: its "vectors" field is relative to it.
nlohmann::ordered_json run_table(const rc_impl& table, const VectorSet& set, const std::filesystem::path& results_file);

}  // namespace rotorcert::vectors
