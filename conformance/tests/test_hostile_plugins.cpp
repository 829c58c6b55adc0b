// Hostile plugins (RESULT-3): plugins that misbehave the ways real ones do, each
// certified with `rotorcert certify` as a user runs it. Each must be reported with a defined result,
// the run must go on to the other clauses, and nothing a plugin does may write the certificate or
// the report (the parent process owns them; the child's channel is untrusted input). The plugins
// (tests/faulty/) compute correct numbers except for their one misbehaviour. The segfault, the
// infinite loop and the allocation bomb are in test_certify.cpp.
//
// Bounds: every plugin run takes a fraction of a second except the one with a hang (two 2 s
// limits); the forking plugin forks at most once per clause process, in two clauses, and its
// helpers end by themselves after 60 s even if the suite failed to end them.
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <rotorcert/certify/isolate.hpp>
#include <rotorcert/testing/clause.hpp>
#include <rotorcert/testing/shell.hpp>

namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using namespace rotorcert;

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("rotorcert_hostile_test_" + std::to_string(::getpid())) / name;
  fs::remove_all(dir);
  fs::create_directories(dir.parent_path());
  return dir;
}

std::string plugin(const std::string& name) { return std::string(ROTORCERT_FAULTY_DIR) + "/" + name + ".so"; }

struct Certified {
  ::rotorcert::testing::ShellRun tool;  // stdout and stderr together, unless the run asked otherwise
  json cert;               // the one certificate of report.json; null when there is no report
  const json& clause(const std::string& id) const {
    for (const json& c : cert.at("clauses"))
      if (c.at("id") == id) return c;
    throw std::runtime_error("no clause " + id + " in the certificate");
  }
  std::string outcome(const std::string& id) const { return clause(id).at("outcome"); }
  std::string note(const std::string& id) const { return clause(id).at("note"); }
};

/// `rotorcert certify --plugin NAME.so --cases 8 ARGS`, with `env` (VAR=value ...) before it.
Certified certify(const std::string& name, const std::string& args = "-q", const std::string& env = "",
                  bool stdout_only = false) {
  const fs::path out = scratch(name);
  std::string command = env + " '" + ROTORCERT_BINARY + "' certify --plugin '" + plugin(name) + "' --cases 8 " + args +
                        " --out '" + out.string() + "'";
  if (stdout_only) command = "(" + command + " 2>/dev/null)";
  Certified c{::rotorcert::testing::run_shell(command), nullptr};
  if (fs::exists(out / "report.json")) {
    std::ifstream in(out / "report.json");
    const json report = json::parse(in);
    if (report.at("implementations").size() == 1) c.cert = report.at("implementations")[0];
  }
  return c;
}

/// Every clause in `ids` was judged normally (PASS): the run went on past the hostile clause.
void expect_pass(const Certified& c, std::initializer_list<const char*> ids) {
  for (const char* id : ids) EXPECT_EQ(c.outcome(id), "PASS") << id << ": " << c.clause(id).dump(2);
}

/// The value of input `name` (first scalar) in a worst-input text "a=[...] t=[0x1p+1]".
double input_value(const std::string& input, const std::string& name) {
  const auto at = input.find(name + "=[");
  if (at == std::string::npos) return NAN;
  return std::strtod(input.c_str() + at + name.size() + 2, nullptr);
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// ---- process faults ------------------------------------------------------------------------------

TEST(HostilePlugins, StackOverflowIsACrashWithItsInput) {
  RC_CLAUSE("RESULT-3");
  // The address-space limit bounds the stack too where RLIMIT_STACK is unlimited.
  const Certified c = certify("deep_recursion", "-q --memory-mb 512");
  ASSERT_FALSE(c.cert.is_null()) << c.tool.output;
  EXPECT_EQ(c.tool.exit_code, 1) << c.tool.output;
  EXPECT_EQ(c.outcome("SLERP-4"), "CRASH") << c.clause("SLERP-4").dump(2);
  const std::string note = c.note("SLERP-4");
  if (certify::built_with_sanitizer())  // ASan reports the stack overflow, then aborts or exits
    EXPECT_TRUE(contains(note, "SIGSEGV") || contains(note, "SIGABRT") || contains(note, "exited with status")) << note;
  else
    EXPECT_TRUE(contains(note, "SIGSEGV")) << note;
  EXPECT_GT(input_value(c.clause("SLERP-4").at("worst").at("input"), "t"), 1.0) << c.clause("SLERP-4").dump(2);
  expect_pass(c, {"NORM-1", "SLERP-1", "SLERP-3", "EDGE-6"});
}

TEST(HostilePlugins, ExitZeroInTheMiddleOfAClauseIsACrashNeverAPass) {
  RC_CLAUSE("RESULT-1");
  RC_CLAUSE("RESULT-3");
  const Certified c = certify("exits_mid_clause");
  ASSERT_FALSE(c.cert.is_null()) << c.tool.output;
  EXPECT_EQ(c.tool.exit_code, 1) << c.tool.output;
  EXPECT_EQ(c.outcome("SLERP-4"), "CRASH") << c.clause("SLERP-4").dump(2);
  const std::string note = c.note("SLERP-4");
  if (certify::built_with_sanitizer())  // exit() runs LeakSanitizer, which may turn the status into its own
    EXPECT_TRUE(contains(note, "without handing over a result") || contains(note, "before handing over a result") ||
                contains(note, "SIGABRT"))
        << note;
  else
    EXPECT_TRUE(contains(note, "exited with status 0 without handing over a result")) << note;
  EXPECT_GT(input_value(c.clause("SLERP-4").at("worst").at("input"), "t"), 1.0) << c.clause("SLERP-4").dump(2);
  expect_pass(c, {"NORM-1", "SLERP-1", "SLERP-3", "EDGE-6"});
}

TEST(HostilePlugins, SignalHandlersHideNeitherAFaultNorAHang) {
  RC_CLAUSE("RESULT-3");
  // The plugin's SIGSEGV handler exits with status 0, and it ignores SIGTERM, SIGINT, SIGALRM ...
  const Certified c = certify("installs_signal_handlers", "-q --timeout 2");
  ASSERT_FALSE(c.cert.is_null()) << c.tool.output;
  EXPECT_EQ(c.tool.exit_code, 1) << c.tool.output;
  EXPECT_EQ(c.outcome("EDGE-6"), "CRASH") << c.clause("EDGE-6").dump(2);
  if (certify::built_with_sanitizer())  // ASan may keep its own SIGSEGV handler (allow_user_segv_handler)
    EXPECT_TRUE(contains(c.note("EDGE-6"), "status 0 without handing over a result") ||
                contains(c.note("EDGE-6"), "SIGABRT") || contains(c.note("EDGE-6"), "exited with status"))
        << c.note("EDGE-6");
  else
    EXPECT_TRUE(contains(c.note("EDGE-6"), "status 0 without handing over a result")) << c.note("EDGE-6");
  EXPECT_TRUE(contains(c.clause("EDGE-6").at("worst").at("input"), "q=[0x0p+0, 0x0p+0, 0x0p+0, 0x0p+0]"))
      << c.clause("EDGE-6").dump(2);
  EXPECT_EQ(c.outcome("SLERP-4"), "TIMEOUT") << c.clause("SLERP-4").dump(2);
  EXPECT_LT(input_value(c.clause("SLERP-4").at("worst").at("input"), "t"), 0.0) << c.clause("SLERP-4").dump(2);
  expect_pass(c, {"NORM-1", "SLERP-1", "SLERP-3"});
}

// ---- what outlives a call ------------------------------------------------------------------------

/// Whether process `pid` still runs in process group `group` (a zombie has ended; a pid reused by
/// another process is in another group).
bool running_in_group(int pid, int group) {
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string line;
  if (!std::getline(stat, line)) return false;
  const auto close = line.rfind(')');
  if (close == std::string::npos) return false;
  std::istringstream rest(line.substr(close + 2));
  char state = '?';
  int ppid = 0, pgrp = 0;
  rest >> state >> ppid >> pgrp;
  return state != 'Z' && state != 'X' && pgrp == group;
}

TEST(HostilePlugins, AForkedHelperIsEndedWithItsClauseProcessGroup) {
  RC_CLAUSE("RESULT-3");
  const fs::path pids = scratch("forks_lingering_child.pids");
  const Certified c = certify("forks_lingering_child", "-q --clause NORM-1 --clause SLERP-1 --clause EDGE-6",
                              "ROTORCERT_FAULTY_PID_FILE='" + pids.string() + "'");
  ASSERT_FALSE(c.cert.is_null()) << c.tool.output;
  // The helper holds the channel open after the clause process exits: the result still counts.
  EXPECT_EQ(c.tool.exit_code, 0) << c.tool.output;
  expect_pass(c, {"NORM-1", "SLERP-1", "EDGE-6"});
  std::ifstream in(pids);
  int pid = 0, group = 0, helpers = 0;
  while (in >> pid >> group) {
    ++helpers;
    // SIGKILL is sent when the clause process exits; a loaded machine may take a moment to run
    // the helper's exit, so allow it a grace period (the helper itself would sleep on for 60 s).
    for (int i = 0; i < 200 && running_in_group(pid, group); ++i) ::usleep(50'000);
    EXPECT_FALSE(running_in_group(pid, group)) << "helper " << pid << " of process group " << group
                                               << " outlived the certification";
  }
  EXPECT_GE(helpers, 1) << "the plugin forked no helper: is ROTORCERT_FAULTY_PID_FILE passed on?";
  EXPECT_LE(helpers, 2);
}

TEST(HostilePlugins, ThreadsThatOutliveTheCallDoNotDisturbTheRun) {
  RC_CLAUSE("RESULT-3");
  // Its worker is a joinable static std::thread: a clause process that ran static destructors
  // on its way out would end in std::terminate after handing over its result.
  const Certified c = certify("threads_outlive_call");
  ASSERT_FALSE(c.cert.is_null()) << c.tool.output;
  EXPECT_EQ(c.tool.exit_code, 0) << c.tool.output;
  expect_pass(c, {"NORM-1", "SLERP-1", "SLERP-3", "SLERP-4", "EDGE-6", "EDGE-8"});
}

// ---- the channel and the tool's own output -------------------------------------------------------

TEST(HostilePlugins, GarbageOnStdioNeverReachesTheToolsStandardOutput) {
  RC_CLAUSE("RESULT-3");
  const Certified c = certify("garbage_on_stdio", "", "", /*stdout_only=*/true);
  ASSERT_FALSE(c.cert.is_null()) << c.tool.output;
  EXPECT_EQ(c.tool.exit_code, 0) << c.tool.output;
  // The plugin wrote a forged frame and a forged summary line too, then closed its stdio.
  expect_pass(c, {"NORM-1", "SLERP-1", "SLERP-3", "SLERP-4", "EDGE-6", "EDGE-8"});
  EXPECT_TRUE(contains(c.tool.output, "report: ")) << c.tool.output;
  EXPECT_FALSE(contains(c.tool.output, "HOSTILE-STDIO-GARBAGE")) << c.tool.output;
  EXPECT_FALSE(contains(c.tool.output, "forged")) << c.tool.output;
}

TEST(HostilePlugins, BytesOnTheChannelThatAreNotAFrameAreACrash) {
  RC_CLAUSE("RESULT-3");
  const Certified c = certify("writes_to_inherited_fds");
  ASSERT_FALSE(c.cert.is_null()) << c.tool.output;
  EXPECT_EQ(c.tool.exit_code, 1) << c.tool.output;
  EXPECT_EQ(c.outcome("SLERP-4"), "CRASH") << c.clause("SLERP-4").dump(2);
  EXPECT_TRUE(contains(c.note("SLERP-4"), "its channel to the certify tool carried")) << c.note("SLERP-4");
  EXPECT_GT(input_value(c.clause("SLERP-4").at("worst").at("input"), "t"), 1.0) << c.clause("SLERP-4").dump(2);
  expect_pass(c, {"NORM-1", "SLERP-1", "SLERP-3", "EDGE-6"});
}

TEST(HostilePlugins, AForgedResultFrameIsACrashNotAPass) {
  RC_CLAUSE("RESULT-3");
  // A well-formed result frame of the tool's format before the token was added, claiming PASS for
  // the clause, then _exit(0): the plugin writes it to every descriptor, the channel included.
  const fs::path payload = scratch("forged_frame");
  const std::string result =
      R"({"result":{"id":"SLERP-4","outcome":"PASS","cases":5,"failures":0},"fp_environment":{"flush_to_zero":false}})";
  std::ofstream(payload) << "R" << result.size() << ":" << result;
  const Certified c = certify("writes_to_inherited_fds", "-q",
                              "ROTORCERT_FAULTY_FD_PAYLOAD_FILE='" + payload.string() + "' ROTORCERT_FAULTY_FD_EXIT=1");
  ASSERT_FALSE(c.cert.is_null()) << c.tool.output;
  EXPECT_EQ(c.tool.exit_code, 1) << c.tool.output;
  EXPECT_EQ(c.outcome("SLERP-4"), "CRASH") << c.clause("SLERP-4").dump(2);
  EXPECT_TRUE(contains(c.note("SLERP-4"), "token")) << c.note("SLERP-4");
  expect_pass(c, {"NORM-1", "SLERP-1", "SLERP-3", "EDGE-6"});
  // Each clause has one slot, whatever id a child's result names.
  std::multiset<std::string> ids;
  for (const json& cl : c.cert.at("clauses")) ids.insert(cl.at("id").get<std::string>());
  EXPECT_EQ(ids.count("SLERP-4"), 1u);
}

// ---- buffers -------------------------------------------------------------------------------------

TEST(HostilePlugins, FewerResultsThanAskedFail) {
  RC_CLAUSE("RESULT-2");
  const Certified c = certify("returns_fewer_results");
  ASSERT_FALSE(c.cert.is_null()) << c.tool.output;
  EXPECT_EQ(c.tool.exit_code, 1) << c.tool.output;
  EXPECT_EQ(c.outcome("NORM-1"), "FAIL") << c.clause("NORM-1").dump(2);
  // The status bytes are pre-filled with a value no implementation writes.
  EXPECT_TRUE(contains(c.clause("NORM-1").at("status").at("detail"), "is neither OK nor DOMAIN_ERROR"))
      << c.clause("NORM-1").dump(2);
  expect_pass(c, {"SLERP-1", "SLERP-3", "SLERP-4"});
}

TEST(HostilePlugins, WritingPastTheOutputsIsNeverAPass) {
  RC_CLAUSE("RESULT-3");
  // One whole element past the end: the heap is corrupted (glibc or ASan aborts: CRASH); with
  // guard elements after the outputs the engine would say FAIL. Never PASS.
  const Certified c = certify("writes_past_output");
  ASSERT_FALSE(c.cert.is_null()) << c.tool.output;
  EXPECT_EQ(c.tool.exit_code, 1) << c.tool.output;
  // The engine keeps guard slots past every output and the status array (RESULT-2): the write
  // past the end is a FAIL that says so, before glibc's heap checks could notice anything.
  for (const char* id : {"SLERP-1", "SLERP-3", "SLERP-4"}) {
    EXPECT_EQ(c.outcome(id), "FAIL") << c.clause(id).dump(2);
    EXPECT_TRUE(contains(c.clause(id).at("worst").at("detail"), "wrote past the end of out_q")) << c.clause(id).dump(2);
  }
  expect_pass(c, {"NORM-1"});
}

TEST(HostilePlugins, ModifiedInputsFailHyg1) {
  RC_CLAUSE("HYG-1");
  const Certified c = certify("modifies_inputs");
  ASSERT_FALSE(c.cert.is_null()) << c.tool.output;
  EXPECT_EQ(c.tool.exit_code, 1) << c.tool.output;
  EXPECT_EQ(c.outcome("HYG-1"), "FAIL") << c.clause("HYG-1").dump(2);
  EXPECT_TRUE(contains(c.clause("HYG-1").at("worst").at("detail"), "normalize modified its input q"))
      << c.clause("HYG-1").dump(2);
  expect_pass(c, {"NORM-1", "SLERP-1", "EDGE-6", "HYG-2"});
}

// ---- the channel, byte by byte -------------------------------------------------------------------

/// One task in a ChildPool of one, with a short limit.
certify::ChildOutcome run_child(const certify::ChildPool::Task& task, double timeout_s = 10) {
  certify::ChildPool pool(1, {timeout_s, 0});
  pool.submit(0, task);
  return pool.wait_any().second;
}

/// What a plugin can do to the channel: write to every descriptor from 3 up (the channel is one).
void write_everywhere(const std::string& bytes) {
  for (int fd = 3; fd < 64; ++fd) [[maybe_unused]] const auto ignored = ::write(fd, bytes.data(), bytes.size());
}

TEST(HostileChannel, WhatIsNotAFrameOfTheChildsOwnIsACrash) {
  RC_CLAUSE("RESULT-3");
  using Kind = certify::ChildOutcome::Kind;
  const certify::ChildOutcome fine = run_child([](certify::ChildChannel& ch) {
    ch.progress("working");
    return std::string("the result");
  });
  EXPECT_EQ(fine.kind, Kind::finished) << fine.message;
  EXPECT_EQ(fine.result, "the result");
  EXPECT_EQ(fine.last_progress, "working");
  for (const std::string& bytes : {std::string("garbage\n"), std::string("R2:{}"), std::string("P99999999999:"),
                                  std::string("R1073741825:"), std::string(1, '\0'), std::string("\xff\xfe")}) {
    const certify::ChildOutcome o = run_child([&](certify::ChildChannel&) {
      write_everywhere(bytes);
      return std::string("a result after the garbage");
    });
    EXPECT_EQ(o.kind, Kind::crashed) << json(bytes).dump(-1, ' ', true, json::error_handler_t::replace);
    EXPECT_TRUE(contains(o.message, "its channel to the certify tool carried")) << o.message;
    EXPECT_NO_THROW((void)json(o.message).dump()) << "the message must be valid UTF-8 for report.json";
  }
}

TEST(HostileChannel, AChildThatNeverReportsIsNeverFinished) {
  RC_CLAUSE("RESULT-3");
  using Kind = certify::ChildOutcome::Kind;
  const certify::ChildOutcome exited = run_child([](certify::ChildChannel&) -> std::string { ::_exit(0); });
  EXPECT_EQ(exited.kind, Kind::crashed);
  EXPECT_TRUE(contains(exited.message, "status 0 without handing over a result")) << exited.message;
  // A child that closes every descriptor it has (the channel included) and goes on: not finished
  // when its channel closes, and killed at the limit.
  const certify::ChildOutcome closed = run_child(
      [](certify::ChildChannel&) -> std::string {
        for (int fd = 3; fd < 64; ++fd) ::close(fd);
        for (;;) ::pause();
      },
      1);
  EXPECT_EQ(closed.kind, Kind::timed_out) << closed.message;
  // An exception whose text is not UTF-8 (a Latin-1 path, say) must not break report.json.
  const certify::ChildOutcome thrown =
      run_child([](certify::ChildChannel&) -> std::string { throw std::runtime_error("caf\xe9 \x01"); });
  EXPECT_EQ(thrown.kind, Kind::crashed);
  EXPECT_EQ(thrown.message, "uncaught exception: caf\\xE9 \\x01");
  EXPECT_NO_THROW((void)json(thrown.message).dump());
}

}  // namespace
