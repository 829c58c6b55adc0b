#include <rotorcert/engine/hygiene.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <map>
#include <thread>

namespace rotorcert::engine {
namespace {

/// Ordinary inputs of an op: the cases of its operation clause (LEVEL-1 ordinary, worked examples
/// included), at most 16 and all with the k of the first, so that one batch call takes them.
std::vector<Case> ordinary_cases(const spec::Spec& spec, const AbiOp& op, ref::Format f, const CaseOptions& options) {
  const std::string clause = main_clause_of(op.name);
  if (clause.empty()) return {};
  CaseOptions o = options;
  o.search_budget = 0;
  const auto checks = checks_for_clause_impl(spec, clause, f, o, {op.name});
  std::vector<Case> cases;
  for (const Check& check : checks) {
    if (check.log_exp_round_trip) continue;
    for (const Case& c : check.cases)
      if (cases.size() < 16 && (cases.empty() || c.k == cases.front().k)) cases.push_back(c);
  }
  return cases;
}

/// Inputs meant to disturb state an implementation keeps between calls: its Robust cases (NaN,
/// infinities, zeros, extreme scales, subnormals), whatever it answers to them.
std::vector<Case> hostile_cases(const spec::Spec& spec, const AbiOp& op, ref::Format f, const CaseOptions& options) {
  std::vector<Case> cases;
  for (const char* clause : {"EDGE-7", "EDGE-6", "EDGE-5", "EDGE-8"}) {
    const auto ops = ops_for_clause(clause);
    if (std::find(ops.begin(), ops.end(), op.name) == ops.end()) continue;
    CaseOptions o = options;
    o.cases_per_family = 4;
    for (const Check& check : checks_for_clause_impl(spec, clause, f, o, {op.name}))
      for (const Case& c : check.cases)
        if (cases.size() < 32) cases.push_back(c);
  }
  return cases;
}

std::vector<const Case*> pointers(const std::vector<Case>& cases) {
  std::vector<const Case*> p;
  for (const Case& c : cases) p.push_back(&c);
  return p;
}

std::string outputs_text(const AbiOp& op, const RawCall& r, std::size_t i, ref::Format f) {
  std::string s = "status " + std::to_string(r.status.at(i));
  for (std::size_t a = 0; a < op.outputs.size(); ++a)
    s += " " + op.outputs[a].name + "=" + join_values(r.output(op, a, i), true, f);
  return s;
}

CaseVerdict passed(std::string detail) { return {ref::Verdict::pass, 0, std::move(detail)}; }
CaseVerdict failed(std::string detail) { return {ref::Verdict::fail, NAN, std::move(detail)}; }

/// HYG-1: the input buffers hold the same bytes after the call.
void inputs_unmodified(const rc_impl& table, const AbiOp& op, const std::vector<Case>& cases, ref::Format f,
                       ClauseJudge& judge) {
  const RawCall r = call_raw(table, op, pointers(cases), cases.front().k);
  for (std::size_t i = 0; i < cases.size(); ++i) {
    std::string changed = r.fault.empty() ? "" : op.name + " " + r.fault;  // memory past the outputs
    for (std::size_t a = 0; a < op.inputs.size() && changed.empty(); ++a) {
      const auto before = r.input(op, a, i, cases[i].k, false), after = r.input(op, a, i, cases[i].k, true);
      bool same = before.size() == after.size();
      for (std::size_t j = 0; same && j < before.size(); ++j)
        same = (before[j] == after[j] && mpfr::signbit(before[j]) == mpfr::signbit(after[j])) ||
               (mpfr::isnan(before[j]) && mpfr::isnan(after[j]));
      if (!same)
        changed = op.name + " modified its input " + op.inputs[a].name + ": " + join_values(before, true, f) + " before the call, " +
                  join_values(after, true, f) + " after it";
    }
    judge.record(changed.empty() ? passed("inputs unchanged") : failed(changed), op, cases[i], f);
  }
}

/// HYG-2: kHygieneThreads threads, released together, each make kHygieneRounds calls on the
/// same elements; every result must be the one call alone gave.
void concurrent_calls_agree(const rc_impl& table, const AbiOp& op, const std::vector<Case>& cases, ref::Format f,
                            ClauseJudge& judge) {
  const auto ptrs = pointers(cases);
  const std::size_t k = cases.front().k;
  const RawCall alone = call_raw(table, op, ptrs, k);
  std::vector<std::vector<RawCall>> got(kHygieneThreads);
  std::atomic<int> ready{0};
  std::vector<std::thread> threads;
  for (int t = 0; t < kHygieneThreads; ++t)
    threads.emplace_back([&, t] {
      ready.fetch_add(1);
      while (ready.load() < kHygieneThreads) std::this_thread::yield();
      for (int round = 0; round < kHygieneRounds; ++round) got[std::size_t(t)].push_back(call_raw(table, op, ptrs, k));
    });
  for (std::thread& t : threads) t.join();
  for (std::size_t i = 0; i < cases.size(); ++i) {
    std::string differs;
    for (const auto& calls : got)
      for (const RawCall& r : calls)
        if (differs.empty() && !r.same_element(op, i, alone, i))
          differs = "called from " + std::to_string(kHygieneThreads) + " threads at once, " + op.name + " gave " +
                    outputs_text(op, r, i, f) + "; called alone, " + outputs_text(op, alone, i, f);
    judge.record(differs.empty() ? passed("the same bits from every thread") : failed(differs), op, cases[i], f);
  }
}

/// HYG-3: each element called alone, first in order, then in reverse order after a batch of
/// hostile inputs; both answers must be the same bits.
void no_hidden_state(const rc_impl& table, const AbiOp& op, const std::vector<Case>& cases,
                     const std::vector<Case>& hostile, ref::Format f, ClauseJudge& judge) {
  std::vector<RawCall> first;
  for (const Case& c : cases) first.push_back(call_raw(table, op, {&c}, c.k));
  std::map<std::size_t, std::vector<const Case*>> by_k;  // n-way hostile inputs share one k per call
  for (const Case& c : hostile) by_k[c.k].push_back(&c);
  for (const auto& [k, group] : by_k) (void)call_raw(table, op, group, k);
  std::vector<RawCall> second(cases.size());
  for (std::size_t i = cases.size(); i-- > 0;) second[i] = call_raw(table, op, {&cases[i]}, cases[i].k);
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const bool same = first[i].same_element(op, 0, second[i], 0);
    judge.record(same ? passed("the same bits before and after other calls")
                      : failed(op.name + " gave " + outputs_text(op, first[i], 0, f) + " first and " +
                               outputs_text(op, second[i], 0, f) + " for the same input after " +
                               std::to_string(hostile.size()) + " calls on Robust inputs (NaN, infinities, zeros, extreme scales)"),
                 op, cases[i], f);
  }
}

}  // namespace

bool is_hygiene_clause(const std::string& clause) { return clause.rfind("HYG-", 0) == 0; }

ClauseResult run_hygiene_clause(const rc_impl& table, const spec::Spec& spec, const std::string& clause,
                                const CaseOptions& options) {
  ClauseResult result;
  result.clause = clause;
  const spec::Clause* cl = spec.find_clause(clause);
  if (cl == nullptr || !is_hygiene_clause(clause)) {
    result.outcome = Outcome::fail;
    result.note = "no hygiene clause " + clause + " in the spec";
    result.worst_detail = result.note;
    return result;
  }
  result.level = cl->level;
  result.tolerance = cl->tolerance;
  const ref::Format f = format_of(table);
  ClauseJudge judge{result};
  bool any = false;
  for (const AbiOp& op : abi_ops()) {
    if (!supports(table, op.name)) continue;
    const std::vector<Case> cases = ordinary_cases(spec, op, f, options);
    if (cases.empty()) continue;
    any = true;
    if (clause == "HYG-1") inputs_unmodified(table, op, cases, f, judge);
    else if (clause == "HYG-2") concurrent_calls_agree(table, op, cases, f, judge);
    else no_hidden_state(table, op, cases, hostile_cases(spec, op, f, options), f, judge);
  }
  if (!any) {
    result.outcome = Outcome::not_supported;
    result.note = "the table provides none of the operations";
    return result;
  }
  judge.finish();
  return result;
}

}  // namespace rotorcert::engine
