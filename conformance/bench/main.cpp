// rotorcert_bench: Google Benchmark over every op of every built-in implementation, the glm
// baselines and the roofline (README.md in this directory). Our flags (options.hpp) are taken
// out first; Google Benchmark parses the rest.
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>
#include <rotorcert/registry.hpp>

#include "frame_bench.hpp"
#include "inputs.hpp"
#include "machine.hpp"
#include "op_cost.hpp"
#include "options.hpp"
#include "register.hpp"
#include "roofline_kernels.hpp"

#ifndef ROTORCERT_VERSION
#define ROTORCERT_VERSION "unknown"
#endif
#ifndef ROTORCERT_BUILD_TYPE
#define ROTORCERT_BUILD_TYPE "unknown"
#endif

int main(int argc, char** argv) {
  using namespace rotorcert::bench;
  CommandLine cl = parse_command_line(argc, argv);
  if (!cl.error.empty()) {
    std::fprintf(stderr, "rotorcert_bench: %s\n%s", cl.error.c_str(), usage().c_str());
    return 2;
  }
  if (cl.help) std::fputs(usage().c_str(), stdout);
  const Options& o = cl.options;

  RunConfig config;
  config.sizes = o.sizes;
  config.stream_bytes = o.stream_bytes != 0 ? o.stream_bytes : default_stream_bytes();

  // Machine and run context, next to Google Benchmark's own (CPUs, MHz, caches, load).
  std::string sizes;
  for (const std::size_t n : o.sizes) sizes += (sizes.empty() ? "" : ",") + std::to_string(n);
  benchmark::AddCustomContext("cpu_model", cpu_model());
  benchmark::AddCustomContext("llc_bytes", std::to_string(last_level_cache_bytes()));
  benchmark::AddCustomContext("rotorcert_version", ROTORCERT_VERSION);
  benchmark::AddCustomContext("rotorcert_build_type", ROTORCERT_BUILD_TYPE);
  benchmark::AddCustomContext("compiler", __VERSION__);
  benchmark::AddCustomContext("rotorcert_quick", o.quick ? "true" : "false");
  benchmark::AddCustomContext("rotorcert_sizes", sizes);
  benchmark::AddCustomContext("rotorcert_stream_bytes", std::to_string(config.stream_bytes));
  benchmark::AddCustomContext("rotorcert_seed", std::to_string(kSeed));
  benchmark::AddCustomContext("rotorcert_influences", std::to_string(kInfluences));
  benchmark::AddCustomContext("rotorcert_transcendental_flops", std::to_string(static_cast<int>(kTranscendentalFlops)));
  benchmark::AddCustomContext("hwy_target", roofline::target_name());

  // Third-party plugins (rotorcert thirdparty --speed): their tables are timed in this run, beside
  // the built-in GLM table they are compared with. A plugin that does not load is a usage error.
  std::vector<std::unique_ptr<rotorcert::impl::Plugin>> plugins;
  std::vector<const rc_impl*> plugin_tables;
  for (const std::string& path : o.plugins) {
    try {
      plugins.push_back(rotorcert::impl::Plugin::load(path));
    } catch (const std::exception& e) {
      std::fprintf(stderr, "rotorcert_bench: --plugin=%s: %s\n", path.c_str(), e.what());
      return 2;
    }
    for (const rc_impl* t : plugins.back()->tables()) plugin_tables.push_back(t);
  }

  register_roofline(config);
  register_baselines(config);
  register_op_benchmarks(config, plugin_tables);
  register_frame_benchmarks(config, o.quick);

  std::vector<char*> args;
  for (std::string& a : cl.args) args.push_back(a.data());
  int n_args = static_cast<int>(args.size());
  args.push_back(nullptr);
  benchmark::Initialize(&n_args, args.data());
  if (benchmark::ReportUnrecognizedArguments(n_args, args.data())) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
