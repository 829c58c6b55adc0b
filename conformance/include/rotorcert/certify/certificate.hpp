// Certificates: the result of certifying one implementation table (an implementation in one
// scalar type) against the spec, as a typed value.
//
// Every route to a certificate fills the same Certificate: `certify` and `report` (the
// implementation runs in child processes), `vectors check` and the third-party vectors adapters
// (results written by an implementation in any language). What follows from it is derived from
// the typed value too (verdict.hpp: levels, claim, accuracy, as expected); JSON appears only where
// data leaves: the child's wire format (wire.hpp) and report.json (report_document.hpp).
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

/// One table certified: the typed value every route fills and every writer reads (verdict.hpp
/// derives the levels, the claim and whether it is as expected; report_document.hpp writes it).
struct Certificate {
  TableInfo table;
  std::vector<std::string> levels;                 // the levels certified (LEVEL-1), in spec order
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

}  // namespace rotorcert::certify
