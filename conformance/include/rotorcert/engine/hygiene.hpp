// API hygiene (HYG-1 .. HYG-3, level Hygiene): what a rotation API must not do whatever its
// numbers, judged through the C ABI on ordinary inputs of every op the table provides.
//   HYG-1  an op does not modify its input buffers (bytes compared before and after the call);
//   HYG-2  calls from several threads at once give bit for bit the results of one call alone;
//   HYG-3  an element's result does not depend on the calls before it (hidden state): the same
//          element called alone gives the same bits before and after calls on hostile inputs.
#pragma once

#include <string>

#include <rotorcert/engine/runner.hpp>

namespace rotorcert::engine {

/// Whether `clause` is one of the hygiene clauses (judged by run_hygiene_clause).
bool is_hygiene_clause(const std::string& clause);

/// Judges one hygiene clause on every op the table provides; NOT_SUPPORTED when it provides none.
ClauseResult run_hygiene_clause(const rc_impl& table, const spec::Spec& spec, const std::string& clause,
                                const CaseOptions& options);

/// Threads that call at once for HYG-2, and the calls each makes.
inline constexpr int kHygieneThreads = 4;
inline constexpr int kHygieneRounds = 4;

}  // namespace rotorcert::engine
