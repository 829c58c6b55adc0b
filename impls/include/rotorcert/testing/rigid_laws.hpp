// Laws of the dual-quaternion ops (DQ-1 .. DQ-6, SKIN-1, SKIN-2, AXIS-1, EDGE-1, EDGE-3, EDGE-5 .. EDGE-9) that
// every built-in table offering them must keep, written once for any table: dq and motor_pga run
// the same checks through their ABI tables (impls/dq/test_dq.cpp, impls/motor_pga/test_motor_pga.cpp),
// each test naming its clauses. Tolerances are the spec's eps class bars.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

#include <gtest/gtest.h>

#include <rotorcert/impl.hpp>
#include <rotorcert/reference/rigid_ops.hpp>
#include <rotorcert/testing/abi_values.hpp>
#include <rotorcert/testing/tolerance.hpp>

namespace rotorcert::testing::rigid_laws {

using namespace rotorcert::testing::abi;
template <class S> using Ops = impl::Ops<S>;

inline double strict(const char* cls) { return eps_class_bars(cls).strict; }

/// Inputs from a fixed seed, so that every run and both tables see the same values (the test
/// files draw their own inputs from it too, each with its own seed).
struct LawRng {
  explicit LawRng(std::uint64_t seed = 20261126) : g(seed) {}
  std::mt19937_64 g;
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(g); }
  template <class S> Q<S> quat() { return {S(uniform(-1, 1)), S(uniform(-1, 1)), S(uniform(-1, 1)), S(uniform(0.1, 1))}; }
  template <class S> V<S> vec(double r) { return {S(uniform(-r, r)), S(uniform(-r, r)), S(uniform(-r, r))}; }
  /// A rigid motion from DQ-1 of the table under test.
  template <class S> D<S> rigid(const Ops<S>& ops) {
    const Q<S> q = quat<S>();
    const V<S> t = vec<S>(10);
    D<S> d;
    std::uint8_t st = 9;
    ops.dq_from_rotation_translation(1, q.data(), t.data(), d.data(), &st);
    return d;
  }
};

/// DQ-1, DQ-2, DQ-3, DQ-5, DQ-6, AXIS-1 on random rigid motions against the reference clauses, at
/// their classes' strict bars (a smoke check: the systematic run is the suite's).
template <class S> void rigid_smoke_against_reference(const Ops<S>& ops) {
  LawRng rng;
  std::uint8_t st = 9;
  for (int i = 0; i < 40; ++i) {
    const Q<S> q = rng.quat<S>();
    const V<S> t = rng.vec<S>(10), p = rng.vec<S>(10), c = rng.vec<S>(10), u = rng.vec<S>(1);
    const S angle = S(rng.uniform(-7, 7)), tt = S(rng.uniform(-0.5, 1.5));
    D<S> a, out;
    ops.dq_from_rotation_translation(1, q.data(), t.data(), a.data(), &st);
    EXPECT_LE(rigid_err(a, ref::clause::DQ_1_from_rotation_translation(rq(q), rv(t)).value), strict("eps16"));
    const D<S> b = rng.rigid<S>(ops);
    ops.dq_compose(1, a.data(), b.data(), out.data(), &st);
    EXPECT_LE(rigid_err(out, ref::clause::DQ_2_compose(rd(a), rd(b)).value), strict("eps16"));
    ops.dq_sclerp(1, a.data(), b.data(), &tt, out.data(), &st);
    EXPECT_LE(rigid_err(out, ref::clause::DQ_5_sclerp(rd(a), rd(b), Real(tt)).value), strict("eps32"));
    const std::array<D<S>, 3> ds{a, b, rng.rigid<S>(ops)};
    const std::array<S, 3> w{S(rng.uniform(0, 1)), S(rng.uniform(0, 1)), S(rng.uniform(0, 1))};
    ops.dq_blend(1, 3, ds.front().data(), w.data(), out.data(), &st);
    const std::vector<ref::DualQuaternion<Real>> rds{rd(ds[0]), rd(ds[1]), rd(ds[2])};
    const std::vector<Real> rw{Real(w[0]), Real(w[1]), Real(w[2])};
    EXPECT_LE(rigid_err(out, ref::clause::DQ_6_dlb<Real>(rds, rw).value), strict("eps32"));
    V<S> moved;
    ops.dq_apply_point(1, a.data(), p.data(), moved.data(), &st);
    EXPECT_LE(vec_err(moved, ref::clause::DQ_3_apply_point(rd(a), rv(p)).value,
                      std::max({Real(1), norm3(rv(p)), norm3(rv(t))})),
              strict("eps16"));
    ops.rotate_about_axis(1, c.data(), u.data(), &angle, p.data(), moved.data(), &st);
    EXPECT_LE(vec_err(moved, axis_expected(rv(c), rv(u), Real(angle), rv(p)), std::max({Real(1), norm3(rv(p)), norm3(rv(c))})),
              strict("eps16"));
  }
}

/// DQ-4, EDGE-5: a non-unit real part at scales 2^-40 .. 2^40 and a dual part with a component
/// along it come out with a unit real part, a dual part orthogonal to it, and DQ-4's value.
template <class S> void normalise_makes_real_unit_and_dual_orthogonal(const Ops<S>& ops) {
  LawRng rng;
  for (int i = 0; i < 200; ++i) {
    const S k = S(std::ldexp(rng.uniform(0.5, 1), int(rng.uniform(-40, 40))));
    D<S> d, n;
    for (int j = 0; j < 8; ++j) d[j] = k * S(rng.uniform(-2, 2));
    std::uint8_t st = 9;
    ops.dq_normalize(1, d.data(), n.data(), &st);
    ASSERT_EQ(st, RC_OK);
    const auto r = rd(n);
    EXPECT_LE((abs(ref::norm(r.real) - 1) / eps<S>()).toDouble(), strict("eps16"));
    EXPECT_LE((abs(ref::dot(r.real, r.dual)) / eps<S>()).toDouble(), strict("eps16"));
    EXPECT_LE(rigid_err(n, ref::clause::DQ_4_normalize(rd(d)).value), strict("eps16"));
  }
}

/// DQ-4, EDGE-5: a unit motion whose dual part gained c r (|c| = 2^4 .. 2^40, the dual part then
/// mostly parallel to the real part: the input of fuzz finding
/// rigid/regression-dq-sclerp-subnormal-real-part-f64, at ordinary scales). Subtracting the
/// parallel part cancels; the result must still be orthogonal, to the bar relative to
/// max(1, |t|) as METRIC-7 measures the translation, and equal DQ-4 of the input as given.
template <class S> void normalise_removes_a_large_parallel_part(const Ops<S>& ops) {
  LawRng rng(7);
  for (int i = 0; i < 200; ++i) {
    const D<S> u = rng.rigid<S>(ops);
    const S c = S(std::ldexp(rng.uniform(0.5, 1) * (i % 2 ? 1 : -1), int(rng.uniform(4, 41))));
    D<S> d = u, n;
    for (int j = 0; j < 4; ++j) d[4 + j] = u[4 + j] + c * u[j];
    std::uint8_t st = 9;
    ops.dq_normalize(1, d.data(), n.data(), &st);
    ASSERT_EQ(st, RC_OK);
    const auto want = ref::clause::DQ_4_normalize(rd(d)).value;
    const auto t = ref::clause::dual_quaternion_translation(want);
    const Real scale = max(Real(1), norm3(t));
    const auto r = rd(n);
    EXPECT_LE((abs(ref::dot(r.real, r.dual)) / scale / eps<S>()).toDouble(), strict("eps16")) << "c = " << c;
    EXPECT_LE(rigid_err(n, want), strict("eps16")) << "c = " << c;
  }
}

/// DQ-8, DQ-9, EDGE-1: a rotation whose vector part is subnormal (from the format's smallest value
/// to just below the smallest normal). Its direction n = v / |v| must be formed without 1 / |v|,
/// which overflows in binary32 (fuzz/corpus/rigid_transforms/regression-campaign-*): exp and
/// log answer OK with finite values that match the reference at their classes' strict bars.
template <class S> void log_exp_keep_a_subnormal_rotation(const impl::Ops4<S>& ops) {
  using L = std::numeric_limits<S>;
  for (const S m : {S(1), S(125), S(std::ldexp(S(1), L::digits - 2))}) {
    const S v = m * L::denorm_min();
    const std::array<S, 6> xi{v, S(3) * L::denorm_min(), S(0), S(0.5), S(-2), S(1)};
    D<S> d;
    std::uint8_t st = 9;
    ops.dq_exp(1, xi.data(), d.data(), &st);
    ASSERT_EQ(st, RC_OK) << "xi_r.x = " << v;
    const ref::DualVector<Real> rxi{rv(V<S>{xi[0], xi[1], xi[2]}), rv(V<S>{xi[3], xi[4], xi[5]})};
    EXPECT_LE(rigid_err(d, ref::clause::DQ_9_exp(rxi).value), strict("eps16")) << "xi_r.x = " << v;
    std::array<S, 6> back;
    ops.dq_log(1, d.data(), back.data(), &st);
    ASSERT_EQ(st, RC_OK) << "xi_r.x = " << v;
    const auto want = ref::clause::DQ_8_log(rd(d)).value;
    const Real scale = max(Real(1), norm3(want.real) + norm3(want.dual));
    const Real err = max(norm3(sub3(rv(V<S>{back[0], back[1], back[2]}), want.real)),
                         norm3(sub3(rv(V<S>{back[3], back[4], back[5]}), want.dual)));
    EXPECT_LE((err / scale / eps<S>()).toDouble(), strict("eps32")) << "xi_r.x = " << v;
  }
}

/// DQ-8 near the branch cut (b -> pi): b / sin b grows like 1 / (pi - b), and only the dual
/// part's component perpendicular to the axis may be multiplied by it. A screw motion whose
/// translation lies mostly along the axis must come back from log with its pitch intact (the
/// parallel part cancelled, or rho^3 overflowed, in the old forms:
/// fuzz/corpus/rigid_transforms/regression-*-log-*), down to gaps pi - b where rho^3 overflows.
/// The error is relative to DQ-8's scale max(1, |xi_ref|, kappa |d_v|) (kappa = b / sin b of
/// DQ-4(sigma): the amplification of the input's own rounding), at eps32's strict bar.
template <class S> void log_near_the_cut_keeps_the_screw(const impl::Ops4<S>& ops) {
  LawRng rng(11);
  const Real pi = ref::ScalarTraits<Real>::pi();
  for (int i = 0; i < 60; ++i) {
    const V<S> axis = rng.vec<S>(1);
    const Real len = norm3(rv(axis));
    const Real gap = ldexp(Real(1), -int(rng.uniform(3, std::numeric_limits<S>::max_exponent / 3 + 20)));
    const Real b = pi - gap;
    const ref::Vec3<Real> nr{rv(axis)[0] / len, rv(axis)[1] / len, rv(axis)[2] / len};
    const Real along = ldexp(Real(rng.uniform(-1, 1)), int(rng.uniform(0, 50))), off = Real(rng.uniform(-1, 1)) * gap;
    const ref::DualVector<Real> xi{{b * nr[0], b * nr[1], b * nr[2]},
                                   {along * nr[0] + off * nr[1], along * nr[1] - off * nr[0], along * nr[2]}};
    const auto exact = ref::clause::DQ_9_exp(xi).value;
    const D<S> d{S(exact.real.x.toDouble()), S(exact.real.y.toDouble()), S(exact.real.z.toDouble()), S(exact.real.w.toDouble()),
                 S(exact.dual.x.toDouble()), S(exact.dual.y.toDouble()), S(exact.dual.z.toDouble()), S(exact.dual.w.toDouble())};
    std::array<S, 6> got;
    std::uint8_t st = 9;
    ops.dq_log(1, d.data(), got.data(), &st);
    ASSERT_EQ(st, RC_OK);
    const auto want = ref::clause::DQ_8_log(rd(d)).value;
    const auto u = ref::clause::DQ_4_normalize(rd(d)).value;
    const Real sin_b = norm3({u.real.x, u.real.y, u.real.z});
    const Real kappa = max(Real(1), atan2(sin_b, u.real.w) / sin_b);
    const Real scale = max(max(Real(1), norm3(want.real) + norm3(want.dual)), kappa * norm3({u.dual.x, u.dual.y, u.dual.z}));
    const Real err = max(norm3(sub3(rv(V<S>{got[0], got[1], got[2]}), want.real)),
                         norm3(sub3(rv(V<S>{got[3], got[4], got[5]}), want.dual)));
    EXPECT_LE((err / scale / eps<S>()).toDouble(), strict("eps32")) << "pi - b = " << gap << ", along = " << along;
  }
}

/// DQ-5: between two pure translations (non-unit representatives) no rotation appears, the real
/// part is the identity exactly, and the translation is linear in t, extrapolation included.
template <class S> void sclerp_of_pure_translation_is_linear_in_t(const Ops<S>& ops) {
  LawRng rng;
  for (int i = 0; i < 50; ++i) {
    const V<S> ta = rng.vec<S>(100), tb = rng.vec<S>(100);
    const S k = S(rng.uniform(0.25, 4));
    const D<S> a{0, 0, 0, k, k * ta[0] / 2, k * ta[1] / 2, k * ta[2] / 2, 0};
    const D<S> b{0, 0, 0, 1, tb[0] / 2, tb[1] / 2, tb[2] / 2, 0};
    for (const S t : {S(-1.5), S(0), S(0.25), S(0.5), S(1), S(2.75)}) {
      D<S> s;
      std::uint8_t st = 9;
      ops.dq_sclerp(1, a.data(), b.data(), &t, s.data(), &st);
      ASSERT_EQ(st, RC_OK);
      EXPECT_EQ((std::array<S, 4>{s[0], s[1], s[2], s[3]}), (std::array<S, 4>{0, 0, 0, 1}));
      ref::Vec3<Real> want;
      for (int j = 0; j < 3; ++j) want[j] = Real(ta[j]) + Real(t) * (Real(tb[j]) - Real(ta[j]));
      const ref::Vec3<Real> got{2 * Real(s[4]), 2 * Real(s[5]), 2 * Real(s[6])};
      EXPECT_LE((norm3(sub3(got, want)) / max(Real(1), norm3(want)) / eps<S>()).toDouble(), strict("eps32"));
    }
  }
}

/// EDGE-1: the identity motion composes, interpolates (inside and outside [0, 1]) and moves a
/// point to exactly itself.
template <class S> void identity_in_identity_out(const Ops<S>& ops) {
  const D<S> id{0, 0, 0, 1, 0, 0, 0, 0};
  const V<S> p{S(0.1), S(-7), S(3e5)};
  std::uint8_t st = 9;
  D<S> d;
  ops.dq_compose(1, id.data(), id.data(), d.data(), &st);
  EXPECT_EQ(d, id);
  for (const S t : {S(0.37), S(-4)}) {
    ops.dq_sclerp(1, id.data(), id.data(), &t, d.data(), &st);
    EXPECT_EQ(d, id);
  }
  V<S> out;
  ops.dq_apply_point(1, id.data(), p.data(), out.data(), &st);
  EXPECT_EQ(out, p);
}

/// EDGE-6, EDGE-7, EDGE-9: a zero real part, a NaN or infinite component, a non-finite t, bad
/// weight sets, a zero influence of weight 0 and a zero rotation axis give DOMAIN_ERROR with NaN
/// outputs; a weight of -0 first is 0, so the pivot is the first positive weight.
template <class S> void outside_the_domain_is_domain_error_with_nan(const Ops<S>& ops) {
  const S nan = std::numeric_limits<S>::quiet_NaN(), inf = std::numeric_limits<S>::infinity();
  const D<S> zero_real{0, -S(0), 0, 0, 1, 0, 0, 0}, good{0, 0, 0, 1, 0, 0, 0, 0};
  const D<S> with_inf{0, 0, 0, 1, inf, 0, 0, 0}, with_nan{0, 0, 0, 1, 0, nan, 0, 0};
  const V<S> p{1, 2, 3};
  for (const D<S>& bad : {zero_real, with_inf, with_nan}) {
    std::uint8_t st = 9;
    V<S> moved;
    ops.dq_apply_point(1, bad.data(), p.data(), moved.data(), &st);
    EXPECT_EQ(st, RC_DOMAIN_ERROR);
    for (S x : moved) EXPECT_TRUE(std::isnan(x));
    D<S> n;
    ops.dq_normalize(1, bad.data(), n.data(), &st);
    EXPECT_EQ(st, RC_DOMAIN_ERROR);
    for (S x : n) EXPECT_TRUE(std::isnan(x));
  }
  std::uint8_t st = 9;
  D<S> out;
  for (const S t : {nan, inf}) {
    ops.dq_sclerp(1, good.data(), good.data(), &t, out.data(), &st);
    EXPECT_EQ(st, RC_DOMAIN_ERROR);
  }
  const std::array<D<S>, 2> two{good, good};
  for (const std::array<S, 2>& w : {std::array<S, 2>{1, -1}, {nan, 1}, {inf, 1}, {0, -S(0)}}) {
    ops.dq_blend(1, 2, two.front().data(), w.data(), out.data(), &st);
    EXPECT_EQ(st, RC_DOMAIN_ERROR);
    for (S x : out) EXPECT_TRUE(std::isnan(x));
  }
  const std::array<D<S>, 2> with_zero{good, zero_real};
  const std::array<S, 2> w{1, 0};
  ops.dq_blend(1, 2, with_zero.front().data(), w.data(), out.data(), &st);
  EXPECT_EQ(st, RC_DOMAIN_ERROR);
  const std::array<D<S>, 2> pivot_test{D<S>{0, 0, 0, -1, 0, 0, 0, 0}, D<S>{0, 0, 0, 1, S(0.5), 0, 0, 0}};
  const std::array<S, 2> w2{-S(0), 1};
  ops.dq_blend(1, 2, pivot_test.front().data(), w2.data(), out.data(), &st);
  EXPECT_EQ(st, RC_OK);
  EXPECT_EQ(out[3], 1);
  const V<S> c{1, 0, 0}, zero_axis{0, -S(0), 0}, origin{0, 0, 0};
  const S angle = 0;
  V<S> moved;
  ops.rotate_about_axis(1, c.data(), zero_axis.data(), &angle, origin.data(), moved.data(), &st);
  EXPECT_EQ(st, RC_DOMAIN_ERROR);
}

/// EDGE-3, DQ-6: a dot of exactly 0 between the real parts does not flip. r1 is a signed
/// permutation of r0 (x, y, z, w) -> (-y, x, -w, z), so r0.r1 = 0 exactly and |r0| = |r1|; neither
/// is unit in the format, so a flip decided on separately normalised copies would see +-tiny.
template <class S> void blend_does_not_flip_on_exactly_zero_dot(const Ops<S>& ops) {
  LawRng rng;
  for (int i = 0; i < 100; ++i) {
    const Q<S> r0 = rng.quat<S>();
    const Q<S> r1{-r0[1], r0[0], -r0[3], r0[2]};
    const std::array<D<S>, 2> ds{D<S>{r0[0], r0[1], r0[2], r0[3], 0, 0, 0, 0}, D<S>{r1[0], r1[1], r1[2], r1[3], 0, 0, 0, 0}};
    const std::array<S, 2> w{1, 1};
    D<S> out;
    std::uint8_t st = 9;
    ops.dq_blend(1, 2, ds.front().data(), w.data(), out.data(), &st);
    ASSERT_EQ(st, RC_OK);
    const auto a = rq(r0), b = rq(r1);
    const ref::Quaternion<Real> no_flip{a.w + b.w, a.x + b.x, a.y + b.y, a.z + b.z};
    EXPECT_LE((ref::clause::METRIC_1_rotation_distance(rd(out).real, no_flip) / eps<S>()).toDouble(), strict("eps32"));
  }
}

/// DQ-6, EDGE-5: the blend of influences scaled by an exact power of two 2^E is the blend of the
/// influences as given, bit for bit, where neither scale over- or underflows: each influence
/// stands for its DQ-4 normalisation, and every step of DLB (normalise, weigh, sum, normalise) is
/// homogeneous, so that only rounding could tell the scales apart, and power-of-two scales round
/// alike. E puts |r|^2 outside the ordinary range (runtime/ordinary_range.hpp) in both
/// directions, so the scaled copies take a table's checked path and the originals its fast
/// paths; any difference between the paths' arithmetic shows as a bit. Per k = 1..5, 61 cases
/// (a few with an exactly zero hemisphere dot, which only the exact sign decides) are blended
/// in four batches: the originals alone (full blocks of SIMD lanes and a tail that is not one),
/// each scaled set alone, and all three interleaved (lanes of a block then take different paths).
template <class S> void blend_fast_and_checked_paths_agree(const Ops<S>& ops) {
  constexpr int E = std::is_same_v<S, float> ? 40 : 300;  // |r|^2 ~ 2^(+-2E): beyond 2^(+-emax/2)
  constexpr std::size_t kCases = 61;  // neither a multiple of 16 nor of 4, nor is 3 x 61
  LawRng rng(7);
  for (std::size_t k = 1; k <= 5; ++k) {
    std::array<std::vector<D<S>>, 3> ds;  // originals, times 2^E, times 2^-E: kCases x k influences
    std::vector<S> w;
    for (std::size_t i = 0, attempt = 0; i < kCases; ++attempt) {
      ASSERT_LT(attempt, 4 * kCases) << "the generator keeps drawing unusable cases";
      std::vector<D<S>> one(k);
      std::vector<S> wk(k);
      bool usable = false, representable = true;
      for (std::size_t j = 0; j < k; ++j) {
        one[j] = rng.rigid<S>(ops);
        if (j == 1 && i % 9 == 4)  // a signed permutation of the first real part: dot exactly 0
          for (std::size_t c = 0; c < 4; ++c) one[j][c] = std::array<S, 4>{-one[0][1], one[0][0], -one[0][3], one[0][2]}[c];
        const S size = S(rng.uniform(0.25, 4));  // non-unit influences too (EDGE-5)
        for (S& c : one[j]) {
          c *= size;
          representable = representable && (c == 0 || std::abs(c) > std::ldexp(std::numeric_limits<S>::min(), E + 8));
        }
        wk[j] = (attempt + j) % 7 == 3 ? S(j % 2 ? -0.0 : 0.0) : S(rng.uniform(0, 2));  // zeros, -0 among them
        usable = usable || wk[j] > 0;
      }
      if (!representable || !usable) continue;
      for (std::size_t j = 0; j < k; ++j) {
        D<S> up, down;
        for (std::size_t c = 0; c < 8; ++c) {
          up[c] = std::ldexp(one[j][c], E);
          down[c] = std::ldexp(one[j][c], -E);
        }
        ds[0].push_back(one[j]);
        ds[1].push_back(up);
        ds[2].push_back(down);
        w.push_back(wk[j]);
      }
      ++i;
    }
    const auto blend = [&](const std::vector<D<S>>& d, const std::vector<S>& ws, std::size_t n) {
      std::vector<D<S>> out(n);
      std::vector<std::uint8_t> st(n, 9);
      ops.dq_blend(n, k, d.front().data(), ws.data(), out.front().data(), st.data());
      for (std::size_t e = 0; e < n; ++e) EXPECT_EQ(st[e], RC_OK) << "k=" << k << " element " << e;
      return out;
    };
    const std::vector<D<S>> want = blend(ds[0], w, kCases);
    std::vector<D<S>> mixed_d;
    std::vector<S> mixed_w;
    for (std::size_t i = 0; i < kCases; ++i)
      for (std::size_t v = 0; v < 3; ++v) {
        mixed_d.insert(mixed_d.end(), ds[v].begin() + i * k, ds[v].begin() + (i + 1) * k);
        mixed_w.insert(mixed_w.end(), w.begin() + i * k, w.begin() + (i + 1) * k);
      }
    const std::vector<D<S>> mixed = blend(mixed_d, mixed_w, 3 * kCases);
    for (std::size_t v = 1; v < 3; ++v) {
      const std::vector<D<S>> got = blend(ds[v], w, kCases);
      for (std::size_t i = 0; i < kCases; ++i)
        for (std::size_t c = 0; c < 8; ++c)
          EXPECT_EQ(got[i][c], want[i][c]) << "k=" << k << " case " << i << " component " << c << ": scaled by 2^"
                                           << (v == 1 ? E : -E);
    }
    for (std::size_t i = 0; i < kCases; ++i)
      for (std::size_t v = 0; v < 3; ++v)
        for (std::size_t c = 0; c < 8; ++c)
          EXPECT_EQ(mixed[3 * i + v][c], want[i][c]) << "k=" << k << " case " << i << " component " << c
                                                     << ": interleaved, variant " << v;
  }
}

/// DQ-3, EDGE-5: a point moved by a dual quaternion scaled by an exact power of two 2^E moves
/// as by the dual quaternion as given, bit for bit (DQ-3 reads sigma through its DQ-4
/// normalisation, homogeneous as in blend_fast_and_checked_paths_agree). 93 random motions,
/// non-unit, with one non-finite point among them: the originals alone (SIMD lanes where a table
/// has them, a scalar tail) against each scaled set alone and all three interleaved.
template <class S> void apply_point_fast_and_checked_paths_agree(const Ops<S>& ops) {
  constexpr int E = std::is_same_v<S, float> ? 40 : 300;
  constexpr std::size_t kCases = 93;  // neither a multiple of 16 nor of 4, nor is 3 x 93
  LawRng rng(11);
  std::array<std::vector<D<S>>, 3> ds;
  std::vector<V<S>> ps;
  while (ps.size() < kCases) {
    D<S> d = rng.rigid<S>(ops);
    const S size = S(rng.uniform(0.25, 4));
    bool representable = true;
    for (S& c : d) {
      c *= size;
      representable = representable && (c == 0 || std::abs(c) > std::ldexp(std::numeric_limits<S>::min(), E + 8));
    }
    if (!representable) continue;
    D<S> up, down;
    for (std::size_t c = 0; c < 8; ++c) {
      up[c] = std::ldexp(d[c], E);
      down[c] = std::ldexp(d[c], -E);
    }
    ds[0].push_back(d);
    ds[1].push_back(up);
    ds[2].push_back(down);
    ps.push_back(ps.size() == 37 ? V<S>{1, std::numeric_limits<S>::quiet_NaN(), 2} : rng.vec<S>(10));
  }
  const auto apply = [&](const std::vector<D<S>>& d, const std::vector<V<S>>& p) {
    std::vector<V<S>> out(d.size());
    std::vector<std::uint8_t> st(d.size(), 9);
    ops.dq_apply_point(d.size(), d.front().data(), p.front().data(), out.front().data(), st.data());
    for (std::size_t e = 0; e < d.size(); ++e)
      EXPECT_EQ(st[e], std::isnan(p[e][1]) ? RC_DOMAIN_ERROR : RC_OK) << "element " << e;
    return out;
  };
  const auto same = [](S a, S b) { return a == b || (std::isnan(a) && std::isnan(b)); };
  const std::vector<V<S>> want = apply(ds[0], ps);
  std::vector<D<S>> mixed_d;
  std::vector<V<S>> mixed_p;
  for (std::size_t i = 0; i < kCases; ++i)
    for (std::size_t v = 0; v < 3; ++v) {
      mixed_d.push_back(ds[v][i]);
      mixed_p.push_back(ps[i]);
    }
  const std::vector<V<S>> mixed = apply(mixed_d, mixed_p);
  for (std::size_t v = 1; v < 3; ++v) {
    const std::vector<V<S>> got = apply(ds[v], ps);
    for (std::size_t i = 0; i < kCases; ++i)
      for (std::size_t c = 0; c < 3; ++c)
        EXPECT_PRED2(same, got[i][c], want[i][c]) << "case " << i << " component " << c << ": scaled by 2^" << (v == 1 ? E : -E);
  }
  for (std::size_t i = 0; i < kCases; ++i)
    for (std::size_t v = 0; v < 3; ++v)
      for (std::size_t c = 0; c < 3; ++c)
        EXPECT_PRED2(same, mixed[3 * i + v][c], want[i][c]) << "case " << i << " component " << c << ": interleaved, variant " << v;
}

/// DQ-1, DQ-2, DQ-4, EDGE-5 .. EDGE-7: the batches of dq_from_rotation_translation, dq_compose and
/// dq_normalize, which run their ordinary elements in SIMD lanes (dq's dlb_lanes.hpp, motor_pga's
/// motor_lanes.hpp), give bit for bit and status for status what a one-element call (the element
/// function) gives for each element alone. 61 elements: 3 blocks of 16, 3 of 4 and one alone
/// (runtime/lane_blocks.hpp). Among ordinary inputs of sizes 1/4 .. 4 (EDGE-5) sit, spread over
/// blocks and lanes: both parts, the real part alone or the dual part alone scaled by 2^+-E beyond
/// the ordinary range (runtime/ordinary_range.hpp), zero real parts and rotations (EDGE-6),
/// subnormal components, NaN and infinities in the real part, the dual part and the translation
/// (EDGE-7), an exactly zero dual part, and dual parts nearly parallel to the real part (whose
/// DQ-4 projection cancels: runtime/perpendicular_part.hpp), so that lanes of one block take
/// different paths. Any difference between the lanes' arithmetic and the element function's
/// shows as a bit.
template <class S> void dq_batches_give_the_element_bits(const Ops<S>& ops) {
  using Lim = std::numeric_limits<S>;
  constexpr int E = std::is_same_v<S, float> ? 40 : 300;  // |r|^2 ~ 2^(+-2E): beyond 2^(+-emax/2)
  constexpr std::size_t kCases = 61;                       // 3 x 16 + 3 x 4 + 1
  LawRng rng(61);
  // The kind of input `which` (0: a, 1: b, 2: q, 3: t) of element i: 1 .. 12 a special below,
  // else ordinary; 7 i spreads each kind over two or three blocks and lanes, the offsets put the
  // inputs' specials at different elements.
  const auto kind = [](std::size_t i, std::size_t which) { return int((7 * i + std::size_t{11} * which) % 29); };
  // A special of the given kind written into the real part r and the dual part d of an ordinary
  // dual quaternion (q and a scratch dual part for the rotation).
  const auto special = [&](int k, S* r, S* d) {
    switch (k) {
      case 1: for (int c = 0; c < 4; ++c) r[c] = std::ldexp(r[c], E), d[c] = std::ldexp(d[c], E); break;
      case 2: for (int c = 0; c < 4; ++c) r[c] = std::ldexp(r[c], -E), d[c] = std::ldexp(d[c], -E); break;
      case 3: for (int c = 0; c < 4; ++c) r[c] = std::ldexp(r[c], -E); break;
      case 4: for (int c = 0; c < 4; ++c) r[c] = S(c % 2 ? -0.0 : 0.0); break;
      case 5: r[0] = Lim::denorm_min(), r[1] = -S(0), r[2] = 3 * Lim::denorm_min(), r[3] = 0; break;
      case 6: d[0] = Lim::denorm_min(), d[1] = 0, d[2] = -2 * Lim::denorm_min(), d[3] = -S(0); break;  // |d|^2 = 0
      case 7: r[1] = Lim::quiet_NaN(); break;
      case 8: d[3] = -Lim::infinity(); break;
      case 9: {  // d = c r + a little: along^2 > 15/16 |d|^2
        const double big = std::ldexp(rng.uniform(0.5, 1) * (r[0] > 0 ? 1 : -1), int(rng.uniform(4, 20)));
        for (int c = 0; c < 4; ++c) d[c] = S(big * double(r[c]) + rng.uniform(-1, 1));
        break;
      }
      case 10: for (int c = 0; c < 4; ++c) d[c] = std::ldexp(d[c], E); break;
      case 11: r[2] = Lim::infinity(); break;
      case 12: for (int c = 0; c < 4; ++c) d[c] = 0; break;
      default: break;
    }
  };
  std::vector<S> a(8 * kCases), b(8 * kCases), q(4 * kCases), t(3 * kCases);
  for (std::size_t i = 0; i < kCases; ++i) {
    for (S* x : {&a[8 * i], &b[8 * i]}) {
      const double size = rng.uniform(0.25, 4);
      for (int c = 0; c < 4; ++c) x[c] = S(rng.uniform(-1, 1) * size), x[4 + c] = S(rng.uniform(-5, 5) * size);
    }
    const double size = rng.uniform(0.25, 4);
    for (int c = 0; c < 4; ++c) q[4 * i + c] = S(rng.uniform(-1, 1) * size);
    for (int c = 0; c < 3; ++c) t[3 * i + c] = S(rng.uniform(-10, 10));
    special(kind(i, 0), &a[8 * i], &a[8 * i + 4]);
    special(kind(i, 1), &b[8 * i], &b[8 * i + 4]);
    S scratch[4] = {1, 2, 3, 4};
    special(kind(i, 2), &q[4 * i], scratch);
    S* ti = &t[3 * i];
    switch (kind(i, 3)) {
      case 6: ti[0] = Lim::denorm_min(), ti[1] = -S(0), ti[2] = -5 * Lim::denorm_min(); break;
      case 7: ti[1] = Lim::quiet_NaN(); break;
      case 8: ti[2] = -Lim::infinity(); break;
      case 10: ti[0] = Lim::max() / 4; break;  // finite: the lanes take it, as the element function does
      case 12: ti[0] = ti[1] = ti[2] = 0; break;
      default: break;
    }
  }
  // One op: the batch of all cases against one-element calls from element i, 8 output scalars per
  // element, bit for bit (NaN outputs included) and status for status.
  const auto check = [&](const char* name, auto call) {
    std::vector<S> batch(8 * kCases), one(8);
    std::vector<std::uint8_t> st(kCases, 9);
    std::uint8_t st1 = 9;
    ASSERT_EQ(call(kCases, std::size_t{0}, batch.data(), st.data()), 0) << name;
    for (std::size_t i = 0; i < kCases; ++i) {
      ASSERT_EQ(call(1, i, one.data(), &st1), 0) << name;
      EXPECT_EQ(st[i], st1) << name << " element " << i;
      EXPECT_EQ(0, std::memcmp(&batch[8 * i], one.data(), 8 * sizeof(S))) << name << " element " << i;
    }
  };
  using Status = std::uint8_t*;
  check("dq_from_rotation_translation", [&](std::size_t n, std::size_t i, S* o, Status s) {
    return ops.dq_from_rotation_translation(n, &q[4 * i], &t[3 * i], o, s);
  });
  check("dq_compose",
        [&](std::size_t n, std::size_t i, S* o, Status s) { return ops.dq_compose(n, &a[8 * i], &b[8 * i], o, s); });
  check("dq_normalize",
        [&](std::size_t n, std::size_t i, S* o, Status s) { return ops.dq_normalize(n, &a[8 * i], o, s); });
  check("dq_normalize of b",
        [&](std::size_t n, std::size_t i, S* o, Status s) { return ops.dq_normalize(n, &b[8 * i], o, s); });
}

/// The check of the batch laws below: `call(n, i, out, status)` runs the op on n elements from
/// element i; the batch of all `cases` against one-element calls (the element function), `width`
/// output scalars per element, bit for bit (NaN outputs included) and status for status.
template <class S, class Call>
void batch_matches_elements(const char* name, std::size_t cases, std::size_t width, Call call) {
  std::vector<S> batch(width * cases), one(width);
  std::vector<std::uint8_t> st(cases, 9);
  std::uint8_t st1 = 9;
  ASSERT_EQ(call(cases, std::size_t{0}, batch.data(), st.data()), 0) << name;
  for (std::size_t i = 0; i < cases; ++i) {
    ASSERT_EQ(call(1, i, one.data(), &st1), 0) << name;
    EXPECT_EQ(st[i], st1) << name << " element " << i;
    EXPECT_EQ(0, std::memcmp(&batch[width * i], one.data(), width * sizeof(S))) << name << " element " << i;
  }
}

/// SKIN-1, SKIN-2, EDGE-3, EDGE-5 .. EDGE-7, EDGE-9: the batches of skin_linear (where the table
/// has it) and skin_dual_quaternion, which run their ordinary elements in SIMD lanes (dq's
/// dlb_lanes.hpp, motor_pga's motor_lanes.hpp), give bit for bit and status for status what a
/// one-element call gives, as dq_batches_give_the_element_bits; k = 1, 4 and 8 influences. Among
/// ordinary influences (sizes 1/4 .. 4, translations and vertices in [-10, 10]) sit, spread over
/// blocks and lanes by 7 i mod 29: a first weight 0 (the pivot moves), all weights 0, a weight -0,
/// -1/2, NaN, +Inf, 1e30 or the largest finite; an influence scaled by 2^+-E beyond the ordinary
/// range, zero, subnormal or NaN; one that is -q_0 (the hemisphere flip) or orthogonal to q_0
/// exactly (EDGE-3's tie against the pivot, which the lanes' filter cannot decide) or at a dot
/// so small and negative that only the exact sign sees the flip; a translation
/// or a vertex that is Inf or NaN, a translation of max / 4 (finite: the lanes take it); large
/// translations (the sum's DQ-4 projection may cancel).
template <class S> void skin_batches_give_the_element_bits(const Ops<S>& ops) {
  using Lim = std::numeric_limits<S>;
  constexpr int E = std::is_same_v<S, float> ? 40 : 300;
  constexpr std::size_t kCases = 61;  // 3 x 16 + 3 x 4 + 1
  LawRng rng(62);
  for (const std::size_t k : {std::size_t{1}, std::size_t{4}, std::size_t{8}}) {
    std::vector<S> q(4 * k * kCases), t(3 * k * kCases), w(k * kCases), v(3 * kCases);
    for (std::size_t i = 0; i < kCases; ++i) {
      S* qi = &q[4 * k * i];
      S* ti = &t[3 * k * i];
      S* wi = &w[k * i];
      S* vi = &v[3 * i];
      for (std::size_t j = 0; j < k; ++j) {
        const double size = rng.uniform(0.25, 4);
        for (std::size_t c = 0; c < 4; ++c) qi[4 * j + c] = S(rng.uniform(-1, 1) * size);
        for (std::size_t c = 0; c < 3; ++c) ti[3 * j + c] = S(rng.uniform(-10, 10));
        wi[j] = S(rng.uniform(0, 1));
      }
      for (std::size_t c = 0; c < 3; ++c) vi[c] = S(rng.uniform(-10, 10));
      S* ql = &qi[4 * (k - 1)];  // the last influence
      S* tl = &ti[3 * (k - 1)];
      switch ((7 * i) % 29) {
        case 1: wi[0] = 0; break;
        case 2: for (std::size_t j = 0; j < k; ++j) wi[j] = 0; break;
        case 3: wi[k - 1] = S(-0.0); break;
        case 4: wi[k - 1] = S(-0.5); break;
        case 5: wi[k - 1] = Lim::quiet_NaN(); break;
        case 6: wi[k - 1] = Lim::infinity(); break;
        case 7: wi[k - 1] = S(1e30); break;
        case 8: wi[0] = Lim::max(); break;
        case 9: for (std::size_t c = 0; c < 4; ++c) ql[c] = std::ldexp(ql[c], E); break;
        case 10: for (std::size_t c = 0; c < 4; ++c) ql[c] = std::ldexp(ql[c], -E); break;
        case 11: for (std::size_t c = 0; c < 4; ++c) ql[c] = S(c % 2 ? -0.0 : 0.0); break;
        case 12: ql[0] = Lim::denorm_min(), ql[1] = -S(0), ql[2] = 3 * Lim::denorm_min(), ql[3] = 0; break;
        case 13: ql[2] = Lim::quiet_NaN(); break;
        case 14: for (std::size_t c = 0; c < 4; ++c) ql[c] = -qi[c]; break;  // k = 1: q_0 itself negated
        case 15: if (k > 1) ql[0] = -qi[1], ql[1] = qi[0], ql[2] = -qi[3], ql[3] = qi[2]; break;
        case 16: if (k > 1) ql[0] = -qi[1], ql[1] = qi[0], ql[2] = -qi[3], ql[3] = qi[2], wi[0] = 0; break;  // tie, pivot 1
        case 17: tl[1] = Lim::infinity(); break;
        case 18: tl[0] = Lim::quiet_NaN(); break;
        case 19: tl[2] = Lim::max() / 4; break;
        case 20: vi[2] = -Lim::infinity(); break;
        case 21: vi[0] = Lim::quiet_NaN(); break;
        case 22: for (std::size_t j = 0; j < 3 * k; ++j) ti[j] = S(rng.uniform(-1, 1) * 1e6); break;
        case 23: for (std::size_t c = 0; c < 4; ++c) ql[c] = std::ldexp(ql[c], -E / 2 - 8); break;  // |q|^2 underflows
        case 24:  // q_0.q_last = -2^(3-p) exactly, within the filter's bound 2^(4-p): only the exact sign flips
          if (k > 1) {
            qi[0] = qi[1] = 1, qi[2] = qi[3] = 0;
            ql[0] = 1, ql[1] = -1 - std::ldexp(S(1), 3 - Lim::digits), ql[2] = ql[3] = 0;
          }
          break;
        default: break;
      }
    }
    using Status = std::uint8_t*;
    const char* const kn = k == 1 ? " k=1" : k == 4 ? " k=4" : " k=8";
    if (ops.skin_linear != nullptr)
      batch_matches_elements<S>((std::string("skin_linear") + kn).c_str(), kCases, 3,
                                [&](std::size_t n, std::size_t i, S* o, Status st) {
                                  return ops.skin_linear(n, k, &q[4 * k * i], &t[3 * k * i], &w[k * i], &v[3 * i], o, st);
                                });
    batch_matches_elements<S>((std::string("skin_dual_quaternion") + kn).c_str(), kCases, 3,
                              [&](std::size_t n, std::size_t i, S* o, Status st) {
                                return ops.skin_dual_quaternion(n, k, &q[4 * k * i], &t[3 * k * i], &w[k * i], &v[3 * i],
                                                                o, st);
                              });
  }
}

/// AXIS-1, EDGE-6, EDGE-7: the batch of rotate_about_axis (SIMD lanes in dq and motor_pga) gives
/// bit for bit and status for status what a one-element call gives, as
/// dq_batches_give_the_element_bits. Among ordinary centres, axes, angles in [-7, 7] and points
/// sit, spread over blocks and lanes: a zero axis (+0 and -0), a subnormal axis and axes scaled by
/// 2^+-E (beyond the ordinary range, still valid), NaN and Inf in the centre, the axis, the angle
/// and the point, angles of 0, -0, 1e6, 1e30 and the largest finite.
template <class S> void axis_batch_gives_the_element_bits(const Ops<S>& ops) {
  using Lim = std::numeric_limits<S>;
  constexpr int E = std::is_same_v<S, float> ? 40 : 300;
  constexpr std::size_t kCases = 61;
  LawRng rng(63);
  std::vector<S> c(3 * kCases), u(3 * kCases), angle(kCases), p(3 * kCases);
  for (std::size_t i = 0; i < kCases; ++i) {
    S* ci = &c[3 * i];
    S* ui = &u[3 * i];
    S* pi = &p[3 * i];
    for (std::size_t j = 0; j < 3; ++j)
      ci[j] = S(rng.uniform(-10, 10)), ui[j] = S(rng.uniform(-1, 1) * rng.uniform(0.25, 4)), pi[j] = S(rng.uniform(-10, 10));
    angle[i] = S(rng.uniform(-7, 7));
    switch ((7 * i) % 29) {
      case 1: ui[0] = ui[1] = ui[2] = 0; break;
      case 2: ui[0] = -S(0), ui[1] = 0, ui[2] = -S(0); break;
      case 3: ui[0] = Lim::denorm_min(), ui[1] = 0, ui[2] = -2 * Lim::denorm_min(); break;
      case 4: for (std::size_t j = 0; j < 3; ++j) ui[j] = std::ldexp(ui[j], E); break;
      case 5: for (std::size_t j = 0; j < 3; ++j) ui[j] = std::ldexp(ui[j], -E); break;
      case 6: ui[1] = Lim::quiet_NaN(); break;
      case 7: ui[2] = Lim::infinity(); break;
      case 8: ci[0] = Lim::quiet_NaN(); break;
      case 9: ci[1] = -Lim::infinity(); break;
      case 10: angle[i] = Lim::quiet_NaN(); break;
      case 11: angle[i] = Lim::infinity(); break;
      case 12: angle[i] = -Lim::infinity(); break;
      case 13: angle[i] = 0; break;
      case 14: angle[i] = -S(0); break;
      case 15: angle[i] = S(1e6); break;
      case 16: angle[i] = S(1e30); break;
      case 17: angle[i] = -Lim::max(); break;
      case 18: pi[2] = Lim::quiet_NaN(); break;
      case 19: pi[0] = Lim::infinity(); break;
      case 20: ci[0] = ci[1] = ci[2] = 0, pi[0] = -S(0); break;
      case 21: ci[2] = Lim::max() / 4; break;  // finite: the lanes take it
      default: break;
    }
  }
  batch_matches_elements<S>("rotate_about_axis", kCases, 3, [&](std::size_t n, std::size_t i, S* o, std::uint8_t* st) {
    return ops.rotate_about_axis(n, &c[3 * i], &u[3 * i], &angle[i], &p[3 * i], o, st);
  });
}

}  // namespace rotorcert::testing::rigid_laws
