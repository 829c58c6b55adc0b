// Property tests: one rapidcheck property per implementation clause of the spec, run against
// every built-in implementation table that claims the clause.
//
// For clause C and table T the property draws an ABI op among ops_for_clause(C) that T provides,
// an input from the families of C for that op (generators.hpp), calls T on it (engine::observe)
// and judges the result against the 256-bit reference with the tolerance class that judges that
// op under C (engine::judge_case / judge_round_trip, the comparison every route shares). A FAIL
// verdict falsifies the property; rapidcheck shrinks the input.
//
// Pairs listed in impls/*/expected_failures.json are known defects: there the property must be
// falsified (the shrunk counterexample is printed), so a defect that disappears breaks the test
// as surely as a new one does (as impls/tests/test_claims.cpp does for the fixed vectors).
//
// Seeds: ctest runs these tests with RC_PARAMS="seed=..." (conformance/CMakeLists.txt), so CI is
// deterministic. Another seed:      RC_PARAMS="seed=N" conformance_test_properties
// More tests per property:          RC_PARAMS="seed=N max_success=1000" conformance_test_properties
// A failure prints the one-line command that replays exactly its shrunk input (reproduce=...).
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <unordered_map>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <rapidcheck.h>

#include <rotorcert/engine/runner.hpp>
#include <rotorcert/registry.hpp>
#include <rotorcert/testing/clause.hpp>

#include "generators.hpp"

namespace rc::detail {
// Defined in librapidcheck (the format RC_PARAMS="reproduce=..." reads), not declared in its
// installed headers: the reproduce string of one failure, printed with the test's own filter.
std::string reproduceMapToString(const std::unordered_map<std::string, Reproduce>& map);
}  // namespace rc::detail

namespace {

using namespace rotorcert;
using properties::Drawn;

const spec::Spec& the_spec() {
  static const spec::Spec s = spec::load_spec(spec::resolve_spec_dir());
  return s;
}

std::string scalar_name(const rc_impl& t) { return t.scalar == RC_SCALAR_FLOAT32 ? "float" : "double"; }

/// impls/*/expected_failures.json: (table, scalar, clause) -> why.
const std::map<std::tuple<std::string, std::string, std::string>, std::string>& expected_failures() {
  static const auto r = [] {
    std::map<std::tuple<std::string, std::string, std::string>, std::string> m;
    for (const auto& dir : std::filesystem::directory_iterator(std::string(ROTORCERT_SOURCE_DIR) + "/impls")) {
      const auto file = dir.path() / "expected_failures.json";
      if (!std::filesystem::exists(file)) continue;
      std::ifstream in(file);
      const auto j = nlohmann::json::parse(in);  // named: a temporary would die before the loop
      for (const auto& e : j.at("failures"))
        m[{e.at("table").get<std::string>(), e.at("scalar").get<std::string>(), e.at("clause").get<std::string>()}] =
            e.at("why").get<std::string>();
    }
    return m;
  }();
  return r;
}

/// The ops of `clause` that `table` provides. EXP-2 runs log then exp: it needs both, and draws
/// log's inputs.
std::vector<std::string> ops_of(const rc_impl& table, const std::string& clause) {
  std::vector<std::string> ops;
  if (clause == "EXP-2") {
    if (engine::supports(table, "log") && engine::supports(table, "exp")) ops.push_back("log");
    return ops;
  }
  for (const std::string& op : engine::ops_for_clause(clause))
    if (engine::supports(table, op)) ops.push_back(op);
  return ops;
}

/// Calls the table on one drawn input and judges it.
engine::CaseVerdict judge(const rc_impl& table, const std::string& clause, const Drawn& d) {
  const engine::AbiOp& op = *engine::find_abi_op(d.op);
  const spec::ToleranceClass& tc = the_spec().lookup(engine::tolerance_for(the_spec(), clause, d.op));
  const std::vector<engine::Observed> got = engine::observe(table, op, {&d.c}, d.c.k);
  if (clause == "EXP-2") {  // exp(log q) = q through the implementation
    const engine::Case logged{{got.at(0).outputs.at(0)}, 0, "log output", {}};
    const std::vector<engine::Observed> back = engine::observe(table, *engine::find_abi_op("exp"), {&logged}, 0);
    return engine::judge_round_trip(tc, d.c, got.at(0), back.at(0), d.format);
  }
  const engine::Declarations declared = engine::declarations_of(table);
  return engine::judge_case(op, tc, d.c, got.at(0), d.format, nullptr, &declared);
}

/// LEVEL-1: an operation clause (Core .. Skinning) judges ordinary inputs only; the generators'
/// extreme values (NaN, Inf, subnormals, huge and zero quaternions, bad weights) belong to the
/// Robust clauses, which run the same generators.
bool judged_by(const std::string& clause, const Drawn& d) {
  const spec::Clause* cl = the_spec().find_clause(clause);
  if (cl == nullptr) return true;
  const std::string home = engine::robust_clause_of(*engine::find_abi_op(d.op), d.c, d.format);
  // The outcome clauses (EDGE-6, EDGE-7, EDGE-9) judge the inputs of their own kind; an ordinary
  // input a generator draws for them is judged by the operation's own clause.
  if (cl->tolerance == "outcome") return home == clause;
  return cl->level == "Robust" || home.empty();
}

/// The failure text of one judged input: clause, table, op, tolerance class, error in eps and in
/// the metric's own unit (radians for rotations and logs), expected versus got, the inputs in
/// hexfloat.
std::string describe_failure(const rc_impl& table, const std::string& clause, const Drawn& d,
                             const engine::CaseVerdict& v) {
  const std::string tc = engine::tolerance_for(the_spec(), clause, d.op);
  const double eps = ref::format_epsilon<ref::Real>(d.format).toDouble();
  std::ostringstream s;
  s << clause << " FAILS on " << table.name << " (" << scalar_name(table) << "), op " << d.op << " ["
    << to_string(d.family) << "], class " << tc << ": error ";
  if (std::isnan(v.error)) s << "NaN (wrong status or NaN output)";
  else s << v.error << " eps = " << v.error * eps << " in the metric's unit (radians for rotations)";
  s << "\n    input (hexfloat): " << engine::describe_inputs(*engine::find_abi_op(d.op), d.c, d.format)
    << "\n    " << v.detail;
  return s.str();
}

/// Swallows rapidcheck's own reporting: this test prints its own, with the gtest filter.
struct QuietListener : rc::detail::TestListener {
  void onTestCaseFinished(const rc::detail::CaseDescription&) override {}
  void onShrinkTried(const rc::detail::CaseDescription&, bool) override {}
  void onTestFinished(const rc::detail::TestMetadata&, const rc::detail::TestResult&) override {}
};

std::string current_filter() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  return std::string(info->test_suite_name()) + "." + info->name();
}

/// Runs the property of `clause` on every built-in table that claims it.
void check_clause(const std::string& clause) {
  const spec::Clause* cl = the_spec().find_clause(clause);
  ASSERT_NE(cl, nullptr) << clause;
  ASSERT_NE(cl->level, "Meta") << clause << " binds the suite, not implementations";
  const auto& config = rc::detail::configuration();
  int claimed = 0;
  for (const rc_impl* table : impl::builtin_tables()) {
    const auto claims = engine::claimed_clauses(*table);
    if (std::find(claims.begin(), claims.end(), clause) == claims.end()) continue;
    ++claimed;
    const std::string scalar = scalar_name(*table);
    const std::string id = clause + " on " + table->name + " (" + scalar + ")";
    const std::vector<std::string> ops = ops_of(*table, clause);
    if (ops.empty()) {
      std::printf("%s: NOT_SUPPORTED (none of the clause's ops)\n", id.c_str());
      continue;
    }
    // Replaying one failure (RC_PARAMS="reproduce=..."): only the property it names runs.
    if (!config.reproduce.empty() && config.reproduce.count(id) == 0) continue;

    const ref::Format f = engine::format_of(*table);
    rc::detail::TestMetadata metadata;
    metadata.id = id;
    metadata.description = id;
    QuietListener listener;
    const auto result = rc::detail::checkProperty(
        rc::detail::toProperty([&] {
          const Drawn d = *properties::drawn(clause, ops, f);
          if (!judged_by(clause, d)) return;  // an extreme input: judged by the Robust clauses
          const engine::CaseVerdict v = judge(*table, clause, d);
          // An input outside a declared precondition is not judged (DECL-1).
          if (v.grade != engine::Grade::excluded && v.verdict == ref::Verdict::fail)
            RC_FAIL(describe_failure(*table, clause, d, v));
        }),
        metadata, config.testParams, listener, config.reproduce);

    const auto known = expected_failures().find({table->name, scalar, clause});
    if (result.is<rc::detail::FailureResult>()) {
      const auto* failure = &result.get<rc::detail::FailureResult>();
      // rapidcheck prefixes the RC_FAIL message with the assertion's location: keep the message.
      const std::string& why = failure->description;
      const auto start = why.find(clause + " FAILS on ");
      std::ostringstream text;
      text << (start == std::string::npos ? why : why.substr(start)) << "\n    shrunk; failed after "
           << failure->numSuccess << " passing tests; reproduce:\n"
           << "    RC_PARAMS=\"reproduce=" << rc::detail::reproduceMapToString({{id, failure->reproduce}}) << "\" "
           << ROTORCERT_PROPERTIES_BINARY << " --gtest_filter=" << current_filter();
      if (known != expected_failures().end()) {
        std::printf("expected failure found: %s\n  (known: %s)\n", text.str().c_str(), known->second.c_str());
      } else {
        ADD_FAILURE() << text.str();
      }
    } else if (result.is<rc::detail::SuccessResult>()) {
      const auto* success = &result.get<rc::detail::SuccessResult>();
      if (known != expected_failures().end() && config.reproduce.empty())
        ADD_FAILURE() << id << ": listed in expected_failures.json (" << known->second
                      << ") but the property found no counterexample in " << success->numSuccess << " tests";
    } else {
      std::ostringstream text;
      rc::detail::printResultMessage(result, text);
      ADD_FAILURE() << id << ": rapidcheck could not run the property: " << text.str();
    }
  }
  std::printf("%s: %d table(s) claim it\n", clause.c_str(), claimed);
}

// One test per implementation clause (spec/clauses.json, level other than Meta), named after it.
TEST(Properties, QUAT_2) { RC_CLAUSE("QUAT-2"); check_clause("QUAT-2"); }
TEST(Properties, AXANG_1) { RC_CLAUSE("AXANG-1"); check_clause("AXANG-1"); }
TEST(Properties, AXANG_2) { RC_CLAUSE("AXANG-2"); check_clause("AXANG-2"); }
TEST(Properties, NORM_1) { RC_CLAUSE("NORM-1"); check_clause("NORM-1"); }
TEST(Properties, COMPOSE_1) { RC_CLAUSE("COMPOSE-1"); check_clause("COMPOSE-1"); }
TEST(Properties, INV_1) { RC_CLAUSE("INV-1"); check_clause("INV-1"); }
TEST(Properties, APPLY_1) { RC_CLAUSE("APPLY-1"); check_clause("APPLY-1"); }
TEST(Properties, APPLY_2) { RC_CLAUSE("APPLY-2"); check_clause("APPLY-2"); }
TEST(Properties, APPLY_3) { RC_CLAUSE("APPLY-3"); check_clause("APPLY-3"); }
TEST(Properties, MAT_1) { RC_CLAUSE("MAT-1"); check_clause("MAT-1"); }
TEST(Properties, MAT_2) { RC_CLAUSE("MAT-2"); check_clause("MAT-2"); }
TEST(Properties, MAT_3) { RC_CLAUSE("MAT-3"); check_clause("MAT-3"); }
TEST(Properties, LOG_1) { RC_CLAUSE("LOG-1"); check_clause("LOG-1"); }
TEST(Properties, LOG_2) { RC_CLAUSE("LOG-2"); check_clause("LOG-2"); }
TEST(Properties, EXP_1) { RC_CLAUSE("EXP-1"); check_clause("EXP-1"); }
TEST(Properties, EXP_2) { RC_CLAUSE("EXP-2"); check_clause("EXP-2"); }
TEST(Properties, SLERP_1) { RC_CLAUSE("SLERP-1"); check_clause("SLERP-1"); }
TEST(Properties, SLERP_2) { RC_CLAUSE("SLERP-2"); check_clause("SLERP-2"); }
TEST(Properties, SLERP_3) { RC_CLAUSE("SLERP-3"); check_clause("SLERP-3"); }
TEST(Properties, SLERP_4) { RC_CLAUSE("SLERP-4"); check_clause("SLERP-4"); }
TEST(Properties, SLERP_5) { RC_CLAUSE("SLERP-5"); check_clause("SLERP-5"); }
TEST(Properties, NLERP_1) { RC_CLAUSE("NLERP-1"); check_clause("NLERP-1"); }
TEST(Properties, QLB_1) { RC_CLAUSE("QLB-1"); check_clause("QLB-1"); }
TEST(Properties, LOGBLEND_1) { RC_CLAUSE("LOGBLEND-1"); check_clause("LOGBLEND-1"); }
TEST(Properties, DQ_1) { RC_CLAUSE("DQ-1"); check_clause("DQ-1"); }
TEST(Properties, DQ_2) { RC_CLAUSE("DQ-2"); check_clause("DQ-2"); }
TEST(Properties, DQ_3) { RC_CLAUSE("DQ-3"); check_clause("DQ-3"); }
TEST(Properties, DQ_4) { RC_CLAUSE("DQ-4"); check_clause("DQ-4"); }
TEST(Properties, DQ_5) { RC_CLAUSE("DQ-5"); check_clause("DQ-5"); }
TEST(Properties, DQ_6) { RC_CLAUSE("DQ-6"); check_clause("DQ-6"); }
TEST(Properties, AXIS_1) { RC_CLAUSE("AXIS-1"); check_clause("AXIS-1"); }
TEST(Properties, SKIN_1) { RC_CLAUSE("SKIN-1"); check_clause("SKIN-1"); }
TEST(Properties, SKIN_2) { RC_CLAUSE("SKIN-2"); check_clause("SKIN-2"); }
TEST(Properties, SKIN_3) { RC_CLAUSE("SKIN-3"); check_clause("SKIN-3"); }
TEST(Properties, AXANG_3) { RC_CLAUSE("AXANG-3"); check_clause("AXANG-3"); }
TEST(Properties, AXANG_4) { RC_CLAUSE("AXANG-4"); check_clause("AXANG-4"); }
TEST(Properties, SQRT_1) { RC_CLAUSE("SQRT-1"); check_clause("SQRT-1"); }
TEST(Properties, DQ_7) { RC_CLAUSE("DQ-7"); check_clause("DQ-7"); }
TEST(Properties, DQ_8) { RC_CLAUSE("DQ-8"); check_clause("DQ-8"); }
TEST(Properties, DQ_9) { RC_CLAUSE("DQ-9"); check_clause("DQ-9"); }
TEST(Properties, RIGID_1) { RC_CLAUSE("RIGID-1"); check_clause("RIGID-1"); }
TEST(Properties, RIGID_2) { RC_CLAUSE("RIGID-2"); check_clause("RIGID-2"); }
TEST(Properties, RIGID_3) { RC_CLAUSE("RIGID-3"); check_clause("RIGID-3"); }
TEST(Properties, EDGE_1) { RC_CLAUSE("EDGE-1"); check_clause("EDGE-1"); }
TEST(Properties, EDGE_2) { RC_CLAUSE("EDGE-2"); check_clause("EDGE-2"); }
TEST(Properties, EDGE_3) { RC_CLAUSE("EDGE-3"); check_clause("EDGE-3"); }
TEST(Properties, EDGE_4) { RC_CLAUSE("EDGE-4"); check_clause("EDGE-4"); }
TEST(Properties, EDGE_5) { RC_CLAUSE("EDGE-5"); check_clause("EDGE-5"); }
TEST(Properties, EDGE_6) { RC_CLAUSE("EDGE-6"); check_clause("EDGE-6"); }
TEST(Properties, EDGE_7) { RC_CLAUSE("EDGE-7"); check_clause("EDGE-7"); }
TEST(Properties, EDGE_8) { RC_CLAUSE("EDGE-8"); check_clause("EDGE-8"); }
TEST(Properties, EDGE_9) { RC_CLAUSE("EDGE-9"); check_clause("EDGE-9"); }

// Every implementation clause has its test above (a clause added to the spec needs one here),
// and every test above names a clause of the spec.
TEST(PropertiesMeta, EveryImplementationClauseHasAProperty) {
  std::set<std::string> tests;
  const auto* suite = [] {
    const auto& unit = *::testing::UnitTest::GetInstance();
    for (int i = 0; i < unit.total_test_suite_count(); ++i)
      if (std::string(unit.GetTestSuite(i)->name()) == "Properties") return unit.GetTestSuite(i);
    return static_cast<const ::testing::TestSuite*>(nullptr);
  }();
  ASSERT_NE(suite, nullptr);
  for (int i = 0; i < suite->total_test_count(); ++i) tests.insert(suite->GetTestInfo(i)->name());
  std::set<std::string> clauses;
  for (const spec::Clause& c : the_spec().clauses) {
    if (c.level == "Meta" || c.level == "Hygiene") continue;  // HYG-*: engine/hygiene.cpp, test_engine.cpp
    std::string name = c.id;
    for (char& ch : name)
      if (ch == '-') ch = '_';
    clauses.insert(name);
    EXPECT_TRUE(tests.count(name)) << c.id << " has no property test (Properties." << name << ")";
    EXPECT_FALSE(engine::ops_for_clause(c.id).empty()) << c.id << ": no ABI op judges it";
  }
  for (const std::string& t : tests) EXPECT_TRUE(clauses.count(t)) << "Properties." << t << " names no implementation clause";
}

// Every pair in expected_failures.json is exercised: the table exists and claims the clause.
TEST(PropertiesMeta, EveryExpectedFailureIsAClaimedClause) {
  EXPECT_FALSE(expected_failures().empty()) << "no impls/*/expected_failures.json found";
  for (const auto& [key, why] : expected_failures()) {
    const auto& [name, scalar, clause] = key;
    const rc_impl* table = impl::find_builtin(name, scalar == "float" ? RC_SCALAR_FLOAT32 : RC_SCALAR_FLOAT64);
    ASSERT_NE(table, nullptr) << name << " (" << scalar << ") is not a built-in table";
    const auto claims = engine::claimed_clauses(*table);
    EXPECT_NE(std::find(claims.begin(), claims.end(), clause), claims.end()) << name << " does not claim " << clause;
  }
}

}  // namespace
