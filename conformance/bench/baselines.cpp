// baseline/glm_slerp/<float|double>/<n> and baseline/glm_mix/...: the denominators of REPORT-2's
// speed targets. A plain loop out[i] = glm::slerp(a[i], b[i], t[i]) (or glm::mix) over AoS
// arrays of glm::quat / glm::dquat, compiled here with the project's flags (no -march), on the
// slerp benchmark's inputs (same generator and seed: op/slerp/<impl>/<scalar>/<n> sees the same
// values). GLM 0.9.9.8's mix on quaternions is slerp without the shorter-arc flip; both count
// the slerp formula's flops. Bytes per element: a, b, out (4 scalars each) and t; there is no
// status byte.
#include <string>
#include <vector>

#include <benchmark/benchmark.h>
#include <glm/gtc/quaternion.hpp>

#include "counters.hpp"
#include "inputs.hpp"
#include "op_cost.hpp"
#include "op_layout.hpp"
#include "options.hpp"
#include "register.hpp"
#include "workspace.hpp"

namespace rotorcert::bench {
namespace {

enum class GlmOp { slerp, mix };

template <class Q>
void run_glm(benchmark::State& state, GlmOp which, std::size_t n, std::size_t stream_bytes, const std::string& key) {
  using S = typename Q::value_type;
  static_assert(std::is_trivially_copyable_v<Q>, "buffer sets are replicated with memcpy");

  SetLayout layout;
  const std::size_t a_at = layout.add(n * sizeof(Q)), b_at = layout.add(n * sizeof(Q)), t_at = layout.add(n * sizeof(S)),
                    out_at = layout.add(n * sizeof(Q));
  const std::size_t sets = set_count(n, layout.size(), stream_bytes, kStreamingSize);

  struct Arrays {
    const Q* a;
    const Q* b;
    const S* t;
    Q* out;
  };
  std::vector<Arrays> sets_of(sets);
  Workspace& ws = workspace();
  std::byte* base = ws.reuse(key);
  const bool fresh = base == nullptr;
  if (fresh) base = ws.fresh(key, sets * layout.size());
  for (std::size_t s = 0; s < sets; ++s) {
    std::byte* set = base + s * layout.size();
    sets_of[s] = {reinterpret_cast<const Q*>(set + a_at), reinterpret_cast<const Q*>(set + b_at),
                  reinterpret_cast<const S*>(set + t_at), reinterpret_cast<Q*>(set + out_at)};
  }
  if (fresh) {
    // The slerp op's inputs in ABI layout [x, y, z, w], converted to GLM's quaternions.
    std::vector<S> a(n * 4), b(n * 4), t(n);
    S* in[kMaxInputs] = {a.data(), b.data(), t.data()};
    fill_inputs<S>(op_spec(OpId::slerp), n, 1, in);
    Q* qa = reinterpret_cast<Q*>(base + a_at);
    Q* qb = reinterpret_cast<Q*>(base + b_at);
    for (std::size_t i = 0; i < n; ++i) {
      new (qa + i) Q(a[i * 4 + 3], a[i * 4], a[i * 4 + 1], a[i * 4 + 2]);  // Q(w, x, y, z)
      new (qb + i) Q(b[i * 4 + 3], b[i * 4], b[i * 4 + 1], b[i * 4 + 2]);
    }
    std::copy(t.begin(), t.end(), reinterpret_cast<S*>(base + t_at));
    replicate(base, layout.size(), sets);
  }

  std::size_t s = 0;
  for (auto _ : state) {
    const Arrays& x = sets_of[s];
    if (which == GlmOp::slerp)
      for (std::size_t i = 0; i < n; ++i) x.out[i] = glm::slerp(x.a[i], x.b[i], x.t[i]);
    else
      for (std::size_t i = 0; i < n; ++i) x.out[i] = glm::mix(x.a[i], x.b[i], x.t[i]);
    benchmark::DoNotOptimize(x.out);
    benchmark::ClobberMemory();  // the outputs count as read: the loop may not be dropped
    if (++s == sets) s = 0;
  }

  ElementBench b;
  b.impl = "glm";
  b.scalar = sizeof(S) == 4 ? "float" : "double";
  b.op = which == GlmOp::slerp ? "slerp" : "mix";
  b.target = "none";
  b.n = n;
  b.flops_per_element = flops_per_element(OpId::slerp, 1);
  b.bytes_per_element = static_cast<double>(3 * sizeof(Q) + sizeof(S));
  b.sets = sets;
  b.working_set_bytes = sets * layout.size();
  report(state, b);
}

template <class Q>
void register_glm(const char* scalar, const RunConfig& config) {
  for (const GlmOp which : {GlmOp::slerp, GlmOp::mix})
    for (const std::size_t n : config.sizes) {
      const std::string name = std::string("baseline/glm_") + (which == GlmOp::slerp ? "slerp" : "mix") + "/" + scalar +
                               "/" + std::to_string(n);
      const std::size_t stream_bytes = config.stream_bytes;
      benchmark::RegisterBenchmark(name.c_str(), [which, n, stream_bytes, name](benchmark::State& st) {
        run_glm<Q>(st, which, n, stream_bytes, name);
      });
    }
}

}  // namespace

void register_baselines(const RunConfig& config) {
  register_glm<glm::quat>("float", config);
  register_glm<glm::dquat>("double", config);
}

}  // namespace rotorcert::bench
