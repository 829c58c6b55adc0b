// The three families of benchmarks of rotorcert_bench, each registered at run time.
#pragma once

#include <cstddef>
#include <vector>

#include <rotorcert/impl_abi.h>

namespace rotorcert::bench {

struct RunConfig {
  std::vector<std::size_t> sizes;  // batch sizes of op/* and baseline/*
  std::size_t stream_bytes = 0;    // bytes streaming sizes cycle through (workspace.hpp)
};

/// op/<op>/<impl>/<float|double>/<n>: every non-NULL op of every built-in table (ops_bench.cpp),
/// and of `extra` tables (third-party plugins loaded by --plugin, timed in the same run).
void register_op_benchmarks(const RunConfig& config, const std::vector<const rc_impl*>& extra = {});

/// baseline/glm_slerp/<float|double>/<n>, baseline/glm_mix/...: plain GLM loops (baselines.cpp).
void register_baselines(const RunConfig& config);

/// roofline/peak_fma/<float|double>, roofline/bandwidth/{read,triad} (roofline.cpp).
void register_roofline(const RunConfig& config);

}  // namespace rotorcert::bench
