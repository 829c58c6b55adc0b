// Certificates: the result of certifying one implementation table (an implementation in one
// scalar type) against the spec, and the report that gathers them. The JSON written here is
// report.json, format "rotorcert-report" version 1, schema spec/report.schema.json.
//
// Every route to a certificate fills the same Certificate: `certify` and `report` (the
// implementation runs in child processes), and `vectors check` (results written by an
// implementation in any language). certificate_json() derives the rest: levels (LEVEL-1), the
// claim line, accuracy tables, detected conventions, whether the results match expectations.
#pragma once

#include <filesystem>
#include <map>
#include <ostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <rotorcert/engine/runner.hpp>
#include <rotorcert/spec/spec.hpp>

namespace rotorcert::certify {

using nlohmann::json;

/// What an implementation table says about itself.
struct TableInfo {
  std::string name;
  std::string scalar;  // "float" or "double"
  std::string version, description;
  std::string source = "built-in";  // "built-in", "plugin", "results file"
  std::string plugin_path;          // for plugins; the results file for "results file"
  std::vector<std::string> claimed_levels;
  std::vector<std::string> claimed_clauses;
  std::vector<std::string> supported_ops;
  /// DECL-1: "op:id" declarations of the table (ABI version 2, or the adapter's manifest).
  std::vector<std::string> declared_preconditions, declared_conventions;
  engine::Declarations declarations() const {
    return {{declared_preconditions.begin(), declared_preconditions.end()},
            {declared_conventions.begin(), declared_conventions.end()}};
  }

  ref::Format format() const { return scalar == "float" ? ref::Format::binary32 : ref::Format::binary64; }
};

TableInfo table_info(const rc_impl& table, std::string source = "built-in", std::string plugin_path = {});
json to_json(const TableInfo& t);
TableInfo table_info_from_json(const json& j);

/// A ClauseResult as JSON and back (the child process hands its result over this way); the
/// error lists travel too, report.json keeps only their summaries.
json to_json(const engine::ClauseResult& r, bool with_errors);
engine::ClauseResult clause_result_from_json(const json& j);

struct Certificate {
  TableInfo table;
  std::vector<engine::ClauseResult> clauses;       // spec order, every clause certified
  std::map<std::string, std::string> expected_failures;  // clause -> why (known defects)
  std::map<std::string, std::string> reproduce;    // clause -> one-line command
  std::string error;  // set when the table could not be certified at all
  /// The floating-point environment observed in the child processes after loading the
  /// implementation (platform.hpp); null when no child got that far.
  json fp_environment;
};

/// The entries of one expected_failures.json (`{"failures": [{"table", "scalar", "clause", "why"}]}`)
/// for this table and scalar type, clause -> why; empty when the file does not exist. The one
/// reader of that format, for built-in tables and third-party adapters alike.
std::map<std::string, std::string> read_expected_failures(const std::filesystem::path& file, const std::string& table,
                                                          const std::string& scalar);

/// impls/<impl_name>/expected_failures.json (the file of the implementation directory of that name).
std::filesystem::path builtin_expected_failures_file(const std::string& impl_name);

/// Known defects of a built-in implementation: impls/<name>/expected_failures.json, entries of
/// this table's scalar type. Empty when the file does not exist.
std::map<std::string, std::string> expected_failures(const std::string& impl_name, const std::string& scalar);

/// LEVEL-1: "met", "met with warnings" or "not met" per level, from the clause results.
json levels_json(const Certificate& c, const std::vector<std::string>& levels);

/// One certificate in the report.json format (see spec/report.schema.json).
json certificate_json(const spec::Spec& spec, const Certificate& c, const std::vector<std::string>& levels);

/// Whether a claimed clause's result is as good as a table can claim: PASS, QUALITY_WARNING, or
/// NOT_SUPPORTED only because its inputs lie outside the table's declared preconditions (DECL-1).
bool claimed_clause_good(const json& clause_result);

/// Whether a certificate holds no surprise: every expected failure FAILs, every other claimed
/// clause is PASS or QUALITY_WARNING.
bool as_expected(const json& certificate);

/// The whole report.json object. `run` is the only part allowed to differ between runs with the
/// same options (timings, date, host).
json report_json(const spec::Spec& spec, const std::string& kind, const json& options, const json& run,
                 const std::vector<json>& certificates);

/// The certificate as a table for a terminal: one line per clause, then the levels.
void print_certificate(std::ostream& out, const json& certificate, bool verbose);

/// Writes `contents` to `file` atomically: a temporary file in the same directory, flushed,
/// then renamed over the target. Readers see the old file or the new one, never a part.
void write_atomically(const std::filesystem::path& file, const std::string& contents);

/// Writes report.json, report.md and report.html into dir (created if needed), each atomically.
void write_report(const std::filesystem::path& dir, const json& report);

}  // namespace rotorcert::certify
