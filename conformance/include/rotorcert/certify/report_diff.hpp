// What changed between two reports of the same library (`rotorcert diff OLD NEW`): per table
// (name and scalar type), the levels (LEVEL-1) and, per clause, the result (RESULT-1) and the
// worst error. A release gate: a regression is a level no longer met (or now met only with
// warnings), a clause whose result got worse, a worst error more than doubled, or a table gone.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <rotorcert/certify/certificate.hpp>
#include <rotorcert/certify/verdict.hpp>

namespace rotorcert::certify {

/// RESULT-1 codes from best to worst, for comparing two results of one clause: PASS,
/// QUALITY_WARNING, NOT_SUPPORTED (the clause can no longer be used), FAIL, TIMEOUT and CRASH.
int outcome_rank(engine::Outcome o);

/// Worst errors are compared from half an eps up: below that both are rounding noise, and a
/// change from 0.1 to 0.3 eps is no regression.
inline constexpr double kDiffErrorFloorEps = 0.5;
/// A worst error that grows by more than this factor (from the floor) is a regression.
inline constexpr double kDiffErrorFactor = 2.0;

enum class Change { better, worse, same };
const char* to_string(Change c);  // "better", "worse", "same"

struct ClauseChange {
  std::string clause;
  std::optional<engine::Outcome> old_outcome, new_outcome;  // empty: the clause is not in that report
  double old_error = 0, new_error = 0;                      // worst error, eps units (NaN: none / NaN)
  Change outcome_change = Change::same, error_change = Change::same;
  bool regression() const { return outcome_change == Change::worse || error_change == Change::worse; }
};

struct LevelChange {
  std::string level;
  std::optional<LevelStatus> old_status, new_status;  // empty: the level was not certified in that report
  Change change = Change::same;
};

struct TableDiff {
  std::string name, scalar;
  bool only_old = false, only_new = false;  // the table is in one report only
  std::vector<LevelChange> levels;          // every level of either report
  std::vector<ClauseChange> clauses;        // the clauses whose result or worst error changed
  bool regression() const;
};

struct ReportDiff {
  std::vector<TableDiff> tables;  // in the old report's order, then tables new in the new one
  std::vector<std::string> notes;  // e.g. the two reports used different seeds
  bool regression() const;
};

/// Compares two sets of certificates (certificates_of_report of each report).
ReportDiff diff_certificates(const std::vector<Certificate>& old_certs, const std::vector<Certificate>& new_certs);

}  // namespace rotorcert::certify
