#include <rotorcert/certify/verdict.hpp>

#include <algorithm>
#include <cmath>

#include <rotorcert/reference/metrics.hpp>

#ifndef ROTORCERT_VERSION
#error "ROTORCERT_VERSION must be defined by the build"
#endif

namespace rotorcert::certify {
namespace {

using engine::Outcome;

/// The unit an op's error is reported in once multiplied by eps (SPEC section 3).
std::string unit_of(const engine::AbiOp& op) {
  switch (op.outputs.front().measure) {
    case engine::Measure::rotation:
    case engine::Measure::quaternion:
    case engine::Measure::unit_rotation:
    case engine::Measure::canonical_rotation:
    case engine::Measure::bivector:
    case engine::Measure::angle: return "rad";
    case engine::Measure::rigid:
    case engine::Measure::unit_rigid:
    case engine::Measure::dual_parts: return "rad/relative";
    default: return "relative";
  }
}

/// Nearest-rank percentile of sorted values.
double percentile(const std::vector<double>& sorted, double p) {
  if (sorted.empty()) return 0;
  const auto rank = static_cast<std::size_t>(std::ceil(p / 100.0 * static_cast<double>(sorted.size())));
  return sorted[std::min(sorted.size() - 1, rank == 0 ? 0 : rank - 1)];
}

const std::vector<double>& histogram_edges() {
  static const std::vector<double> edges = {0.5, 1, 2, 4, 8, 16, 32, 64, 128, 256, 512, 1024};
  return edges;
}

bool good(Outcome o) { return o == Outcome::pass || o == Outcome::quality_warning; }

}  // namespace

const char* to_string(LevelStatus s) {
  switch (s) {
    case LevelStatus::met: return "met";
    case LevelStatus::met_with_warnings: return "met with warnings";
    case LevelStatus::not_met: return "not met";
  }
  return "not met";
}

std::vector<LevelResult> level_results(const Certificate& c) {
  std::vector<LevelResult> all;
  for (const std::string& level : c.levels) {
    LevelResult l;
    l.level = level;
    bool met = true, warnings = false, any = false;
    for (const engine::ClauseResult& r : c.clauses) {
      if (r.level != level) continue;
      any = true;
      ++l.counts[r.outcome];
      if (r.outcome != Outcome::pass) l.not_pass.push_back(r.clause);
      if (r.outcome == Outcome::quality_warning) warnings = true;
      else if (r.outcome != Outcome::pass) met = false;
    }
    if (!any) continue;
    l.status = !met ? LevelStatus::not_met : warnings ? LevelStatus::met_with_warnings : LevelStatus::met;
    all.push_back(std::move(l));
  }
  return all;
}

std::string claim(const Certificate& c) {
  std::string met;
  for (const LevelResult& l : level_results(c))
    if (l.status != LevelStatus::not_met) met += (met.empty() ? "" : ", ") + l.level;
  return std::string("rotorcert ") + ROTORCERT_VERSION + ": " + (met.empty() ? "no level met" : met) + " (" +
         (c.table.format() == ref::Format::binary32 ? "binary32" : "binary64") + ")";
}

bool claimed(const Certificate& c, const std::string& clause) {
  return std::find(c.table.claimed_clauses.begin(), c.table.claimed_clauses.end(), clause) !=
         c.table.claimed_clauses.end();
}

const std::string* expected_failure(const Certificate& c, const std::string& clause) {
  const auto it = c.expected_failures.find(clause);
  return it == c.expected_failures.end() ? nullptr : &it->second;
}

bool claimed_clause_good(const engine::ClauseResult& r) {
  // DECL-1: NOT_SUPPORTED because every input, or the Robust inputs, lie outside the table's
  // declared preconditions is what the table declared, not a surprise.
  return good(r.outcome) || (r.outcome == Outcome::not_supported && !r.excluded.empty());
}

bool is_defect(Outcome o) { return o == Outcome::fail || o == Outcome::crash || o == Outcome::timeout; }

bool as_expected(const Certificate& c) {
  if (!c.error.empty()) return false;
  for (const engine::ClauseResult& r : c.clauses) {
    if (!claimed(c, r.clause)) continue;
    if (expected_failure(c, r.clause) == nullptr ? !claimed_clause_good(r) : r.outcome != Outcome::fail) return false;
  }
  return true;
}

bool all_claimed_good(const Certificate& c) {
  if (!c.error.empty()) return false;
  return std::all_of(c.clauses.begin(), c.clauses.end(),
                     [&](const engine::ClauseResult& r) { return !claimed(c, r.clause) || good(r.outcome); });
}

std::vector<OpAccuracy> accuracy(const Certificate& c) {
  std::vector<OpAccuracy> all;
  const double eps = ref::format_epsilon<double>(c.table.format());
  for (const engine::AbiOp& op : engine::abi_ops()) {
    std::vector<double> errors;
    const engine::WorstCase* worst = nullptr;
    std::string worst_clause;
    for (const engine::ClauseResult& r : c.clauses) {
      if (r.level == "Hygiene") continue;  // bit-for-bit checks of the API, not accuracy (HYG-*)
      if (const auto it = r.errors.find(op.name); it != r.errors.end())
        errors.insert(errors.end(), it->second.begin(), it->second.end());
      if (const auto it = r.worst_by_op.find(op.name); it != r.worst_by_op.end())
        if (worst == nullptr || it->second.error > worst->error) {
          worst = &it->second;
          worst_clause = r.clause;
        }
    }
    if (errors.empty()) continue;
    std::sort(errors.begin(), errors.end());
    OpAccuracy a;
    a.op = op.name;
    a.unit = unit_of(op);
    a.eps = eps;
    a.cases = errors.size();
    a.max_eps = errors.back();
    a.p50_eps = percentile(errors, 50);
    a.p99_eps = percentile(errors, 99);
    a.worst_clause = worst_clause;
    if (worst != nullptr) a.worst = *worst;
    a.histogram_edges_eps = histogram_edges();
    a.histogram_counts.assign(histogram_edges().size() + 1, 0);
    for (double e : errors)
      ++a.histogram_counts[std::lower_bound(histogram_edges().begin(), histogram_edges().end(), e) -
                           histogram_edges().begin()];
    all.push_back(std::move(a));
  }
  return all;
}

std::vector<ConventionFinding> convention_findings(const Certificate& c) {
  std::vector<ConventionFinding> all;
  for (const engine::Convention& cv : engine::conventions()) {
    ConventionFinding f{cv.id, cv.description, {}};
    for (const engine::ClauseResult& r : c.clauses)
      if (std::find(r.conventions.begin(), r.conventions.end(), cv.id) != r.conventions.end()) f.clauses.push_back(r.clause);
    if (!f.clauses.empty()) all.push_back(std::move(f));
  }
  return all;
}

}  // namespace rotorcert::certify
