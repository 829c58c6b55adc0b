// Checks that the tests of two third-party quaternion libraries' adapters (impls/eigen_quat,
// impls/glm_quat) share: where the library keeps w, whether the adapter keeps the ABI's order, and
// a short smoke test of the Core ops against the reference. The tests call them and name the
// clauses; each test file keeps the facts of its own library.
#pragma once

#include <array>
#include <cstdint>
#include <cstring>
#include <string_view>
#include <type_traits>

#include <gtest/gtest.h>

#include <rotorcert/impl.hpp>
#include <rotorcert/impl_abi.h>
#include <rotorcert/reference/metrics.hpp>
#include <rotorcert/reference/rotation_ops.hpp>
#include <rotorcert/testing/tolerance.hpp>

namespace rotorcert::testing::quat_library {

using ref::Format;
using ref::Real;
using ref::Verdict;
using RQ = ref::Quaternion<Real>;
template <class S> using Q = std::array<S, 4>;  // ABI order [x, y, z, w]
template <class S> using V = std::array<S, 3>;
template <class S> using Ops = impl::Ops<S>;

/// The table of an entry point with this name and scalar type, or null.
inline const rc_impl* find_table(rc_impl_entry_fn entry, std::string_view name, std::uint32_t scalar) {
  for (std::uint32_t i = 0;; ++i) {
    const rc_impl* t = entry(RC_ABI_VERSION, i);
    if (t == nullptr) return nullptr;
    if (name == t->name && t->scalar == scalar) return t;
  }
}
/// The ops of scalar S of that table.
template <class S> const Ops<S>* ops_of(rc_impl_entry_fn entry, std::string_view name) {
  if constexpr (std::is_same_v<S, float>) return find_table(entry, name, RC_SCALAR_FLOAT32)->f32;
  else return find_table(entry, name, RC_SCALAR_FLOAT64)->f64;
}
template <class S> constexpr Format format() { return sizeof(S) == 4 ? Format::binary32 : Format::binary64; }

/// The exact value of an input or output at the reference precision (NUM-2).
template <class S> RQ exact(const Q<S>& q) { return RQ::from_xyzw({Real(q[0]), Real(q[1]), Real(q[2]), Real(q[3])}); }
template <class S> ref::Vec3<Real> exact(const V<S>& v) { return {Real(v[0]), Real(v[1]), Real(v[2])}; }

/// An error (in the metric's natural unit) in eps units of S, as a double.
template <class S> double eps_units(const Real& err) { return ref::clause::METRIC_2_eps_units(err, format<S>()).toDouble(); }
/// TOL-1's verdict on that error in the eps class cls.
template <class S> Verdict verdict(const Real& err, const char* cls) {
  return ref::clause::TOL_1_verdict(eps_units<S>(err), eps_class_bars(cls));
}

/// QUAT-3: the library's binary32 and binary64 quaternions, each constructed from w, x, y, z =
/// 1, 2, 3, 4, hold x, y, z, w in memory.
template <class QuatF, class QuatD> void expect_memory_holds_xyzw(const QuatF& q, const QuatD& d) {
  static_assert(sizeof(QuatF) == 4 * sizeof(float) && sizeof(QuatD) == 4 * sizeof(double));
  float mem[4];
  std::memcpy(mem, &q, sizeof mem);
  EXPECT_EQ(mem[0], 2.0f);
  EXPECT_EQ(mem[1], 3.0f);
  EXPECT_EQ(mem[2], 4.0f);
  EXPECT_EQ(mem[3], 1.0f);
  double dmem[4];
  std::memcpy(dmem, &d, sizeof dmem);
  EXPECT_EQ(dmem[0], 2.0);
  EXPECT_EQ(dmem[3], 1.0);
}

/// QUAT-3: i j = k (Hamilton) and normalize((0,0,0,2)) = 1: exact results that a swapped w would break.
inline void adapter_keeps_the_abi_order(const Ops<float>& f32, const Ops<double>& f64) {
  const Q<float> i{1, 0, 0, 0}, j{0, 1, 0, 0}, two{0, 0, 0, 2};
  Q<float> out;
  std::uint8_t st = 0xff;
  f32.compose(1, i.data(), j.data(), out.data(), &st);
  EXPECT_EQ(out, (Q<float>{0, 0, 1, 0}));
  f32.normalize(1, two.data(), out.data(), &st);
  EXPECT_EQ(out, (Q<float>{0, 0, 0, 1}));
  const Q<double> id{1, 0, 0, 0}, jd{0, 1, 0, 0};
  Q<double> outd;
  f64.compose(1, id.data(), jd.data(), outd.data(), &st);
  EXPECT_EQ(outd, (Q<double>{0, 0, 1, 0}));
}

/// NORM-1, COMPOSE-1, APPLY-1, MAT-1, SLERP-1 of the adapter, each on one input, at its class:
/// a and b are unit quaternions that the library rounded to S (a 2 rad turn about (1,2,2)/3 and a
/// 0.7 rad turn about (0,0.6,0.8)).
template <class S> void smoke_against_reference(const Ops<S>& o, const Q<S>& a, const Q<S>& b) {
  namespace clause = ref::clause;
  const Q<S> raw{S(0.25), S(-1.5), S(3), S(0.5)};
  const V<S> v{S(1), S(-2), S(0.5)};
  const S t = S(0.3);
  Q<S> q;
  V<S> w;
  std::array<S, 9> m;
  std::uint8_t st = 0xff;

  o.normalize(1, raw.data(), q.data(), &st);
  EXPECT_EQ(verdict<S>(clause::METRIC_1_rotation_distance(exact(q), clause::NORM_1_normalize(exact(raw)).value), "eps4"),
            Verdict::pass);
  o.compose(1, a.data(), b.data(), q.data(), &st);
  EXPECT_EQ(verdict<S>(clause::METRIC_1_rotation_distance(exact(q), clause::COMPOSE_1_compose(exact(a), exact(b)).value),
                       "eps8"),
            Verdict::pass);
  o.apply_vector(1, a.data(), v.data(), w.data(), &st);
  EXPECT_EQ(verdict<S>(clause::METRIC_3_vector_error(exact(w), clause::APPLY_1_apply_vector(exact(a), exact(v)).value),
                       "eps8"),
            Verdict::pass);
  o.to_matrix(1, a.data(), m.data(), &st);
  ref::Mat3<Real> mm;
  for (std::size_t k = 0; k < 9; ++k) mm[k] = Real(m[k]);
  EXPECT_EQ(verdict<S>(clause::METRIC_4_matrix_error(mm, clause::MAT_1_to_matrix(exact(a)).value), "eps8"), Verdict::pass);
  o.slerp(1, a.data(), b.data(), &t, q.data(), &st);
  const auto rs = clause::SLERP_1_slerp(exact(a), exact(b), Real(t)).value;
  EXPECT_EQ(verdict<S>(clause::METRIC_1_rotation_distance(exact(q), rs), "eps16"), Verdict::pass);
  EXPECT_EQ(verdict<S>(clause::METRIC_6_norm_defect(exact(q)), "eps16"), Verdict::pass);
}

/// The two formats, for a test typed over them.
using Formats = ::testing::Types<float, double>;

}  // namespace rotorcert::testing::quat_library
