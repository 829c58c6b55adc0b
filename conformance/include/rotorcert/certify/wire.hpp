// The wire format between the certify tool and its child processes: a child runs one clause
// (isolate.hpp) and hands back its ClauseResult as JSON over a pipe; a plugin's tables come back
// from the probing child as TableInfo JSON. This is a process boundary, so JSON is the edge here;
// on either side the values are typed. The error lists travel too; report.json keeps only their
// summaries (report_document.hpp).
#pragma once

#include <cmath>

#include <nlohmann/json.hpp>

#include <rotorcert/certify/certificate.hpp>
#include <rotorcert/engine/runner.hpp>

namespace rotorcert::certify {

json to_json(const TableInfo& t);
TableInfo table_info_from_json(const json& j);

/// A ClauseResult as JSON and back. Without `with_errors`: the form report.json shows per clause.
json to_json(const engine::ClauseResult& r, bool with_errors);
engine::ClauseResult clause_result_from_json(const json& j);

/// The worst input of a clause as report.json shows it ({"error_eps", "op", "label", "input",
/// "detail"}), null when the clause has none.
json worst_json(const engine::ClauseResult& r);

/// What a child is about to do, sent as a progress frame before every call into the
/// implementation (isolate.hpp keeps the last one): the op, the case's label and its inputs when
/// one case is called alone, and a line for people. A crash or hang is pinned on these fields.
struct WorkingOn {
  std::string op, label, input;
  std::string text;  // "slerp [near-antipodal pair] a=[...] ...", "loading ...", "convention detection ..."
};
json to_json(const WorkingOn& w);
/// From the child's progress frame, untrusted: anything that is not a WorkingOn object (a torn or
/// truncated frame, a progress line of an older child) becomes {text = the frame as it came}.
WorkingOn working_on_from_progress(const std::string& frame);

/// NaN and infinities have no JSON number: they become null.
inline json number_or_null(double x) { return std::isfinite(x) ? json(x) : json(nullptr); }

}  // namespace rotorcert::certify
