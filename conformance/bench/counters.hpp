// The counters and label every element-wise benchmark (op/*, baseline/*) reports, so that the
// JSON alone carries what the report needs:
//   items_per_second   elements per second (SetItemsProcessed)
//   bytes_per_second   bytes_per_element x elements per second (SetBytesProcessed)
//   ns_per_element     CPU nanoseconds per element
//   flops_per_element  nominal flops of one element (op_cost.hpp)
//   bytes_per_element  bytes one element reads and writes in its layout (op_cost.hpp)
//   n, k               batch size, influences per element (1 for the other ops)
//   sets               buffer sets cycled through (1 in cache, more when streaming)
//   working_set_bytes  bytes of all the sets together
//   generated_mul, generated_add, generated_div, generated_sqrt
//                      only for rotor_gen: the arithmetic of the op's fast path as its generator
//                      counted it (impls/rotor_gen, kAbiOpCounts), so that the report can set the
//                      algebra's cost beside the time
// and the label "impl=<table> scalar=<float|double> op=<op> n=<n> k=<k> target=<SIMD target|none>".
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

#include <benchmark/benchmark.h>

namespace rotorcert::bench {

struct ElementBench {
  std::string impl, scalar, op, target;
  std::size_t n = 0, k = 1;
  double flops_per_element = 0, bytes_per_element = 0;
  std::size_t sets = 1, working_set_bytes = 0;
  /// The generated fast path's operation counts, where the table has them (rotor_gen).
  struct Generated {
    double mul = 0, add = 0, div = 0, sqrt = 0;
  };
  std::optional<Generated> generated;
};

inline void report(benchmark::State& state, const ElementBench& b) {
  using benchmark::Counter;
  const auto elements = static_cast<std::int64_t>(state.iterations()) * static_cast<std::int64_t>(b.n);
  state.SetItemsProcessed(elements);
  state.SetBytesProcessed(static_cast<std::int64_t>(static_cast<double>(elements) * b.bytes_per_element));
  // n * 1e-9 per iteration, times iterations, per second, inverted: seconds/element in ns.
  state.counters["ns_per_element"] =
      Counter(static_cast<double>(b.n) * 1e-9, Counter::kIsIterationInvariantRate | Counter::kInvert);
  state.counters["flops_per_element"] = b.flops_per_element;
  state.counters["bytes_per_element"] = b.bytes_per_element;
  state.counters["n"] = static_cast<double>(b.n);
  state.counters["k"] = static_cast<double>(b.k);
  state.counters["sets"] = static_cast<double>(b.sets);
  state.counters["working_set_bytes"] = static_cast<double>(b.working_set_bytes);
  if (b.generated) {
    state.counters["generated_mul"] = b.generated->mul;
    state.counters["generated_add"] = b.generated->add;
    state.counters["generated_div"] = b.generated->div;
    state.counters["generated_sqrt"] = b.generated->sqrt;
  }
  state.SetLabel("impl=" + b.impl + " scalar=" + b.scalar + " op=" + b.op + " n=" + std::to_string(b.n) +
                 " k=" + std::to_string(b.k) + " target=" + b.target);
}

}  // namespace rotorcert::bench
