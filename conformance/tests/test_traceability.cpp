// Clause traceability: every clause of spec/clauses.json is checked by some test (tagged with the
// clause macro of rotorcert/testing/clause.hpp) or listed, with a reason, in spec/pending.json;
// the pending list can only shrink; every clause is defined in SPEC.md; worked examples and
// clauses refer to each other consistently.
//
// This test is meta: it checks the tags, it names no clause itself. (The macro name is spelled
// in pieces below so that this file does not match its own scan.)
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <rotorcert/spec/spec.hpp>

namespace {

namespace fs = std::filesystem;
using rotorcert::spec::load_spec;
using rotorcert::spec::Spec;

const fs::path kSourceDir = ROTORCERT_SOURCE_DIR;
/// The source tree's spec/, or $ROTORCERT_SPEC_DIR (to run the checks on a modified copy).
const fs::path kSpecDir = rotorcert::spec::resolve_spec_dir();

/// Where tests live (relative to the project root); those that do not exist yet are skipped.
const char* const kTestDirs[] = {"reference/tests", "conformance/tests", "impls", "fuzz", "render_check"};

const Spec& spec() {
  static const Spec s = load_spec(kSpecDir);
  return s;
}

std::string read(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// Clause id -> "file:line" of every tag naming it.
using Tags = std::map<std::string, std::vector<std::string>>;

const Tags& tags() {
  static const Tags found = [] {
    const std::string macro = std::string("RC_") + "CLAUSE";
    const std::regex pattern(macro + R"re(\(\s*"([^"]*)"\s*\))re");
    Tags t;
    for (const char* dir : kTestDirs) {
      const fs::path root = kSourceDir / dir;
      if (!fs::is_directory(root)) continue;
      std::vector<fs::path> files;
      for (const auto& entry : fs::recursive_directory_iterator(root)) {
        const std::string ext = entry.path().extension().string();
        if (entry.is_regular_file() && (ext == ".cpp" || ext == ".hpp")) files.push_back(entry.path());
      }
      std::sort(files.begin(), files.end());
      for (const fs::path& file : files) {
        std::istringstream lines(read(file));
        std::string line;
        for (int n = 1; std::getline(lines, line); ++n)
          for (std::sregex_iterator m(line.begin(), line.end(), pattern), end; m != end; ++m)
            t[(*m)[1].str()].push_back(fs::relative(file, kSourceDir).string() + ":" + std::to_string(n));
      }
    }
    return t;
  }();
  return found;
}

std::string list(const std::vector<std::string>& items) {
  std::string s;
  for (const auto& i : items) s += "\n  " + i;
  return s;
}

TEST(Traceability, TheScanFindsTaggedTests) {
  EXPECT_FALSE(tags().empty()) << "no clause tags found under " << kSourceDir << ": is the scan broken?";
}

TEST(Traceability, EveryClauseIsTestedOrPending) {
  std::vector<std::string> untested;
  for (const auto& c : spec().clauses)
    if (!tags().count(c.id) && !spec().pending.count(c.id)) untested.push_back(c.id + "  " + c.title);
  EXPECT_TRUE(untested.empty()) << untested.size()
                                << " clause(s) named by no test and not in spec/pending.json (tag a test with the "
                                   "clause, or list it in pending.json with the issue and reason):"
                                << list(untested);
}

TEST(Traceability, NoClauseIsBothTestedAndPending) {
  std::vector<std::string> both;
  for (const auto& [id, reason] : spec().pending)
    if (tags().count(id))
      both.push_back("remove " + id + " from spec/pending.json: it is tested at " + tags().at(id).front());
  EXPECT_TRUE(both.empty()) << "the pending list only shrinks:" << list(both);
}

TEST(Traceability, EveryNamedClauseExists) {
  std::vector<std::string> unknown;
  for (const auto& [id, where] : tags())
    if (!spec().find_clause(id))
      for (const auto& w : where) unknown.push_back(w + ": tag names \"" + id + "\", which is not in clauses.json");
  for (const auto& [id, reason] : spec().pending)
    if (!spec().find_clause(id)) unknown.push_back("spec/pending.json lists \"" + id + "\", which is not in clauses.json");
  EXPECT_TRUE(unknown.empty()) << "clause ids that do not exist:" << list(unknown);
}

TEST(Traceability, EveryClauseIsDefinedInSpecMd) {
  const fs::path spec_md = kSpecDir / "SPEC.md";
  ASSERT_TRUE(fs::exists(spec_md)) << spec_md << " does not exist";
  const std::string text = read(spec_md);
  std::vector<std::string> undefined;
  for (const auto& c : spec().clauses)
    if (text.find("**" + c.id + "**") == std::string::npos) undefined.push_back(c.id);
  EXPECT_TRUE(undefined.empty()) << "clauses without a bold definition **ID** in spec/SPEC.md:" << list(undefined);
}

TEST(Traceability, EveryExampleNamesAnExistingClause) {
  std::vector<std::string> orphans;
  for (const auto& e : spec().examples)
    if (!spec().find_clause(e.clause))
      orphans.push_back(e.id + " (" + e.json_path + ") names \"" + e.clause + "\", which is not in clauses.json");
  EXPECT_TRUE(orphans.empty()) << "examples of unknown clauses:" << list(orphans);
}

TEST(Traceability, EveryClauseWithAnOpHasAWorkedExample) {
  std::set<std::string> with_examples;
  for (const auto& e : spec().examples) with_examples.insert(e.clause);
  std::vector<std::string> missing;
  for (const auto& c : spec().clauses)
    if (c.op && !with_examples.count(c.id)) missing.push_back(c.id + " (op \"" + *c.op + "\")");
  EXPECT_TRUE(missing.empty()) << "clauses with an op in clauses.json but no worked example in spec/examples.json:"
                               << list(missing);
}

}  // namespace
