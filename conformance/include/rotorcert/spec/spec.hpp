// The machine-readable spec: spec/clauses.json, spec/examples.json, spec/pending.json.
//
// Loading checks the structure every tool relies on (types, required fields, unique ids, levels
// and tolerance classes that exist) and reports the first problem as a SpecError naming the
// file and the JSON path ("/examples/3/in"). What an example's fields mean for its op is the
// selfcheck dispatcher's business, not the loader's.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <rotorcert/reference/scalar.hpp>

namespace rotorcert::spec {

/// A spec file that cannot be read or does not have the expected structure. Tools exit with 2.
class SpecError : public std::runtime_error {
 public:
  SpecError(std::filesystem::path file, std::string json_path, const std::string& message);
  const std::filesystem::path& file() const { return file_; }
  /// JSON pointer of the offending value ("" for the whole file).
  const std::string& json_path() const { return json_path_; }

 private:
  std::filesystem::path file_;
  std::string json_path_;
};

/// TOL-2: a tolerance class of clauses.json. `strict` / `loose` hold the bar as written
/// (a number such as "4", an expression such as "1e-60", or a formula such as "16 eps + 2 delta").
struct ToleranceClass {
  std::string name;
  std::string kind;  // "exact", "outcome", "eps", "formula", "absolute", "informative"
  std::optional<std::string> strict, loose;
  std::string doc;

  /// The strict / loose bar as a number when the class is "exact", "eps" or "absolute"
  /// (eps classes: in units of eps; absolute: the bar itself). nullopt otherwise.
  std::optional<ref::Real> strict_value() const;
  std::optional<ref::Real> loose_value() const;
};

struct Clause {
  std::string id;
  std::string title;
  std::string level;
  std::string tolerance;  // name of a ToleranceClass
  std::optional<std::string> op;
};

/// A worked example. `in` and `out` are kept as JSON: the op decides their types.
struct Example {
  std::string id;
  std::string clause;
  std::string op;
  nlohmann::json in, out;
  std::string status;  // "OK" or "DOMAIN_ERROR"
  std::optional<std::string> compare;  // "rotation": quaternion outputs equal up to sign
  std::string comment;
  std::string json_path;  // "/examples/N", for messages
};

struct Spec {
  std::filesystem::path dir;
  std::string version;
  std::vector<std::string> levels;
  std::map<std::string, ToleranceClass> tolerance_classes;
  std::vector<Clause> clauses;  // in file order
  std::string examples_version;
  std::vector<Example> examples;  // in file order
  std::map<std::string, std::string> pending;  // clause id -> reason

  const Clause* find_clause(const std::string& id) const;
  /// The tolerance class of that name; throws SpecError if there is none.
  const ToleranceClass& lookup(const std::string& name) const;
  std::filesystem::path clauses_file() const { return dir / "clauses.json"; }
  std::filesystem::path examples_file() const { return dir / "examples.json"; }
  std::filesystem::path pending_file() const { return dir / "pending.json"; }
};

/// The tool's spec directory: the installed share/rotorcert/spec, else the source tree's spec/
/// (data_layout.hpp).
std::filesystem::path default_spec_dir();

/// `option` if given, else $ROTORCERT_SPEC_DIR if set and nonempty, else default_spec_dir().
std::filesystem::path resolve_spec_dir(const std::optional<std::filesystem::path>& option = std::nullopt);

/// Reads and parses one JSON file; SpecError on I/O or syntax errors.
nlohmann::json read_json(const std::filesystem::path& file);

// The three parts, each from its own JSON value (so tests can build them in memory).
void parse_clauses(const nlohmann::json& j, const std::filesystem::path& file, Spec& spec);
std::vector<Example> parse_examples(const nlohmann::json& j, const std::filesystem::path& file,
                                    std::string* version = nullptr);
std::map<std::string, std::string> parse_pending(const nlohmann::json& j, const std::filesystem::path& file);

/// Loads clauses.json (required), examples.json and pending.json (each optional: empty if absent).
Spec load_spec(const std::filesystem::path& dir);

/// The tolerance class `name` of the spec in resolve_spec_dir() (loaded once, then cached):
/// for tests that take their tolerances from the spec data. Throws SpecError.
ToleranceClass lookup(const std::string& name);

}  // namespace rotorcert::spec
