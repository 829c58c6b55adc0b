// What a certificate says, derived from the typed Certificate alone: the status of each level
// (LEVEL-1), the claim line, the accuracy of each op, and whether the results hold no surprise
// against the table's known defects. Every writer (report.json, the terminal, the third-party
// section) reads these values; none re-derives them from JSON.
#pragma once

#include <map>
#include <string>
#include <vector>

#include <rotorcert/certify/certificate.hpp>

namespace rotorcert::certify {

/// LEVEL-1: a level is met when every clause of it PASSes; met with warnings when the others are
/// QUALITY_WARNING; not met otherwise.
/// Declared best first (rotorcert diff ranks levels by it).
enum class LevelStatus { met, met_with_warnings, not_met };
const char* to_string(LevelStatus s);  // "met", "met with warnings", "not met"

struct LevelResult {
  std::string level;
  LevelStatus status = LevelStatus::not_met;
  std::map<engine::Outcome, int> counts;  // clauses of the level per RESULT-1 code
  std::vector<std::string> not_pass;      // the clauses of the level that did not PASS, in spec order
};

/// The certificate's levels (Certificate::levels) that have at least one clause result.
std::vector<LevelResult> level_results(const Certificate& c);

/// "rotorcert VERSION: Core, Interp (binary64)", or "no level met".
std::string claim(const Certificate& c);

/// Whether the table claims the clause.
bool claimed(const Certificate& c, const std::string& clause);

/// The known-defect reason of a clause (expected_failures.json), or null when it is not listed.
const std::string* expected_failure(const Certificate& c, const std::string& clause);

/// Whether a claimed clause's result is as good as a table can claim: PASS, QUALITY_WARNING, or
/// NOT_SUPPORTED only because its inputs lie outside the table's declared preconditions (DECL-1).
bool claimed_clause_good(const engine::ClauseResult& r);

/// RESULT-1: FAIL, CRASH and TIMEOUT are what a defect looks like.
bool is_defect(engine::Outcome o);

/// Whether a certificate holds no surprise: it could be made, every expected failure FAILs (one
/// not run, filtered out, is no surprise), every other claimed clause is good.
bool as_expected(const Certificate& c);

/// Whether every claimed clause is good and the certificate could be made (certify's exit code).
bool all_claimed_good(const Certificate& c);

/// The accuracy of one op over every clause of a certificate (errors in eps units).
struct OpAccuracy {
  std::string op;
  std::string unit;  // what eps multiplies: "rad", "rad/relative", "relative" (SPEC section 3)
  double eps = 0;    // the format's epsilon
  std::size_t cases = 0;
  double max_eps = 0, p50_eps = 0, p99_eps = 0;
  std::string worst_clause;
  engine::WorstCase worst;
  std::vector<double> histogram_edges_eps;
  std::vector<int> histogram_counts;  // one more than edges: the last counts errors above every edge
};

/// One row per ABI op that has finite errors, in ABI order.
std::vector<OpAccuracy> accuracy(const Certificate& c);

/// The conventions (convention.hpp) some clause is consistent with, in convention order, with the
/// clauses that are.
struct ConventionFinding {
  std::string id, description;
  std::vector<std::string> clauses;
};
std::vector<ConventionFinding> convention_findings(const Certificate& c);

}  // namespace rotorcert::certify
