// The C++ face of the implementation interface.
//
// A built-in implementation is a struct of static functions, one per operation it supports,
// each working on ONE element with the ABI's array layouts (impl_abi.h):
//
//   struct GlmQuat {
//     using Scalar = float;
//     static rc::Status normalize(const rc::Quat<float>& q, rc::Quat<float>& out);
//     static rc::Status slerp(const rc::Quat<float>& a, const rc::Quat<float>& b, const float& t,
//                             rc::Quat<float>& out);
//     static rc::Status blend_qlb(std::span<const rc::Quat<float>> q, std::span<const float> w,
//                                 rc::Quat<float>& out);
//     ...
//   };
//
// Inputs are const references and come first, outputs are non-const references; scalars are
// plain S. make_ops<Impl>() turns whatever subset is defined into the batched C table (a
// missing function becomes a NULL pointer: NOT_SUPPORTED; make_ops3<Impl>() does the same for the
// operations of ABI version 3: to_angle, to_axis, sqrt, dq_to_rotation_translation, and make_ops4 for
// those of version 4: dq_log, dq_exp, rigid_compose, rigid_apply, rigid_inverse). An implementation that batches
// itself (SIMD) defines `static int NAME_batch(...)` with the C signature instead, and that is
// used as is.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include "impl_abi.h"

namespace rotorcert::impl {

enum class Status : std::uint8_t { ok = RC_OK, domain_error = RC_DOMAIN_ERROR };

/// EDGE-9: a weight set is usable when it is not empty, every weight is finite and >= 0 (-0
/// counts as 0) and some weight is > 0. For glue that writes a blend around a library that has
/// none: the blend rules are the glue's, the arithmetic the library's.
template <class S>
bool usable_weights(std::span<const S> w) {
  bool positive = false;
  for (const S& x : w) {
    if (!(x >= S(0)) || x == std::numeric_limits<S>::infinity()) return false;  // NaN, negative, +Inf
    positive = positive || x > S(0);
  }
  return positive;
}

/// The pivot of the blend rules (QLB-1, DQ-6): the first influence of positive weight (-0 and
/// NaN are not positive); the last index when there is none (the caller has rejected that set).
template <class S>
std::size_t first_positive_weight(std::span<const S> w) {
  std::size_t p = 0;
  while (p + 1 < w.size() && !(w[p] > S(0))) ++p;
  return p;
}

/// EDGE-9 as the blends that divide by the largest weight check it: the largest weight (their
/// sums are taken over w_i / w_max, so that they cannot overflow), or 0 when the set is empty, a
/// weight is NaN, infinite or negative, or all are zero (-0 counts as 0).
template <class S>
S largest_weight(std::span<const S> w) {
  S largest = 0;
  for (S x : w) {
    if (!(x >= S(0) && x <= std::numeric_limits<S>::max())) return 0;  // NaN, negative, +Inf
    largest = std::max(largest, x);
  }
  return largest;
}

/// The weights' half of a blend fast path's cheap test (EDGE-9): every weight in [0, max] and
/// some > 0. Sets the largest weight and the pivot (first_positive_weight) and returns true;
/// false, leaving them unspecified, sends the element to the checked path.
template <class S>
bool ordinary_weights(std::span<const S> w, S& w_max, std::size_t& pivot) {
  w_max = 0;
  pivot = w.size();
  for (std::size_t i = 0; i < w.size(); ++i) {
    if (!(w[i] >= 0 && w[i] <= std::numeric_limits<S>::max())) return false;  // NaN, < 0, +inf
    if (w[i] > w_max) w_max = w[i];
    if (pivot == w.size() && w[i] > 0) pivot = i;
  }
  return pivot != w.size();
}

template <class S> using Quat = std::array<S, 4>;      // [x, y, z, w]
template <class S> using Vec3 = std::array<S, 3>;      // [x, y, z]; bivectors [e23, e31, e12]
template <class S> using Mat3 = std::array<S, 9>;      // column-major
template <class S> using DualQuat = std::array<S, 8>;  // [real xyzw, dual xyzw]

template <class S> struct OpsFor;
template <> struct OpsFor<float> { using type = rc_ops_f32; };
template <> struct OpsFor<double> { using type = rc_ops_f64; };
template <class S> using Ops = typename OpsFor<S>::type;
template <class S> struct Ops3For;
template <> struct Ops3For<float> { using type = rc_ops3_f32; };
template <> struct Ops3For<double> { using type = rc_ops3_f64; };
template <class S> using Ops3 = typename Ops3For<S>::type;  // the ABI version 3 operations
template <class S> struct Ops4For;
template <> struct Ops4For<float> { using type = rc_ops4_f32; };
template <> struct Ops4For<double> { using type = rc_ops4_f64; };
template <class S> using Ops4 = typename Ops4For<S>::type;  // the ABI version 4 operations

namespace detail {

// How one parameter of an element function maps to an ABI array.
template <class P> struct Param;
template <class S, std::size_t N> struct Param<const std::array<S, N>&> {
  static constexpr bool output = false;
  static constexpr std::size_t stride = N;
  using value_type = std::array<S, N>;
  using pointer = const S*;
  static value_type load(pointer p, std::size_t i) {
    value_type v;
    for (std::size_t j = 0; j < N; ++j) v[j] = p[i * N + j];
    return v;
  }
};
template <class S, std::size_t N> struct Param<std::array<S, N>&> {
  static constexpr bool output = true;
  using value_type = std::array<S, N>;
  using pointer = S*;
  static value_type load(pointer, std::size_t) { return {}; }
  static void store(pointer p, std::size_t i, const value_type& v) {
    for (std::size_t j = 0; j < N; ++j) p[i * N + j] = v[j];
  }
  static void poison(value_type& v) { v.fill(std::numeric_limits<S>::quiet_NaN()); }
};
template <class S> requires std::is_floating_point_v<S> struct Param<const S&> {
  static constexpr bool output = false;
  using value_type = S;
  using pointer = const S*;
  static value_type load(pointer p, std::size_t i) { return p[i]; }
};
template <class S> requires std::is_floating_point_v<S> struct Param<S&> {
  static constexpr bool output = true;
  using value_type = S;
  using pointer = S*;
  static value_type load(pointer, std::size_t) { return S(0); }
  static void store(pointer p, std::size_t i, const value_type& v) { p[i] = v; }
  static void poison(value_type& v) { v = std::numeric_limits<S>::quiet_NaN(); }
};

template <auto Fn, class Signature> struct Elementwise;

/// The batch loop around an element function: load element i of every input, call, store the
/// outputs and the status. On DOMAIN_ERROR every output component is set to a quiet NaN, the
/// one defined outcome of EDGE-6/7/9, so element functions need only return the status.
template <auto Fn, class... P>
struct Elementwise<Fn, Status (*)(P...)> {
  static int run(std::size_t n, typename Param<P>::pointer... ptrs, std::uint8_t* status) {
    for (std::size_t i = 0; i < n; ++i) {
      std::tuple<typename Param<P>::value_type...> values{Param<P>::load(ptrs, i)...};
      const Status s = std::apply(Fn, values);
      finish(i, ptrs..., values, s, std::index_sequence_for<P...>{});
      status[i] = static_cast<std::uint8_t>(s);
    }
    return 0;
  }

 private:
  template <std::size_t... I>
  static void finish(std::size_t i, typename Param<P>::pointer... ptrs,
                     std::tuple<typename Param<P>::value_type...>& values, Status s, std::index_sequence<I...>) {
    (store_one<P>(i, ptrs, std::get<I>(values), s), ...);
  }
  template <class Q>
  static void store_one(std::size_t i, typename Param<Q>::pointer p, typename Param<Q>::value_type& v, Status s) {
    if constexpr (Param<Q>::output) {
      if (s == Status::domain_error) Param<Q>::poison(v);
      Param<Q>::store(p, i, v);
    }
  }
};

/// n-way operations: element i has k influences. Influence arrays are copied into reused
/// buffers and handed over as spans.
template <class S, std::size_t A>
void gather(const S* p, std::size_t i, std::size_t k, std::vector<std::array<S, A>>& out) {
  out.resize(k);
  for (std::size_t j = 0; j < k; ++j)
    for (std::size_t c = 0; c < A; ++c) out[j][c] = p[(i * k + j) * A + c];
}
template <class S>
void gather(const S* p, std::size_t i, std::size_t k, std::vector<S>& out) {
  out.assign(p + i * k, p + i * k + k);
}

template <class S, std::size_t N>
void store_poisonable(S* p, std::size_t i, std::array<S, N> v, Status s) {
  if (s == Status::domain_error) v.fill(std::numeric_limits<S>::quiet_NaN());
  for (std::size_t c = 0; c < N; ++c) p[i * N + c] = v[c];
}

/// Blend shape: (k influences of A scalars, k weights) -> one output of B scalars.
template <auto Fn, class S, std::size_t A, std::size_t B>
int blend(std::size_t n, std::size_t k, const S* x, const S* w, S* out, std::uint8_t* status) {
  std::vector<std::array<S, A>> xs;
  std::vector<S> ws;
  for (std::size_t i = 0; i < n; ++i) {
    gather(x, i, k, xs);
    gather(w, i, k, ws);
    std::array<S, B> r{};
    const Status s = Fn(std::span<const std::array<S, A>>(xs), std::span<const S>(ws), r);
    store_poisonable(out, i, r, s);
    status[i] = static_cast<std::uint8_t>(s);
  }
  return 0;
}

/// Skinning shape: k influences (rotation, translation, weight) and one vertex per element.
template <auto Fn, class S>
int skin(std::size_t n, std::size_t k, const S* q, const S* t, const S* w, const S* v, S* out,
         std::uint8_t* status) {
  std::vector<Quat<S>> qs;
  std::vector<Vec3<S>> ts;
  std::vector<S> ws;
  for (std::size_t i = 0; i < n; ++i) {
    gather(q, i, k, qs);
    gather(t, i, k, ts);
    gather(w, i, k, ws);
    const Vec3<S> vertex{v[i * 3], v[i * 3 + 1], v[i * 3 + 2]};
    Vec3<S> r{};
    const Status s = Fn(std::span<const Quat<S>>(qs), std::span<const Vec3<S>>(ts), std::span<const S>(ws), vertex, r);
    store_poisonable(out, i, r, s);
    status[i] = static_cast<std::uint8_t>(s);
  }
  return 0;
}

/// The strides of a blend element function (k influences of A scalars, k weights -> B scalars).
template <class Fn> struct BlendShape;
template <class S, std::size_t A, std::size_t B>
struct BlendShape<Status (*)(std::span<const std::array<S, A>>, std::span<const S>, std::array<S, B>&)> {
  static constexpr std::size_t in = A, out = B;
};

}  // namespace detail

// For one row of the op list (abi_op_list.h), ROTORCERT_OP_<kind> picks the implementation's batch
// function if it has one (NAME_batch, with the slot's C signature), else its element function
// wrapped in the batch loop of that kind, else leaves the slot NULL (NOT_SUPPORTED).
#define ROTORCERT_OP_ELEM(ops, Impl, name)                                                       \
  if constexpr (requires { &Impl::name##_batch; }) {                                            \
    ops.name = &Impl::name##_batch;                                                              \
  } else if constexpr (requires { &Impl::name; }) {                                              \
    ops.name = &::rotorcert::impl::detail::Elementwise<&Impl::name, decltype(&Impl::name)>::run; \
  }
#define ROTORCERT_OP_BLEND(ops, Impl, name)                                                                  \
  if constexpr (requires { &Impl::name##_batch; }) {                                                         \
    ops.name = &Impl::name##_batch;                                                                          \
  } else if constexpr (requires { &Impl::name; }) {                                                          \
    using Shape = ::rotorcert::impl::detail::BlendShape<decltype(&Impl::name)>;                              \
    ops.name = &::rotorcert::impl::detail::blend<&Impl::name, typename Impl::Scalar, Shape::in, Shape::out>; \
  }
#define ROTORCERT_OP_SKIN(ops, Impl, name)                                             \
  if constexpr (requires { &Impl::name##_batch; }) {                                   \
    ops.name = &Impl::name##_batch;                                                     \
  } else if constexpr (requires { &Impl::name; }) {                                     \
    ops.name = &::rotorcert::impl::detail::skin<&Impl::name, typename Impl::Scalar>;    \
  }
#define ROTORCERT_OP_SLOT(name, since, level, clauses, kind, in, out) ROTORCERT_OP_##kind(ops, Impl, name)

/// The batched C table of an implementation struct: ABI version 1's operations.
template <class Impl>
Ops<typename Impl::Scalar> make_ops() {
  Ops<typename Impl::Scalar> ops{};
  RC_ABI_OPS_V1(ROTORCERT_OP_SLOT, S)
  return ops;
}

/// The batched C table of the ABI version 3 operations of an implementation struct.
template <class Impl>
Ops3<typename Impl::Scalar> make_ops3() {
  Ops3<typename Impl::Scalar> ops{};
  RC_ABI_OPS_V3(ROTORCERT_OP_SLOT, S)
  return ops;
}

/// The batched C table of the ABI version 4 operations of an implementation struct.
template <class Impl>
Ops4<typename Impl::Scalar> make_ops4() {
  Ops4<typename Impl::Scalar> ops{};
  RC_ABI_OPS_V4(ROTORCERT_OP_SLOT, S)
  return ops;
}

}  // namespace rotorcert::impl
