// The roofline's roofs, for one core (every op benchmark is single-threaded):
//   roofline/peak_fma/<float|double>  kFmaChains independent FMA chains in registers on the best
//                                     Highway target; counter flops_per_second (an FMA = 2 flops)
//   roofline/bandwidth/read           sum of an array of stream_bytes
//   roofline/bandwidth/triad          a = b + s c over three arrays of stream_bytes each
// bytes_per_second of the bandwidth benchmarks counts the bytes the kernel reads and writes
// (read: 8 per element; triad: 24), not write-allocate traffic: the STREAM convention, the same
// as op_cost.hpp's bytes_per_element. The arrays are twice the last-level cache by default
// (--stream-mib), so every pass comes from memory.
#include <string>

#include <benchmark/benchmark.h>

#include "register.hpp"
#include "roofline_kernels.hpp"
#include "workspace.hpp"

namespace rotorcert::bench {
namespace {

/// Rounds of the FMA kernel per iteration: about 100k FMA issues, tens of microseconds.
constexpr std::size_t kFmaRounds = std::size_t{1} << 14;

template <class T>
void peak_fma(benchmark::State& state) {
  // Runtime values so the compiler cannot fold the chains. Read through volatile, not passed
  // through benchmark::DoNotOptimize(T&): with GCC 12 and Google Benchmark 1.7.1 its "+m,r"
  // constraint lets GCC drop the store, so m and a arrived as whatever the stack slot held
  // (seen: 0, and FMA chains 200x slower, as on subnormals).
  static volatile T m_source = T(0.999), a_source = T(0.001);
  const T m = m_source, a = a_source;
  double flops = 0;
  for (auto _ : state) {
    const roofline::FmaRun run = sizeof(T) == 4 ? roofline::fma_f32(kFmaRounds, static_cast<float>(m), static_cast<float>(a))
                                                : roofline::fma_f64(kFmaRounds, m, a);
    benchmark::DoNotOptimize(run.checksum);
    flops += run.flops;
  }
  state.counters["flops_per_second"] = benchmark::Counter(flops, benchmark::Counter::kIsRate);
  state.counters["chains"] = static_cast<double>(roofline::kFmaChains);
  state.counters["lanes"] = static_cast<double>(roofline::lanes_f32() * 4 / sizeof(T));
  state.SetLabel(std::string("target=") + roofline::target_name());
}

enum class Stream { read, triad };

void bandwidth(benchmark::State& state, Stream kind, std::size_t stream_bytes) {
  const std::size_t n = stream_bytes / sizeof(double);
  const std::size_t array_bytes = n * sizeof(double);
  const std::string key = "roofline/bandwidth";  // read and triad share the arrays
  Workspace& ws = workspace();
  std::byte* base = ws.reuse(key);
  if (base == nullptr) {
    base = ws.fresh(key, 3 * array_bytes);
    double* p = reinterpret_cast<double*>(base);
    for (std::size_t i = 0; i < 3 * n; ++i) p[i] = 1.0 + static_cast<double>(i % 7);  // touches every page
  }
  double* a = reinterpret_cast<double*>(base);
  double* b = a + n;
  double* c = b + n;
  for (auto _ : state) {
    if (kind == Stream::read) {
      const double sum = roofline::read_sum(b, n);
      benchmark::DoNotOptimize(sum);
    } else {
      roofline::triad(a, b, c, 0.5, n);
      benchmark::ClobberMemory();
    }
  }
  const double per_pass = static_cast<double>(kind == Stream::read ? array_bytes : 3 * array_bytes);
  state.SetBytesProcessed(static_cast<std::int64_t>(per_pass * static_cast<double>(state.iterations())));
  state.counters["array_bytes"] = static_cast<double>(array_bytes);
  state.SetLabel(std::string("target=") + roofline::target_name());
}

}  // namespace

void register_roofline(const RunConfig& config) {
  benchmark::RegisterBenchmark("roofline/peak_fma/float", peak_fma<float>);
  benchmark::RegisterBenchmark("roofline/peak_fma/double", peak_fma<double>);
  const std::size_t stream_bytes = config.stream_bytes;
  benchmark::RegisterBenchmark("roofline/bandwidth/read",
                               [stream_bytes](benchmark::State& st) { bandwidth(st, Stream::read, stream_bytes); });
  benchmark::RegisterBenchmark("roofline/bandwidth/triad",
                               [stream_bytes](benchmark::State& st) { bandwidth(st, Stream::triad, stream_bytes); });
}

}  // namespace rotorcert::bench
