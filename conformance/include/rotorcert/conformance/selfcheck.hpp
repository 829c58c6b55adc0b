// `rotorcert selfcheck`: every worked example of spec/examples.json against the reference
// (NUM-2). For each example: decode its inputs per the op table, call the reference clause
// function at the reference precision, and compare with the expected outputs:
//   * the status (OK / DOMAIN_ERROR) must match;
//   * each component: |got - expected| <= bar * max(1, |expected|), bar = the strict value of
//     the "ref" tolerance class of clauses.json; NaN matches NaN only; infinities match exactly;
//   * "compare": "rotation": a quaternion (dual quaternion, rotor) output may be the negative;
//   * multivector outputs compare all 2^n blades (blades missing from the example are 0).
#pragma once

#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <rotorcert/spec/spec.hpp>

namespace rotorcert::conformance {

/// One problem of one example: a field that differs (field, expected, got filled in; message
/// the numeric difference, if any), or an example that could not be run (field empty, message
/// only: unknown op, bad input, ...).
struct Mismatch {
  std::string field;  // "q[2]", "r[e13]", "status"; empty for whole-example problems
  std::string expected, got;
  std::string message;
};

struct ExampleResult {
  std::string id;
  std::string clause;
  std::string op;
  bool passed = false;
  std::vector<Mismatch> mismatches;
};

enum class ClauseOutcome { pass, fail, definition };
const char* to_string(ClauseOutcome o);  // "PASS", "FAIL", "DEF"

struct ClauseResult {
  std::string id;
  std::string title;
  bool has_op = false;  // the clause names an op in clauses.json
  ClauseOutcome outcome = ClauseOutcome::definition;
  int examples_passed = 0;
  int examples_total = 0;
  std::vector<ExampleResult> failures;  // failing examples only
};

struct SelfcheckReport {
  std::filesystem::path spec_dir;
  std::string spec_version;
  std::string tolerance;                   // the "ref" bar as written in clauses.json
  std::vector<ClauseResult> clauses;       // every clause of clauses.json, in order
  std::vector<ExampleResult> orphans;      // examples naming no clause of clauses.json (failures)
  int passed = 0, failed = 0, definitions = 0;  // clauses (orphan examples count as failed)
  int examples_passed = 0, examples_total = 0;

  bool ok() const { return failed == 0; }
};

/// The ops the selfcheck dispatcher handles (the op table of SPEC.md, Appendix A), sorted.
std::vector<std::string> supported_ops();

/// The comparison bar: the strict value of the "ref" tolerance class of `spec` (SpecError if none).
ref::Real reference_bar(const spec::Spec& spec);

/// Checks one example against the reference, with the bar and tolerance classes of `spec`.
/// Never throws for problems of the example itself. The reference precision must be set.
ExampleResult check_example(const spec::Example& example, const spec::Spec& spec);

/// Runs every example of `spec`; throws spec::SpecError if the "ref" class is missing.
SelfcheckReport run_selfcheck(const spec::Spec& spec);

/// One line per clause, failing examples under their clause, and the summary line.
void print_report(std::ostream& out, const SelfcheckReport& report, bool verbose = false);

nlohmann::json to_json(const SelfcheckReport& report);

/// Writes `text` to `file` atomically: a temporary file in the same directory, then rename.
/// Throws std::runtime_error on failure (the target is then untouched).
void write_file_atomically(const std::filesystem::path& file, const std::string& text);

}  // namespace rotorcert::conformance
