// `rotorcert certify` and `rotorcert report` as a user runs them: plugins that segfault, hang or
// allocate without bound are reported as CRASH or TIMEOUT with the input, and the run completes
// (RESULT-1, RESULT-3); levels (LEVEL-1); exit codes, determinism and atomic writes (REPORT-1);
// convention diagnosis on mutants whose bug is a convention (CONV-1).
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <map>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <rotorcert/certify/certificate.hpp>
#include <rotorcert/certify/atomic_file.hpp>
#include <rotorcert/certify/report_document.hpp>
#include <rotorcert/certify/verdict.hpp>
#include <rotorcert/certify/isolate.hpp>
#include <rotorcert/certify/wire.hpp>
#include <rotorcert/engine/runner.hpp>
#include <rotorcert/registry.hpp>
#include <rotorcert/testing/clause.hpp>
#include <rotorcert/testing/shell.hpp>

namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using namespace rotorcert;

using ToolRun = ::rotorcert::testing::ShellRun;

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("rotorcert_certify_test_" + std::to_string(::getpid())) / name;
  fs::remove_all(dir);
  fs::create_directories(dir.parent_path());
  return dir;
}

ToolRun rotorcert_tool(const std::string& args) { return ::rotorcert::testing::run_rotorcert(args); }

json read(const fs::path& file) {
  std::ifstream in(file);
  return json::parse(in);
}

const json& clause_of(const json& certificate, const std::string& id) {
  for (const json& c : certificate.at("clauses"))
    if (c.at("id") == id) return c;
  throw std::runtime_error("no clause " + id + " in the certificate");
}

std::string faulty(const std::string& name) { return std::string(ROTORCERT_FAULTY_DIR) + "/" + name + ".so"; }

/// The value of input `name` (first scalar) in a worst-input text "a=[...] t=[0x1p+1]".
double input_value(const std::string& input, const std::string& name) {
  const auto at = input.find(name + "=[");
  if (at == std::string::npos) return NAN;
  return std::strtod(input.c_str() + at + name.size() + 2, nullptr);
}

// ---- isolation ---------------------------------------------------------------------------------

TEST(Certify, ASegfaultIsACrashWithItsInputAndTheRunGoesOn) {
  RC_CLAUSE("RESULT-1");
  RC_CLAUSE("RESULT-3");
  const fs::path out = scratch("segfault");
  const ToolRun r = rotorcert_tool("certify --plugin '" + faulty("segfault_on_extrapolation") + "' --cases 8 -q --out '" +
                                   out.string() + "'");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  const json report = read(out / "report.json");
  ASSERT_EQ(report.at("implementations").size(), 1u);
  const json& cert = report.at("implementations")[0];
  const json& slerp4 = clause_of(cert, "SLERP-4");
  EXPECT_EQ(slerp4.at("outcome"), "CRASH") << slerp4.dump(2);
  const std::string note = slerp4.at("note");
  if (certify::built_with_sanitizer()) {
    // ASan's own SIGSEGV handler reports the fault and then aborts (abort_on_error=1, the asan
    // preset) or exits with its error code (ASan's default): the child never dies of SIGSEGV.
    EXPECT_TRUE(note.find("SIGABRT") != std::string::npos || note.find("exited with status") != std::string::npos)
        << slerp4.dump(2);
    EXPECT_EQ(note.find("address-space limit"), std::string::npos) << "no limit applies in sanitizer builds";
  } else {
    EXPECT_NE(note.find("SIGSEGV"), std::string::npos) << slerp4.dump(2);
  }
  // The plugin faults exactly when t > 1: the input named must be such a t.
  const double t = input_value(slerp4.at("worst").at("input"), "t");
  EXPECT_GT(t, 1.0) << slerp4.dump(2);
  EXPECT_EQ(slerp4.at("worst").at("op"), "slerp");
  // Clauses that never reach t > 1 are judged normally, before and after the crash.
  EXPECT_EQ(clause_of(cert, "NORM-1").at("outcome"), "PASS");
  EXPECT_EQ(clause_of(cert, "SLERP-3").at("outcome"), "PASS");
  EXPECT_EQ(clause_of(cert, "EDGE-6").at("outcome"), "PASS");
  EXPECT_EQ(clause_of(cert, "EDGE-8").at("outcome"), "PASS");
  EXPECT_TRUE(fs::exists(out / "report.html"));
  EXPECT_TRUE(fs::exists(out / "report.md"));
}

// The crash site travels as fields of the child's progress frame (wire.hpp), never parsed out of
// a line of text: a label with "] " in it stays whole, and a frame that is not a WorkingOn object
// (torn, truncated, hostile) is kept as text with no op or label invented from it.
TEST(Certify, TheCrashSiteComesFromTheProgressFrameAsFields) {
  RC_CLAUSE("RESULT-3");
  const certify::WorkingOn w{"slerp", "pair [a] and [b]", "a=[0x1p+0, 0, 0, 0] t=[0x1p+1]", "slerp [pair [a] and [b]] ..."};
  const certify::WorkingOn back = certify::working_on_from_progress(certify::to_json(w).dump());
  EXPECT_EQ(back.op, w.op);
  EXPECT_EQ(back.label, w.label);
  EXPECT_EQ(back.input, w.input);
  EXPECT_EQ(back.text, w.text);
  for (const std::string frame : {"{\"op\": \"slerp\", \"label\": \"x\"", "[\"slerp\"]", "slerp [random] a=[1, 0, 0, 0]",
                                  "{\"op\": \"slerp\", \"label\": 7}"}) {
    const certify::WorkingOn g = certify::working_on_from_progress(frame);
    EXPECT_EQ(g.op, "") << frame;
    EXPECT_EQ(g.label, "") << frame;
    EXPECT_EQ(g.text, frame);
  }
}

TEST(Certify, AHangIsATimeoutWithItsInput) {
  RC_CLAUSE("RESULT-1");
  RC_CLAUSE("RESULT-3");
  const fs::path out = scratch("hang");
  const ToolRun r = rotorcert_tool("certify --plugin '" + faulty("hang_on_negative_t") +
                                   "' --cases 8 --timeout 2 -q --out '" + out.string() + "'");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  const json cert = read(out / "report.json").at("implementations")[0];
  const json& slerp4 = clause_of(cert, "SLERP-4");
  EXPECT_EQ(slerp4.at("outcome"), "TIMEOUT") << slerp4.dump(2);
  EXPECT_NE(slerp4.at("note").get<std::string>().find("2 s"), std::string::npos) << slerp4.dump(2);
  EXPECT_LT(input_value(slerp4.at("worst").at("input"), "t"), 0.0) << slerp4.dump(2);
  EXPECT_EQ(clause_of(cert, "NORM-1").at("outcome"), "PASS");
  EXPECT_EQ(clause_of(cert, "SLERP-3").at("outcome"), "PASS");
}

TEST(Certify, ARunawayAllocationHitsTheMemoryLimitAndIsACrash) {
  RC_CLAUSE("RESULT-3");
  if (certify::built_with_sanitizer())
    GTEST_SKIP() << "sanitizer build: children run without an address-space limit (RESULT-3; ASan's shadow memory "
                    "cannot live under RLIMIT_AS), so the plugin would allocate until the machine runs out of memory";
  const fs::path out = scratch("alloc");
  const ToolRun r = rotorcert_tool("certify --plugin '" + faulty("runaway_allocation") +
                                   "' --cases 8 --memory-mb 512 -q --out '" + out.string() + "'");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  const json cert = read(out / "report.json").at("implementations")[0];
  const json& edge6 = clause_of(cert, "EDGE-6");
  EXPECT_EQ(edge6.at("outcome"), "CRASH") << edge6.dump(2);
  EXPECT_NE(edge6.at("worst").at("input").get<std::string>().find("q=[0x0p+0, 0x0p+0, 0x0p+0, 0x0p+0]"),
            std::string::npos)
      << edge6.dump(2);
  EXPECT_EQ(clause_of(cert, "NORM-1").at("outcome"), "PASS");
}

TEST(Certify, RecordsTheFloatingPointEnvironmentTheImplementationRanIn) {
  RC_CLAUSE("NUM-1");
  const fs::path out = scratch("ftz");
  rotorcert_tool("certify --plugin '" + faulty("sets_flush_to_zero") + "' --cases 8 -q --out '" + out.string() + "'");
  const json report = read(out / "report.json");
  const json& env = report.at("implementations")[0].at("fp_environment");
  EXPECT_TRUE(env.at("flush_to_zero").get<bool>()) << env.dump();
  EXPECT_TRUE(env.at("denormals_are_zero").get<bool>()) << env.dump();
  // The tool itself runs without FTZ/DAZ (the plugin is loaded only in child processes).
  EXPECT_FALSE(report.at("platform").at("fp_environment").at("flush_to_zero").get<bool>());
  // Under DAZ a subnormal input reads as zero: the subnormal clause must fail (the same code passes
  // it without FTZ/DAZ, see ASegfaultIsACrash...), and the judging must not be affected.
  EXPECT_EQ(clause_of(report.at("implementations")[0], "EDGE-8").at("outcome"), "FAIL");
  EXPECT_EQ(clause_of(report.at("implementations")[0], "NORM-1").at("outcome"), "PASS");
}

TEST(Certify, APluginThatCannotBeLoadedIsAUsageError) {
  RC_CLAUSE("RESULT-3");
  const ToolRun r = rotorcert_tool("certify --plugin /nonexistent/plugin.so --out '" + scratch("none").string() + "'");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("/nonexistent/plugin.so"), std::string::npos) << r.output;
}

// ---- exit codes, levels, determinism ------------------------------------------------------------

TEST(Certify, ExitCodesFollowTheResults) {
  RC_CLAUSE("REPORT-1");
  const ToolRun good = rotorcert_tool("certify --impl rotor_m2 --scalar double --cases 4 -q --out '" +
                                      scratch("m2").string() + "'");
  EXPECT_EQ(good.exit_code, 0) << good.output;
  const ToolRun bad = rotorcert_tool("certify --impl paper_literal --cases 4 --out '" + scratch("paper").string() + "'");
  EXPECT_EQ(bad.exit_code, 1) << bad.output;
  EXPECT_NE(bad.output.find("FAIL"), std::string::npos) << bad.output;
  for (const std::string args : {"certify --impl no_such_impl --out x", "certify --impl dq --clause NOPE-1 --out x",
                                 "certify --impl dq --level Meta --out x", "certify --impl dq",
                                 "certify --impl dq --plugin x.so --out x", "certify --impl dq --clause SLERP-1 --level Core --out x"}) {
    const ToolRun r = rotorcert_tool(args);
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.output;
  }
}

TEST(Certify, PaperLiteralFailsExactlyItsErrata) {
  RC_CLAUSE("RESULT-1");
  const fs::path out = scratch("paper_exact");
  rotorcert_tool("certify --impl paper_literal --cases 8 -q --out '" + out.string() + "'");
  const json cert = read(out / "report.json").at("implementations")[0];
  EXPECT_TRUE(cert.at("as_expected").get<bool>());
  const auto expected = certify::expected_failures("paper_literal", "float");
  ASSERT_FALSE(expected.empty());
  for (const json& c : cert.at("clauses")) {
    if (!c.at("claimed").get<bool>()) continue;
    const bool known = expected.count(c.at("id")) > 0;
    EXPECT_EQ(c.at("outcome"), known ? "FAIL" : "PASS") << c.dump(2);
  }
}

TEST(Certify, SameSeedSameReportExceptTheRunObject) {
  RC_CLAUSE("REPORT-1");
  const fs::path a = scratch("det_a"), b = scratch("det_b"), c = scratch("det_c");
  const std::string base = "certify --impl glm_quat --scalar float --cases 6 -q ";
  rotorcert_tool(base + "--seed 7 --jobs 1 --out '" + a.string() + "'");
  rotorcert_tool(base + "--seed 7 --jobs 2 --out '" + b.string() + "'");
  rotorcert_tool(base + "--seed 8 --out '" + c.string() + "'");
  json ra = read(a / "report.json"), rb = read(b / "report.json"), rc = read(c / "report.json");
  for (json* r : {&ra, &rb, &rc}) r->erase("run");
  EXPECT_EQ(ra, rb) << "same seed, different report.json";
  EXPECT_NE(ra.at("implementations"), rc.at("implementations")) << "the seed has no effect";
}

TEST(Certify, WritesAtomically) {
  RC_CLAUSE("REPORT-1");
  const fs::path dir = scratch("atomic");
  fs::create_directories(dir);
  certify::write_atomically(dir / "f.json", "old");
  certify::write_atomically(dir / "f.json", "new contents");
  std::ifstream in(dir / "f.json");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(text, "new contents");
  std::size_t files = 0;
  for (const auto& e : fs::directory_iterator(dir)) files += e.is_regular_file() ? 1 : 0;
  EXPECT_EQ(files, 1u) << "a temporary file was left behind";
  EXPECT_THROW(certify::write_atomically(dir / "missing" / "f.json", "x"), std::runtime_error);
}

engine::ClauseResult result(const std::string& id, const std::string& level, engine::Outcome o) {
  engine::ClauseResult r;
  r.clause = id;
  r.level = level;
  r.outcome = o;
  return r;
}

TEST(Levels, MetMetWithWarningsNotMet) {
  RC_CLAUSE("LEVEL-1");
  using engine::Outcome;
  certify::Certificate c;
  c.table.name = "synthetic";
  c.table.scalar = "double";
  c.clauses = {result("NORM-1", "Core", Outcome::pass),          result("MAT-2", "Core", Outcome::quality_warning),
               result("SLERP-1", "Interp", Outcome::pass),       result("SLERP-4", "Interp", Outcome::pass),
               result("QLB-1", "Blend", Outcome::not_supported), result("DQ-1", "Rigid", Outcome::crash),
               result("SKIN-1", "Skinning", Outcome::timeout),   result("EDGE-1", "Robust", Outcome::fail)};
  c.levels = {"Core", "Interp", "Blend", "Rigid", "Skinning", "Robust"};
  std::map<std::string, certify::LevelResult> by;
  for (const certify::LevelResult& l : certify::level_results(c)) by[l.level] = l;
  EXPECT_EQ(by.at("Core").status, certify::LevelStatus::met_with_warnings);
  EXPECT_EQ(by.at("Core").not_pass, std::vector<std::string>{"MAT-2"});
  EXPECT_EQ(by.at("Core").counts.at(Outcome::pass), 1);
  EXPECT_EQ(by.at("Interp").status, certify::LevelStatus::met);
  for (const char* l : {"Blend", "Rigid", "Skinning", "Robust"}) EXPECT_EQ(by.at(l).status, certify::LevelStatus::not_met) << l;
  EXPECT_NE(certify::claim(c).find(": Core, Interp (binary64)"), std::string::npos) << certify::claim(c);
  // report.json says the same as the typed values it is written from.
  const json cert = certify::certificate_json(c);
  EXPECT_EQ(cert.at("claim"), certify::claim(c));
  for (const json& l : cert.at("levels"))
    EXPECT_EQ(l.at("status"), certify::to_string(by.at(l.at("level")).status)) << l.dump();
}

// A certificate is as expected when every listed defect FAILs and every other claimed clause is
// good; a claimed clause that is NOT_SUPPORTED only because its inputs lie outside a declared
// precondition is good (DECL-1), any other NOT_SUPPORTED is not.
TEST(Levels, AsExpectedFromTypedCertificate) {
  RC_CLAUSE("DECL-1");
  using engine::Outcome;
  certify::Certificate c;
  c.table.name = "synthetic";
  c.table.scalar = "float";
  c.table.claimed_clauses = {"NORM-1", "MAT-2", "EDGE-1"};
  c.levels = {"Core", "Robust"};
  c.clauses = {result("NORM-1", "Core", Outcome::pass), result("MAT-2", "Core", Outcome::fail),
               result("EDGE-1", "Robust", Outcome::not_supported), result("LOG-1", "Core", Outcome::fail)};
  c.clauses[2].excluded["unit_quaternion"] = 3;
  c.expected_failures["MAT-2"] = "listed";
  EXPECT_TRUE(certify::as_expected(c));  // LOG-1 fails but is not claimed
  EXPECT_FALSE(certify::all_claimed_good(c));
  c.clauses[2].excluded.clear();
  EXPECT_FALSE(certify::as_expected(c)) << "NOT_SUPPORTED without a declared precondition is a surprise";
  c.clauses[2].excluded["unit_quaternion"] = 3;
  c.clauses[1].outcome = Outcome::pass;
  EXPECT_FALSE(certify::as_expected(c)) << "a listed defect that passes is news";
  c.clauses[1].outcome = Outcome::fail;
  c.error = "could not load";
  EXPECT_FALSE(certify::as_expected(c));
  EXPECT_FALSE(certify::certificate_json(c).at("as_expected").get<bool>());
}

TEST(Report, EveryBuiltinAsExpectedAndEveryMutantKilled) {
  RC_CLAUSE("REPORT-1");
  const fs::path out = scratch("report");
  const ToolRun r = rotorcert_tool("report --impl dq --impl paper_literal --cases 4 --no-third-party -q --out '" + out.string() + "'");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  const json report = read(out / "report.json");
  EXPECT_TRUE(report.at("summary").at("as_expected").get<bool>());
  const json& m = report.at("sections").at("mutants");
  EXPECT_EQ(m.at("killed"), m.at("total"));
  EXPECT_GE(m.at("total").get<int>(), 30);
  for (const json& mutant : m.at("mutants"))
    for (const json& c : mutant.at("clauses")) EXPECT_EQ(c.at("outcome"), "FAIL") << mutant.dump(2);
}

// ---- convention diagnosis -----------------------------------------------------------------------

const spec::Spec& the_spec() {
  static const spec::Spec s = spec::load_spec(spec::resolve_spec_dir());
  return s;
}

std::vector<std::string> diagnose(const rc_impl& table, const std::string& clause) {
  engine::CaseOptions o;
  o.seed = 3;
  o.cases_per_family = 8;
  EXPECT_EQ(engine::run_clause(table, the_spec(), clause, o).outcome, engine::Outcome::fail) << clause;
  return engine::detect_conventions(table, the_spec(), clause, o);
}

bool contains(const std::vector<std::string>& v, const std::string& x) { return std::find(v.begin(), v.end(), x) != v.end(); }

TEST(Conventions, MutantsWhoseBugIsAConventionAreDiagnosed) {
  RC_CLAUSE("CONV-1");
  // mutant -> the convention its bug is (the scalar type and clauses come from mutants.json).
  const std::map<std::string, std::string> convention_of = {{"wxyz_order", "wxyz_order"},
                                                            {"apply_reversed", "inverse_sandwich"},
                                                            {"compose_swapped", "compose_reversed"},
                                                            {"axang_degrees", "degrees"}};
  std::size_t checked = 0;
  for (const json& m : read(ROTORCERT_MUTANTS_JSON)) {
    const auto it = convention_of.find(m.at("mutant"));
    if (it == convention_of.end()) continue;
    const auto plugin =
        impl::Plugin::load(std::string(ROTORCERT_MUTANT_DIR) + "/rotorcert_mutant_" + it->first + ".so");
    const rc_impl* table = nullptr;
    for (const rc_impl* t : plugin->tables())
      if ((t->scalar == RC_SCALAR_FLOAT32) == (m.at("scalar") == "float")) table = t;
    ASSERT_NE(table, nullptr) << it->first;
    for (const std::string clause : m.at("breaks")) {
      const auto found = diagnose(*table, clause);
      EXPECT_TRUE(contains(found, it->second)) << it->first << " " << clause << ": " << ::testing::PrintToString(found);
      ++checked;
    }
  }
  EXPECT_GE(checked, convention_of.size());
}

TEST(Conventions, NumericalBugsAreNotPassedOffAsConventions) {
  RC_CLAUSE("CONV-1");
  for (const auto& [mutant, clause] : std::vector<std::pair<std::string, std::string>>{
           {"slerp_no_flip", "SLERP-1"}, {"qlb_no_renorm", "QLB-1"}, {"to_matrix_transposed", "MAT-1"}}) {
    const auto plugin = impl::Plugin::load(std::string(ROTORCERT_MUTANT_DIR) + "/rotorcert_mutant_" + mutant + ".so");
    const rc_impl& table = *plugin->tables().front();
    const auto found = diagnose(table, clause);
    // A transposed matrix is the inverse rotation: the ~R x R sandwich explains it, honestly.
    if (mutant == "to_matrix_transposed") EXPECT_TRUE(contains(found, "inverse_sandwich")) << ::testing::PrintToString(found);
    else EXPECT_TRUE(found.empty()) << mutant << ": " << ::testing::PrintToString(found);
  }
}

TEST(Conventions, PaperLiteralIsTheReverseMap) {
  RC_CLAUSE("CONV-1");
  const rc_impl* table = impl::find_builtin("paper_literal", RC_SCALAR_FLOAT32);
  ASSERT_NE(table, nullptr);
  for (const char* clause : {"APPLY-1", "COMPOSE-1", "MAT-1"})
    EXPECT_TRUE(contains(diagnose(*table, clause), "reverse_map")) << clause;
}

}  // namespace
