// Where the rotorcert tool finds the files it reads at run time, so that an installed tool never
// reads the source tree and a build-tree tool needs no installation.
//
//   installed (the tool finds PREFIX/share/rotorcert/spec/clauses.json, PREFIX = its own
//   directory's parent; the layout `cmake --install` and the Debian package make):
//     PREFIX/share/rotorcert/spec/                   clauses.json, examples.json, SPEC.md, schemas
//     PREFIX/share/rotorcert/impls/NAME/expected_failures.json
//     PREFIX/share/rotorcert/mutants/mutants.json
//     PREFIX/share/rotorcert/adapters/NAME/          adapter manifests, scripts, known defects
//     PREFIX/share/rotorcert/setup-adapters          installs the adapters' environments
//     PREFIX/lib/rotorcert/mutants/                  rotorcert_mutant_*.so
//     PREFIX/lib/rotorcert/adapter_plugins/          the adapters' C-ABI plugins
//     PREFIX/libexec/rotorcert/rotorcert_bench
//   build tree (anything else): the compiled-in paths of the source and build directories.
//
// $ROTORCERT_SPEC_DIR still overrides the spec directory (spec::resolve_spec_dir).
#pragma once

#include <filesystem>
#include <string>

namespace rotorcert::spec {

struct DataLayout {
  bool installed = false;
  std::filesystem::path prefix;  // installed: the installation prefix; build tree: the source tree
  std::filesystem::path spec_dir, impls_dir, mutants_json, mutant_plugin_dir, adapters_dir, adapter_plugin_dir,
      bench_binary;
  /// Where scripts/setup-adapters installs the adapters' environments by default: build/adapters
  /// of the source tree, or $XDG_CACHE_HOME/rotorcert/adapters (~/.cache/...) when installed.
  std::filesystem::path adapters_env;
  /// scripts/setup-adapters of the source tree, or PREFIX/share/rotorcert/setup-adapters.
  std::filesystem::path setup_adapters;
};

/// The layout of this process's tool, decided once from the location of /proc/self/exe.
const DataLayout& data_layout();

/// The layout for a tool binary at `exe` (the decision data_layout() makes, for tests).
DataLayout layout_for_executable(const std::filesystem::path& exe);

}  // namespace rotorcert::spec
