// Grading a results file against the vectors it answers (`rotorcert vectors check`): every
// result is judged by engine::judge_case() (judge_round_trip() for EXP-2) with the vector's
// tolerance class, and gathered per clause by engine::ClauseJudge, exactly as `certify` judges
// an implementation it runs itself. The outcome is a certify::Certificate.
#pragma once

#include <string>
#include <vector>

#include <rotorcert/certify/certificate.hpp>
#include <rotorcert/vectors/results.hpp>
#include <rotorcert/vectors/vector_set.hpp>

namespace rotorcert::vectors {

struct Grading {
  /// Source "results file"; clauses in spec order; levels: the claimed levels, else those of
  /// the claimed clauses.
  certify::Certificate certificate;
  std::size_t results = 0;           // results judged
};

/// Grades `results` against `set` (vectors of the results' format). Per clause:
///   - no vectors of the clause in the set, or no result for any of its operations (or every one
///     declared unsupported): NOT_SUPPORTED;
///   - otherwise the ClauseJudge outcome, where a vector of a supported operation without a
///     result counts as a failed case ("N vectors without a result").
/// An operation is supported unless declared in unsupported_ops or without any result at all.
/// Throws VectorsError for a result that does not fit: unknown or duplicate id, a value that is
/// not a number of the format, a missing output.
Grading grade(const spec::Spec& spec, const VectorSet& set, const ResultsFile& results);

/// The ClauseResult of a clause as `vectors check` reports it (for tests comparing routes).
const engine::ClauseResult* find_clause(const Grading& g, const std::string& clause);

}  // namespace rotorcert::vectors
