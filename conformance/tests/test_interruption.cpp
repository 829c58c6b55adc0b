// Interruption and --resume (RESULT-4): SIGTERM or Ctrl-C during `certify` leaves
// the previous complete report as it was (byte for byte), keeps every clause finished so far in the
// journal, and `--resume` finishes the run without redoing them, giving the report an
// uninterrupted run gives. The runs certify rotor_m2 (both tables, about 60 clauses, a few seconds).
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <rotorcert/testing/clause.hpp>
#include <rotorcert/testing/shell.hpp>

namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using rotorcert::testing::run_shell;

const std::string kCertify = std::string("'") + ROTORCERT_BINARY + "' certify --impl rotor_m2 -q -j 1 --cases 256";

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("rotorcert_interrupt_test_" + std::to_string(::getpid())) / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// The report without its run object, the only part that may differ between equal runs.
json results_of(const fs::path& report) {
  json j = json::parse(read(report));
  j.erase("run");
  return j;
}

/// Starts `certify --out DIR`, sends `signal` once its journal holds `clauses` finished clauses,
/// and returns the tool's exit code and output ("never interrupted" when it finished first).
rotorcert::testing::ShellRun interrupt_after(const fs::path& out, int clauses, const char* signal,
                                             const std::string& extra = "") {
  const std::string journal = (out / "certify-journal.jsonl").string();
  // env --default-signal: sh starts background jobs with SIGINT ignored, which the tool respects.
  return run_shell("(env --default-signal=INT,TERM " + kCertify + " " + extra + " --out '" + out.string() + "' & pid=$!; i=0; " +
                   "while kill -0 $pid 2>/dev/null && [ \"$(cat '" + journal + "' 2>/dev/null | wc -l)\" -le " +
                   std::to_string(clauses) + " ] && [ $i -lt 1200 ]; do sleep 0.05; i=$((i+1)); done; " +
                   "if kill -0 $pid 2>/dev/null; then kill -" + signal + " $pid; else echo never interrupted; fi; " +
                   "wait $pid)");
}

TEST(Interruption, SigtermKeepsThePreviousReportAndResumeFinishesTheRun) {
  RC_CLAUSE("RESULT-4");
  const fs::path out = scratch("sigterm");
  const auto first = run_shell(kCertify + " --out '" + out.string() + "'");
  ASSERT_EQ(first.exit_code, 0) << first.output;
  const std::string previous = read(out / "report.json");
  const json complete = results_of(out / "report.json");
  EXPECT_FALSE(fs::exists(out / "certify-journal.jsonl")) << "a complete run leaves no journal";

  const auto cut = interrupt_after(out, 3, "TERM");
  ASSERT_EQ(cut.output.find("never interrupted"), std::string::npos) << "the run ended before the signal";
  EXPECT_EQ(cut.exit_code, 128 + 15) << cut.output;
  EXPECT_NE(cut.output.find("interrupted by SIGTERM"), std::string::npos) << cut.output;
  EXPECT_NE(cut.output.find("--resume"), std::string::npos) << cut.output;
  EXPECT_EQ(read(out / "report.json"), previous) << "the previous complete report must stay as it was";
  for (const char* f : {"report.html", "report.md"}) EXPECT_TRUE(fs::exists(out / f)) << f;

  // The results collected so far: a header and one complete result per finished clause.
  std::ifstream journal(out / "certify-journal.jsonl");
  std::string line;
  int finished = 0;
  ASSERT_TRUE(std::getline(journal, line));
  EXPECT_EQ(json::parse(line).at("rotorcert_journal"), 1);
  while (std::getline(journal, line)) {
    const json entry = json::parse(line);
    EXPECT_TRUE(entry.at("result").contains("outcome")) << line;
    ++finished;
  }
  EXPECT_GE(finished, 3);

  // Another run's options may not continue this journal, and trying leaves it as it was.
  const std::string before = read(out / "certify-journal.jsonl");
  const auto other = run_shell(kCertify + " --seed 2 --resume --out '" + out.string() + "'");
  EXPECT_EQ(other.exit_code, 2) << other.output;
  EXPECT_NE(other.output.find("seed differs"), std::string::npos) << other.output;
  EXPECT_EQ(read(out / "certify-journal.jsonl"), before);

  // A line cut short (a kill -9 while writing) is dropped, not an error.
  { std::ofstream(out / "certify-journal.jsonl", std::ios::app) << "{\"table\": \"rotor_m2/fl"; }

  const auto resumed = run_shell(kCertify + " --resume --out '" + out.string() + "'");
  ASSERT_EQ(resumed.exit_code, 0) << resumed.output;
  const json report = json::parse(read(out / "report.json"));
  EXPECT_EQ(report.at("run").at("resumed_clauses"), finished) << "every finished clause is taken over, none redone";
  EXPECT_EQ(results_of(out / "report.json"), complete) << "a resumed run gives the uninterrupted run's report";
  EXPECT_FALSE(fs::exists(out / "certify-journal.jsonl"));
}

TEST(Interruption, CtrlCStopsAFirstRunWithoutWritingAReport) {
  RC_CLAUSE("RESULT-4");
  const fs::path out = scratch("sigint");
  const auto cut = interrupt_after(out, 2, "INT");
  ASSERT_EQ(cut.output.find("never interrupted"), std::string::npos) << "the run ended before the signal";
  EXPECT_EQ(cut.exit_code, 128 + 2) << cut.output;
  EXPECT_FALSE(fs::exists(out / "report.json")) << "no report from a half-finished run";
  const auto resumed = run_shell(kCertify + " --resume --out '" + out.string() + "'");
  EXPECT_EQ(resumed.exit_code, 0) << resumed.output;
  EXPECT_TRUE(fs::exists(out / "report.json"));
}

TEST(Interruption, ResumeWithoutAJournalIsAUsageError) {
  RC_CLAUSE("RESULT-4");
  const fs::path out = scratch("nothing");
  const auto r = run_shell(kCertify + " --resume --out '" + out.string() + "'");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("nothing to resume"), std::string::npos) << r.output;
}

}  // namespace
