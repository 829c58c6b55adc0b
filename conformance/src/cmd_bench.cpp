// `rotorcert bench [--quick] --out DIR`: runs rotorcert_bench (conformance/bench/), keeps its
// Google Benchmark JSON as DIR/bench.json and its console output as DIR/bench.log, and writes the
// speed section (rotorcert/report/speed.hpp) as a report of kind "bench" (report.json, .md, .html).
// `--accuracy REPORT.json` adds the accuracy-versus-speed chart from an earlier report's
// certificates. `rotorcert report` runs the same quick run for its speed section (run_bench).
// Exit 0 when the benchmarks ran (speed is reported, never a pass/fail), 1 when the benchmark
// binary failed, 2 on usage errors.
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>

#include <rotorcert/report/write.hpp>
#include <rotorcert/certify/certify.hpp>
#include <rotorcert/certify/report_document.hpp>
#include <rotorcert/report/speed.hpp>

#include "certify_cli.hpp"
#include <rotorcert/spec/data_layout.hpp>

#include "commands.hpp"


extern char** environ;

namespace rotorcert::cli {

namespace fs = std::filesystem;

int run_bench(const BenchRequest& r, const char* who, nlohmann::json& bench_json) {
  const fs::path out = r.out;
  std::error_code ec;
  fs::create_directories(out, ec);
  if (ec) {
    std::cerr << who << ": cannot create " << out << ": " << ec.message() << '\n';
    return kExitUsage;
  }
  const std::string binary = r.binary.empty() ? spec::data_layout().bench_binary.string() : r.binary;
  if (!fs::exists(binary)) {
    std::cerr << who << ": the benchmark binary " << binary
              << " does not exist (build the target rotorcert_bench, or pass --bench-binary)\n";
    return kExitUsage;
  }
  // The binary writes to a partial file that is renamed only when it finished: bench.json is
  // either a whole run or the previous one.
  const fs::path partial = out / "bench.json.partial";
  const fs::path log = out / "bench.log";
  std::vector<std::string> args = {binary, "--benchmark_out=" + partial.string(), "--benchmark_out_format=json"};
  if (r.quick) args.push_back("--quick");
  if (!r.filter.empty()) args.push_back("--benchmark_filter=" + r.filter);
  for (const std::string& p : r.plugins) args.push_back("--plugin=" + p);
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, binary.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) {
    std::cerr << who << ": cannot start " << binary << ": " << std::strerror(spawned) << '\n';
    return kExitFailed;
  }
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    std::cerr << who << ": " << binary << " failed (" << (WIFEXITED(status) ? "exit " + std::to_string(WEXITSTATUS(status))
                                                                            : "signal " + std::to_string(WTERMSIG(status)))
              << "); its output is in " << log << '\n';
    return kExitFailed;
  }
  try {
    std::ifstream in(partial);
    bench_json = nlohmann::json::parse(in);
  } catch (const std::exception& e) {
    std::cerr << who << ": " << partial << " is not valid JSON: " << e.what() << '\n';
    return kExitFailed;
  }
  fs::rename(partial, out / "bench.json");
  return kExitOk;
}

namespace {

struct BenchCli {
  BenchRequest request;
  std::string accuracy;  // a report.json whose certificates give the accuracy of each op
};

int run(const BenchCli& o) {
  const auto started = std::chrono::steady_clock::now();
  std::vector<nlohmann::json> certificates;
  if (!o.accuracy.empty()) {
    try {
      std::ifstream in(o.accuracy);
      if (!in) throw std::runtime_error("cannot be read");
      const auto rep = nlohmann::json::parse(in);
      for (const auto& c : rep.at("implementations")) certificates.push_back(c);
    } catch (const std::exception& e) {
      std::cerr << "rotorcert bench: --accuracy " << o.accuracy << ": " << e.what() << '\n';
      return kExitUsage;
    }
  }
  spec::Spec spec;
  certify::CertifyOptions options;
  CertifyCli common;
  common.out = o.request.out;
  if (!load_spec_and_options("bench", common, spec, options)) return kExitUsage;

  nlohmann::json bench;
  std::cout << "rotorcert bench: running " << (o.request.quick ? "the quick set" : "every benchmark") << " ("
            << (o.request.binary.empty() ? spec::data_layout().bench_binary.string() : o.request.binary) << ") ...\n"
            << std::flush;
  if (const int rc = run_bench(o.request, "rotorcert bench", bench); rc != kExitOk) return rc;
  nlohmann::json speed;
  try {
    speed = report::speed_section(bench, certificates, (fs::path(o.request.out) / "bench.json").string());
  } catch (const std::exception& e) {
    std::cerr << "rotorcert bench: " << e.what() << '\n';
    return kExitFailed;
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  nlohmann::json rep = certify::report_json(spec, "bench", certify::options_json(options),
                                            run_json(seconds, command_line(), 1), {});
  rep["summary"]["exit_code"] = 0;
  rep["sections"]["speed"] = speed;
  print_speed_summary(std::cout, speed);
  try {
    report::write_report(o.request.out, rep);
  } catch (const std::exception& e) {
    std::cerr << "rotorcert bench: cannot write the report: " << e.what() << '\n';
    return kExitUsage;
  }
  std::cout << "wrote " << o.request.out << "/bench.json (Google Benchmark), bench.log, report.html, report.md, report.json\n";
  return kExitOk;
}

}  // namespace

void print_speed_summary(std::ostream& out, const nlohmann::json& speed) {
  const auto num = [](const nlohmann::json& j, const char* k) {
    return j.contains(k) && j[k].is_number() ? j[k].get<double>() : std::nan("");
  };
  for (const auto& t : speed.at("targets")) {
    char line[256];
    std::snprintf(line, sizeof line, "target %-10s %-48s %6.2fx (>= %.0fx) %s", t.at("id").get<std::string>().c_str(),
                  t.at("what").get<std::string>().c_str(), num(t, "ratio"), num(t, "target"),
                  !t.at("met").is_boolean() ? "not measured" : t.at("met").get<bool>() ? "met" : "MISSED");
    out << line << '\n';
  }
  const auto verdict = [](const nlohmann::json& c, const char* k) {
    return c.contains(k) && c[k].is_string() ? c[k].get<std::string>() : std::string("?");
  };
  for (const auto& c : speed.at("paper_claim")) {
    char line[320];
    std::snprintf(line, sizeof line,
                  "frame %-14s %-6s QLB %9.1f us  DQB %9.1f us  %s %9.1f us (medians): vs QLB %s, vs DQB %s; "
                  "GA rotors faster: %s",
                  c.at("scene").get<std::string>().c_str(), c.at("scalar").get<std::string>().c_str(), num(c, "qlb_us"),
                  num(c, "dqb_us"), c.at("rotor").get<std::string>().c_str(), num(c, "rotor_us"),
                  verdict(c, "verdict_qlb").c_str(), verdict(c, "verdict_dqb").c_str(),
                  c.at("holds").get<bool>() ? "yes" : "no");
    out << line << '\n';
  }
}

Command add_bench(CLI::App& parent) {
  auto o = std::make_shared<BenchCli>();
  CLI::App* app = parent.add_subcommand(
      "bench", "Speed: every op of every implementation, the glm baselines, the frame pipeline and the roofline");
  app->add_option("--out", o->request.out, "Output directory (bench.json, bench.log, report.*)")->required();
  app->add_flag("--quick", o->request.quick, "Sizes 64 and 4096 only, short runs (what `rotorcert report` runs)");
  app->add_option("--filter", o->request.filter, "Only benchmarks matching this regex (Google Benchmark's filter)");
  app->add_option("--bench-binary", o->request.binary, "The rotorcert_bench executable")
      ->default_str(spec::data_layout().bench_binary.string());
  app->add_option("--accuracy", o->accuracy, "A report.json whose certificates give each op's accuracy");
  return {app, [o] { return run(*o); }};
}

}  // namespace rotorcert::cli
