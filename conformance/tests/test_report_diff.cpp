// `rotorcert diff` (report_diff.hpp): the regression gate of a library's CI. Each rule is tested on
// typed certificates both ways round (a regression one way is an improvement the other), then the
// tool on two real reports: the worked example plugin and its planted bug.
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <rotorcert/certify/report_diff.hpp>
#include <rotorcert/certify/report_document.hpp>
#include <rotorcert/testing/clause.hpp>
#include <rotorcert/testing/shell.hpp>

namespace {

namespace fs = std::filesystem;
using namespace rotorcert;
using engine::Outcome;
using nlohmann::json;

engine::ClauseResult result(const std::string& id, const std::string& level, Outcome o, double worst_eps) {
  engine::ClauseResult r;
  r.clause = id;
  r.level = level;
  r.outcome = o;
  r.worst_error = worst_eps;
  r.worst_op = "compose";
  r.worst_input = "a=[0x1p+0]";
  return r;
}

/// A double table claiming Core with two clauses.
certify::Certificate table(Outcome compose, double compose_eps) {
  certify::Certificate c;
  c.table.name = "lib";
  c.table.scalar = "double";
  c.table.claimed_levels = {"Core"};
  c.table.claimed_clauses = {"NORM-1", "COMPOSE-1"};
  c.levels = {"Core"};
  c.clauses = {result("NORM-1", "Core", Outcome::pass, 0.5), result("COMPOSE-1", "Core", compose, compose_eps)};
  return c;
}

bool regression(const certify::Certificate& before, const certify::Certificate& after) {
  return certify::diff_certificates({before}, {after}).regression();
}

TEST(ReportDiff, ALostLevelAndAWorseResultAreRegressions) {
  RC_CLAUSE("LEVEL-1");
  const certify::Certificate good = table(Outcome::pass, 1.0), bad = table(Outcome::fail, 1e6);
  const certify::ReportDiff d = certify::diff_certificates({good}, {bad});
  ASSERT_EQ(d.tables.size(), 1u);
  ASSERT_EQ(d.tables[0].levels.size(), 1u);
  EXPECT_EQ(d.tables[0].levels[0].change, certify::Change::worse);
  EXPECT_EQ(*d.tables[0].levels[0].old_status, certify::LevelStatus::met);
  EXPECT_EQ(*d.tables[0].levels[0].new_status, certify::LevelStatus::not_met);
  ASSERT_EQ(d.tables[0].clauses.size(), 1u) << "NORM-1 did not change";
  EXPECT_EQ(d.tables[0].clauses[0].clause, "COMPOSE-1");
  EXPECT_EQ(d.tables[0].clauses[0].outcome_change, certify::Change::worse);
  EXPECT_TRUE(d.regression());
  EXPECT_FALSE(regression(bad, good)) << "a fixed clause is an improvement";
  EXPECT_FALSE(regression(good, good));
  // PASS -> QUALITY_WARNING: the level is only met with warnings now.
  EXPECT_TRUE(regression(good, table(Outcome::quality_warning, 1.0)));
}

TEST(ReportDiff, AWorstErrorMoreThanDoubledIsARegressionAboveHalfAnEps) {
  RC_CLAUSE("REPORT-1");
  EXPECT_TRUE(regression(table(Outcome::pass, 1.0), table(Outcome::pass, 2.5)));
  EXPECT_FALSE(regression(table(Outcome::pass, 1.0), table(Outcome::pass, 1.9)));
  EXPECT_FALSE(regression(table(Outcome::pass, 2.5), table(Outcome::pass, 1.0)));
  // Below the floor both are rounding noise.
  EXPECT_FALSE(regression(table(Outcome::pass, 0.1), table(Outcome::pass, 0.45)));
  EXPECT_TRUE(regression(table(Outcome::pass, 0.1), table(Outcome::pass, 1.2)));
  // A NaN worst error is a status or NaN output: the result change says it, not the error.
  EXPECT_FALSE(regression(table(Outcome::fail, NAN), table(Outcome::fail, 3.0)));
}

TEST(ReportDiff, ATableOrAClaimedClauseGoneIsARegression) {
  RC_CLAUSE("LEVEL-1");
  const certify::Certificate c = table(Outcome::pass, 1.0);
  EXPECT_TRUE(certify::diff_certificates({c}, {}).regression());
  EXPECT_FALSE(certify::diff_certificates({}, {c}).regression()) << "a new table is no regression";
  certify::Certificate fewer = c;
  fewer.clauses.pop_back();
  EXPECT_TRUE(regression(c, fewer)) << "claimed COMPOSE-1 no longer certified";
}

TEST(ReportDiff, CertificatesReadBackFromReportJsonCompareEqual) {
  RC_CLAUSE("REPORT-1");
  certify::Certificate c = table(Outcome::fail, 7.0);
  c.expected_failures["COMPOSE-1"] = "listed";
  c.reproduce["COMPOSE-1"] = "rotorcert certify --impl lib --clause COMPOSE-1 --out x";
  const certify::Certificate back = certify::certificate_from_json(certify::certificate_json(c));
  EXPECT_EQ(certify::certificate_json(back), certify::certificate_json(c));
  EXPECT_FALSE(certify::diff_certificates({c}, {back}).regression());
  EXPECT_TRUE(certify::diff_certificates({c}, {back}).tables[0].clauses.empty());
}

fs::path scratch(const std::string& name) {
  const fs::path p = fs::temp_directory_path() / ("rotorcert_test_report_diff_" + std::to_string(::getpid())) / name;
  fs::remove_all(p);
  return p;
}

TEST(ReportDiff, ToolExitsOneOnARegressionAndZeroOnAnImprovement) {
  RC_CLAUSE("LEVEL-1");
  const fs::path good = scratch("good"), bad = scratch("bad");
  const rotorcert::testing::ShellRun a = rotorcert::testing::run_rotorcert("certify --plugin '" + std::string(ROTORCERT_EXAMPLE_PLUGIN) + "' -q --out '" + good.string() + "'");
  const rotorcert::testing::ShellRun b = rotorcert::testing::run_rotorcert("certify --plugin '" + std::string(ROTORCERT_EXAMPLE_PLUGIN_BUG) + "' -q --out '" + bad.string() + "'");
  ASSERT_EQ(a.exit_code, 0) << a.output;
  ASSERT_EQ(b.exit_code, 1) << b.output;
  const std::string g = (good / "report.json").string(), x = (bad / "report.json").string();
  const rotorcert::testing::ShellRun worse = rotorcert::testing::run_rotorcert("diff '" + g + "' '" + x + "'");
  EXPECT_EQ(worse.exit_code, 1) << worse.output;
  EXPECT_NE(worse.output.find("COMPOSE-1  PASS -> FAIL  (worse)"), std::string::npos) << worse.output;
  const rotorcert::testing::ShellRun better = rotorcert::testing::run_rotorcert("diff '" + x + "' '" + g + "'");
  EXPECT_EQ(better.exit_code, 0) << better.output;
  const rotorcert::testing::ShellRun as_json = rotorcert::testing::run_rotorcert("diff --json '" + g + "' '" + x + "'");
  EXPECT_EQ(as_json.exit_code, 1);
  EXPECT_TRUE(json::parse(as_json.output).at("regression").get<bool>()) << as_json.output;
  EXPECT_EQ(rotorcert::testing::run_rotorcert("diff '" + g + "' '" + (good / "missing.json").string() + "'").exit_code, 2);
}

}  // namespace
