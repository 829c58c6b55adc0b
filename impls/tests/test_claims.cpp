// Every built-in implementation against every clause it claims (issue 3): the worked examples
// and the engine's fixed reference vectors, judged by the spec's tolerance classes.
//
// A claimed clause must PASS (QUALITY_WARNING is reported and allowed: the level is "met with
// warnings"), except where impls/<id>/expected_failures.json says the implementation is known to
// FAIL it — paper_literal by design, third-party libraries by their own defects. Those must FAIL
// exactly: a defect that disappears or a new failure both break the test, so the files stay true.
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <rotorcert/engine/runner.hpp>
#include <rotorcert/registry.hpp>
#include <rotorcert/testing/clause.hpp>

namespace {

using namespace rotorcert;

struct TableId {
  std::string name, scalar;
  bool operator<(const TableId& o) const { return std::tie(name, scalar) < std::tie(o.name, o.scalar); }
};

std::string scalar_name(const rc_impl& t) { return t.scalar == RC_SCALAR_FLOAT32 ? "float" : "double"; }

/// All impls/*/expected_failures.json merged: table -> clause -> why.
std::map<TableId, std::map<std::string, std::string>> expected_failures() {
  std::map<TableId, std::map<std::string, std::string>> r;
  for (const auto& dir : std::filesystem::directory_iterator(std::string(ROTORCERT_SOURCE_DIR) + "/impls")) {
    const auto file = dir.path() / "expected_failures.json";
    if (!std::filesystem::exists(file)) continue;
    std::ifstream in(file);
    const auto j = nlohmann::json::parse(in);
    for (const auto& e : j.at("failures"))
      r[{e.at("table").get<std::string>(), e.at("scalar").get<std::string>()}][e.at("clause").get<std::string>()] =
          e.at("why").get<std::string>();
  }
  return r;
}

const spec::Spec& the_spec() {
  static const spec::Spec s = spec::load_spec(spec::resolve_spec_dir());
  return s;
}

class Claims : public ::testing::TestWithParam<const rc_impl*> {};

TEST_P(Claims, EveryClaimedClauseHasItsExpectedResult) {
  const rc_impl& table = *GetParam();
  const TableId id{table.name, scalar_name(table)};
  const auto expected = expected_failures()[id];
  engine::CaseOptions options;
  options.seed = 20261122;
  options.cases_per_family = 24;
  std::set<std::string> claimed;
  for (const std::string& clause : engine::claimed_clauses(table)) {
    claimed.insert(clause);
    RC_CLAUSE(clause.c_str());
    const engine::ClauseResult r = engine::run_clause(table, the_spec(), clause, options);
    const std::string where = id.name + " (" + id.scalar + ") " + clause + ": " + engine::to_string(r.outcome) +
                              ", worst " + std::to_string(r.worst_error) + " (" + r.tolerance + ") in " + r.worst_op +
                              " [" + r.worst_label + "] " + r.worst_input + " -> " + r.worst_detail;
    const auto known = expected.find(clause);
    if (known != expected.end()) {
      EXPECT_EQ(r.outcome, engine::Outcome::fail) << where << "\n  expected to FAIL: " << known->second;
      continue;
    }
    // A claimed clause passes, or is NOT_SUPPORTED only because its inputs lie outside the
    // table's declared preconditions (DECL-1).
    const bool outside_preconditions = r.outcome == engine::Outcome::not_supported && !r.excluded.empty();
    EXPECT_TRUE(r.outcome == engine::Outcome::pass || r.outcome == engine::Outcome::quality_warning ||
                outside_preconditions)
        << where;
    if (r.outcome == engine::Outcome::quality_warning) std::printf("QUALITY_WARNING %s\n", where.c_str());
  }
  for (const auto& [clause, why] : expected)
    EXPECT_TRUE(claimed.count(clause)) << id.name << " lists " << clause << " as an expected failure but does not claim it";
}

std::string table_name(const ::testing::TestParamInfo<const rc_impl*>& info) {
  std::string n = std::string(info.param->name) + "_" + scalar_name(*info.param);
  for (char& c : n)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return n;
}

INSTANTIATE_TEST_SUITE_P(Builtin, Claims, ::testing::ValuesIn(impl::builtin_tables()), table_name);

TEST(Claims, EveryTableIsValidAndClaimsOnlyKnownImplementationClauses) {
  for (const rc_impl* t : impl::builtin_tables()) {
    EXPECT_EQ(impl::validate_table(*t), "") << t->name;
    // The table's own claims (rc_impl.clauses); the hygiene clauses the suite adds to every table
    // (engine::claimed_clauses) are no claim of the table's.
    for (int i = 0; t->clauses && t->clauses[i]; ++i) {
      const std::string clause = t->clauses[i];
      const spec::Clause* c = the_spec().find_clause(clause);
      ASSERT_NE(c, nullptr) << t->name << " claims unknown clause " << clause;
      EXPECT_NE(c->level, "Meta") << t->name << " claims " << clause << ", a Meta clause that binds only the suite";
      EXPECT_FALSE(engine::ops_for_clause(clause).empty()) << t->name << " claims " << clause << ", which no ABI op judges";
      const std::string level_bit = c->level;
      const std::map<std::string, std::uint32_t> bits = {{"Core", RC_LEVEL_CORE}, {"Interp", RC_LEVEL_INTERP},
                                                         {"Blend", RC_LEVEL_BLEND}, {"Rigid", RC_LEVEL_RIGID},
                                                         {"Skinning", RC_LEVEL_SKINNING}, {"Robust", RC_LEVEL_ROBUST}};
      // Levels without a bit in rc_impl.levels (Extended, Hygiene) are claimed by their clauses alone.
      if (bits.count(level_bit)) {
        EXPECT_TRUE(t->levels & bits.at(level_bit)) << t->name << " claims " << clause << " without its level " << level_bit;
      }
    }
  }
}

}  // namespace
