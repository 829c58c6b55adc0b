// op/<op>/<impl>/<float|double>/<n>: one benchmark per non-NULL op of every built-in table and
// batch size. Each times one batched call through the C ABI on seeded valid inputs
// (inputs.hpp) prepared outside the timed loop, cycling over buffer sets when streaming
// (workspace.hpp), and reports the counters of counters.hpp.
#include <string>
#include <string_view>
#include <vector>

#include <benchmark/benchmark.h>
#include <rotorcert/registry.hpp>
#include <rotor_gen_kernels.hpp>  // kAbiOpCounts: the generated rotor's arithmetic per op

#include "counters.hpp"
#include "inputs.hpp"
#include "op_call.hpp"
#include "op_cost.hpp"
#include "op_layout.hpp"
#include "options.hpp"
#include "register.hpp"
#include "workspace.hpp"

namespace rotorcert::bench {
namespace {

template <class S>
constexpr const char* scalar_name() {
  return sizeof(S) == 4 ? "float" : "double";
}

template <class S>
void run_op(benchmark::State& state, const rc_impl& table, OpId id, std::size_t n,
            std::size_t stream_bytes, const std::string& key) {
  const OpSpec& op = op_spec(id);
  const std::size_t k = op.nway ? kInfluences : 1;

  SetLayout layout;
  std::size_t in_at[kMaxInputs] = {}, out_at[kMaxOutputs] = {};
  for (std::size_t j = 0; j < op.n_in; ++j) in_at[j] = layout.add(array_scalars(op.in[j], n, k) * sizeof(S));
  for (std::size_t j = 0; j < op.n_out; ++j) out_at[j] = layout.add(array_scalars(op.out[j], n, k) * sizeof(S));
  const std::size_t status_at = layout.add(n);
  const std::size_t sets = set_count(n, layout.size(), stream_bytes, kStreamingSize);

  std::vector<CallArgs<S>> args(sets);
  auto point_args = [&](std::byte* base) {
    for (std::size_t s = 0; s < sets; ++s) {
      std::byte* set = base + s * layout.size();
      CallArgs<S>& a = args[s];
      a.n = n;
      a.k = k;
      for (std::size_t j = 0; j < op.n_in; ++j) a.in[j] = reinterpret_cast<const S*>(set + in_at[j]);
      for (std::size_t j = 0; j < op.n_out; ++j) a.out[j] = reinterpret_cast<S*>(set + out_at[j]);
      a.status = reinterpret_cast<std::uint8_t*>(set + status_at);
    }
  };

  bool ran = true;
  with_call<S>(table, id, [&](auto call) {
    Workspace& ws = workspace();
    if (std::byte* base = ws.reuse(key)) {
      point_args(base);
    } else {
      base = ws.fresh(key, sets * layout.size());
      point_args(base);
      S* in[kMaxInputs] = {};
      for (std::size_t j = 0; j < op.n_in; ++j) in[j] = reinterpret_cast<S*>(base + in_at[j]);
      fill_inputs<S>(op, n, k, in);
      replicate(base, layout.size(), sets);
      // The inputs are valid, so the op must run and say OK for every element; timing an error
      // path would measure something else.
      const int rc = call(args[0]);
      std::size_t bad = 0;
      for (std::size_t i = 0; i < n; ++i) bad += args[0].status[i] != RC_OK;
      if (rc != 0 || bad != 0) {
        ws.forget();
        state.SkipWithError(rc != 0 ? ("call returned " + std::to_string(rc)).c_str()
                                    : (std::to_string(bad) + " of " + std::to_string(n) +
                                       " valid elements got a non-OK status")
                                          .c_str());
        ran = false;
        return;
      }
    }

    std::size_t s = 0;
    for (auto _ : state) {
      const int rc = call(args[s]);
      benchmark::DoNotOptimize(rc);  // the const overload: an input operand, nothing to drop
      benchmark::ClobberMemory();  // the outputs count as read: nothing may be dropped or hoisted
      if (++s == sets) s = 0;
    }
  });
  if (!ran) return;

  ElementBench b;
  b.impl = table.name;
  b.scalar = scalar_name<S>();
  b.op = std::string(op.name);
  b.target = table.current_target != nullptr ? table.current_target() : "none";
  b.n = n;
  b.k = k;
  b.flops_per_element = flops_per_element(id, k);
  b.bytes_per_element = static_cast<double>(bytes_per_element(op, sizeof(S), k));
  b.sets = sets;
  b.working_set_bytes = sets * layout.size();
  if (std::string_view(table.name) == "rotor_gen")
    for (const rotor_gen::OpCount& c : rotor_gen::kAbiOpCounts)
      if (b.op == c.kernel) b.generated = ElementBench::Generated{double(c.mul), double(c.add), double(c.div), double(c.sqrt)};
  report(state, b);
}

template <class S>
void register_table(const rc_impl& table, const RunConfig& config) {
  for (const OpSpec& op : kTimedOps) {
    if (!has_op(table, op.id)) continue;
    for (const std::size_t n : config.sizes) {
      const std::string name = "op/" + std::string(op.name) + "/" + table.name + "/" + scalar_name<S>() + "/" +
                               std::to_string(n);
      const std::size_t stream_bytes = config.stream_bytes;
      benchmark::RegisterBenchmark(name.c_str(), [&table, id = op.id, n, stream_bytes, name](benchmark::State& st) {
        run_op<S>(st, table, id, n, stream_bytes, name);
      });
    }
  }
}

}  // namespace

void register_op_benchmarks(const RunConfig& config, const std::vector<const rc_impl*>& extra) {
  std::vector<const rc_impl*> tables = impl::builtin_tables();
  tables.insert(tables.end(), extra.begin(), extra.end());
  for (const rc_impl* t : tables) {
    if (t->scalar == RC_SCALAR_FLOAT32) register_table<float>(*t, config);
    if (t->scalar == RC_SCALAR_FLOAT64) register_table<double>(*t, config);
  }
}

}  // namespace rotorcert::bench
