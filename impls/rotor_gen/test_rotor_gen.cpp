// rotor_gen: (a) the generated kernels against the reference algebra's own products, exactly (the
// inputs are small integers, so every product and sum is exact in binary64); (b) the batched ops
// against the reference on batches that mix fast-path and slow-path elements (ordinary, beyond the
// ordinary range, subnormal, zero, NaN, hemisphere ties), every element also equal to the same
// element computed alone; (c) a smoke check of every op.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <rotorcert/reference/algebra.hpp>
#include <rotorcert/reference/multivector.hpp>
#include <rotorcert/testing/clause.hpp>

#include "../rotor/rotor_test_support.hpp"
#include "../tests/rotor_smoke.hpp"
#include "rotor_gen_kernels.hpp"

extern "C" const rc_impl* rotorcert_impl_entry_rotor_gen(std::uint32_t abi, std::uint32_t index);

namespace {

using namespace rotor_test;
namespace gen = rotorcert::rotor_gen;
namespace ref = rotorcert::ref;

// ---- (a) generated kernels = reference products ----------------------------------------------------

template <class A> using MVd = ref::Multivector<A, double>;

/// sum_k x_k * (the reference's signed blade of name_k), e.g. "e31" = e3 e1 = -e13.
template <class A, std::size_t N>
MVd<A> from_names(const std::array<const char*, N>& names, const std::array<double, N>& x) {
  MVd<A> m;
  for (std::size_t k = 0; k < N; ++k) m = m + x[k] * ref::blade_from_name<A, double>(names[k]);
  return m;
}
/// The coefficient of a named blade (its signed basis blade has a single +-1 entry).
template <class A>
double component(const MVd<A>& m, const char* name) {
  const MVd<A> b = ref::blade_from_name<A, double>(name);
  for (ref::Bitmap i = 0; i < ref::Bitmap(A::size); ++i)
    if (b.c[i] != 0) return b.c[i] * m.c[i];
  return 0;
}
template <class A>
bool only_grades(const MVd<A>& m, std::initializer_list<int> grades) {
  for (ref::Bitmap i = 0; i < ref::Bitmap(A::size); ++i)
    if (m.c[i] != 0 && std::find(grades.begin(), grades.end(), ref::grade_of(i)) == grades.end()) return false;
  return true;
}

constexpr std::array<const char*, 4> kEvenNames{"1", "e23", "e31", "e12"};
constexpr std::array<const char*, 3> kVectorNames{"e1", "e2", "e3"};
constexpr std::array<const char*, 8> kMotorNames{"1", "e23", "e31", "e12", "e01", "e02", "e03", "e0123"};
constexpr std::array<const char*, 4> kPointNames{"e032", "e013", "e021", "e123"};

template <std::size_t N>
std::array<double, N> small_integers() {
  std::array<double, N> a;
  for (double& x : a) x = *rc::gen::inRange(-9, 10);
  return a;
}

gen::Cl3Even<double> even(const std::array<double, 4>& x) { return {x[0], x[1], x[2], x[3]}; }
gen::PgaMotor<double> motor(const std::array<double, 8>& x) { return {x[0], x[1], x[2], x[3], x[4], x[5], x[6], x[7]}; }

RC_GTEST_PROP(RotorGenKernels, Cl3MatchTheReferenceExactly, ()) {
  RC_CLAUSE("ALG-1");
  RC_CLAUSE("ALG-2");
  RC_CLAUSE("ALG-4");
  RC_CLAUSE("ALG-6");
  using A = ref::Cl3;
  const auto xa = small_integers<4>(), xb = small_integers<4>();
  const auto xv = small_integers<3>();
  const MVd<A> a = from_names<A>(kEvenNames, xa), b = from_names<A>(kEvenNames, xb);
  const MVd<A> v = from_names<A>(kVectorNames, xv);

  const MVd<A> ab = ref::gp(a, b);
  const gen::Cl3Even<double> g = gen::cl3_gp(even(xa), even(xb));
  RC_ASSERT(only_grades(ab, {0, 2}));
  RC_ASSERT(g.s == component(ab, "1"));
  RC_ASSERT(g.e23 == component(ab, "e23"));
  RC_ASSERT(g.e31 == component(ab, "e31"));
  RC_ASSERT(g.e12 == component(ab, "e12"));

  const gen::Cl3Even<double> r = gen::cl3_reverse(even(xa));
  const MVd<A> ra = ref::reverse(a);
  RC_ASSERT(r.s == component(ra, "1") && r.e23 == component(ra, "e23") && r.e31 == component(ra, "e31") &&
            r.e12 == component(ra, "e12"));
  RC_ASSERT(gen::cl3_norm2(even(xa)) == ref::gp(a, ref::reverse(a)).c[0]);
  RC_ASSERT(gen::cl3_scalar_product(even(xa), even(xb)) == ref::gp(a, ref::reverse(b)).c[0]);

  const MVd<A> s = ref::gp(ref::gp(a, v), ref::reverse(a));
  RC_ASSERT(only_grades(s, {1}));
  const gen::Cl3Vector<double> w = gen::cl3_sandwich_vector(even(xa), gen::Cl3Vector<double>{xv[0], xv[1], xv[2]});
  RC_ASSERT(w.e1 == component(s, "e1"));
  RC_ASSERT(w.e2 == component(s, "e2"));
  RC_ASSERT(w.e3 == component(s, "e3"));
}

RC_GTEST_PROP(RotorGenKernels, PgaMatchTheReferenceExactly, ()) {
  RC_CLAUSE("ALG-7");
  RC_CLAUSE("ALG-2");
  RC_CLAUSE("ALG-6");
  using A = ref::PGA3;
  const auto xa = small_integers<8>(), xb = small_integers<8>();
  const auto xp = small_integers<4>();
  const MVd<A> a = from_names<A>(kMotorNames, xa), b = from_names<A>(kMotorNames, xb);

  const MVd<A> ab = ref::gp(a, b);
  const gen::PgaMotor<double> g = gen::pga_gp(motor(xa), motor(xb));
  const std::array<double, 8> got{g.s, g.e23, g.e31, g.e12, g.e01, g.e02, g.e03, g.e0123};
  RC_ASSERT(only_grades(ab, {0, 2, 4}));
  for (std::size_t k = 0; k < 8; ++k) RC_ASSERT(got[k] == component(ab, kMotorNames[k]));

  const gen::PgaMotor<double> r = gen::pga_reverse(motor(xa));
  const MVd<A> ra = ref::reverse(a);
  const std::array<double, 8> rev{r.s, r.e23, r.e31, r.e12, r.e01, r.e02, r.e03, r.e0123};
  for (std::size_t k = 0; k < 8; ++k) RC_ASSERT(rev[k] == component(ra, kMotorNames[k]));
  RC_ASSERT(gen::pga_norm2(motor(xa)) == ref::gp(a, ref::reverse(a)).c[0]);

  // A weighted point (any w), a point (w = 1) and a direction (w = 0).
  for (const double weight : {xp[3], 1.0, 0.0}) {
    const std::array<double, 4> p{xp[0], xp[1], xp[2], weight};
    const MVd<A> s = ref::gp(ref::gp(a, from_names<A>(kPointNames, p)), ref::reverse(a));
    RC_ASSERT(only_grades(s, {3}));
    const gen::PgaPoint<double> in{p[0], p[1], p[2], p[3]};
    const gen::PgaPoint<double> y = weight == 1.0   ? gen::pga_sandwich_point(motor(xa), in)
                                    : weight == 0.0 ? gen::pga_sandwich_direction(motor(xa), in)
                                                    : gen::pga_sandwich(motor(xa), in);
    const std::array<double, 4> out{y.x, y.y, y.z, y.w};
    for (std::size_t k = 0; k < 4; ++k) RC_ASSERT(out[k] == component(s, kPointNames[k]));
    const gen::PgaPoint<double> z = gen::pga_sandwich(motor(xa), in);  // the general kernel agrees too
    RC_ASSERT(z.x == y.x && z.y == y.y && z.z == y.z && z.w == y.w);
  }
}

// ---- (b) the batched ops on both paths --------------------------------------------------------------

template <class S> const Ops<S>& gen_ops() { return ops_of<S>(&rotorcert_impl_entry_rotor_gen); }

/// Scales that send an element down the fast path (1), or the slow one: |q|^2 beyond the ordinary
/// range either way, components subnormal, components near the overflow threshold.
template <class S>
std::vector<S> scales() {
  constexpr int w = std::numeric_limits<S>::max_exponent / 4;
  return {S(1), S(1), S(1), std::ldexp(S(1), w + 6), std::ldexp(S(1), -w - 6),
          std::numeric_limits<S>::denorm_min() * S(64), std::numeric_limits<S>::max() / S(4),
          sizeof(S) == 4 ? S(1e30) : S(1e300), sizeof(S) == 4 ? S(1e-30) : S(1e-300)};
}

template <class S>
Q<S> times(const Q<S>& q, S k) { return {q[0] * k, q[1] * k, q[2] * k, q[3] * k}; }

/// One batch of `n` elements per hot op, each element of random rotation and random scale; every
/// element is judged against the reference and must equal the same element computed alone.
template <class S>
void hot_ops_on_both_paths() {
  namespace c = rotorcert::ref::clause;
  using rotorcert::testing::quaternion;
  using rotorcert::testing::real_in;
  using rotorcert::testing::vector3;
  const Ops<S>& o = gen_ops<S>();
  const std::vector<S> k = scales<S>();
  const std::size_t n = *rc::gen::inRange<std::size_t>(1, 150);
  std::vector<Q<S>> a(n), b(n);
  std::vector<V<S>> v(n);
  std::vector<S> t(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Q<S> ua = round_to<S>(*quaternion()), ub = round_to<S>(*quaternion());
    // Exactly representable after scaling: the scales are powers of two or keep the grid's few bits.
    a[i] = times(ua, k[*rc::gen::inRange<std::size_t>(0, k.size())]);
    b[i] = times(ub, k[*rc::gen::inRange<std::size_t>(0, k.size())]);
    for (int j = 0; j < 4; ++j) a[i][j] = std::isfinite(a[i][j]) ? a[i][j] : ua[j];
    for (int j = 0; j < 4; ++j) b[i][j] = std::isfinite(b[i][j]) ? b[i][j] : ub[j];
    v[i] = round_to<S>(*vector3());
    t[i] = round_to<S>(*real_in(2));
  }
  std::vector<Q<S>> q(n);
  std::vector<V<S>> w(n);
  std::vector<std::uint8_t> st(n);
  Q<S> q1;
  V<S> w1;
  std::uint8_t st1;
  auto same = [](const auto& x, const auto& y) {
    for (std::size_t j = 0; j < x.size(); ++j)
      if (!(x[j] == y[j] || (std::isnan(x[j]) && std::isnan(y[j])))) return false;
    return true;
  };

  o.normalize(n, a[0].data(), q[0].data(), st.data());
  for (std::size_t i = 0; i < n; ++i) {
    RC_ASSERT(st[i] == RC_OK);
    RC_ASSERT(rotation_error(q[i], c::NORM_1_normalize(real(a[i])).value) <= bar("eps4"));
    o.normalize(1, a[i].data(), q1.data(), &st1);
    RC_ASSERT(same(q1, q[i]));
  }
  o.compose(n, a[0].data(), b[0].data(), q[0].data(), st.data());
  for (std::size_t i = 0; i < n; ++i) {
    RC_ASSERT(st[i] == RC_OK);
    const RQ ab = real(a[i]) * real(b[i]);
    // A product beyond the format (huge * huge) or below it (tiny * tiny) is not representable.
    const double scale = norm(ab).toDouble();
    if (scale < double(std::numeric_limits<S>::max()) / 4 && scale > double(std::numeric_limits<S>::min()))
      RC_ASSERT(relative_error(q[i], ab) <= bar("eps8"));
    o.compose(1, a[i].data(), b[i].data(), q1.data(), &st1);
    RC_ASSERT(same(q1, q[i]));
  }
  o.apply_vector(n, a[0].data(), v[0].data(), w[0].data(), st.data());
  for (std::size_t i = 0; i < n; ++i) {
    RC_ASSERT(st[i] == RC_OK);
    RC_ASSERT(vector_error(w[i], c::APPLY_1_apply_vector(real(a[i]), real(v[i])).value, length(real(v[i]))) <=
              bar("eps8"));
    o.apply_vector(1, a[i].data(), v[i].data(), w1.data(), &st1);
    RC_ASSERT(same(w1, w[i]));
  }
  o.nlerp(n, a[0].data(), b[0].data(), t.data(), q[0].data(), st.data());
  for (std::size_t i = 0; i < n; ++i) {
    RC_ASSERT(st[i] == RC_OK);
    RC_ASSERT(rotation_error(q[i], c::NLERP_1_nlerp(real(a[i]), real(b[i]), Real(t[i])).value) <= bar("eps16"));
    o.nlerp(1, a[i].data(), b[i].data(), &t[i], q1.data(), &st1);
    RC_ASSERT(same(q1, q[i]));
  }
  o.slerp(n, a[0].data(), b[0].data(), t.data(), q[0].data(), st.data());
  for (std::size_t i = 0; i < n; ++i) {
    RC_ASSERT(st[i] == RC_OK);
    RC_ASSERT(rotation_error(q[i], c::SLERP_1_slerp(real(a[i]), real(b[i]), Real(t[i])).value) <= bar("eps16"));
    o.slerp(1, a[i].data(), b[i].data(), &t[i], q1.data(), &st1);
    RC_ASSERT(same(q1, q[i]));
  }
}

RC_GTEST_PROP(RotorGen, HotOpsAgreeWithTheReferenceOnBothPaths, ()) {
  RC_CLAUSE("NORM-1");
  RC_CLAUSE("COMPOSE-1");
  RC_CLAUSE("APPLY-1");
  RC_CLAUSE("NLERP-1");
  RC_CLAUSE("SLERP-1");
  RC_CLAUSE("EDGE-5");
  RC_CLAUSE("EDGE-8");
  hot_ops_on_both_paths<float>();
  hot_ops_on_both_paths<double>();
}

/// Zero and NaN elements among good ones: DOMAIN_ERROR and NaN outputs for them only.
template <class S>
void bad_elements_among_good_ones() {
  const Ops<S>& o = gen_ops<S>();
  const S nan = std::numeric_limits<S>::quiet_NaN(), inf = std::numeric_limits<S>::infinity();
  const std::size_t n = 70;  // two blocks
  std::vector<Q<S>> a(n, Q<S>{S(0.5), S(-0.5), S(0.5), S(0.5)}), b(n, Q<S>{0, S(0.6), 0, S(0.8)});
  std::vector<V<S>> v(n, V<S>{1, 2, 3});
  std::vector<S> t(n, S(0.25));
  const std::vector<std::size_t> bad{3, 64, 69};
  a[3] = Q<S>{0, -S(0), 0, 0};
  a[64] = Q<S>{nan, 0, 0, 1};
  b[69] = Q<S>{0, inf, 0, 1};
  v[3] = V<S>{nan, 0, 0};
  t[64] = inf;
  std::vector<Q<S>> q(n);
  std::vector<V<S>> w(n);
  std::vector<std::uint8_t> st(n);
  auto expect = [&](auto& out, const char* op, bool b_matters) {
    for (std::size_t i = 0; i < n; ++i) {
      const bool is_bad = i == 3 || i == 64 || (b_matters && i == 69);
      EXPECT_EQ(st[i], is_bad ? RC_DOMAIN_ERROR : RC_OK) << op << " element " << i;
      EXPECT_EQ(std::isnan(out[i][0]), is_bad) << op << " element " << i;
    }
  };
  o.normalize(n, a[0].data(), q[0].data(), st.data());
  expect(q, "normalize", false);
  o.compose(n, a[0].data(), b[0].data(), q[0].data(), st.data());
  expect(q, "compose", true);
  o.apply_vector(n, a[0].data(), v[0].data(), w[0].data(), st.data());
  expect(w, "apply_vector", false);
  o.nlerp(n, a[0].data(), b[0].data(), t.data(), q[0].data(), st.data());
  expect(q, "nlerp", true);
  o.slerp(n, a[0].data(), b[0].data(), t.data(), q[0].data(), st.data());
  expect(q, "slerp", true);
}

TEST(RotorGen, ZeroAndNonFiniteElementsAreDomainErrorsAlone) {
  RC_CLAUSE("EDGE-6");
  RC_CLAUSE("EDGE-7");
  bad_elements_among_good_ones<float>();
  bad_elements_among_good_ones<double>();
}

/// Ties and identities, which the fast path hands to the exact slow path.
TEST(RotorGen, HemisphereTiesAndIdentitiesInABatch) {
  RC_CLAUSE("EDGE-1");
  RC_CLAUSE("EDGE-3");
  namespace c = rotorcert::ref::clause;
  const Ops<double>& o = gen_ops<double>();
  // slerp(1, i, 1/2) and slerp(1, -i, 1/2): dot 0, no flip (EDGE-3); slerp(1, 1, t) = 1 (EDGE-1).
  const std::array<Q<double>, 3> a{Q<double>{0, 0, 0, 1}, Q<double>{0, 0, 0, 1}, Q<double>{0, 0, 0, 1}};
  const std::array<Q<double>, 3> b{Q<double>{1, 0, 0, 0}, Q<double>{-1, 0, 0, 0}, Q<double>{0, 0, 0, 1}};
  const std::array<double, 3> t{0.5, 0.5, 0.3};
  std::array<Q<double>, 3> q;
  std::array<std::uint8_t, 3> st;
  for (auto op : {o.slerp, o.nlerp}) {
    op(3, a[0].data(), b[0].data(), t.data(), q[0].data(), st.data());
    for (int i = 0; i < 2; ++i) {
      const RQ r = op == o.slerp ? c::SLERP_1_slerp(real(a[i]), real(b[i]), Real(t[i])).value
                                 : c::NLERP_1_nlerp(real(a[i]), real(b[i]), Real(t[i])).value;
      // Componentwise (not METRIC-1, which is sign-blind): the tie must not flip.
      EXPECT_LE(relative_error(q[i], r), bar("eps16"));
    }
    EXPECT_EQ(q[2], a[2]);
  }
  const V<double> v{0.1, -3, 7};
  V<double> w;
  std::uint8_t s1;
  o.apply_vector(1, a[0].data(), v.data(), w.data(), &s1);
  EXPECT_EQ(w, v);
  o.compose(1, a[0].data(), a[0].data(), q[0].data(), &s1);
  EXPECT_EQ(q[0], a[0]);
}

// ---- (c) every op -----------------------------------------------------------------------------------

RC_GTEST_PROP(RotorGen, SmokeAgainstReference, ()) {
  smoke_against_reference(gen_ops<float>(), gen_ops<double>());  // names its clauses (../tests/rotor_smoke.hpp)
}

}  // namespace
