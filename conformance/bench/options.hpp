// rotorcert_bench's own command-line flags. They are removed from argv before
// benchmark::Initialize, which then sees only Google Benchmark's flags.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace rotorcert::bench {

/// Batch sizes of a full run: one call, a small batch, an in-cache batch, a streaming batch.
inline const std::vector<std::size_t> kDefaultSizes = {1, 64, 4096, 65536};
/// Sizes of a --quick run.
inline const std::vector<std::size_t> kQuickSizes = {64, 4096};
/// Batches of at least this many elements stream from memory (buffers.hpp).
inline constexpr std::size_t kStreamingSize = 65536;
/// --benchmark_min_time (seconds) when the command line gives none: full and --quick runs.
/// A full run over every implementation and op must stay well under 5 minutes on 2 cores.
inline constexpr double kDefaultMinTime = 0.05;
inline constexpr double kQuickMinTime = 0.01;
/// Repetitions of every frame benchmark (full and --quick runs): the report's paper-claim verdicts
/// compare the ranges of the repetitions.
inline constexpr int kFrameRepetitions = 7;
inline constexpr int kQuickFrameRepetitions = 5;

struct Options {
  bool quick = false;
  std::vector<std::size_t> sizes = kDefaultSizes;
  std::size_t stream_bytes = 0;  // bytes a streaming benchmark cycles through; 0 = machine default
  double min_time = kDefaultMinTime;
  bool min_time_given = false;  // --benchmark_min_time was on the command line
  std::vector<std::string> plugins;  // --plugin=PATH: third-party tables timed beside the built-in ones
};

struct CommandLine {
  Options options;
  std::vector<std::string> args;  // for benchmark::Initialize: argv[0], Google Benchmark flags
  std::string error;              // non-empty: a bad flag of ours
  bool help = false;
};

/// Splits argv into our flags and Google Benchmark's, adding --benchmark_min_time=<default>
/// (kDefaultMinTime, or kQuickMinTime with --quick) unless the command line sets it.
CommandLine parse_command_line(int argc, char** argv);

/// Usage of our flags, for --help (Google Benchmark prints its own after it).
std::string usage();

}  // namespace rotorcert::bench
