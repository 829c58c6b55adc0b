// One test-vector file: the cases of one (clause, op, format), with exact inputs, the expected
// status and outputs of the 256-bit reference, and everything an adapter in another language
// needs to run and grade them (array layouts, tolerance class, flags). Format
// "rotorcert-vectors" version 1, schema spec/vectors.schema.json, documented in
// conformance/VECTORS.md.
//
// The cases are the engine's (checks_for_clause): `rotorcert vectors check` and `certify` judge
// the same inputs with the same judge_case(), whichever route the outputs took.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <rotorcert/engine/abi_op.hpp>
#include <rotorcert/engine/cases.hpp>
#include <rotorcert/reference/metrics.hpp>
#include <rotorcert/spec/spec.hpp>

namespace rotorcert::vectors {

inline constexpr int kFormatVersion = 1;
/// The file op of EXP-2: log then exp through the implementation, compared with the input.
inline constexpr const char* kRoundTripOp = "log_exp_round_trip";

/// One test vector.
struct Vector {
  int tc_id = 0;                    // 1-based position in its file
  std::string id;                   // "SLERP-1/slerp/binary64/0001": unique within an export
  engine::Case input;               // exact inputs in ABI layout, k, and the case label (the comment)
  std::vector<std::string> flags;   // sorted_flags(input.flags), RoundTrip first for EXP-2
  ref::Status status = ref::Status::ok;  // the status the spec requires
  engine::Values expected;          // the reference outputs (exact at 256 bits when built, as read when parsed)
  std::string result;               // "valid", "invalid" (DOMAIN_ERROR required) or "acceptable" (ACC-1)
  std::vector<std::string> acceptable;  // ACC-1 conventions that may give another correct output
};

/// One file: the vectors of one (clause, op, format).
struct VectorFile {
  std::string clause, clause_title, level;
  std::string op;      // file op: an ABI op, or kRoundTripOp
  ref::Format format = ref::Format::binary64;
  std::string tolerance;  // class name (tolerance_for(spec, clause, abi op))
  std::uint64_t seed = 1;
  int cases_per_family = 16;
  std::string spec_version, rotorcert_version;
  std::vector<Vector> tests;
  std::filesystem::path path;  // where it was read from (parsed files only)

  bool round_trip() const { return op == kRoundTripOp; }
  /// The ABI op whose descriptor (inputs, reference, bars) judges the vectors: "log" for the round trip.
  const engine::AbiOp& abi_op() const;
};

const char* format_name(ref::Format f);    // "binary32" / "binary64"
const char* scalar_name(ref::Format f);    // "float" / "double"

/// Output arrays of a file op as `clause` judges them (engine::judged_op; for the round trip: out_q,
/// the result of exp(log q)).
std::vector<engine::Array> file_outputs(const std::string& clause, const std::string& file_op);

struct BuildOptions {
  std::uint64_t seed = 1;
  int cases_per_family = 16;
  std::vector<ref::Format> formats = {ref::Format::binary32, ref::Format::binary64};
  std::vector<std::string> clauses;  // empty: every clause with an implementation-visible check
};

/// The vector files of the spec's clauses (spec order, then the clause's ops, then format).
std::vector<VectorFile> build_vector_files(const spec::Spec& spec, const BuildOptions& options);

/// "SLERP-1_slerp_binary64.json"
std::string file_name(const VectorFile& f);

/// The file as JSON text: the header pretty-printed, one test per line (diffable, deterministic).
std::string render(const spec::Spec& spec, const VectorFile& f);

/// Parses a vector file and checks it against the spec: structure, exact inputs, and every
/// expected status and output against the reference recomputed at 256 bits. Throws
/// VectorsError (file and JSON path) on any mismatch: an altered file or another spec version.
VectorFile parse_vector_file(const spec::Spec& spec, const nlohmann::json& j, const std::filesystem::path& file);

/// Parses a value of a vector or results file: a hexfloat or decimal string ("0x1.8p+0", "-0x0p+0",
/// "0.5", "nan", "inf", "-inf"), or a JSON number. Decimals are rounded to the format; a hexfloat
/// must be a value of the format. Returns false (with `why`) for anything else.
bool parse_value(const nlohmann::json& v, ref::Format f, ref::Real& out, std::string& why);

}  // namespace rotorcert::vectors
