// What the Markdown and HTML renderings of report.json share: reading optional fields, number
// formatting (errors with 3 significant digits), outcome abbreviations, the clause columns of the
// overview and the text form of an error histogram. Private to rotorcert_report.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace rotorcert::report::detail {

using nlohmann::json;

/// The result codes of RESULT-1, in the order the summaries list them.
inline constexpr const char* kOutcomes[] = {"PASS", "QUALITY_WARNING", "FAIL", "NOT_SUPPORTED", "CRASH", "TIMEOUT"};

/// obj[key] as text: "" when obj is not an object, the key is absent or null; numbers and other
/// values as their JSON text. The renderers must not throw on a report with a missing field.
std::string str(const json& obj, const char* key);
/// obj[key] when it is an array, else an empty array.
const json& arr(const json& obj, const char* key);
/// obj[key] when it is an object, else an empty object.
const json& obj_at(const json& obj, const char* key);

std::string join(const std::vector<std::string>& items, const std::string& sep);
/// An array of strings (other values as JSON text) joined by sep.
std::string join(const json& items, const std::string& sep);

/// x with 3 significant digits ("12.5", "1.49e-06", "1230").
std::string fmt3(double x);
/// An error in eps: 3 significant digits; null is a NaN or a wrong status.
std::string error_eps_text(const json& error_eps);
/// A statistic that may be absent (no finite error measured): 3 significant digits or "—".
std::string stat_text(const json& value);
/// "12.5 ε = 1.49e-06 rad" from an Accuracy object.
std::string accuracy_max_text(const json& accuracy);

/// P, QW, F, NS, C, T; the code itself when unknown.
std::string outcome_abbrev(const std::string& outcome);

/// "glm_quat (float)".
std::string table_label(const json& certificate);
/// The anchor id of a certificate's section: name-scalar, characters outside [A-Za-z0-9_.-] as '_'.
std::string anchor(const json& certificate);

/// "9 PASS, 2 QUALITY_WARNING" from a counts object (codes in RESULT-1 order, then unknown ones).
std::string counts_text(const json& counts);

/// The clause columns of the overview: the clauses some certificate has, grouped by level (spec
/// level order), within a level in spec order (spec.clauses), then clauses the spec list lacks in
/// the order they first appear.
struct ClauseColumn {
  std::string id, level;
};
std::vector<ClauseColumn> clause_columns(const json& report);
/// The levels of the overview: options.levels (the levels certified), else the spec's without Meta.
std::vector<std::string> report_levels(const json& report);
/// JSON text that never throws (invalid UTF-8 replaced).
std::string dump(const json& value, int indent = -1);
/// The certificate's result for a clause id, or nullptr.
const json* find_clause(const json& certificate, const std::string& id);

/// The label of histogram bin i: "≤0.5", ..., ">1024".
std::string histogram_bin_label(const json& histogram, std::size_t i);
/// Non-empty bins as "≤0.5:120 ≤1:30 >1024:2"; "no finite errors" when every bin is empty.
std::string histogram_text(const json& histogram);

/// The verdict notes of one clause result, one line each, for both renderers (REPORT-1):
/// inputs with a wrong status, outputs accepted under a convention (ACC-1), inputs not
/// judged under a declared precondition (DECL-1), per-input convention diagnoses (CONV-1), and the
/// worst-case search. Plain text; the renderers escape it.
std::vector<std::string> verdict_notes(const json& clause_result);

/// The declarations of a certificate (DECL-1), one line, or "" when it declares nothing.
std::string declarations_text(const json& certificate);

/// The floating-point environment ({"mxcsr", "flush_to_zero", "denormals_are_zero", "rounding"},
/// SPEC NUM-1) as one line: "MXCSR 0x1f80, rounding to nearest, flush-to-zero off,
/// denormals-are-zero off"; "not observed" when env is null or not an object.
std::string fp_env_text(const json& env);
/// Why a certificate's environment deserves a warning, one line per reason: flush-to-zero on,
/// denormals-are-zero on, a rounding mode other than the platform's (to nearest when the platform
/// recorded none), or, when none of these, an MXCSR that still differs from the platform's
/// (unmasked exceptions). Empty when the environment is the platform's or was not observed.
std::vector<std::string> fp_env_warnings(const json& cert_env, const json& platform_env);
/// Short flags for the overview: "FTZ", "DAZ", "rounding".
std::vector<std::string> fp_env_flags(const json& cert_env, const json& platform_env);
/// The platform object as one line: "Linux 6.1 x86_64, Intel Xeon (2 cores), GCC 12.2.0, MPFR 4.2.0
/// (reference 256 bits)"; "" when the report has none (reports written before it was recorded).
std::string platform_text(const json& platform);

/// sections.mutants when it is the mutants list ({"directory", "killed", "total", "mutants"}),
/// as opposed to {"note"} or something this renderer does not know.
bool is_mutant_list(const json& section);
/// "35 of 35 killed (100%)"; the percentage rounded down, so that 100% means every one.
std::string kill_rate_text(const json& section);
/// The clauses a mutant must break, each with the outcome it got ("" when it did not run): the
/// breaks list first, then clauses the mutant ran that the list lacks.
struct MutantClause {
  std::string id, outcome;
  const json* result;  // the entry of the mutant's "clauses", or nullptr
};
std::vector<MutantClause> mutant_clauses(const json& mutant);

/// The unit of the accuracy tables (eps of the table's format).
inline constexpr const char* kEps = "\u03b5";

}  // namespace rotorcert::report::detail
