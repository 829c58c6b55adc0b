// Running a command line from a test, as a user would in a shell: its exit status and everything
// it printed (stdout and stderr together). For the tests of the `rotorcert` tool.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace rotorcert::testing {

struct ShellRun {
  int exit_code;  // -1 when the command did not exit normally
  std::string output;
};

/// Runs `command` through /bin/sh. Output goes through a file unique to this process and call,
/// so tests running in parallel do not mix their output.
inline ShellRun run_shell(const std::string& command) {
  static std::atomic<int> counter{0};
  const std::filesystem::path out = std::filesystem::temp_directory_path() /
                                    ("rotorcert_test_output_" + std::to_string(::getpid()) + "_" +
                                     std::to_string(counter++) + ".txt");
  const int status = std::system((command + " > '" + out.string() + "' 2>&1").c_str());
  std::ifstream in(out);
  std::stringstream text;
  text << in.rdbuf();
  std::error_code ignored;
  std::filesystem::remove(out, ignored);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, text.str()};
}

/// `rotorcert ARGS` with the binary the build made (ROTORCERT_BINARY).
inline ShellRun run_rotorcert(const std::string& args) {
  return run_shell(std::string("'") + ROTORCERT_BINARY + "' " + args);
}

}  // namespace rotorcert::testing
