#include <rotorcert/spec/data_layout.hpp>

#include <cstdlib>
#include <system_error>

#ifndef ROTORCERT_SOURCE_DIR
#error "ROTORCERT_SOURCE_DIR must be defined by the build"
#endif
#ifndef ROTORCERT_BUILD_DIR
#error "ROTORCERT_BUILD_DIR must be defined by the build"
#endif
#ifndef ROTORCERT_BENCH_BINARY
#error "ROTORCERT_BENCH_BINARY must be defined by the build"
#endif

namespace rotorcert::spec {
namespace fs = std::filesystem;

DataLayout layout_for_executable(const fs::path& exe) {
  DataLayout l;
  const fs::path prefix = exe.parent_path().parent_path();
  std::error_code ec;
  if (!exe.empty() && fs::is_regular_file(prefix / "share/rotorcert/spec/clauses.json", ec)) {
    l.installed = true;
    l.prefix = prefix;
    const fs::path share = prefix / "share/rotorcert", lib = prefix / "lib/rotorcert";
    l.spec_dir = share / "spec";
    l.impls_dir = share / "impls";
    l.mutants_json = share / "mutants/mutants.json";
    l.adapters_dir = share / "adapters";
    l.mutant_plugin_dir = lib / "mutants";
    l.adapter_plugin_dir = lib / "adapter_plugins";
    l.bench_binary = prefix / "libexec/rotorcert/rotorcert_bench";
    l.setup_adapters = share / "setup-adapters";
    const char* cache = std::getenv("XDG_CACHE_HOME");
    const char* home = std::getenv("HOME");
    l.adapters_env = cache && *cache ? fs::path(cache) / "rotorcert/adapters"
                     : home && *home ? fs::path(home) / ".cache/rotorcert/adapters"
                                     : fs::temp_directory_path() / "rotorcert-adapters";
    return l;
  }
  const fs::path source = ROTORCERT_SOURCE_DIR, build = ROTORCERT_BUILD_DIR;
  l.prefix = source;
  l.spec_dir = source / "spec";
  l.impls_dir = source / "impls";
  l.mutants_json = source / "conformance/mutants/mutants.json";
  l.adapters_dir = source / "conformance/adapters";
  l.mutant_plugin_dir = build / "mutants";
  l.adapter_plugin_dir = build / "adapter_plugins";
  l.bench_binary = ROTORCERT_BENCH_BINARY;
  l.adapters_env = source / "build/adapters";
  l.setup_adapters = source / "scripts/setup-adapters";
  return l;
}

const DataLayout& data_layout() {
  static const DataLayout layout = [] {
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    return layout_for_executable(ec ? fs::path() : exe);
  }();
  return layout;
}

}  // namespace rotorcert::spec
