// `rotorcert thirdparty --out DIR [--adapter NAME]...`: certifies the third-party libraries of
// conformance/adapters/ (spec REPORT-3; guide: conformance/CERTIFY.md), each by the route its
// adapter.json declares, and writes report.json (kind "third-party"), report.md and report.html
// with the third-party section and every certificate. Exit 0 when every library that ran gives
// exactly its known defects (expected_failures.json beside its adapter, impls/ for the built-in
// GLM and Eigen), 1 otherwise (a library not as expected, an adapter that failed to run), 2 on
// usage. A library whose adapter cannot run here (package not installable, plugin not built) is
// "not run" with the reason and does not change the exit code.
#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <set>
#include <tuple>

#include <rotorcert/report/write.hpp>
#include <rotorcert/certify/print.hpp>
#include <rotorcert/certify/report_document.hpp>
#include <rotorcert/certify/verdict.hpp>
#include <rotorcert/engine/abi_op.hpp>
#include <rotorcert/report/speed.hpp>
#include <rotorcert/spec/data_layout.hpp>
#include <rotorcert/thirdparty/thirdparty.hpp>

#include "certify_cli.hpp"
#include "commands.hpp"


namespace rotorcert::cli {

std::string default_adapters_env() {
  const char* env = std::getenv("ROTORCERT_ADAPTERS_ENV");
  return env != nullptr && *env != '\0' ? env : spec::data_layout().adapters_env.string();
}

ThirdPartyRequest::ThirdPartyRequest()
    : adapters_dir(spec::data_layout().adapters_dir.string()),
      env_dir(default_adapters_env()),
      plugin_dir(spec::data_layout().adapter_plugin_dir.string()) {}

int run_third_party(const ThirdPartyRequest& r, const spec::Spec& spec, const certify::CertifyOptions& options,
                    const thirdparty::KnownCertificates& known, const char* who, thirdparty::Outcome& outcome,
                    nlohmann::json& section) {
  thirdparty::Options o;
  o.adapters_dir = r.adapters_dir;
  o.env_dir = r.env_dir;
  o.plugin_dir = r.plugin_dir;
  o.out = r.out;
  o.names = r.names;
  o.certify = options;
  o.adapter_timeout_s = r.adapter_timeout_s;
  o.quiet = r.quiet;
  for (const std::string& v : r.versions) {
    const std::size_t eq = v.find('=');
    if (eq == 0 || eq == std::string::npos || eq + 1 == v.size()) {
      std::cerr << who << ": --version " << v << ": expected NAME=VERSION (e.g. three=0.179.0)\n";
      return kExitUsage;
    }
    o.versions.emplace_back(v.substr(0, eq), v.substr(eq + 1));
  }
  // Another version is installed on first use, by the same installer and into the same place as
  // the pins (scripts/setup-adapters --version NAME=VER: ENV/NAME@VER), from the package registry.
  for (const auto& [name, version] : o.versions) {
    if (std::filesystem::exists(o.env_dir / (name + "@" + version) / "status.json")) continue;
    const std::filesystem::path log = std::filesystem::path(r.out) / ("setup-" + name + "@" + version + ".log");
    std::filesystem::create_directories(log.parent_path());
    if (!r.quiet) std::cout << who << ": installing " << name << " " << version << " (" << spec::data_layout().setup_adapters.string()
                            << ") ...\n" << std::flush;
    const thirdparty::ProgramRun setup = thirdparty::run_program(
        {"python3", spec::data_layout().setup_adapters.string(), "--env", o.env_dir.string(), "--version", name + "=" + version},
        {}, log, 1800);
    if (!setup.started || setup.exit_code != 0)
      std::cerr << who << ": setup-adapters --version " << name << "=" << version << " failed; see " << log << '\n';
  }
  try {
    outcome = thirdparty::certify_third_party(spec, o, known);
  } catch (const std::exception& e) {
    std::cerr << who << ": " << e.what() << '\n';
    return kExitUsage;
  }
  section = thirdparty::section_json(outcome, o);
  if (r.speed) add_third_party_speed(r, outcome, who, section);
  return outcome.as_expected() ? kExitOk : kExitFailed;
}

namespace {

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : (v[m - 1] + v[m]) / 2;
}

}  // namespace

void add_third_party_speed(const ThirdPartyRequest& r, const thirdparty::Outcome& outcome, const char* who,
                           nlohmann::json& section) {
  constexpr int kElements = 4096;
  constexpr const char* kBaseline = "glm_quat";
  // The native tables: every certificate of a C-ABI library (plugins, and GLM/Eigen built in).
  std::set<std::string> tables = {kBaseline}, plugins;
  for (const thirdparty::Library& lib : outcome.libraries) {
    if (lib.manifest.route != "abi" || lib.status != thirdparty::LibraryStatus::certified) continue;
    for (const certify::Certificate& c : lib.certificates) {
      tables.insert(c.table.name);
      if (!c.table.plugin_path.empty()) plugins.insert(c.table.plugin_path);
    }
  }
  if (tables.size() == 1) {
    section["speed"] = {{"note", "no native (C-ABI) library was certified in this run"}};
    return;
  }
  BenchRequest bench;
  bench.out = (std::filesystem::path(r.out) / "speed").string();
  bench.quick = true;
  bench.binary = r.bench_binary;
  bench.plugins.assign(plugins.begin(), plugins.end());
  std::string alternatives;
  for (const std::string& t : tables) alternatives += (alternatives.empty() ? "" : "|") + t;
  bench.filter = "^op/[^/]+/(" + alternatives + ")/(float|double)/" + std::to_string(kElements) + "$";
  if (!r.quiet) std::cout << who << ": timing " << tables.size() - 1 << " native table(s) against " << kBaseline << " ...\n" << std::flush;
  nlohmann::json out;
  if (run_bench(bench, who, out) != kExitOk) {
    section["speed"] = {{"note", "the benchmark run failed; its log is " + (std::filesystem::path(bench.out) / "bench.log").string()}};
    return;
  }
  // ns per element of one batch call, by (table, scalar, op).
  std::map<std::tuple<std::string, std::string, std::string>, double> ns;
  for (const nlohmann::json& b : out.value("benchmarks", nlohmann::json::array())) {
    auto f = report::bench_label_fields(b);
    if (b.value("name", "").rfind("op/", 0) != 0 || !b.contains("ns_per_element") || !b["ns_per_element"].is_number())
      continue;
    ns[{f["impl"], f["scalar"], f["op"]}] = b["ns_per_element"].get<double>();
  }
  const std::string cpu = out.contains("context") ? out["context"].value("cpu_model", "") : "";
  section["speed"] = {{"baseline", kBaseline}, {"elements", kElements}, {"cpu", cpu},
                      {"bench_json", (std::filesystem::path(bench.out) / "bench.json").string()},
                      {"note", "ns per element of one batch call of " + std::to_string(kElements) +
                                   " valid elements through the C ABI (the adapter's conversions, and a Rust adapter's per-element panic guard, included), measured in the same run as " + kBaseline +
                                   "'s same op and scalar; ratio = library / " + kBaseline + " (below 1: faster)"}};
  for (nlohmann::json& lib : section["libraries"]) {
    const auto it = std::find_if(outcome.libraries.begin(), outcome.libraries.end(),
                                 [&](const thirdparty::Library& l) { return l.manifest.run_name() == lib.value("name", ""); });
    if (it == outcome.libraries.end() || it->manifest.route != "abi") continue;
    nlohmann::json per_table = nlohmann::json::array();
    for (const certify::Certificate& c : it->certificates) {
      nlohmann::json ops = nlohmann::json::array();
      std::vector<double> ratios;
      for (const engine::AbiOp& op : engine::abi_ops()) {
        const auto own = ns.find({c.table.name, c.table.scalar, op.name});
        if (own == ns.end()) continue;
        const auto base = ns.find({kBaseline, c.table.scalar, op.name});
        nlohmann::json o = {{"op", op.name}, {"ns_per_element", own->second}};
        if (base != ns.end() && base->second > 0) {
          o["baseline_ns_per_element"] = base->second;
          o["ratio"] = own->second / base->second;
          ratios.push_back(own->second / base->second);
        }
        ops.push_back(o);
      }
      if (ops.empty()) continue;
      nlohmann::json t = {{"table", c.table.name}, {"scalar", c.table.scalar}, {"ops", ops}};
      if (!ratios.empty()) {
        t["median_ratio"] = median(ratios);
        t["ops_compared"] = ratios.size();
      }
      per_table.push_back(t);
    }
    if (!per_table.empty()) lib["speed"] = per_table;
  }
}

void print_third_party_summary(std::ostream& out, const thirdparty::Outcome& outcome) {
  for (const thirdparty::Library& lib : outcome.libraries) {
    out << "third-party " << lib.manifest.name << ": " << thirdparty::to_string(lib.status);
    if (lib.status == thirdparty::LibraryStatus::certified) {
      std::string claims;
      for (const certify::Certificate& c : lib.certificates) claims += (claims.empty() ? "" : "; ") + certify::claim(c);
      out << ", " << lib.defects.size() << " defect(s), " << (lib.as_expected ? "as expected" : "NOT as expected") << " ("
          << claims << ")";
    } else {
      out << ": " << lib.reason;
    }
    out << '\n';
  }
}

namespace {

struct Args {
  CertifyCli common;
  ThirdPartyRequest request;
};

int run(Args a) {
  const auto started = std::chrono::steady_clock::now();
  spec::Spec spec;
  certify::CertifyOptions options;
  if (!load_spec_and_options("thirdparty", a.common, spec, options)) return kExitUsage;
  a.request.out = a.common.out;
  a.request.quiet = a.common.quiet;
  thirdparty::Outcome outcome;
  certify::json section;
  const int rc = run_third_party(a.request, spec, options, {}, "rotorcert thirdparty", outcome, section);
  if (rc == kExitUsage) return rc;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  const std::vector<certify::Certificate> certificates = outcome.certificates();
  certify::json report = certify::report_json(spec, "third-party", certify::options_json(options),
                                              run_json(seconds, command_line(), options.jobs), certificates);
  report["summary"]["as_expected"] = outcome.as_expected();
  report["summary"]["exit_code"] = rc;
  report["sections"]["third_party"] = std::move(section);
  if (!a.common.quiet) {
    for (const certify::Certificate& c : certificates) certify::print_certificate(std::cout, c, a.common.verbose);
    print_third_party_summary(std::cout, outcome);
  }
  try {
    report::write_report(a.common.out, report);
  } catch (const std::exception& e) {
    std::cerr << "rotorcert thirdparty: cannot write the report: " << e.what() << '\n';
    return kExitUsage;
  }
  if (!a.common.quiet) std::cout << "report: " << a.common.out << "/report.html (and report.json, report.md)\n";
  return rc;
}

}  // namespace

void add_third_party_options(CLI::App& app, ThirdPartyRequest& r) {
  app.add_option("--adapters", r.adapters_dir, "Directory of the adapters (each NAME/adapter.json)")->capture_default_str();
  app.add_option("--adapters-env", r.env_dir,
                 "Where scripts/setup-adapters installed their environments (default $ROTORCERT_ADAPTERS_ENV, else build/adapters)")
      ->capture_default_str();
  app.add_option("--plugins", r.plugin_dir, "Directory of the adapters' plugins the build made")->capture_default_str();
  app.add_option("--adapter-timeout", r.adapter_timeout_s, "Wall-clock limit of one run of a vectors adapter, seconds")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--version", r.versions,
                 "NAME=VER: also certify version VER of adapter NAME's library (installed on first use into "
                 "ENV/NAME@VER), compared with the pin's known defects; repeatable")
      ->option_text("NAME=VER");
}

Command add_thirdparty(CLI::App& parent) {
  auto args = std::make_shared<Args>();
  CLI::App* app = parent.add_subcommand(
      "thirdparty", "Certify the third-party libraries of conformance/adapters (C ABI and JSON-vector adapters)");
  app->add_option("--adapter", args->request.names, "Only this adapter (e.g. clifford); repeatable");
  app->add_flag("--speed", args->request.speed,
                "Also time every native (C-ABI) library's ops against glm_quat in one benchmark run (4096 elements)");
  app->add_option("--bench-binary", args->request.bench_binary, "The rotorcert_bench executable (for --speed)")
      ->default_str(spec::data_layout().bench_binary.string());
  add_third_party_options(*app, args->request);
  add_certify_options(*app, args->common);
  return {app, [args] { return run(*args); }};
}

}  // namespace rotorcert::cli
