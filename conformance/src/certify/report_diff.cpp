#include <rotorcert/certify/report_diff.hpp>

#include <algorithm>
#include <cmath>
#include <map>

#include <rotorcert/certify/verdict.hpp>

namespace rotorcert::certify {
namespace {

using engine::Outcome;

/// LevelStatus is declared best first: met, met with warnings, not met.
int level_rank(LevelStatus s) { return static_cast<int>(s); }

Change compare_ranks(int old_rank, int new_rank) {
  return new_rank < old_rank ? Change::better : new_rank > old_rank ? Change::worse : Change::same;
}

/// The worst errors of one clause: worse when the new one exceeds kDiffErrorFactor times the old
/// one (both counted from kDiffErrorFloorEps); better the other way round. A NaN (a status
/// failure, a NaN output) is not compared here: the result change says it.
Change compare_errors(double old_error, double new_error) {
  if (!std::isfinite(old_error) || !std::isfinite(new_error)) return Change::same;
  const double o = std::max(old_error, kDiffErrorFloorEps), n = std::max(new_error, kDiffErrorFloorEps);
  return n > kDiffErrorFactor * o ? Change::worse : o > kDiffErrorFactor * n ? Change::better : Change::same;
}

std::string key_of(const Certificate& c) { return c.table.name + "/" + c.table.scalar; }

TableDiff diff_table(const Certificate* o, const Certificate* n) {
  TableDiff d;
  const Certificate& any = o != nullptr ? *o : *n;
  d.name = any.table.name;
  d.scalar = any.table.scalar;
  d.only_old = n == nullptr;
  d.only_new = o == nullptr;

  std::map<std::string, LevelStatus> old_levels, new_levels;
  std::vector<std::string> level_order;
  for (const auto& [from, into] : {std::pair{o, &old_levels}, std::pair{n, &new_levels}})
    if (from != nullptr)
      for (const LevelResult& l : level_results(*from)) {
        (*into)[l.level] = l.status;
        if (std::find(level_order.begin(), level_order.end(), l.level) == level_order.end()) level_order.push_back(l.level);
      }
  for (const std::string& level : level_order) {
    LevelChange lc{level, std::nullopt, std::nullopt, Change::same};
    if (const auto it = old_levels.find(level); it != old_levels.end()) lc.old_status = it->second;
    if (const auto it = new_levels.find(level); it != new_levels.end()) lc.new_status = it->second;
    // A level certified in one report only (other --level options) is listed, not judged.
    if (lc.old_status && lc.new_status) lc.change = compare_ranks(level_rank(*lc.old_status), level_rank(*lc.new_status));
    d.levels.push_back(std::move(lc));
  }

  std::map<std::string, const engine::ClauseResult*> old_clauses;
  if (o != nullptr)
    for (const engine::ClauseResult& r : o->clauses) old_clauses[r.clause] = &r;
  std::vector<std::string> seen;
  auto add = [&](const engine::ClauseResult* before, const engine::ClauseResult* after) {
    ClauseChange c;
    c.clause = before != nullptr ? before->clause : after->clause;
    c.old_error = before != nullptr ? before->worst_error : NAN;
    c.new_error = after != nullptr ? after->worst_error : NAN;
    if (before != nullptr) c.old_outcome = before->outcome;
    if (after != nullptr) c.new_outcome = after->outcome;
    if (before != nullptr && after != nullptr) {
      c.outcome_change = compare_ranks(outcome_rank(before->outcome), outcome_rank(after->outcome));
      c.error_change = compare_errors(before->worst_error, after->worst_error);
    } else if (before != nullptr && n != nullptr && claimed(*o, c.clause)) {
      c.outcome_change = Change::worse;  // a claimed clause the new report did not certify
    }
    if (c.outcome_change != Change::same || c.error_change != Change::same ||
        (before == nullptr) != (after == nullptr))
      d.clauses.push_back(std::move(c));
  };
  if (n != nullptr)
    for (const engine::ClauseResult& r : n->clauses) {
      const auto it = old_clauses.find(r.clause);
      add(it == old_clauses.end() ? nullptr : it->second, &r);
      seen.push_back(r.clause);
    }
  if (o != nullptr)
    for (const engine::ClauseResult& r : o->clauses)
      if (std::find(seen.begin(), seen.end(), r.clause) == seen.end()) add(&r, nullptr);
  return d;
}

}  // namespace

int outcome_rank(Outcome o) {
  switch (o) {
    case Outcome::pass: return 0;
    case Outcome::quality_warning: return 1;
    case Outcome::not_supported: return 2;
    case Outcome::fail: return 3;
    case Outcome::timeout:
    case Outcome::crash: return 4;
  }
  return 4;
}

const char* to_string(Change c) {
  switch (c) {
    case Change::better: return "better";
    case Change::worse: return "worse";
    case Change::same: return "same";
  }
  return "same";
}

bool TableDiff::regression() const {
  return only_old || std::any_of(levels.begin(), levels.end(), [](const LevelChange& l) { return l.change == Change::worse; }) ||
         std::any_of(clauses.begin(), clauses.end(), [](const ClauseChange& c) { return c.regression(); });
}

bool ReportDiff::regression() const {
  return std::any_of(tables.begin(), tables.end(), [](const TableDiff& t) { return t.regression(); });
}

ReportDiff diff_certificates(const std::vector<Certificate>& old_certs, const std::vector<Certificate>& new_certs) {
  ReportDiff diff;
  std::map<std::string, const Certificate*> by_key;
  for (const Certificate& c : new_certs) by_key.emplace(key_of(c), &c);
  std::vector<std::string> seen;
  for (const Certificate& o : old_certs) {
    // A report may hold a table twice (report: GLM and Eigen also in the third-party section).
    if (std::find(seen.begin(), seen.end(), key_of(o)) != seen.end()) continue;
    const auto it = by_key.find(key_of(o));
    diff.tables.push_back(diff_table(&o, it == by_key.end() ? nullptr : it->second));
    seen.push_back(key_of(o));
  }
  for (const Certificate& n : new_certs)
    if (std::find(seen.begin(), seen.end(), key_of(n)) == seen.end()) diff.tables.push_back(diff_table(nullptr, &n));
  return diff;
}

}  // namespace rotorcert::certify
