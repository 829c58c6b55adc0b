// A results file: what an implementation in any language returned for exported test vectors.
// Format "rotorcert-results" version 1, schema spec/results.schema.json, documented in
// conformance/VECTORS.md. Parsing checks the structure only; the values are decoded against
// the vectors they answer (check.hpp), which know each output's layout.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <rotorcert/reference/metrics.hpp>

namespace rotorcert::vectors {

/// One result: the status and outputs of one vector.
struct ResultEntry {
  std::string id;               // the vector's id
  std::string json_path;        // "/results/17", for messages
  std::uint8_t status = 0;      // RC_OK, RC_DOMAIN_ERROR, or the raw byte an adapter passed through
  int call_rc = 0;              // nonzero: the call as a whole failed (optional field "call_rc")
  nlohmann::json out;           // {"out_q": [values...]}, decoded by the grading
  std::string modified_inputs;  // HYG-1: what the call modified in its inputs ("" = nothing)
};

struct ResultsFile {
  std::filesystem::path file;
  std::string name, version, scalar, description;  // "implementation"
  std::optional<std::vector<std::string>> claimed_clauses, claimed_levels;
  std::string vectors;                     // as written: the export's directory or index.json, relative to `file`
  std::vector<std::string> unsupported_ops;  // ABI ops declared NOT_SUPPORTED (RESULT-1)
  std::vector<std::string> preconditions, conventions;  // DECL-1 declarations, "op:id"
  std::vector<std::string> hygiene;  // the hygiene clauses the writer checked on every call ("HYG-1")
  std::vector<ResultEntry> results;

  ref::Format format() const { return scalar == "float" ? ref::Format::binary32 : ref::Format::binary64; }
  /// `vectors` resolved against the directory of `file`.
  std::filesystem::path vectors_path() const;
};

inline constexpr int kResultsFormatVersion = 1;

/// Parses the structure of a results file. Throws VectorsError naming the file and JSON path.
ResultsFile parse_results(const nlohmann::json& j, const std::filesystem::path& file);

}  // namespace rotorcert::vectors
