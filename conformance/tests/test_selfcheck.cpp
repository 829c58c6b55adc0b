// `rotorcert selfcheck`: the reference against the worked examples of the spec (NUM-2), the
// comparison rules, the spec loader's typed errors, and the tool's exit codes.
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <rotorcert/conformance/selfcheck.hpp>
#include <rotorcert/spec/spec.hpp>
#include <rotorcert/testing/clause.hpp>

namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using rotorcert::conformance::check_example;
using rotorcert::conformance::ClauseOutcome;
using rotorcert::conformance::ExampleResult;
using rotorcert::conformance::print_report;
using rotorcert::conformance::run_selfcheck;
using rotorcert::spec::Example;
using rotorcert::spec::load_spec;
using rotorcert::spec::Spec;
using rotorcert::spec::SpecError;

/// The source tree's spec/, or $ROTORCERT_SPEC_DIR (to run the checks on a modified copy).
const fs::path kSpecDir = rotorcert::spec::resolve_spec_dir();

const Spec& real_spec() {
  static const Spec spec = load_spec(kSpecDir);
  return spec;
}

/// One example from its JSON text (the "examples" wrapper is added here).
Example example(const std::string& text) {
  return rotorcert::spec::parse_examples(json{{"examples", json::array({json::parse(text)})}}, "test")[0];
}

std::string describe(const ExampleResult& r) {
  std::ostringstream s;
  for (const auto& m : r.mismatches) s << "  " << m.field << " " << m.expected << " " << m.got << " " << m.message << '\n';
  return s.str();
}

/// A scratch directory, removed at the end of the test.
struct ScratchDir {
  fs::path path;
  explicit ScratchDir(const std::string& name)
      : path(fs::temp_directory_path() / ("rotorcert_" + name + "_" + std::to_string(::getpid()))) {
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~ScratchDir() {
    std::error_code ignored;
    fs::remove_all(path, ignored);
  }
  void write(const std::string& file, const std::string& text) const { std::ofstream(path / file) << text; }
  /// clauses.json of the real spec, plus `examples` as examples.json.
  void spec_with_examples(const std::string& examples) const {
    fs::copy_file(kSpecDir / "clauses.json", path / "clauses.json");
    write("examples.json", examples);
  }
};

int run_tool(const std::string& args, const fs::path& output) {
  const std::string command = std::string("'") + ROTORCERT_BINARY + "' " + args + " > '" + output.string() + "' 2>&1";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string read(const fs::path& file) {
  std::ifstream in(file);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// ---- the real spec --------------------------------------------------------------------------

TEST(Selfcheck, EveryWorkedExampleAgreesWithTheReference) {
  RC_CLAUSE("NUM-2");
  const auto report = run_selfcheck(real_spec());
  std::ostringstream text;
  print_report(text, report);
  EXPECT_TRUE(report.ok()) << "the reference disagrees with spec/examples.json:\n" << text.str();
  EXPECT_EQ(report.examples_passed, report.examples_total);
  EXPECT_GT(report.examples_total, 0) << "spec/examples.json has no examples";
  EXPECT_EQ(report.clauses.size(), real_spec().clauses.size()) << "every clause gets a line";
  // The summary line has the documented form.
  EXPECT_NE(text.str().find("selfcheck: " + std::to_string(report.passed) + " passed, " +
                            std::to_string(report.failed) + " failed"),
            std::string::npos);
}

TEST(Selfcheck, ExampleFieldsFollowTheLayouts) {
  RC_CLAUSE("LAYOUT-1");
  // Quaternion [x, y, z, w]: the layout op places (w, x, y, z) in that order.
  const auto quaternion = example(R"({"id":"L-1","clause":"LAYOUT-1","op":"layout",
      "in":{"w":"4","x":"1","y":"2","z":"3"},"out":{"q":["1","2","3","4"]},"status":"OK"})");
  EXPECT_TRUE(check_example(quaternion, real_spec()).passed) << describe(check_example(quaternion, real_spec()));
  // 3x3 column-major m[c*3 + r]: a quarter turn about z maps e1 -> e2, so column 0 is (0, 1, 0).
  const auto matrix = example(R"({"id":"L-2","clause":"LAYOUT-1","op":"to_matrix",
      "in":{"q":["0","0","sqrt(2)/2","sqrt(2)/2"]},"out":{"m":["0","1","0", "-1","0","0", "0","0","1"]},"status":"OK"})");
  EXPECT_TRUE(check_example(matrix, real_spec()).passed) << describe(check_example(matrix, real_spec()));
  // Dual quaternion [real xyzw, dual xyzw]: identity rotation, t = (2, 0, 0): q_d = t q_r / 2 = i.
  const auto dual = example(R"({"id":"L-3","clause":"LAYOUT-1","op":"dq_from_rt",
      "in":{"q":["0","0","0","1"],"t":["2","0","0"]},"out":{"d":["0","0","0","1", "1","0","0","0"]},"status":"OK"})");
  EXPECT_TRUE(check_example(dual, real_spec()).passed) << describe(check_example(dual, real_spec()));
  // Vector [x, y, z]: a quarter turn about z maps (1, 0, 0) to (0, 1, 0).
  const auto vector = example(R"({"id":"L-4","clause":"LAYOUT-1","op":"apply_vector",
      "in":{"q":["0","0","sqrt(2)/2","sqrt(2)/2"],"v":["1","0","0"]},"out":{"v":["0","1","0"]},"status":"OK"})");
  EXPECT_TRUE(check_example(vector, real_spec()).passed) << describe(check_example(vector, real_spec()));
  // Bivector [e23, e31, e12]: the quarter turn about z maps e2 -> -e1, so e23 -> -e13 = e31:
  // (1, 0, 0) -> (0, 1, 0).
  const auto bivector = example(R"({"id":"L-5","clause":"LAYOUT-1","op":"apply_bivector",
      "in":{"q":["0","0","sqrt(2)/2","sqrt(2)/2"],"b":["1","0","0"]},"out":{"b":["0","1","0"]},"status":"OK"})");
  EXPECT_TRUE(check_example(bivector, real_spec()).passed) << describe(check_example(bivector, real_spec()));
  // The same fields in another order must fail (the layout is not guessed).
  const auto swapped = example(R"({"id":"L-6","clause":"LAYOUT-1","op":"layout",
      "in":{"w":"4","x":"1","y":"2","z":"3"},"out":{"q":["4","1","2","3"]},"status":"OK"})");
  EXPECT_FALSE(check_example(swapped, real_spec()).passed);
}

/// The op names of the op table in SPEC.md, Appendix A ("| slerp / rotor_interp / nlerp | ...").
std::set<std::string> spec_md_ops() {
  std::istringstream lines(read(kSpecDir / "SPEC.md"));
  std::set<std::string> ops;
  bool in_table = false;
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("## ", 0) == 0) in_table = line.find("Op table") != std::string::npos;
    if (!in_table || line.rfind("| ", 0) != 0 || line.rfind("| op |", 0) == 0) continue;
    std::istringstream names(line.substr(2, line.find('|', 2) - 2));
    for (std::string name; names >> name;)
      if (name != "/") ops.insert(name);
  }
  return ops;
}

TEST(Selfcheck, EveryOpOfTheSpecOpTableHasAHandler) {
  const std::set<std::string> documented = spec_md_ops();
  ASSERT_FALSE(documented.empty()) << "no op table (Appendix A) found in " << kSpecDir / "SPEC.md";
  const auto handled = rotorcert::conformance::supported_ops();
  const std::set<std::string> supported(handled.begin(), handled.end());
  for (const auto& op : documented) EXPECT_TRUE(supported.count(op)) << "op \"" << op << "\" has no selfcheck handler";
  for (const auto& op : supported) EXPECT_TRUE(documented.count(op)) << "op \"" << op << "\" is not in the op table of SPEC.md";
  for (const auto& e : real_spec().examples)
    EXPECT_TRUE(documented.count(e.op)) << e.id << ": op \"" << e.op << "\" is not in the op table of SPEC.md";
}

// ---- comparison rules -----------------------------------------------------------------------

TEST(Selfcheck, CorrectExamplePasses) {
  const auto r = check_example(example(R"({"id":"T-1","clause":"NORM-1","op":"normalize",
      "in":{"q":["0","0","3","4"]},"out":{"q":["0","0","3/5","4/5"]},"status":"OK"})"), real_spec());
  EXPECT_TRUE(r.passed) << describe(r);
}

TEST(Selfcheck, WrongValueFailsNamingTheField) {
  const auto r = check_example(example(R"({"id":"T-2","clause":"NORM-1","op":"normalize",
      "in":{"q":["0","0","3","4"]},"out":{"q":["0","0","0.6","0.8000000001"]},"status":"OK"})"), real_spec());
  ASSERT_FALSE(r.passed);
  ASSERT_EQ(r.mismatches.size(), 1u) << describe(r);  // 0.6 itself is within the bar
  EXPECT_EQ(r.mismatches[0].field, "q[3]");
  EXPECT_EQ(r.mismatches[0].got, "0.8");  // 25 significant digits, trailing zeros dropped
  EXPECT_EQ(r.mismatches[0].expected, "0.8000000001");
}

TEST(Selfcheck, TheBarIsRelativeAndTiny) {
  // |got - expected| <= 1e-60 max(1, |expected|): a difference of 1e-50 on a value of 1 fails,
  // the same relative difference on 1e20 is absolute 1e-30 and fails too; 1e-70 passes.
  auto normalize_to = [](const std::string& z) {
    return example(R"({"id":"T-3","clause":"NORM-1","op":"normalize","in":{"q":["0","0","0","5"]},
        "out":{"q":["0","0","0",")" + z + R"("]},"status":"OK"})");
  };
  EXPECT_FALSE(check_example(normalize_to("1 + 1e-50"), real_spec()).passed);
  EXPECT_TRUE(check_example(normalize_to("1 + 1e-70"), real_spec()).passed);
  const auto big = example(R"({"id":"T-4","clause":"APPLY-1","op":"apply_vector",
      "in":{"q":["0","0","0","1"],"v":["1e20","0","0"]},"out":{"v":["1e20 + 1e-45","0","0"]},"status":"OK"})");
  EXPECT_TRUE(check_example(big, real_spec()).passed) << "relative: 1e-65 of 1e20";
}

TEST(Selfcheck, StatusMustMatch) {
  const auto r = check_example(example(R"({"id":"T-5","clause":"EDGE-6","op":"normalize",
      "in":{"q":["0","0","0","0"]},"out":{"q":["0","0","0","1"]},"status":"OK"})"), real_spec());
  ASSERT_FALSE(r.passed);
  EXPECT_EQ(r.mismatches[0].field, "status");
  EXPECT_EQ(r.mismatches[0].expected, "OK");
  EXPECT_EQ(r.mismatches[0].got, "DOMAIN_ERROR");
}

TEST(Selfcheck, NanMatchesNanOnly) {
  const auto domain = check_example(example(R"({"id":"T-6","clause":"EDGE-6","op":"normalize",
      "in":{"q":["0","0","0","0"]},"out":{"q":["nan","nan","nan","nan"]},"status":"DOMAIN_ERROR"})"), real_spec());
  EXPECT_TRUE(domain.passed) << describe(domain);
  const auto not_nan = check_example(example(R"({"id":"T-7","clause":"EDGE-6","op":"normalize",
      "in":{"q":["0","0","0","0"]},"out":{"q":["nan","nan","nan","0"]},"status":"DOMAIN_ERROR"})"), real_spec());
  EXPECT_FALSE(not_nan.passed);
  const auto nan_expected = check_example(example(R"({"id":"T-8","clause":"NORM-1","op":"normalize",
      "in":{"q":["0","0","0","2"]},"out":{"q":["nan","0","0","1"]},"status":"OK"})"), real_spec());
  EXPECT_FALSE(nan_expected.passed);
}

TEST(Selfcheck, RotationComparisonAcceptsTheNegative) {
  const std::string body = R"("clause":"NORM-1","op":"normalize","in":{"q":["0","0","3","4"]},
      "out":{"q":["-0","-0","-3/5","-4/5"]},"status":"OK")";
  EXPECT_FALSE(check_example(example(R"({"id":"T-9",)" + body + "}"), real_spec()).passed);
  EXPECT_TRUE(check_example(example(R"({"id":"T-10","compare":"rotation",)" + body + "}"), real_spec()).passed);
  // Up to ONE sign for the whole quaternion, not per component.
  const auto mixed = example(R"({"id":"T-11","compare":"rotation","clause":"NORM-1","op":"normalize",
      "in":{"q":["0","0","3","4"]},"out":{"q":["0","0","-3/5","4/5"]},"status":"OK"})");
  EXPECT_FALSE(check_example(mixed, real_spec()).passed);
}

TEST(Selfcheck, MultivectorOutputsCompareEveryBlade) {
  // e1 e2 = e12; written as e21 with the opposite sign; a missing blade is 0.
  const auto ok = example(R"({"id":"T-12","clause":"ALG-2","op":"gp","in":{"algebra":"cl3","a":{"e1":"1"},"b":{"e2":"1"}},
      "out":{"r":{"e21":"-1"}},"status":"OK"})");
  EXPECT_TRUE(check_example(ok, real_spec()).passed) << describe(check_example(ok, real_spec()));
  const auto extra = example(R"({"id":"T-13","clause":"ALG-2","op":"gp","in":{"algebra":"cl3","a":{"e1":"1"},"b":{"e2":"1"}},
      "out":{"r":{"e12":"1","e3":"0.5"}},"status":"OK"})");
  const auto r = check_example(extra, real_spec());
  ASSERT_FALSE(r.passed);
  EXPECT_EQ(r.mismatches[0].field, "r[e3]");
}

TEST(Selfcheck, UnknownOpFailsTheExampleWithAMessage) {
  const auto r = check_example(example(R"({"id":"T-14","clause":"NORM-1","op":"normalise",
      "in":{"q":["0","0","0","1"]},"out":{"q":["0","0","0","1"]},"status":"OK"})"), real_spec());
  ASSERT_FALSE(r.passed);
  ASSERT_EQ(r.mismatches.size(), 1u);
  EXPECT_NE(r.mismatches[0].message.find("unknown op \"normalise\""), std::string::npos) << r.mismatches[0].message;
}

TEST(Selfcheck, BadInputsFailTheExampleNamingThePath) {
  const auto bad_expr = check_example(example(R"({"id":"T-15","clause":"NORM-1","op":"normalize",
      "in":{"q":["0","0","0","1 +"]},"out":{"q":["0","0","0","1"]},"status":"OK"})"), real_spec());
  ASSERT_FALSE(bad_expr.passed);
  EXPECT_NE(bad_expr.mismatches[0].message.find("/in/q/3"), std::string::npos) << bad_expr.mismatches[0].message;
  const auto bad_shape = check_example(example(R"({"id":"T-16","clause":"NORM-1","op":"normalize",
      "in":{"q":["0","0","1"]},"out":{"q":["0","0","0","1"]},"status":"OK"})"), real_spec());
  ASSERT_FALSE(bad_shape.passed);
  EXPECT_NE(bad_shape.mismatches[0].message.find("/in/q"), std::string::npos) << bad_shape.mismatches[0].message;
  const auto missing = check_example(example(R"({"id":"T-17","clause":"COMPOSE-1","op":"compose",
      "in":{"a":["0","0","0","1"]},"out":{"q":["0","0","0","1"]},"status":"OK"})"), real_spec());
  ASSERT_FALSE(missing.passed);
  EXPECT_NE(missing.mismatches[0].message.find("missing input \"b\""), std::string::npos) << missing.mismatches[0].message;
  const auto wrong_out = check_example(example(R"({"id":"T-18","clause":"NORM-1","op":"normalize",
      "in":{"q":["0","0","0","1"]},"out":{"v":["0","0","0"]},"status":"OK"})"), real_spec());
  ASSERT_FALSE(wrong_out.passed);
  EXPECT_NE(wrong_out.mismatches[0].message.find("\"v\" is not an output"), std::string::npos);
}

TEST(Selfcheck, TheBarComesFromClausesJson) {
  // Loosen the "ref" class to 1e-3: an example off by 1e-4 now passes.
  Spec loose = real_spec();
  loose.tolerance_classes.at("ref").strict = "1e-3";
  const auto off = example(R"({"id":"T-19","clause":"NORM-1","op":"normalize","in":{"q":["0","0","0","5"]},
      "out":{"q":["0","0","0","1.0001"]},"status":"OK"})");
  EXPECT_FALSE(check_example(off, real_spec()).passed);
  EXPECT_TRUE(check_example(off, loose).passed);
}

TEST(Selfcheck, AWrongExampleFailsItsClauseInTheReport) {
  Spec spec = real_spec();
  spec.examples.push_back(example(R"({"id":"T-20","clause":"NORM-1","op":"normalize",
      "in":{"q":["0","0","3","4"]},"out":{"q":["0","0","0.6","0.7"]},"status":"OK"})"));
  const auto report = run_selfcheck(spec);
  EXPECT_FALSE(report.ok());
  bool found = false;
  for (const auto& c : report.clauses) {
    if (c.id != "NORM-1") continue;
    found = true;
    EXPECT_EQ(c.outcome, ClauseOutcome::fail);
    ASSERT_FALSE(c.failures.empty());
    EXPECT_EQ(c.failures.back().id, "T-20");
  }
  EXPECT_TRUE(found);
  std::ostringstream text;
  print_report(text, report);
  EXPECT_NE(text.str().find("FAIL  NORM-1"), std::string::npos) << text.str();
  EXPECT_NE(text.str().find("T-20  q[3]: expected 0.7"), std::string::npos) << text.str();
}

// ---- malformed spec files: a typed error, never a crash ---------------------------------

void expect_spec_error(const std::string& examples, const std::string& path_fragment, const std::string& what_fragment) {
  const ScratchDir dir("malformed");
  dir.spec_with_examples(examples);
  try {
    (void)load_spec(dir.path);
    ADD_FAILURE() << "no SpecError for " << examples;
  } catch (const SpecError& e) {
    EXPECT_EQ(e.file(), dir.path / "examples.json");
    EXPECT_NE(e.json_path().find(path_fragment), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(what_fragment), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("examples.json"), std::string::npos) << e.what();
  }
}

TEST(Selfcheck, MalformedExamplesFileGivesTypedError) {
  expect_spec_error(R"({"examples": [ {"id": "X"  )", "", "not valid JSON");
  expect_spec_error(R"({"examples": {}})", "/examples", "expected an array");
  expect_spec_error(R"({"examples": [{"id":"X","clause":"NORM-1","in":{},"out":{},"status":"OK"}]})", "/examples/0",
                    "missing field \"op\"");
  expect_spec_error(R"({"examples": [{"id":"X","clause":"NORM-1","op":"normalize","in":[],"out":{},"status":"OK"}]})",
                    "/examples/0/in", "expected an object");
  expect_spec_error(R"({"examples": [{"id":"X","clause":"NORM-1","op":"normalize","in":{},"out":{},"status":"MAYBE"}]})",
                    "/examples/0/status", "DOMAIN_ERROR");
  expect_spec_error(R"({"examples": [{"id":"X","clause":"NORM-1","op":"n","in":{},"out":{},"status":"OK"},
                                     {"id":"X","clause":"NORM-1","op":"n","in":{},"out":{},"status":"OK"}]})",
                    "/examples/1/id", "duplicate");
}

TEST(Selfcheck, MalformedClausesFileGivesTypedError) {
  const ScratchDir dir("malformed_clauses");
  json clauses = rotorcert::spec::read_json(kSpecDir / "clauses.json");
  clauses["clauses"][2]["level"] = "Nonsense";
  dir.write("clauses.json", clauses.dump());
  try {
    (void)load_spec(dir.path);
    ADD_FAILURE() << "no SpecError";
  } catch (const SpecError& e) {
    EXPECT_EQ(e.json_path(), "/clauses/2/level") << e.what();
  }
  EXPECT_THROW((void)load_spec(dir.path / "does-not-exist"), SpecError);
}

TEST(Selfcheck, ToleranceLookupReadsTheSpec) {
  const auto ref = real_spec().lookup("ref");
  EXPECT_EQ(ref.kind, "absolute");
  ASSERT_TRUE(ref.strict_value().has_value());
  EXPECT_EQ(rotorcert::spec::lookup("eps4").strict_value().value(), rotorcert::ref::Real(4));
  EXPECT_FALSE(rotorcert::spec::lookup("inherited-mat").strict_value().has_value());
  EXPECT_THROW((void)rotorcert::spec::lookup("no-such-class"), SpecError);
}

// ---- the tool ---------------------------------------------------------------------------------

TEST(SelfcheckTool, ExitCodes) {
  const ScratchDir dir("tool");
  const fs::path out = dir.path / "out.txt";

  // A spec whose only example is right: exit 0, JSON written atomically (no temp file left).
  const ScratchDir good("tool_good");
  good.spec_with_examples(R"({"examples":[{"id":"G-1","clause":"NORM-1","op":"normalize",
      "in":{"q":["0","0","3","4"]},"out":{"q":["0","0","3/5","4/5"]},"status":"OK"}]})");
  EXPECT_EQ(run_tool("selfcheck --spec '" + good.path.string() + "' --json '" + (dir.path / "r.json").string() + "'", out), 0)
      << read(out);
  EXPECT_NE(read(out).find("PASS  NORM-1"), std::string::npos) << read(out);
  EXPECT_NE(read(out).find("DEF   LEVEL-1"), std::string::npos) << read(out);
  EXPECT_NE(read(out).find("selfcheck: 1 passed, 0 failed"), std::string::npos) << read(out);
  const json result = json::parse(read(dir.path / "r.json"));
  EXPECT_EQ(result["summary"]["passed"], 1);
  EXPECT_EQ(result["summary"]["ok"], true);
  for (const auto& entry : fs::directory_iterator(dir.path))
    EXPECT_EQ(entry.path().filename().string().find(".tmp."), std::string::npos) << entry.path();

  // A wrong example: exit 1, the example and field named.
  const ScratchDir bad("tool_bad");
  bad.spec_with_examples(R"({"examples":[{"id":"B-1","clause":"NORM-1","op":"normalize",
      "in":{"q":["0","0","3","4"]},"out":{"q":["0","0","3/5","3/5"]},"status":"OK"}]})");
  EXPECT_EQ(run_tool("selfcheck --spec '" + bad.path.string() + "'", out), 1) << read(out);
  EXPECT_NE(read(out).find("B-1  q[3]: expected 0.6"), std::string::npos) << read(out);

  // The environment variable selects the spec when --spec is absent.
  const char* saved = std::getenv("ROTORCERT_SPEC_DIR");
  const std::string original = saved ? saved : "";
  EXPECT_EQ(::setenv("ROTORCERT_SPEC_DIR", bad.path.c_str(), 1), 0);
  EXPECT_EQ(run_tool("selfcheck", out), 1) << read(out);
  EXPECT_EQ(::setenv("ROTORCERT_SPEC_DIR", good.path.c_str(), 1), 0);
  EXPECT_EQ(run_tool("selfcheck", out), 0) << read(out);
  EXPECT_EQ(run_tool("selfcheck --spec '" + bad.path.string() + "'", out), 1) << "--spec wins over the environment";
  if (saved) ::setenv("ROTORCERT_SPEC_DIR", original.c_str(), 1);
  else ::unsetenv("ROTORCERT_SPEC_DIR");

  // Malformed spec file, unknown option, missing subcommand: exit 2.
  const ScratchDir broken("tool_broken");
  broken.spec_with_examples("{ not json");
  EXPECT_EQ(run_tool("selfcheck --spec '" + broken.path.string() + "'", out), 2) << read(out);
  EXPECT_NE(read(out).find("examples.json"), std::string::npos) << read(out);
  EXPECT_EQ(run_tool("selfcheck --no-such-option", out), 2) << read(out);
  EXPECT_EQ(run_tool("", out), 2) << read(out);
  EXPECT_EQ(run_tool("--version", out), 0) << read(out);
  EXPECT_NE(read(out).find("rotorcert "), std::string::npos);
  EXPECT_EQ(run_tool("--help", out), 0) << read(out);
  EXPECT_NE(read(out).find("selfcheck"), std::string::npos);
}

}  // namespace
