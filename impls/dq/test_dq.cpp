// Implementation-specific facts of `dq` (impls/dq/dq.cpp), through its ABI tables, and a short
// smoke check against the reference (the systematic differential run is the suite's job).
// Tolerances are the spec's eps class bars (spec/clauses.json), never ad-hoc epsilons.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <span>
#include <vector>

#include <gtest/gtest.h>

#include <rotorcert/impl.hpp>
#include <rotorcert/reference/metrics.hpp>
#include <rotorcert/reference/rigid_ops.hpp>
#include <rotorcert/reference/rotation_ops.hpp>
#include <rotorcert/testing/abi_values.hpp>
#include <rotorcert/testing/clause.hpp>
#include <rotorcert/testing/quat_batch_laws.hpp>
#include <rotorcert/testing/rigid_law_tests.hpp>
#include <rotorcert/testing/rigid_laws.hpp>
#include <rotorcert/testing/tolerance.hpp>

extern "C" const rc_impl* rotorcert_impl_entry_dq(std::uint32_t abi, std::uint32_t index);

namespace {

namespace ref = rotorcert::ref;
namespace cl = rotorcert::ref::clause;
using ref::Real;
using rotorcert::testing::eps_class_bars;
using namespace rotorcert::testing::abi;
namespace rigid_laws = rotorcert::testing::rigid_laws;

// ---- the tables and single-element calls ----------------------------------------------------------

template <class S> const rotorcert::impl::Ops<S>& ops() {
  if constexpr (std::is_same_v<S, float>) return *rotorcert_impl_entry_dq(RC_ABI_VERSION, 0)->f32;
  else return *rotorcert_impl_entry_dq(RC_ABI_VERSION, 1)->f64;
}

double strict(const char* cls) { return eps_class_bars(cls).strict; }

template <class S> D<S> normalize_dq(const D<S>& d, std::uint8_t& st) {
  D<S> out;
  ops<S>().dq_normalize(1, d.data(), out.data(), &st);
  return out;
}
template <class S> D<S> sclerp(const D<S>& a, const D<S>& b, S t) {
  D<S> out;
  std::uint8_t st = 9;
  ops<S>().dq_sclerp(1, a.data(), b.data(), &t, out.data(), &st);
  EXPECT_EQ(st, RC_OK);
  return out;
}
template <class S> V<S> skin(bool dual, const std::vector<Q<S>>& q, const std::vector<V<S>>& t, const std::vector<S>& w,
                             const V<S>& v, std::uint8_t& st) {
  V<S> out;
  const auto f = dual ? ops<S>().skin_dual_quaternion : ops<S>().skin_linear;
  f(1, q.size(), q.front().data(), t.front().data(), w.data(), v.data(), out.data(), &st);
  return out;
}

// Conversions to the reference's types and errors in eps units: rotorcert/testing/abi_values.hpp.

// ---- random inputs (fixed seed: reproducible) --------------------------------------------------------

struct Rng : rigid_laws::LawRng {
  Rng() : LawRng(20240611) {}
  /// A rigid motion from DQ-1 of the table under test.
  template <class S> D<S> rigid() { return LawRng::rigid<S>(ops<S>()); }
};

template <class F> void both(F f) {
  f(float{});
  f(double{});
}

// ---- facts -------------------------------------------------------------------------------------------

TEST(Dq, SclerpNearZeroRotationHasNoZeroOverZero) {
  RC_CLAUSE("DQ-5");
  RC_CLAUSE("EDGE-2");
  both([](auto tag) {
    using S = decltype(tag);
    Rng rng;
    for (const double angle : {1e-30, 1e-9, 1e-6, 1e-3, 0.5}) {
      const D<S> a = rng.rigid<S>();
      // b = a composed with a small screw about a random axis: rotation `angle`, offset axis.
      const V<S> axis = rng.vec<S>(1);
      const S sn = S(std::sin(angle / 2)), cs = S(std::cos(angle / 2));
      const double len = std::sqrt(double(axis[0]) * axis[0] + double(axis[1]) * axis[1] + double(axis[2]) * axis[2]);
      const Q<S> q{S(sn * axis[0] / len), S(sn * axis[1] / len), S(sn * axis[2] / len), cs};
      const V<S> t = rng.vec<S>(5);
      D<S> small, b;
      std::uint8_t st;
      ops<S>().dq_from_rotation_translation(1, q.data(), t.data(), small.data(), &st);
      ops<S>().dq_compose(1, a.data(), small.data(), b.data(), &st);
      for (const S tt : {S(0.3), S(-2)}) {
        const D<S> s = sclerp(a, b, tt);
        for (S x : s) EXPECT_TRUE(std::isfinite(x));
        EXPECT_LE(rigid_err(s, cl::DQ_5_sclerp(rd(a), rd(b), Real(tt)).value), strict("eps32")) << angle;
      }
    }
  });
}

/// Candy wrapper: a vertex at radius r around the bone axis x, two influences that twist by +theta
/// and -theta about the bone with equal weights. LBS averages the two positions and pulls the
/// vertex onto the axis by |cos theta| (at theta = pi/2 to the axis itself). DQS of the same
/// vertex keeps the radius: RigidLaws.DqsKeepsTheRadiusOfATwistedVertex (rigid_law_tests.hpp).
TEST(Dq, CandyWrapperLbsShrinks) {
  RC_CLAUSE("SKIN-1");
  both([](auto tag) {
    using S = decltype(tag);
    for (int k = 1; k < 16; ++k) {
      const double theta = k * 3.14159265358979323846 / 16;
      const S sn = S(std::sin(theta / 2)), cs = S(std::cos(theta / 2));
      const std::vector<Q<S>> q{{sn, 0, 0, cs}, {-sn, 0, 0, cs}};
      const std::vector<V<S>> t{{0, 0, 0}, {0, 0, 0}};
      const std::vector<S> w{S(0.5), S(0.5)};
      const V<S> v{S(0.75), S(1.5), S(0)};
      const Real radius(v[1]);
      std::uint8_t st1 = 9;
      const V<S> lbs = skin<S>(false, q, t, w, v, st1);
      ASSERT_EQ(st1, RC_OK);
      // The exact radii of the quaternions as rounded: cos theta = cs^2 - sn^2 over |q|^2.
      const Real c2 = (Real(cs) * Real(cs) - Real(sn) * Real(sn)) / (Real(cs) * Real(cs) + Real(sn) * Real(sn));
      const Real scale = max(Real(1), norm3(rv(v)));
      const auto radius_of = [](const V<S>& p) { return sqrt(Real(p[1]) * Real(p[1]) + Real(p[2]) * Real(p[2])); };
      EXPECT_LE((abs(radius_of(lbs) - radius * abs(c2)) / scale / eps<S>()).toDouble(), strict("eps64")) << theta;
      // It leaves the position along the bone alone.
      EXPECT_LE((abs(Real(lbs[0]) - Real(v[0])) / scale / eps<S>()).toDouble(), strict("eps64"));
    }
  });
}

/// dq also offers the quaternion ops of Core: the identity quaternion composes and rotates exactly
/// (the identity motion: RigidLaws.IdentityInIdentityOut).
TEST(Dq, QuaternionIdentityInIdentityOut) {
  RC_CLAUSE("EDGE-1");
  both([](auto tag) {
    using S = decltype(tag);
    const Q<S> one{0, 0, 0, 1};
    const V<S> p{S(0.1), S(-7), S(3e5)};
    std::uint8_t st = 9;
    Q<S> q;
    ops<S>().compose(1, one.data(), one.data(), q.data(), &st);
    EXPECT_EQ(q, one);
    V<S> out;
    ops<S>().apply_vector(1, one.data(), p.data(), out.data(), &st);
    EXPECT_EQ(out, p);
  });
}

TEST(Dq, SubnormalAndHugeInputsKeepFullAccuracy) {
  RC_CLAUSE("NORM-1");
  RC_CLAUSE("INV-1");
  RC_CLAUSE("EDGE-8");
  both([](auto tag) {
    using S = decltype(tag);
    const S tiny = std::numeric_limits<S>::denorm_min(), huge = std::numeric_limits<S>::max() / 2;
    std::uint8_t st = 9;
    Q<S> out;
    const Q<S> sub{tiny, -S(0), 0, 0};
    ops<S>().normalize(1, sub.data(), out.data(), &st);
    EXPECT_EQ(st, RC_OK);
    EXPECT_EQ(out, (Q<S>{1, -S(0), 0, 0}));
    EXPECT_TRUE(std::signbit(out[1]));
    for (const Q<S>& q : {Q<S>{3 * tiny, 0, 4 * tiny, 0}, Q<S>{huge, huge, -huge, huge}}) {
      ops<S>().normalize(1, q.data(), out.data(), &st);
      EXPECT_LE((cl::METRIC_1_rotation_distance(rq(out), rq(q)) / eps<S>()).toDouble(), strict("eps4"));
      EXPECT_LE((cl::METRIC_6_norm_defect(rq(out)) / eps<S>()).toDouble(), strict("eps4"));
    }
    // INV-1 of a subnormal quaternion: |q|^2 underflows unless scaled first; the inverse is near
    // the overflow threshold.
    const int e = std::is_same_v<S, float> ? -130 : -1026;
    const Q<S> q{S(3) * std::ldexp(S(1), e), 0, 0, S(4) * std::ldexp(S(1), e)};
    ops<S>().inverse(1, q.data(), out.data(), &st);
    EXPECT_EQ(st, RC_OK);
    const auto want = cl::INV_1_inverse(rq(q)).value;
    const auto got = rq(out);
    const Real err = max(max(abs(got.w - want.w), abs(got.x - want.x)), max(abs(got.y - want.y), abs(got.z - want.z)));
    EXPECT_LE((err / ref::norm(want) / eps<S>()).toDouble(), strict("eps4"));
  });
}

// ---- smoke check against the reference -------------------------------------------------------------

TEST(Dq, QuaternionBatchesGiveTheElementFunctionsBits) {
  RC_CLAUSE("NORM-1");
  RC_CLAUSE("COMPOSE-1");
  RC_CLAUSE("APPLY-1");
  RC_CLAUSE("EDGE-5");
  RC_CLAUSE("EDGE-8");
  rotorcert::testing::quat_batch_laws::batch_gives_the_element_bits<float>(ops<float>());
  rotorcert::testing::quat_batch_laws::batch_gives_the_element_bits<double>(ops<double>());
}

/// INV-1's batch (SIMD lanes where |q|^2 is ordinary: dq.cpp InverseLanes) gives bit for bit and
/// status for status what one-element calls give, on 61 elements (blocks of 16, of 4, one alone)
/// with, spread over blocks and lanes, quaternions scaled by 2^+-E beyond the ordinary range, with
/// components near the largest finite, zero and -0, subnormal, NaN and +-Inf (the quaternion batch
/// law above sees fewer of these).
TEST(Dq, InverseBatchGivesTheElementBits) {
  RC_CLAUSE("INV-1");
  RC_CLAUSE("EDGE-5");
  RC_CLAUSE("EDGE-6");
  RC_CLAUSE("EDGE-7");
  RC_CLAUSE("EDGE-8");
  both([](auto tag) {
    using S = decltype(tag);
    using Lim = std::numeric_limits<S>;
    constexpr int E = std::is_same_v<S, float> ? 40 : 300;
    constexpr std::size_t kCases = 61;
    Rng rng;
    std::vector<S> q(4 * kCases);
    for (std::size_t i = 0; i < kCases; ++i) {
      S* x = &q[4 * i];
      const Q<S> r = rng.quat<S>();
      for (std::size_t c = 0; c < 4; ++c) x[c] = r[c] * S(1 + i % 4);
      switch ((7 * i) % 23) {
        case 1: for (std::size_t c = 0; c < 4; ++c) x[c] = std::ldexp(x[c], E); break;
        case 2: for (std::size_t c = 0; c < 4; ++c) x[c] = std::ldexp(x[c], -E); break;
        case 3: x[1] = Lim::max(), x[2] = -Lim::max() / 2; break;
        case 4: x[0] = x[1] = x[2] = x[3] = 0; break;
        case 5: x[0] = -S(0), x[1] = 0, x[2] = -S(0), x[3] = -S(0); break;
        case 6: x[0] = Lim::denorm_min(), x[1] = x[2] = x[3] = -S(0); break;
        case 7: x[3] = Lim::quiet_NaN(); break;
        case 8: x[0] = Lim::infinity(); break;
        case 9: x[2] = -Lim::infinity(); break;
        case 10: x[0] = x[1] = x[2] = 0; break;  // a scalar quaternion: conj keeps -0 signs
        default: break;
      }
    }
    std::vector<S> batch(4 * kCases);
    std::vector<std::uint8_t> st(kCases, 9);
    ASSERT_EQ(ops<S>().inverse(kCases, q.data(), batch.data(), st.data()), 0);
    for (std::size_t i = 0; i < kCases; ++i) {
      S one[4];
      std::uint8_t st1 = 9;
      ASSERT_EQ(ops<S>().inverse(1, &q[4 * i], one, &st1), 0);
      EXPECT_EQ(st[i], st1) << "element " << i;
      EXPECT_EQ(0, std::memcmp(&batch[4 * i], one, sizeof one)) << "element " << i;
    }
  });
}

/// dq's quaternion ops of Core (its rigid ops: RigidLaws.SmokeAgainstReference).
TEST(Dq, QuaternionSmokeAgainstReference) {
  RC_CLAUSE("COMPOSE-1");
  RC_CLAUSE("APPLY-1");
  both([](auto tag) {
    using S = decltype(tag);
    Rng rng;
    std::uint8_t st = 9;
    for (int i = 0; i < 40; ++i) {
      const Q<S> q = rng.quat<S>(), q2 = rng.quat<S>();
      const V<S> p = rng.vec<S>(10);
      V<S> moved;
      ops<S>().apply_vector(1, q.data(), p.data(), moved.data(), &st);
      EXPECT_LE(vec_err(moved, cl::APPLY_1_apply_vector(rq(q), rv(p)).value, norm3(rv(p))), strict("eps8"));
      Q<S> prod;
      ops<S>().compose(1, q.data(), q2.data(), prod.data(), &st);
      // COMPOSE-1 defines the exact product of the inputs as given (QUAT-1), norm |a||b|.
      const auto want = rq(q) * rq(q2), got = rq(prod);
      const Real err = max(max(abs(got.w - want.w), abs(got.x - want.x)), max(abs(got.y - want.y), abs(got.z - want.z)));
      EXPECT_LE((err / ref::norm(want) / eps<S>()).toDouble(), strict("eps8"));
    }
  });
}

TEST(Dq, SkinningSmokeAgainstReference) {
  RC_CLAUSE("SKIN-1");
  RC_CLAUSE("SKIN-2");
  RC_CLAUSE("SKIN-3");
  both([](auto tag) {
    using S = decltype(tag);
    Rng rng;
    for (int i = 0; i < 40; ++i) {
      const std::size_t k = 1 + i % 4;
      std::vector<Q<S>> q;
      std::vector<V<S>> t;
      std::vector<S> w;
      std::vector<ref::Quaternion<Real>> rqs;
      std::vector<ref::Vec3<Real>> rts;
      std::vector<Real> rws;
      Real scale(1);
      for (std::size_t j = 0; j < k; ++j) {
        q.push_back(rng.quat<S>());
        t.push_back(rng.vec<S>(10));
        w.push_back(S(rng.uniform(0, 1)));
        rqs.push_back(rq(q.back()));
        rts.push_back(rv(t.back()));
        rws.push_back(Real(w.back()));
        scale = max(scale, norm3(rts.back()));
      }
      const V<S> v = rng.vec<S>(10);
      scale = max(scale, norm3(rv(v)));
      std::uint8_t st;
      EXPECT_LE(vec_err(skin<S>(false, q, t, w, v, st), cl::SKIN_1_linear_blend<Real>(rqs, rts, rws, rv(v)).value, scale),
                strict("eps64"));
      EXPECT_LE(vec_err(skin<S>(true, q, t, w, v, st), cl::SKIN_2_dual_quaternion<Real>(rqs, rts, rws, rv(v)).value, scale),
                strict("eps64"));
    }
  });
}

}  // namespace

// The laws that every table of dual-quaternion ops keeps, on dq's tables: Dq/RigidLaws/0.*
// (rotorcert/testing/rigid_law_tests.hpp; ctest shows Dq.<law><DqTables>).
struct DqTables : rotorcert::testing::rigid_laws::AbiTables<&rotorcert_impl_entry_dq> {};
namespace rotorcert::testing::rigid_laws {
INSTANTIATE_TYPED_TEST_SUITE_P(Dq, RigidLaws, DqTables);
}  // namespace rotorcert::testing::rigid_laws
