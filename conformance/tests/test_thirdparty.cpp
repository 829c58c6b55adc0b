// Third-party certification (REPORT-3, rotorcert/thirdparty/): manifests are checked, a vectors
// adapter runs in the environment its status.json names and is graded, its known defects decide
// whether it is as expected, and every way an adapter cannot run ends in a stated reason, never a
// crash. The adapter here is the stdlib-only Python example (tests/vectors_example_adapter.py), so
// these tests need no registry; the real libraries are tested by conformance_adapter_<name>.
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <rotorcert/report/render.hpp>
#include <rotorcert/testing/clause.hpp>
#include <rotorcert/thirdparty/thirdparty.hpp>

namespace {
namespace fs = std::filesystem;
using namespace rotorcert;
using nlohmann::json;

const spec::Spec& the_spec() {
  static const spec::Spec s = spec::load_spec(spec::resolve_spec_dir());
  return s;
}

fs::path scratch(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("rotorcert_thirdparty_" + std::to_string(::getpid()) + "_" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

void write(const fs::path& file, const json& j) {
  fs::create_directories(file.parent_path());
  std::ofstream(file) << j.dump(2) << '\n';
}

const std::string kExample = std::string(ROTORCERT_SOURCE_DIR) + "/conformance/tests/vectors_example_adapter.py";

/// An adapters directory with the example adapter under the name it writes into its results
/// ("python_example", "python_example_bug" with --bug), an environment that runs `command`, and
/// options limited to two Core clauses.
struct Fixture {
  fs::path root;
  thirdparty::Options o;
  std::string adapter = "python_example";

  explicit Fixture(const std::string& name, const std::vector<std::string>& command,
                   const json& expected_failures = json::array()) {
    root = scratch(name);
    if (std::find(command.begin(), command.end(), "--bug") != command.end()) adapter += "_bug";
    write(root / "adapters" / adapter / "adapter.json",
          {{"format", "rotorcert-adapter"}, {"format_version", 1}, {"name", adapter}, {"library", "example"},
           {"package", {{"registry", "pypi"}, {"name", "none"}, {"version", "1"}}}, {"route", "vectors"},
           {"language", "python"}, {"entry", "vectors_example_adapter.py"}, {"scalars", {"double"}},
           {"description", "the example adapter"}, {"conventions", {"quaternion [x, y, z, w] as is"}}});
    write(root / "adapters" / adapter / "expected_failures.json", {{"failures", expected_failures}});
    if (!command.empty())
      write(root / "env" / adapter / "status.json", {{"installed", true}, {"reason", nullptr}, {"command", command}, {"env", json::object()}});
    o.adapters_dir = root / "adapters";
    o.env_dir = root / "env";
    o.plugin_dir = root / "plugins";
    o.out = root / "out";
    o.certify.cases.cases_per_family = 4;
    o.certify.clauses = {"NORM-1", "COMPOSE-1"};
    o.quiet = true;
  }
  json library() { return thirdparty::section_json(thirdparty::certify_third_party(the_spec(), o), o).at("libraries").at(0); }
};

const json* clause(const json& cert, const std::string& id) {
  for (const json& c : cert.at("clauses"))
    if (c.at("id") == id) return &c;
  return nullptr;
}

TEST(ThirdParty, VectorsAdapterIsCertifiedByTheGradingOfVectorsCheck) {
  RC_CLAUSE("REPORT-3");
  Fixture f("good", {"python3", kExample});
  const json lib = f.library();
  ASSERT_EQ(lib.at("status"), "certified") << lib.at("reason");
  EXPECT_TRUE(lib.at("as_expected").get<bool>());
  EXPECT_TRUE(lib.at("defects").empty());
  ASSERT_EQ(lib.at("certificates").size(), 1u);
  const json& cert = lib.at("certificates").at(0);
  EXPECT_EQ(cert.at("source"), "results file");
  for (const char* id : {"NORM-1", "COMPOSE-1"}) {
    const json* c = clause(cert, id);
    ASSERT_NE(c, nullptr) << id;
    EXPECT_EQ(c->at("outcome"), "PASS") << id;
    EXPECT_EQ(c->at("reproduce"), "rotorcert thirdparty --adapter python_example --clause " + std::string(id) +
                                      " --cases 4 --search 0 --out third-party-python_example");
  }
  EXPECT_TRUE(fs::exists(f.o.out / "python_example/results.json"));
}

TEST(ThirdParty, UnlistedDefectIsNotAsExpectedAndStatesItsInput) {
  RC_CLAUSE("REPORT-3");
  Fixture f("bug", {"python3", kExample, "--bug"});  // composes b a
  const json lib = f.library();
  ASSERT_EQ(lib.at("status"), "certified") << lib.at("reason");
  EXPECT_FALSE(lib.at("as_expected").get<bool>());
  ASSERT_EQ(lib.at("defects").size(), 1u);
  const json& d = lib.at("defects").at(0);
  EXPECT_EQ(d.at("clause"), "COMPOSE-1");
  EXPECT_EQ(d.at("outcome"), "FAIL");
  EXPECT_FALSE(d.at("known").get<bool>());
  EXPECT_NE(d.at("worst").at("input").get<std::string>().find("0x"), std::string::npos) << d.dump();
  EXPECT_TRUE(d.at("worst").at("error_eps").is_number()) << d.dump();
}

TEST(ThirdParty, ListedDefectIsAsExpected) {
  RC_CLAUSE("REPORT-3");
  Fixture f("listed", {"python3", kExample, "--bug"},
            json::array({{{"table", "python_example_bug"}, {"scalar", "double"}, {"clause", "COMPOSE-1"}, {"why", "b a"}}}));
  const json lib = f.library();
  ASSERT_EQ(lib.at("status"), "certified") << lib.at("reason");
  EXPECT_TRUE(lib.at("as_expected").get<bool>());
  ASSERT_EQ(lib.at("defects").size(), 1u);
  EXPECT_TRUE(lib.at("defects").at(0).at("known").get<bool>());
  EXPECT_EQ(lib.at("defects").at(0).at("why"), "b a");
}

TEST(ThirdParty, ListedDefectCarriesWhatTheLibrarysTrackerSays) {
  RC_CLAUSE("REPORT-3");
  const json upstream = {{"status", "reported"},
                         {"refs", {"https://github.com/example/example/issues/1"}},
                         {"note", "open: compose in the wrong order"},
                         {"searched", "2026-11-27"}};
  Fixture f("upstream", {"python3", kExample, "--bug"},
            json::array({{{"table", "python_example_bug"}, {"scalar", "double"}, {"clause", "COMPOSE-1"}, {"why", "b a"},
                          {"upstream", upstream}}}));
  const json lib = f.library();
  ASSERT_EQ(lib.at("status"), "certified") << lib.at("reason");
  ASSERT_EQ(lib.at("defects").size(), 1u);
  EXPECT_EQ(lib.at("defects").at(0).at("upstream"), upstream);
  // The report shows it beside the defect, in both renderings (as text: the page links nothing).
  const json report = {{"sections", {{"third_party", {{"libraries", json::array({lib})}}}}}};
  for (const std::string& page : {report::render_html(report), report::render_markdown(report)}) {
    EXPECT_NE(page.find("https://github.com/example/example/issues/1"), std::string::npos);
    EXPECT_NE(page.find("reported"), std::string::npos);
  }
}

TEST(ThirdParty, AnUpstreamFieldSaysWhatIsWrongWithIt) {
  RC_CLAUSE("REPORT-3");
  const json good = {{"status", "not found"}, {"refs", json::array()}, {"note", "searched x"}, {"searched", "2026-11-27"}};
  EXPECT_EQ(thirdparty::parse_upstream(good).status, thirdparty::Upstream::Status::not_found);
  const auto with = [&](const char* key, const json& value) {
    json j = good;
    j[key] = value;
    return j;
  };
  for (const json& bad : {with("status", "known"), with("refs", json::array({"http://example.org"})),
                          with("status", "reported"), with("searched", "yesterday"), with("note", ""),
                          with("link", "x")})
    EXPECT_THROW(thirdparty::parse_upstream(bad), std::invalid_argument) << bad.dump();
}

// REPORT-3: every listed defect of a third-party library has been searched for in its tracker, and
// every "upstream" in the checkout is well formed (the entries the report shows).
TEST(ThirdParty, EveryListedDefectOfTheCheckoutSaysWhatItsTrackerKnows) {
  RC_CLAUSE("REPORT-3");
  const fs::path src(ROTORCERT_SOURCE_DIR);
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(src / "conformance/adapters"))
    if (fs::exists(e.path() / "expected_failures.json")) files.push_back(e.path() / "expected_failures.json");
  files.push_back(src / "impls/glm_quat/expected_failures.json");
  files.push_back(src / "impls/eigen_quat/expected_failures.json");
  ASSERT_GE(files.size(), 18u);
  std::size_t entries = 0;
  for (const fs::path& file : files) {
    std::ifstream in(file);
    const json listed = json::parse(in);
    for (const json& f : listed.at("failures")) {
      ++entries;
      const std::string where = file.string() + ": " + f.value("scalar", "") + " " + f.value("clause", "");
      ASSERT_TRUE(f.contains("upstream")) << where << " was not searched for in the library's tracker";
      EXPECT_NO_THROW(thirdparty::parse_upstream(f.at("upstream"))) << where;
    }
  }
  EXPECT_GT(entries, 100u);
}

TEST(ThirdParty, ListedDefectThatPassesIsNews) {
  RC_CLAUSE("REPORT-3");
  Fixture f("fixed", {"python3", kExample},
            json::array({{{"table", "python_example"}, {"scalar", "double"}, {"clause", "COMPOSE-1"}, {"why", "b a"}}}));
  f.o.certify.cases.cases_per_family = thirdparty::kListedAtCases;
  const json lib = f.library();
  ASSERT_EQ(lib.at("status"), "certified") << lib.at("reason");
  EXPECT_FALSE(lib.at("as_expected").get<bool>());
}

TEST(ThirdParty, AnotherVersionIsComparedWithThePin) {
  RC_CLAUSE("REPORT-3");
  // The pin composes b a (a listed defect); "version 2" fixed it. Both run, as two libraries.
  Fixture f("version", {"python3", kExample, "--bug"},
            json::array({{{"table", "python_example_bug"}, {"scalar", "double"}, {"clause", "COMPOSE-1"}, {"why", "b a"}}}));
  f.o.certify.cases.cases_per_family = thirdparty::kListedAtCases;
  write(f.root / "env" / "python_example_bug@2" / "status.json",
        {{"installed", true}, {"reason", nullptr}, {"env", json::object()},
         {"command", {"python3", kExample, "--name", "python_example_bug", "--version", "2"}}});
  f.o.versions = {{"python_example_bug", "2"}};
  const thirdparty::Outcome outcome = thirdparty::certify_third_party(the_spec(), f.o);
  const json section = thirdparty::section_json(outcome, f.o);
  ASSERT_EQ(section.at("libraries").size(), 2u);
  const json& pin = section.at("libraries").at(0);
  const json& v2 = section.at("libraries").at(1);
  EXPECT_EQ(pin.at("name"), "python_example_bug");
  EXPECT_TRUE(pin.at("as_expected").get<bool>());
  ASSERT_EQ(v2.at("name"), "python_example_bug@2") << v2.at("reason");
  EXPECT_EQ(v2.at("status"), "certified") << v2.at("reason");
  EXPECT_EQ(v2.at("requested_version"), "2");
  EXPECT_EQ(v2.at("version"), "2");  // what the library reported, not the pin
  ASSERT_EQ(v2.at("against_pin").at("fixed").size(), 1u) << v2.dump();
  EXPECT_EQ(v2.at("against_pin").at("fixed").at(0).at("clause"), "COMPOSE-1");
  EXPECT_TRUE(v2.at("against_pin").at("appeared").empty());
  EXPECT_NE(v2.at("reproduce").get<std::string>().find("--version python_example_bug=2"), std::string::npos);
  // Differing from the pin is the finding, not a failure of the run.
  EXPECT_TRUE(section.at("as_expected").get<bool>());
  // A version of a library that has no environment of its own (a build's plugin) is refused.
  f.o.versions = {{"no_such_adapter", "2"}};
  EXPECT_THROW(thirdparty::certify_third_party(the_spec(), f.o), std::runtime_error);
}

TEST(ThirdParty, ListedDefectNotReachedWithFewerCasesIsNoSurprise) {
  RC_CLAUSE("REPORT-3");
  Fixture f("fewer_cases", {"python3", kExample},
            json::array({{{"table", "python_example"}, {"scalar", "double"}, {"clause", "COMPOSE-1"}, {"why", "b a"}}}));
  ASSERT_LT(f.o.certify.cases.cases_per_family, thirdparty::kListedAtCases);
  json lib = f.library();
  ASSERT_EQ(lib.at("status"), "certified") << lib.at("reason");
  EXPECT_TRUE(lib.at("as_expected").get<bool>());
  ASSERT_EQ(lib.at("not_reproduced").size(), 1u);
  EXPECT_EQ(lib.at("not_reproduced").at(0).at("clause"), "COMPOSE-1");
  f.o.certify.cases.cases_per_family = thirdparty::kListedAtCases;
  lib = f.library();
  EXPECT_FALSE(lib.at("as_expected").get<bool>());
}

TEST(ThirdParty, EveryWayNotToRunHasAReason) {
  RC_CLAUSE("REPORT-3");
  {
    Fixture f("no_env", {});
    const json lib = f.library();
    EXPECT_EQ(lib.at("status"), "not run");
    EXPECT_NE(lib.at("reason").get<std::string>().find("setup-adapters"), std::string::npos) << lib.at("reason");
  }
  {
    Fixture f("not_installed", {});
    write(f.o.env_dir / "python_example/status.json",
          {{"installed", false}, {"reason", "pip could not install none from PyPI: no network"}, {"command", json::array()}});
    const json lib = f.library();
    EXPECT_EQ(lib.at("status"), "not run");
    EXPECT_EQ(lib.at("reason"), "pip could not install none from PyPI: no network");
  }
  {
    Fixture f("exits", {"python3", "-c", "import sys; print('adapter broke'); sys.exit(3)"});
    const json lib = f.library();
    EXPECT_EQ(lib.at("status"), "error");
    EXPECT_NE(lib.at("reason").get<std::string>().find("exited with 3: adapter broke"), std::string::npos) << lib.at("reason");
  }
  {
    Fixture f("hangs", {"python3", "-c", "import time; time.sleep(30)"});
    f.o.adapter_timeout_s = 0.5;
    const json lib = f.library();
    EXPECT_EQ(lib.at("status"), "error");
    EXPECT_NE(lib.at("reason").get<std::string>().find("ran past"), std::string::npos) << lib.at("reason");
  }
  {
    Fixture f("plugin_not_built", {"python3", kExample});
    write(f.o.adapters_dir / "python_example/adapter.json",
          {{"format", "rotorcert-adapter"}, {"format_version", 1}, {"name", "python_example"}, {"library", "example"},
           {"route", "abi"}, {"language", "c"}, {"entry", {{"plugin", "rotorcert_adapter_missing"}}}, {"scalars", {"double"}}});
    const json lib = f.library();
    EXPECT_EQ(lib.at("status"), "not run");
    EXPECT_NE(lib.at("reason").get<std::string>().find("was not built"), std::string::npos) << lib.at("reason");
  }
}

TEST(ThirdParty, MalformedManifestIsAUsageErrorNamingTheField) {
  RC_CLAUSE("REPORT-3");
  Fixture f("malformed", {"python3", kExample});
  write(f.o.adapters_dir / "python_example/adapter.json",
        {{"format", "rotorcert-adapter"}, {"format_version", 1}, {"name", "python_example"}, {"library", "example"},
         {"route", "carrier pigeon"}, {"language", "python"}, {"scalars", {"double"}}});
  try {
    thirdparty::certify_third_party(the_spec(), f.o);
    FAIL() << "a manifest with an unknown route was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/route"), std::string::npos) << e.what();
  }
  Fixture g("unknown_name", {"python3", kExample});
  g.o.names = {"nonesuch"};
  try {
    thirdparty::certify_third_party(the_spec(), g.o);
    FAIL() << "an unknown adapter name was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("no adapter named 'nonesuch'"), std::string::npos) << e.what();
  }
}

}  // namespace
