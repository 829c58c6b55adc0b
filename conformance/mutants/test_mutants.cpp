// Mutation testing of the suite (issue 4): every mutant plugin in the mutants directory is a
// correct implementation but for one real-world bug, and mutants.json names the clauses it must
// break. The engine must judge each of those clauses FAIL (kill rate 100%), and the directory and
// the list must agree. ROTORCERT_MUTANT_SURVEY=1 also prints every other clause's outcome.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <rotorcert/engine/runner.hpp>
#include <rotorcert/registry.hpp>
#include <rotorcert/testing/clause.hpp>

namespace {

using namespace rotorcert;

struct Mutant {
  std::string name, scalar, bug;
  std::vector<std::string> breaks;
  /// ACC-1: clauses on which the mutant's behaviour is a convention a correct library may choose:
  /// there it must be graded ACCEPTABLE with that convention named, never FAIL (no crying wolf).
  std::vector<std::pair<std::string, std::string>> accepts;
};

std::vector<Mutant> listed() {
  std::ifstream in(ROTORCERT_MUTANTS_JSON);
  const auto j = nlohmann::json::parse(in);
  std::vector<Mutant> r;
  for (const auto& e : j) {
    Mutant m{e.at("mutant").get<std::string>(), e.at("scalar").get<std::string>(), e.at("bug").get<std::string>(),
             e.at("breaks").get<std::vector<std::string>>(), {}};
    for (const auto& a : e.value("accepts", nlohmann::json::array()))
      m.accepts.emplace_back(a.at("clause").get<std::string>(), a.at("convention").get<std::string>());
    r.push_back(std::move(m));
  }
  return r;
}

std::string plugin_path(const std::string& name) {
  return std::string(ROTORCERT_MUTANT_DIR) + "/rotorcert_mutant_" + name + ".so";
}

const spec::Spec& the_spec() {
  static const spec::Spec s = spec::load_spec(spec::resolve_spec_dir());
  return s;
}

engine::CaseOptions options() {
  engine::CaseOptions o;
  o.seed = 20261122;
  o.cases_per_family = 24;
  return o;
}

TEST(Mutants, EveryMutantIsKilledByEveryClauseItBreaks) {
  const std::vector<Mutant> mutants = listed();
  ASSERT_GE(mutants.size(), 30u);
  const bool survey = std::getenv("ROTORCERT_MUTANT_SURVEY") != nullptr;
  std::size_t killed = 0, defects = 0;
  for (const Mutant& m : mutants) {
    SCOPED_TRACE("mutant " + m.name + ": " + m.bug);
    ASSERT_FALSE(m.breaks.empty() && m.accepts.empty()) << m.name << " names no clause it breaks or is accepted on";
    const auto plugin = impl::Plugin::load(plugin_path(m.name));
    ASSERT_EQ(plugin->tables().size(), 1u);
    const rc_impl& table = *plugin->tables()[0];
    EXPECT_EQ(m.scalar, table.scalar == RC_SCALAR_FLOAT32 ? "float" : "double");
    for (const auto& [clause, convention] : m.accepts) {
      RC_CLAUSE(clause.c_str());
      RC_CLAUSE("ACC-1");
      const engine::ClauseResult r = engine::run_clause(table, the_spec(), clause, options());
      EXPECT_TRUE(r.outcome == engine::Outcome::pass || r.outcome == engine::Outcome::quality_warning)
          << m.name << " is graded " << engine::to_string(r.outcome) << " on " << clause << ", not ACCEPTABLE: "
          << r.worst_input << " -> " << r.worst_detail;
      const std::string& expected = convention;  // clang 14 cannot capture a structured binding
      const bool named = std::any_of(r.acceptable.begin(), r.acceptable.end(),
                                     [&](const engine::ClauseResult::Acceptable& a) { return a.convention == expected; });
      EXPECT_TRUE(named) << m.name << " on " << clause << ": the convention " << convention << " is not named";
      std::printf("%-28s %-10s %-15s accepted as %s\n", m.name.c_str(), clause.c_str(), engine::to_string(r.outcome),
                  convention.c_str());
    }
    if (m.breaks.empty()) continue;
    ++defects;
    bool all_fail = true;
    for (const std::string& clause : m.breaks) {
      RC_CLAUSE(clause.c_str());
      ASSERT_NE(the_spec().find_clause(clause), nullptr) << "unknown clause " << clause;
      const engine::ClauseResult r = engine::run_clause(table, the_spec(), clause, options());
      const bool fail = r.outcome == engine::Outcome::fail;
      all_fail = all_fail && fail;
      EXPECT_TRUE(fail) << m.name << " survives " << clause << ": " << engine::to_string(r.outcome) << ", worst "
                        << r.worst_error << " (" << r.tolerance << ") in " << r.worst_op << " [" << r.worst_label
                        << "] over " << r.cases << " cases: " << r.worst_input << " -> " << r.worst_detail;
      std::printf("%-28s %-10s %-15s %zu/%zu failing, worst %g [%s]\n", m.name.c_str(), clause.c_str(),
                  engine::to_string(r.outcome), r.failures, r.cases, r.worst_error, r.worst_label.c_str());
      if (survey) std::printf("  worst case %s -> %s\n", r.worst_input.c_str(), r.worst_detail.c_str());
    }
    if (all_fail) ++killed;
    if (survey)
      for (const spec::Clause& c : the_spec().clauses) {
        if (c.level == "Meta") continue;
        const engine::ClauseResult r = engine::run_clause(table, the_spec(), c.id, options());
        if (r.outcome != engine::Outcome::not_supported)
          std::printf("  survey %-28s %-10s %s\n", m.name.c_str(), c.id.c_str(), engine::to_string(r.outcome));
      }
  }
  std::printf("mutants killed: %zu of %zu (%.0f%%)\n", killed, defects, 100.0 * double(killed) / double(defects));
  EXPECT_EQ(killed, defects);
}

TEST(Mutants, TheDirectoryAndTheListAgree) {
  std::set<std::string> built, names;
  const std::string prefix = "rotorcert_mutant_";
  for (const auto& e : std::filesystem::directory_iterator(ROTORCERT_MUTANT_DIR)) {
    const std::string f = e.path().filename().string();
    if (e.path().extension() == ".so" && f.rfind(prefix, 0) == 0)
      built.insert(f.substr(prefix.size(), f.size() - prefix.size() - 3));
  }
  for (const Mutant& m : listed()) {
    EXPECT_TRUE(names.insert(m.name).second) << m.name << " is listed twice";
    EXPECT_TRUE(built.count(m.name)) << m.name << " is listed in mutants.json but " << plugin_path(m.name) << " is not built";
  }
  for (const std::string& b : built) EXPECT_TRUE(names.count(b)) << "plugin " << plugin_path(b) << " is not listed in mutants.json";
}

}  // namespace
