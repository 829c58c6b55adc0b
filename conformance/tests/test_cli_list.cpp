// `rotorcert list`: every built-in implementation appears with its scalar type and levels, the
// SIMD implementation with its dispatch targets, and a plugin path that does not load is a usage
// error (exit 2) with a message, not a crash.
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include <rotorcert/registry.hpp>
#include <rotorcert/testing/shell.hpp>

namespace {

namespace fs = std::filesystem;

using ToolRun = ::rotorcert::testing::ShellRun;
ToolRun rotorcert(const std::string& args) { return ::rotorcert::testing::run_rotorcert(args); }

TEST(CliList, ShowsEveryBuiltinWithScalarLevelsAndSimdTargets) {
  const ToolRun r = rotorcert("list");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const rc_impl* t : rotorcert::impl::builtin_tables()) {
    const std::string scalar = t->scalar == RC_SCALAR_FLOAT32 ? "float" : "double";
    bool found = false;
    std::istringstream lines(r.output);
    for (std::string line; std::getline(lines, line);)
      if (line.rfind(std::string(t->name) + " ", 0) == 0 && line.find(" " + scalar + " ") != std::string::npos) {
        found = true;
        if (t->simd_targets) {
          for (int i = 0; t->simd_targets[i]; ++i) EXPECT_NE(line.find(t->simd_targets[i]), std::string::npos) << line;
        }
      }
    EXPECT_TRUE(found) << t->name << " (" << scalar << ") is missing from\n" << r.output;
  }
  EXPECT_NE(r.output.find("Core,Interp,Blend"), std::string::npos) << r.output;
}

TEST(CliList, AddsAPluginAndRejectsOneThatDoesNotLoad) {
  const fs::path plugin = fs::path(ROTORCERT_PLUGIN_DIR) / "rotorcert_impl_dq.so";
  const ToolRun ok = rotorcert("list --plugin '" + plugin.string() + "'");
  EXPECT_EQ(ok.exit_code, 0) << ok.output;
  EXPECT_NE(ok.output.find("plugin"), std::string::npos) << ok.output;
  const ToolRun bad = rotorcert("list --plugin /nonexistent/plugin.so");
  EXPECT_EQ(bad.exit_code, 2) << bad.output;
  EXPECT_NE(bad.output.find("cannot load plugin /nonexistent/plugin.so"), std::string::npos) << bad.output;
}

}  // namespace

namespace {

// `vectors run --plugin`: a plugin with two tables of one scalar (glm_quat's plugin holds glm_quat
// and glm_mix, both float) is ambiguous without --table, which picks one by name.
TEST(CliVectorsRun, ChoosesOneOfSeveralTablesByName) {
  const fs::path plugin = fs::path(ROTORCERT_PLUGIN_DIR) / "rotorcert_impl_glm_quat.so";
  const fs::path dir = fs::temp_directory_path() / ("rotorcert_cli_table_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  ASSERT_EQ(rotorcert("vectors export --out '" + (dir / "v").string() + "' --scalar float --cases 2 --clause NORM-1").exit_code, 0);
  const std::string common = "vectors run --plugin '" + plugin.string() + "' --scalar float --vectors '" + (dir / "v").string() +
                             "' --out '" + (dir / "r.json").string() + "'";
  const ToolRun ambiguous = rotorcert(common);
  EXPECT_EQ(ambiguous.exit_code, 2) << ambiguous.output;
  EXPECT_NE(ambiguous.output.find("glm_quat, glm_mix"), std::string::npos) << ambiguous.output;
  EXPECT_NE(ambiguous.output.find("--table NAME"), std::string::npos) << ambiguous.output;
  const ToolRun chosen = rotorcert(common + " --table glm_mix");
  EXPECT_EQ(chosen.exit_code, 0) << chosen.output;
  EXPECT_NE(chosen.output.find("results of glm_mix (float)"), std::string::npos) << chosen.output;
  const ToolRun unknown = rotorcert(common + " --table nope");
  EXPECT_EQ(unknown.exit_code, 2) << unknown.output;
  EXPECT_NE(unknown.output.find("no float table named 'nope'"), std::string::npos) << unknown.output;
  fs::remove_all(dir);
}

}  // namespace
