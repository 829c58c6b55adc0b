// Test vectors (`rotorcert vectors export / check / run`): the export is deterministic, complete
// and valid against its schema; a results file graded by `vectors check` gives the verdicts of
// run_clause() on the same implementation; perturbed, missing and malformed results and altered
// vectors are caught; and an adapter in another language (Python) passes, its buggy variant not.
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include <rotorcert/engine/hygiene.hpp>

#include <rotorcert/engine/runner.hpp>
#include <rotorcert/registry.hpp>
#include <rotorcert/testing/clause.hpp>
#include <rotorcert/testing/shell.hpp>
#include <rotorcert/vectors/check.hpp>
#include <rotorcert/vectors/error.hpp>
#include <rotorcert/vectors/flags.hpp>
#include <rotorcert/vectors/run.hpp>
#include <rotorcert/vectors/vector_set.hpp>

namespace {

namespace fs = std::filesystem;
using namespace rotorcert;
using nlohmann::json;

constexpr int kCases = 8;  // per family: enough to reach every family, quick to run

const spec::Spec& the_spec() {
  static const spec::Spec s = spec::load_spec(spec::resolve_spec_dir());
  return s;
}

vectors::BuildOptions options(std::uint64_t seed = 1) {
  vectors::BuildOptions o;
  o.seed = seed;
  o.cases_per_family = kCases;
  return o;
}

/// A fresh directory per test (tests run as separate processes, possibly in parallel).
fs::path scratch(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("rotorcert_vectors_" + std::to_string(::getpid()) + "_" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

using ToolRun = ::rotorcert::testing::ShellRun;
ToolRun shell(const std::string& command_line) { return ::rotorcert::testing::run_shell(command_line); }

ToolRun rotorcert(const std::string& args) { return ::rotorcert::testing::run_rotorcert(args); }

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

void write(const fs::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }

/// An export written to dir, loaded back for one format.
vectors::VectorSet exported(const fs::path& dir, ref::Format f) {
  vectors::write_export(dir, vectors::render_export(the_spec(), options()));
  return vectors::load_vectors(the_spec(), dir, &f);
}

const rc_impl& builtin(const char* name, std::uint32_t scalar) {
  const rc_impl* t = impl::find_builtin(name, scalar);
  if (t == nullptr) throw std::runtime_error(std::string("no built-in ") + name);
  return *t;
}

/// The results file of a built-in table, as JSON (what an adapter would write).
json results_of(const rc_impl& table, const vectors::VectorSet& set, const fs::path& file) {
  return json::parse(vectors::run_table(table, set, file).dump());
}

vectors::Grading grade(const vectors::VectorSet& set, const json& results, const fs::path& file) {
  return vectors::grade(the_spec(), set, vectors::parse_results(results, file));
}

/// The first vector of (clause, op) with that label, and its file.
std::pair<const vectors::VectorFile*, const vectors::Vector*> find_vector(const vectors::VectorSet& set, const std::string& clause,
                                                                          const std::string& op, const std::string& label) {
  for (const auto& f : set.files)
    if (f.clause == clause && f.op == op)
      for (const auto& v : f.tests)
        if (v.input.label == label) return {&f, &v};
  return {nullptr, nullptr};
}

json& result_for(json& results, const std::string& id) {
  for (json& e : results["results"])
    if (e["id"] == id) return e;
  throw std::runtime_error("no result " + id);
}

bool good(engine::Outcome o) { return o == engine::Outcome::pass || o == engine::Outcome::quality_warning; }

// ---- export -------------------------------------------------------------------------------

TEST(VectorsExport, IsDeterministicAndTheToolWritesExactlyThat) {
  const auto a = vectors::render_export(the_spec(), options());
  const auto b = vectors::render_export(the_spec(), options());
  EXPECT_EQ(a, b);
  // Another seed gives other random vectors (the seed is not ignored)...
  const auto c = vectors::render_export(the_spec(), options(2));
  EXPECT_NE(a.at("SLERP-1_slerp_binary64.json"), c.at("SLERP-1_slerp_binary64.json"));
  // ...and the tool writes byte for byte what render_export gives, twice the same.
  const fs::path d1 = scratch("det1"), d2 = scratch("det2");
  for (const fs::path& d : {d1, d2}) {
    const ToolRun r = rotorcert("vectors export --out '" + d.string() + "' --cases " + std::to_string(kCases));
    ASSERT_EQ(r.exit_code, 0) << r.output;
  }
  std::size_t files = 0;
  for (const auto& [name, text] : a) {
    EXPECT_EQ(slurp(d1 / name), text) << name;
    EXPECT_EQ(slurp(d2 / name), text) << name;
    ++files;
  }
  EXPECT_EQ(files, static_cast<std::size_t>(std::distance(fs::directory_iterator(d1), fs::directory_iterator())));
  fs::remove_all(d1);
  fs::remove_all(d2);
}

TEST(VectorsExport, CoversEveryClauseAndOpInBothFormats) {
  std::set<std::string> files;
  for (const auto& [name, text] : vectors::render_export(the_spec(), options())) {
    files.insert(name);
    if (name == "index.json") continue;
    EXPECT_GT(json::parse(text).at("numberOfTests").get<int>(), 0) << name;
  }
  std::size_t expected = 0;
  for (const spec::Clause& cl : the_spec().clauses) {
    if (cl.level == "Meta") continue;
    if (engine::is_hygiene_clause(cl.id)) continue;  // HYG-*: judged through the C ABI only, no vectors
    const auto ops = engine::ops_for_clause(cl.id);
    EXPECT_FALSE(ops.empty()) << cl.id << " has no operation that judges it";
    for (const char* format : {"binary32", "binary64"}) {
      if (cl.id == "EXP-2") {  // one round trip through log and exp
        EXPECT_TRUE(files.count(cl.id + "_log_exp_round_trip_" + format + ".json")) << cl.id;
        ++expected;
        continue;
      }
      for (const std::string& op : ops) {
        EXPECT_TRUE(files.count(cl.id + "_" + op + "_" + format + ".json")) << cl.id << " / " << op << " / " << format;
        ++expected;
      }
    }
  }
  EXPECT_EQ(files.size(), expected + 1);  // + index.json
}

TEST(VectorsExport, IdsAreUniqueStableAndNameTheirVector) {
  const fs::path dir = scratch("ids");
  vectors::write_export(dir, vectors::render_export(the_spec(), options()));
  const vectors::VectorSet set = vectors::load_vectors(the_spec(), dir);
  std::set<std::string> ids;
  std::size_t n = 0;
  for (const auto& f : set.files)
    for (const auto& v : f.tests) {
      ++n;
      EXPECT_TRUE(ids.insert(v.id).second) << "duplicate " << v.id;
      char tail[16];
      std::snprintf(tail, sizeof tail, "/%04d", v.tc_id);
      EXPECT_EQ(v.id, f.clause + "/" + f.op + "/" + vectors::format_name(f.format) + tail);
      EXPECT_FALSE(v.flags.empty()) << v.id;
      // In vocabulary order, each once (RoundTrip leads on EXP-2's round trip).
      std::vector<std::string> rest(v.flags.begin() + (f.round_trip() ? 1 : 0), v.flags.end());
      if (f.round_trip()) {
        EXPECT_EQ(v.flags.front(), "RoundTrip") << v.id;
      }
      EXPECT_EQ(vectors::sorted_flags(rest), rest) << v.id;
    }
  EXPECT_EQ(n, json::parse(slurp(dir / "index.json")).at("numberOfTests").get<std::size_t>());
  // More cases per family extend the families; the worked examples come first and keep their ids.
  vectors::BuildOptions more = options();
  more.cases_per_family = kCases * 2;
  more.clauses = {"NORM-1"};
  for (const auto& f : vectors::build_vector_files(the_spec(), more))
    for (const auto& v : f.tests)
      if (v.input.label.rfind("example ", 0) == 0) {
        EXPECT_TRUE(ids.count(v.id)) << v.id;
      }
  fs::remove_all(dir);
}

TEST(VectorsExport, EveryFlagIsDocumentedAndUnknownLabelsAreRejected) {
  for (const auto& [name, text] : vectors::render_export(the_spec(), options())) {
    if (name == "index.json") continue;
    const json j = json::parse(text);
    for (const json& t : j.at("tests"))
      for (const json& flag : t.at("flags")) EXPECT_TRUE(j.at("flags").contains(flag.get<std::string>())) << name << " " << flag;
  }
  EXPECT_THROW(vectors::sorted_flags({"AFlagNoOneDocumented"}), std::logic_error);
  EXPECT_THROW(vectors::sorted_flags({}), std::logic_error);
  EXPECT_EQ(vectors::sorted_flags({"HugeScale", "NonUnit", "HugeScale"}), (std::vector<std::string>{"NonUnit", "HugeScale"}));
}

// The flags are set where each case is made (engine::Case::flags), never parsed from labels: every
// case of every clause's checks carries documented flags, and the scale families say by their flags
// whether |q|^2 leaves the format (EDGE-5: beyond 2^+-10).
TEST(VectorsExport, EveryEngineCaseCarriesItsFlagsAsData) {
  std::size_t cases = 0, huge = 0, tiny = 0;
  for (const auto& f : vectors::build_vector_files(the_spec(), options()))
    for (const auto& v : f.tests) {
      ++cases;
      EXPECT_FALSE(v.flags.empty()) << v.id << " [" << v.input.label << "]";
      const bool has_huge = std::count(v.flags.begin(), v.flags.end(), "HugeScale") != 0;
      const bool has_tiny = std::count(v.flags.begin(), v.flags.end(), "TinyScale") != 0;
      huge += has_huge;
      tiny += has_tiny;
      const std::string prefix = "non-unit scale 2^";
      if (v.input.label.rfind(prefix, 0) == 0 && v.input.label.find("..") == std::string::npos) {
        const int e = std::stoi(v.input.label.substr(prefix.size()));
        EXPECT_EQ(has_huge, e > 10) << v.id << " [" << v.input.label << "]";
        EXPECT_EQ(has_tiny, e < -10) << v.id << " [" << v.input.label << "]";
      }
    }
  EXPECT_GT(cases, 1000u);
  EXPECT_GT(huge, 0u);
  EXPECT_GT(tiny, 0u);
}

TEST(VectorsExport, FilesValidateAgainstTheSchemas) {
  if (shell("python3 -c 'import jsonschema'").exit_code != 0) GTEST_SKIP() << "python3 with jsonschema is not installed";
  const fs::path dir = scratch("schema");
  const auto set = exported(dir, ref::Format::binary32);
  write(dir / "results.json", results_of(builtin("rotor_m2", RC_SCALAR_FLOAT32), set, dir / "results.json").dump(1));
  const std::string validate = std::string("python3 '") + ROTORCERT_SOURCE_DIR + "/conformance/tests/vectors_validate.py' ";
  const ToolRun v = shell(validate + "'" + ROTORCERT_SPEC_DIR + "/vectors.schema.json' '" + dir.string() + "'/*_*.json '" +
                          (dir / "index.json").string() + "'");
  EXPECT_EQ(v.exit_code, 0) << v.output;
  const ToolRun r = shell(validate + "'" + ROTORCERT_SPEC_DIR + "/results.schema.json' '" + (dir / "results.json").string() + "'");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  // The schema is not a rubber stamp: a file without its tests is rejected.
  json broken = json::parse(slurp(dir / "NORM-1_normalize_binary32.json"));
  broken.erase("tests");
  write(dir / "broken.json", broken.dump());
  EXPECT_EQ(shell(validate + "'" + ROTORCERT_SPEC_DIR + "/vectors.schema.json' '" + (dir / "broken.json").string() + "'").exit_code, 1);
  fs::remove_all(dir);
}

// ---- grading ------------------------------------------------------------------------------

/// Grades a built-in table through a results file and compares every clause with run_clause().
void expect_same_as_run_clause(const char* name, std::uint32_t scalar) {
  const rc_impl& table = builtin(name, scalar);
  const fs::path dir = scratch(std::string("route_") + name);
  const auto set = exported(dir, engine::format_of(table));
  const vectors::Grading g = grade(set, results_of(table, set, dir / "results.json"), dir / "results.json");
  const engine::CaseOptions case_options{1, kCases, true};
  ASSERT_FALSE(g.certificate.clauses.empty());
  for (const engine::ClauseResult& got : g.certificate.clauses) {
    SCOPED_TRACE(std::string(name) + " " + got.clause);
    if (engine::is_hygiene_clause(got.clause)) {  // the route cannot watch the library's calls (section 9a)
      EXPECT_EQ(got.outcome, engine::Outcome::not_supported);
      continue;
    }
    const engine::ClauseResult want = engine::run_clause(table, the_spec(), got.clause, case_options);
    EXPECT_EQ(engine::to_string(got.outcome), std::string(engine::to_string(want.outcome)));
    if (want.outcome == engine::Outcome::not_supported) continue;
    EXPECT_EQ(got.cases, want.cases);
    EXPECT_EQ(got.failures, want.failures);
    EXPECT_EQ(got.worst_op, want.worst_op);
    EXPECT_EQ(got.worst_label, want.worst_label);
    EXPECT_EQ(got.worst_input, want.worst_input);
    EXPECT_EQ(got.worst_detail, want.worst_detail);
    if (std::isnan(want.worst_error)) EXPECT_TRUE(std::isnan(got.worst_error));
    else EXPECT_EQ(got.worst_error, want.worst_error);
    EXPECT_EQ(got.errors, want.errors);
  }
  // A correct table passes what it claims.
  for (const std::string& c : g.certificate.table.claimed_clauses)
    if (const auto* r = vectors::find_clause(g, c); r && !g.certificate.expected_failures.count(c))
      if (std::string(name) != "glm_quat") {
        EXPECT_TRUE(good(r->outcome)) << name << " " << c << ": " << r->worst_detail;
      }
  fs::remove_all(dir);
}

TEST(VectorsCheck, ResultsFileRouteGivesTheVerdictsOfRunClause) {
  RC_CLAUSE("TOL-1");
  RC_CLAUSE("RESULT-1");
  expect_same_as_run_clause("dq", RC_SCALAR_FLOAT64);
  expect_same_as_run_clause("rotor_m2", RC_SCALAR_FLOAT32);
  expect_same_as_run_clause("glm_quat", RC_SCALAR_FLOAT32);  // many FAILs: the worst cases must agree too
}

/// rotor_m2 (float) results with the COMPOSE-1 output of one random vector scaled by 1 + delta,
/// delta chosen so that the error is `bar_eps` eps (the compose measure is relative).
vectors::Grading perturbed_compose(double bar_eps, std::string* id, std::string* input) {
  const fs::path dir = scratch("perturb");
  const rc_impl& table = builtin("rotor_m2", RC_SCALAR_FLOAT32);
  const auto set = exported(dir, ref::Format::binary32);
  json results = results_of(table, set, dir / "results.json");
  const auto [file, vec] = find_vector(set, "COMPOSE-1", "compose", "random");
  if (vec == nullptr) throw std::runtime_error("no random COMPOSE-1 vector");
  *id = vec->id;
  *input = engine::describe_inputs(file->abi_op(), vec->input, file->format);
  // max_i |r_i| / |r| of the expected product: scaling by 1 + delta moves the relative error by delta times it.
  double m = 0, n = 0;
  for (const auto& x : vec->expected[0]) {
    m = std::max(m, std::abs(x.toDouble()));
    n += x.toDouble() * x.toDouble();
  }
  const double delta = bar_eps * std::ldexp(1.0, -23) / (m / std::sqrt(n));
  json& e = result_for(results, vec->id);
  for (json& x : e["out"]["out_q"]) {
    const float v = static_cast<float>(std::strtod(x.get<std::string>().c_str(), nullptr) * (1 + delta));
    char buf[64];
    std::snprintf(buf, sizeof buf, "%a", double(v));
    x = buf;
  }
  auto g = grade(set, results, dir / "results.json");
  fs::remove_all(dir);
  return g;
}

TEST(VectorsCheck, AnOutputBeyondTheLooseBarFailsItsClauseAndIsTheWorstCase) {
  RC_CLAUSE("TOL-1");
  RC_CLAUSE("COMPOSE-1");
  const spec::ToleranceClass& tc = the_spec().lookup(engine::tolerance_for(the_spec(), "COMPOSE-1", "compose"));
  const double strict = tc.strict_value()->toDouble(), loose = tc.loose_value()->toDouble();
  std::string id, input;
  {
    const auto g = perturbed_compose(4 * loose, &id, &input);
    const engine::ClauseResult* r = vectors::find_clause(g, "COMPOSE-1");
    ASSERT_NE(r, nullptr);
    EXPECT_EQ(r->outcome, engine::Outcome::fail);
    EXPECT_EQ(r->failures, 1u);
    EXPECT_EQ(r->worst_label, "random");
    EXPECT_EQ(r->worst_input, input) << id;
    EXPECT_GT(r->worst_error, loose);
  }
  {
    // Between the bars: QUALITY_WARNING, not FAIL (TOL-1 has three verdicts).
    const auto g = perturbed_compose((strict + loose) / 2, &id, &input);
    const engine::ClauseResult* r = vectors::find_clause(g, "COMPOSE-1");
    ASSERT_NE(r, nullptr);
    EXPECT_EQ(r->outcome, engine::Outcome::quality_warning) << r->worst_error;
    EXPECT_EQ(r->worst_input, input);
  }
}

TEST(VectorsCheck, AMissingResultFailsItsClause) {
  RC_CLAUSE("RESULT-1");
  const fs::path dir = scratch("missing");
  const auto set = exported(dir, ref::Format::binary32);
  json results = results_of(builtin("rotor_m2", RC_SCALAR_FLOAT32), set, dir / "results.json");
  ASSERT_TRUE(good(vectors::find_clause(grade(set, results, dir / "results.json"), "COMPOSE-1")->outcome));
  const auto [file, vec] = find_vector(set, "COMPOSE-1", "compose", "random");
  ASSERT_NE(vec, nullptr);
  auto& list = results["results"];
  for (auto it = list.begin(); it != list.end(); ++it)
    if ((*it)["id"] == vec->id) {
      list.erase(it);
      break;
    }
  const auto g = grade(set, results, dir / "results.json");
  const engine::ClauseResult* r = vectors::find_clause(g, "COMPOSE-1");
  ASSERT_NE(r, nullptr);
  EXPECT_EQ(r->outcome, engine::Outcome::fail);
  EXPECT_NE(r->note.find("1 vector without a result"), std::string::npos) << r->note;
  EXPECT_NE(r->worst_detail.find(vec->id), std::string::npos) << r->worst_detail;
  // Without any result for an op, its clauses are NOT_SUPPORTED, not FAIL (RESULT-1).
  json kept = json::array();
  for (const json& e : list)
    if (e["id"].get<std::string>().find("/compose/") == std::string::npos) kept.push_back(e);
  list = kept;
  const auto g2 = grade(set, results, dir / "results.json");
  EXPECT_EQ(vectors::find_clause(g2, "COMPOSE-1")->outcome, engine::Outcome::not_supported);
  fs::remove_all(dir);
}

TEST(VectorsCheck, StatusMismatchesInEitherDirectionFail) {
  RC_CLAUSE("RESULT-2");
  const fs::path dir = scratch("status");
  const auto set = exported(dir, ref::Format::binary32);
  const json base = results_of(builtin("rotor_m2", RC_SCALAR_FLOAT32), set, dir / "results.json");
  ASSERT_TRUE(good(vectors::find_clause(grade(set, base, dir / "r.json"), "EDGE-6")->outcome));
  const auto [zf, zero] = find_vector(set, "EDGE-6", "normalize", "zero quaternion in q");
  ASSERT_TRUE(good(vectors::find_clause(grade(set, base, dir / "r.json"), "COMPOSE-1")->outcome));
  const auto [cf, unit] = find_vector(set, "COMPOSE-1", "compose", "random");
  ASSERT_NE(zero, nullptr);
  ASSERT_NE(unit, nullptr);
  EXPECT_EQ(zero->result, "acceptable");  // DOMAIN_ERROR expected, ACC-1 zero_sentinel accepted (EDGE-6)
  EXPECT_EQ(zero->acceptable, std::vector<std::string>{"zero_sentinel"});
  EXPECT_EQ(unit->result, "valid");
  auto outcome = [&](const std::string& id, const json& status, const json& out, const std::string& clause) {
    json r = base;
    result_for(r, id)["status"] = status;
    result_for(r, id)["out"]["out_q"] = out;
    return vectors::find_clause(grade(set, r, dir / "r.json"), clause)->outcome;
  };
  json copy = base;
  const json base_out = result_for(copy, unit->id)["out"]["out_q"];
  const json nans = {"nan", "nan", "nan", "nan"}, numbers = {"0x0p+0", "0x0p+0", "0x0p+0", "0x1p+0"};
  const json half_turn = {"0x1p+0", "0x0p+0", "0x0p+0", "0x0p+0"};
  EXPECT_EQ(outcome(zero->id, "OK", half_turn, "EDGE-6"), engine::Outcome::fail);        // bad input hidden
  EXPECT_EQ(outcome(zero->id, "OK", numbers, "EDGE-6"), engine::Outcome::pass);          // the identity sentinel
  EXPECT_EQ(outcome(zero->id, "DOMAIN_ERROR", numbers, "EDGE-6"), engine::Outcome::fail);  // status without NaN
  EXPECT_EQ(outcome(zero->id, "DOMAIN_ERROR", nans, "EDGE-6"), engine::Outcome::pass);
  EXPECT_EQ(outcome(unit->id, "DOMAIN_ERROR", nans, "COMPOSE-1"), engine::Outcome::fail);  // spurious error
  EXPECT_EQ(outcome(unit->id, 7, base_out, "COMPOSE-1"), engine::Outcome::fail);  // no such status
  EXPECT_EQ(outcome(unit->id, "OK", base_out, "COMPOSE-1"), engine::Outcome::pass);
  fs::remove_all(dir);
}

// ---- the tool: malformed files -------------------------------------------------------------

struct CliFixture : ::testing::Test {
  fs::path dir;
  json results;
  void SetUp() override {
    dir = scratch(::testing::UnitTest::GetInstance()->current_test_info()->name());
    const ToolRun e = rotorcert("vectors export --out '" + (dir / "v").string() + "' --cases 4 --scalar float");
    ASSERT_EQ(e.exit_code, 0) << e.output;
    const ToolRun r = rotorcert("vectors run --impl rotor_m2 --scalar float --vectors '" + (dir / "v").string() + "' --out '" +
                                (dir / "results.json").string() + "'");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    results = json::parse(slurp(dir / "results.json"));
  }
  void TearDown() override { fs::remove_all(dir); }
  ToolRun check(const json& r) {
    write(dir / "edited.json", r.dump(1));
    return rotorcert("vectors check '" + (dir / "edited.json").string() + "'");
  }
};

TEST_F(CliFixture, CheckPassesACorrectTableAndWritesTheReport) {
  const ToolRun r = rotorcert("vectors check '" + (dir / "results.json").string() + "' --out '" + (dir / "report").string() + "'");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("rotor_m2 (float, results file)"), std::string::npos) << r.output;
  const json report = json::parse(slurp(dir / "report" / "report.json"));
  EXPECT_EQ(report.at("kind"), "vectors-check");
  EXPECT_EQ(report.at("implementations").at(0).at("source"), "results file");
  EXPECT_TRUE(fs::exists(dir / "report" / "report.html"));
}

TEST_F(CliFixture, MalformedResultsExitWith2NamingTheJsonPath) {
  auto expect_usage = [&](json r, const std::string& path) {
    const ToolRun t = check(r);
    EXPECT_EQ(t.exit_code, 2) << t.output;
    EXPECT_NE(t.output.find(path), std::string::npos) << "expected " << path << " in\n" << t.output;
  };
  {
    json r = results;
    r["results"][3]["out"].begin().value()[1] = "0x1.zzp+0";
    expect_usage(r, "/results/3/out/");
  }
  {
    json r = results;
    r["results"][2]["out"].begin().value()[0] = "0x1.0000000000001p+0";  // not a binary32 value
    expect_usage(r, "/results/2/out/");
  }
  {
    json r = results;
    r["results"][5]["id"] = "NORM-1/normalize/binary32/9999";
    expect_usage(r, "/results/5/id");
  }
  {
    json r = results;
    r["results"][4].erase("status");
    expect_usage(r, "/results/4");
  }
  {
    json r = results;
    r["results"][1]["out"] = json::object();
    expect_usage(r, "/results/1/out");
  }
  {
    json r = results;
    r["results"].push_back(r["results"][0]);
    expect_usage(r, "/results/" + std::to_string(r["results"].size() - 1) + "/id");
  }
  {
    json r = results;
    r["implementation"].erase("scalar");
    expect_usage(r, "/implementation");
  }
}

TEST_F(CliFixture, AResultsFileThatIsNotUsableJsonExitsWith2NamingTheFile) {
  // A number beyond binary64 makes nlohmann::json throw out_of_range, not parse_error: found by
  // fuzz_results_file, it used to escape as "internal error".
  for (const std::string text : {"7e824", "{\"results\": [1e999]}", "{\"a\":", ""}) {
    write(dir / "bad.json", text);
    const ToolRun t = rotorcert("vectors check '" + (dir / "bad.json").string() + "'");
    EXPECT_EQ(t.exit_code, 2) << text << "\n" << t.output;
    EXPECT_NE(t.output.find("bad.json"), std::string::npos) << text << "\n" << t.output;
    EXPECT_EQ(t.output.find("internal error"), std::string::npos) << text << "\n" << t.output;
  }
}

TEST_F(CliFixture, AlteredVectorsOrAnotherSpecVersionExitWith2) {
  const fs::path file = dir / "v" / "SLERP-1_slerp_binary32.json";
  const std::string original = slurp(file);
  json v = json::parse(original);
  // One ulp off in one expected component: the reference disagrees.
  std::string& hex = v["tests"][2]["expected"]["out"]["out_q"]["hex"].at(3).get_ref<std::string&>();
  const float x = std::strtof(hex.c_str(), nullptr);
  char buf[64];
  std::snprintf(buf, sizeof buf, "%a", double(std::nextafter(x, 2.0f)));
  hex = buf;
  write(file, v.dump(1));
  ToolRun t = check(results);
  EXPECT_EQ(t.exit_code, 2) << t.output;
  EXPECT_NE(t.output.find("/tests/2/expected/out/out_q/hex/3"), std::string::npos) << t.output;
  EXPECT_NE(t.output.find("altered"), std::string::npos) << t.output;
  v = json::parse(original);
  v["spec_version"] = "0.9.0";
  write(file, v.dump(1));
  t = check(results);
  EXPECT_EQ(t.exit_code, 2) << t.output;
  EXPECT_NE(t.output.find("/spec_version"), std::string::npos) << t.output;
  write(file, original);
  EXPECT_EQ(check(results).exit_code, 0);
}

// ---- an adapter in another language ------------------------------------------------------

TEST(VectorsPython, ExampleAdapterPassesAndItsBugFailsCompose) {
  RC_CLAUSE("COMPOSE-1");
  if (shell("python3 -c 'import json, math'").exit_code != 0) GTEST_SKIP() << "python3 is not installed";
  const fs::path dir = scratch("python");
  ASSERT_EQ(rotorcert("vectors export --out '" + (dir / "v").string() + "' --scalar double --cases 8").exit_code, 0);
  const std::string adapter = std::string("python3 '") + ROTORCERT_SOURCE_DIR + "/conformance/tests/vectors_example_adapter.py'";
  for (const bool bug : {false, true}) {
    const fs::path results = dir / (bug ? "bug.json" : "ok.json"), report = dir / (bug ? "bug" : "ok");
    const ToolRun a = shell(adapter + " --vectors '" + (dir / "v").string() + "' --out '" + results.string() + "'" + (bug ? " --bug" : ""));
    ASSERT_EQ(a.exit_code, 0) << a.output;
    const ToolRun c = rotorcert("vectors check '" + results.string() + "' --out '" + report.string() + "'");
    EXPECT_EQ(c.exit_code, bug ? 1 : 0) << c.output;
    const json cert = json::parse(slurp(report / "report.json")).at("implementations").at(0);
    std::set<std::string> claimed;
    for (const json& r : cert.at("clauses")) {
      if (!r.at("claimed").get<bool>()) continue;
      claimed.insert(r.at("id").get<std::string>());
      if (r.at("id") == "COMPOSE-1" && bug) {
        EXPECT_EQ(r.at("outcome"), "FAIL");
        // Swapped operands are a consistent convention, and the certificate says so.
        const auto conv = r.at("conventions").get<std::vector<std::string>>();
        EXPECT_NE(std::find(conv.begin(), conv.end(), "reverse_map"), conv.end()) << r.dump();
      } else if (!bug || r.at("id") == "NORM-1") {
        EXPECT_EQ(r.at("outcome"), "PASS") << r.dump();
      }
    }
    for (const char* id : {"NORM-1", "COMPOSE-1", "INV-1", "APPLY-1", "QUAT-2", "EDGE-7"}) EXPECT_TRUE(claimed.count(id)) << id;
  }
  fs::remove_all(dir);
}

}  // namespace
