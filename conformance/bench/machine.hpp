// What the benchmarks need to know about the machine beyond Google Benchmark's own context
// (which already records CPUs, frequency and every cache level): the CPU model and the size of
// the last-level cache, read from Linux's /proc and /sys.
#pragma once

#include <cstddef>
#include <string>

namespace rotorcert::bench {

/// "model name" of /proc/cpuinfo, or "unknown".
std::string cpu_model();

/// Size in bytes of the largest cache of cpu0 (/sys/devices/system/cpu/cpu0/cache/index*/size),
/// or 0 where it cannot be read.
std::size_t last_level_cache_bytes();

/// Bytes a streaming benchmark cycles through by default: twice the last-level cache, so that
/// every buffer set has been evicted before it is used again, and at least 64 MiB.
std::size_t default_stream_bytes();

}  // namespace rotorcert::bench
