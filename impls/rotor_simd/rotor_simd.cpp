// rotor_simd: batched rotor kernels in binary32 on Google Highway 1.0.3, with runtime dispatch.
//
// One concern per file (in the manner of klein's headers and Highway's -inl.h convention):
//   shared.hpp          shared scalar code (compiled once): the dispatch table type, the exact
//                       sign of a dot product, binary64 fallbacks for far-out lanes;
//   layout-inl.h        per target: SoA types and the data-layout transform (AoS ABI arrays <->
//                       SoA lanes), padded tails;
//   kernels-inl.h       per target: the SoA math kernels;
//   fast_paths-inl.h    per target: the fast paths of slerp, nlerp and QLB (k = 4) for blocks of
//                       ordinary inputs;
//   batch-inl.h         per target: the batch loops;
//   rotor_simd.cpp      this file: compiles the -inl.h files once per Highway target
//                       (foreach_target.h) and holds the dispatch (compiled once): Highway's HWY_DYNAMIC_DISPATCH picks the default target, an
//      explicit table of the compiled targets lets select_target / ROTORCERT_SIMD_TARGET force one;
//      with the default target, a batch's tail shorter than one block (a single-element call is
//      all tail) runs on the one-lane SCALAR target when it is one or two elements, else on the
//      narrowest SIMD target (split_tail).
//
// The rotor R = Phi(q) = w - x e23 - y e31 - z e12 (Q2R-1) is stored by its quaternion
// coefficients: the sandwich R v ~R, the product Phi(a)Phi(b) and the rotor log/exp are written
// in that view (they are the same numbers), so no sign conversion happens at the ABI boundary.
//
// Edge outcomes (EDGE-5..9) are computed branch-free with masks: every kernel computes a
// `bad` lane mask (zero or non-finite quaternion, non-finite vector or t, bad weights) and
// poisons that lane's outputs with quiet NaN and status RC_DOMAIN_ERROR. Non-unit inputs are
// scaled by an exact power of two near their largest |component| before any square is taken,
// so no input the format holds overflows or underflows (NORM-1, EDGE-5, EDGE-8). The fast
// paths (2b') skip all of that for blocks whose every lane is ordinary (unit inputs, t in
// [0, 1], ...) and hand any other block to these general kernels.

#include "rotor/rotor3.hpp"  // from_matrix: the scalar Cl(3,0) code of rotor_m1 / rotor_m2
#include "rotor_simd/shared.hpp"

// ---- per-target code: the -inl.h files, once per Highway target --------------------------------
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "rotor_simd/rotor_simd.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "rotor_simd/batch-inl.h"

HWY_BEFORE_NAMESPACE();
namespace rotorcert::rotor_simd::HWY_NAMESPACE {

const Kernels* GetKernels() {
  static const Kernels k{hwy::TargetName(HWY_TARGET), HWY_TARGET, hn::Lanes(D()), &Normalize, &Compose, &ApplyVector,
                         &ToMatrix, &Inverse, &ToAxisAngle, &FromAxisAngle, &Log, &Exp, &Slerp, &Nlerp,
                         &BlendQlb, &BlendLog};
  return &k;
}

}  // namespace rotorcert::rotor_simd::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

// ---- dispatch (compiled once) -------------------------------------------------------------------------------
#if HWY_ONCE
namespace rotorcert::rotor_simd {

HWY_EXPORT(GetKernels);

namespace {

using GetKernelsFn = const Kernels* (*)();

/// Every target compiled into this file, worst first (HWY_CHOOSE_* is nullptr for a target
/// that this Highway build and compiler did not compile).
const GetKernelsFn kCompiled[] = {HWY_CHOOSE_FALLBACK(GetKernels), HWY_CHOOSE_SSSE3(GetKernels),
                                  HWY_CHOOSE_SSE4(GetKernels),     HWY_CHOOSE_AVX2(GetKernels),
                                  HWY_CHOOSE_AVX3(GetKernels),     HWY_CHOOSE_AVX3_DL(GetKernels)};
constexpr std::size_t kMaxTargets = sizeof(kCompiled) / sizeof(kCompiled[0]);

struct State {
  const Kernels* runnable[kMaxTargets] = {};  // compiled and supported by this CPU, worst first
  std::size_t count = 0;
  const Kernels* fallback_default = nullptr;  // Highway's own choice
  const Kernels* env_default = nullptr;       // ROTORCERT_SIMD_TARGET, if it names a runnable target
  const Kernels* narrowest = nullptr;         // the runnable SIMD target with the fewest lanes
  const Kernels* one_lane = nullptr;          // HWY_SCALAR: the same kernels one element at a time
  std::atomic<const Kernels*> active{nullptr};
  std::atomic<bool> forced{false};            // a target chosen by select_target or the environment
};

/// The names of the runnable targets, NULL-terminated (rc_impl::simd_targets). Filled once.
const char* g_target_names[kMaxTargets + 1] = {};

const Kernels* find(const State& s, const char* name) {
  for (std::size_t i = 0; i < s.count; ++i)
    if (std::strcmp(s.runnable[i]->name, name) == 0) return s.runnable[i];
  return nullptr;
}

State& state() {
  // A static object, not a heap one: State is trivially destructible, so nothing runs at exit,
  // and a dlclose'd plugin leaves nothing behind (a `new State` leaked 80 bytes per unload).
  static State s;
  static const bool filled = [] {
    State* st = &s;
    const std::int64_t supported = hwy::SupportedTargets();
    for (GetKernelsFn f : kCompiled) {
      if (f == nullptr) continue;
      const Kernels* k = f();
      const bool fallback = (k->target == HWY_SCALAR || k->target == HWY_EMU128);
      if (fallback || (supported & k->target) != 0) st->runnable[st->count++] = k;
    }
    for (std::size_t i = 0; i < st->count; ++i) {
      g_target_names[i] = st->runnable[i]->name;
      const Kernels* k = st->runnable[i];
      const bool simd = k->target != HWY_SCALAR && k->target != HWY_EMU128;
      if (simd && (st->narrowest == nullptr || k->lanes <= st->narrowest->lanes)) st->narrowest = k;  // best of the narrowest
      if (k->target == HWY_SCALAR) st->one_lane = k;
    }
    st->fallback_default = HWY_DYNAMIC_DISPATCH(GetKernels)();
    if (const char* env = std::getenv("ROTORCERT_SIMD_TARGET"); env != nullptr && *env != '\0') {
      st->env_default = find(*st, env);
      if (st->env_default == nullptr)
        std::fprintf(stderr, "rotor_simd: ROTORCERT_SIMD_TARGET=%s is not a runnable target; using %s\n", env,
                     st->fallback_default->name);
    }
    st->active.store(st->env_default ? st->env_default : st->fallback_default);
    st->forced.store(st->env_default != nullptr);
    return true;
  }();
  (void)filled;
  return s;
}

// Fill the target list at load time (dlopen runs this too), so simd_targets is complete before
// any hook is called.
const bool g_init = (state(), true);

inline const Kernels& active() { return *state().active.load(std::memory_order_relaxed); }

/// Tails of at most this many elements run on the one-lane target: a SIMD target computes a tail
/// as a whole block through padded copies of the inputs (on AVX-512 with SSE4 for the tail, a
/// single-element normalize or nlerp took several times as long as on SCALAR), and one lane
/// computes each element alone, so from three elements on the narrowest SIMD block is cheaper.
constexpr std::size_t kOneLaneTail = 2;

/// Runs a batch as call(kernels, first, count): the whole batch on the active target, except that
/// with the default target a tail shorter than its block (n mod lanes elements; a single-element
/// call is all tail) runs on the one-lane target (kOneLaneTail elements at most) or on the
/// narrowest SIMD target, if it is narrower than the active one. A forced target
/// (select_target, ROTORCERT_SIMD_TARGET) runs everything itself, so that the tests of each
/// target see its own tail code.
template <class Call>
int split_tail(std::size_t n, const Call& call) {
  State& s = state();
  const Kernels& wide = *s.active.load(std::memory_order_relaxed);
  if (s.forced.load(std::memory_order_relaxed) || wide.lanes == 1) return call(wide, 0, n);
  const std::size_t full = n - n % wide.lanes;
  if (full != 0)
    if (const int rc = call(wide, 0, full); rc != 0) return rc;
  if (full == n) return 0;
  const std::size_t tail = n - full;
  const Kernels* k = &wide;
  if (s.one_lane != nullptr && tail <= kOneLaneTail) k = s.one_lane;
  else if (s.narrowest != nullptr && s.narrowest->lanes < wide.lanes) k = s.narrowest;
  return call(*k, full, tail);
}

}  // namespace

/// The implementation struct behind the "rotor_simd" table (binary32).
struct RotorSimd {
  using Scalar = float;
  static constexpr const char* name = "rotor_simd";
  static constexpr const char* version = "1.0.0 (Google Highway 1.0.3)";
  static constexpr const char* description =
      "Batched SoA rotor kernels in binary32 on Google Highway with runtime dispatch "
      "(scalar/EMU128, SSSE3, SSE4, AVX2, AVX-512)";
  static constexpr std::uint32_t levels = RC_LEVEL_CORE | RC_LEVEL_INTERP | RC_LEVEL_BLEND | RC_LEVEL_ROBUST;
  static constexpr const char* const clauses[] = {
      // Core
      "QUAT-2", "AXANG-1", "AXANG-2", "NORM-1", "COMPOSE-1", "INV-1", "APPLY-1", "APPLY-2", "APPLY-3", "MAT-1",
      "MAT-2",
      // Interp
      "LOG-1", "LOG-2", "EXP-1", "EXP-2", "SLERP-1", "SLERP-2", "SLERP-3", "SLERP-4", "SLERP-5", "NLERP-1",
      // Blend
      "QLB-1", "LOGBLEND-1",
      // Robust
      "MAT-3", "EDGE-1", "EDGE-2", "EDGE-3", "EDGE-4", "EDGE-5", "EDGE-6", "EDGE-7", "EDGE-8", "EDGE-9", nullptr};

  static int normalize_batch(std::size_t n, const float* q, float* out, std::uint8_t* status) {
    return split_tail(n, [&](const Kernels& k, std::size_t i, std::size_t m) {
      return k.normalize(m, q + 4 * i, out + 4 * i, status + i);
    });
  }
  static int compose_batch(std::size_t n, const float* a, const float* b, float* out, std::uint8_t* status) {
    return split_tail(n, [&](const Kernels& k, std::size_t i, std::size_t m) {
      return k.compose(m, a + 4 * i, b + 4 * i, out + 4 * i, status + i);
    });
  }
  static int apply_vector_batch(std::size_t n, const float* q, const float* v, float* out, std::uint8_t* status) {
    return split_tail(n, [&](const Kernels& k, std::size_t i, std::size_t m) {
      return k.apply_vector(m, q + 4 * i, v + 3 * i, out + 3 * i, status + i);
    });
  }
  static int apply_bivector_batch(std::size_t n, const float* q, const float* b, float* out, std::uint8_t* status) {
    return apply_vector_batch(n, q, b, out, status);  // I is central: R (I b) ~R = I (R b ~R)
  }
  /// APPLY-3: R (s I) ~R = s I for every rotor; only the domain is checked.
  static int apply_trivector_batch(std::size_t n, const float* q, const float* s, float* out, std::uint8_t* status) {
    for (std::size_t i = 0; i < n; ++i) {
      bool ok = std::isfinite(s[i]);
      bool nonzero = false;
      for (int c = 0; c < 4; ++c) {
        ok = ok && std::isfinite(q[i * 4 + c]);
        nonzero = nonzero || q[i * 4 + c] != 0;
      }
      ok = ok && nonzero;
      out[i] = ok ? s[i] : std::numeric_limits<float>::quiet_NaN();
      status[i] = ok ? RC_OK : RC_DOMAIN_ERROR;
    }
    return 0;
  }
  static int inverse_batch(std::size_t n, const float* q, float* out, std::uint8_t* status) {
    return split_tail(n, [&](const Kernels& k, std::size_t i, std::size_t m) {
      return k.inverse(m, q + 4 * i, out + 4 * i, status + i);
    });
  }
  static int to_axis_angle_batch(std::size_t n, const float* q, float* angle, float* axis, std::uint8_t* status) {
    return split_tail(n, [&](const Kernels& k, std::size_t i, std::size_t m) {
      return k.to_axis_angle(m, q + 4 * i, angle + i, axis + 3 * i, status + i);
    });
  }
  static int from_axis_angle_batch(std::size_t n, const float* angle, const float* axis, float* out,
                                   std::uint8_t* status) {
    return split_tail(n, [&](const Kernels& k, std::size_t i, std::size_t m) {
      return k.from_axis_angle(m, angle + i, axis + 3 * i, out + 4 * i, status + i);
    });
  }
  /// MAT-2, MAT-3: element by element in scalar code, the Cl(3,0) rotors' (impls/rotor/rotor3.hpp):
  /// Higham's polar iteration runs a data-dependent number of steps and Shepperd's pivot
  /// branches four ways per element, which SIMD lanes would all pay for.
  static rotorcert::impl::Status from_matrix(const rotorcert::impl::Mat3<float>& m, rotorcert::impl::Quat<float>& out) {
    const std::optional<rotor::Rotor3<float>> r = rotor::rotor_from_matrix(m);
    if (!r) return rotorcert::impl::Status::domain_error;
    out = rotor::canonical_sign(rotor::PhiReadout::out(*r));
    return rotorcert::impl::Status::ok;
  }
  static int to_matrix_batch(std::size_t n, const float* q, float* out, std::uint8_t* status) {
    return split_tail(n, [&](const Kernels& k, std::size_t i, std::size_t m) {
      return k.to_matrix(m, q + 4 * i, out + 9 * i, status + i);
    });
  }
  static int log_batch(std::size_t n, const float* q, float* out, std::uint8_t* status) {
    return split_tail(n, [&](const Kernels& k, std::size_t i, std::size_t m) {
      return k.log(m, q + 4 * i, out + 3 * i, status + i);
    });
  }
  static int exp_batch(std::size_t n, const float* v, float* out, std::uint8_t* status) {
    return split_tail(n, [&](const Kernels& k, std::size_t i, std::size_t m) {
      return k.exp(m, v + 3 * i, out + 4 * i, status + i);
    });
  }
  static int slerp_batch(std::size_t n, const float* a, const float* b, const float* t, float* out,
                         std::uint8_t* status) {
    return split_tail(n, [&](const Kernels& k, std::size_t i, std::size_t m) {
      return k.slerp(m, a + 4 * i, b + 4 * i, t + i, out + 4 * i, status + i);
    });
  }
  static int nlerp_batch(std::size_t n, const float* a, const float* b, const float* t, float* out,
                         std::uint8_t* status) {
    return split_tail(n, [&](const Kernels& k, std::size_t i, std::size_t m) {
      return k.nlerp(m, a + 4 * i, b + 4 * i, t + i, out + 4 * i, status + i);
    });
  }
  static int blend_qlb_batch(std::size_t n, std::size_t k, const float* q, const float* w, float* out,
                             std::uint8_t* status) {
    try {
      return split_tail(n, [&](const Kernels& ks, std::size_t i, std::size_t m) {
        return ks.blend_qlb(m, k, q + 4 * k * i, w + k * i, out + 4 * i, status + i);
      });
    } catch (...) {  // the tail buffer could not be allocated
      return 1;
    }
  }
  static int blend_log_batch(std::size_t n, std::size_t k, const float* q, const float* w, float* out,
                             std::uint8_t* status) {
    try {
      return split_tail(n, [&](const Kernels& ks, std::size_t i, std::size_t m) {
        return ks.blend_log(m, k, q + 4 * k * i, w + k * i, out + 4 * i, status + i);
      });
    } catch (...) {
      return 1;
    }
  }

  // SIMD dispatch hooks (rc_impl): the list is filled at load time.
  static constexpr const char* const* simd_targets = g_target_names;
  static int select_target(const char* target) {
    State& s = state();
    if (target == nullptr) {
      s.active.store(s.env_default ? s.env_default : s.fallback_default);
      s.forced.store(s.env_default != nullptr);
      return 0;
    }
    const Kernels* k = find(s, target);
    if (k == nullptr) return 1;
    s.active.store(k);
    s.forced.store(true);
    return 0;
  }
  static const char* current_target() { return active().name; }
};

}  // namespace rotorcert::rotor_simd

ROTORCERT_DEFINE_ENTRY(rotor_simd, ::rotorcert::rotor_simd::RotorSimd)

#endif  // HWY_ONCE
