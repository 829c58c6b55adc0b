// Implementation-specific facts of `motor_pga`: the hand-expanded motor algebra of motor.hpp
// against the reference's generic geometric product (rotorcert::ref pga), and the ABI tables
// against the reference's dual-quaternion clauses (a short smoke check; the systematic run is
// the suite's). Tolerances are the spec's eps class bars, never ad-hoc epsilons.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <span>
#include <vector>

#include <gtest/gtest.h>

#include <rotorcert/impl.hpp>
#include <rotorcert/reference/metrics.hpp>
#include <rotorcert/reference/motor.hpp>
#include <rotorcert/reference/pga.hpp>
#include <rotorcert/reference/rigid_ops.hpp>
#include <rotorcert/reference/rotation_ops.hpp>
#include <rotorcert/testing/abi_values.hpp>
#include <rotorcert/testing/clause.hpp>
#include <rotorcert/testing/rigid_law_tests.hpp>
#include <rotorcert/testing/rigid_laws.hpp>
#include <rotorcert/testing/tolerance.hpp>

#include "motor.hpp"

extern "C" const rc_impl* rotorcert_impl_entry_motor_pga(std::uint32_t abi, std::uint32_t index);

namespace {

namespace ref = rotorcert::ref;
namespace cl = rotorcert::ref::clause;
namespace mp = rotorcert::motor_pga;
using ref::Real;
using rotorcert::testing::eps_class_bars;
using namespace rotorcert::testing::abi;
namespace rigid_laws = rotorcert::testing::rigid_laws;
using RMV = ref::pga::MV<Real>;

template <class S> const rotorcert::impl::Ops<S>& ops() {
  if constexpr (std::is_same_v<S, float>) return *rotorcert_impl_entry_motor_pga(RC_ABI_VERSION, 0)->f32;
  else return *rotorcert_impl_entry_motor_pga(RC_ABI_VERSION, 1)->f64;
}
double strict(const char* cls) { return eps_class_bars(cls).strict; }

// ---- motors <-> the reference's multivectors (exact) -----------------------------------------------

template <class S> RMV rmv(const mp::Motor<S>& m) {
  RMV r;
  r.c[0] = m.s;
  r.c[ref::pga::kE23] = m.e23;
  r.c[ref::pga::kE13] = -Real(m.e31);  // e31 = -e13
  r.c[ref::pga::kE12] = m.e12;
  r.c[ref::pga::kE01] = m.e01;
  r.c[ref::pga::kE02] = m.e02;
  r.c[ref::pga::kE03] = m.e03;
  r.c[ref::pga::kE0123] = m.e0123;
  return r;
}
template <class S> RMV rmv(const mp::Bivector<S>& b) {
  return ref::pga::bivector<Real>({Real(b.e23), Real(b.e31), Real(b.e12)}, {Real(b.e01), Real(b.e02), Real(b.e03)});
}
/// The 8 even coefficients of a reference multivector in Motor order (other grades must be 0).
std::array<Real, 8> even_coefficients(const RMV& m) {
  using namespace ref::pga;
  return {m.c[0], m.c[kE23], -m.c[kE13], m.c[kE12], m.c[kE01], m.c[kE02], m.c[kE03], m.c[kE0123]};
}
template <class S> std::array<Real, 8> coefficients(const mp::Motor<S>& m) {
  return {Real(m.s), Real(m.e23), Real(m.e31), Real(m.e12), Real(m.e01), Real(m.e02), Real(m.e03), Real(m.e0123)};
}
Real norm8(const std::array<Real, 8>& a) {
  Real s(0);
  for (const Real& x : a) s += x * x;
  return sqrt(s);
}
/// Largest coefficient difference over a scale, in eps units of S.
template <class S> double coefficient_err(const std::array<Real, 8>& got, const std::array<Real, 8>& want, const Real& scale) {
  Real e(0);
  for (int i = 0; i < 8; ++i) e = max(e, Real(abs(got[i] - want[i])));
  return (e / scale / eps<S>()).toDouble();
}

struct Rng : rigid_laws::LawRng {
  Rng() : LawRng(20240612) {}
  template <class S> mp::Motor<S> motor(double r) {
    return {S(uniform(-r, r)), S(uniform(-r, r)), S(uniform(-r, r)), S(uniform(-r, r)),
            S(uniform(-r, r)), S(uniform(-r, r)), S(uniform(-r, r)), S(uniform(-r, r))};
  }
  template <class S> mp::Motor<S> integer_motor() {
    const auto k = [&] { return S(std::floor(uniform(-8, 9))); };
    return {k(), k(), k(), k(), k(), k(), k(), k()};
  }
};

template <class F> void both(F f) {
  f(float{});
  f(double{});
}

// ---- the motor algebra against the reference's geometric product --------------------------------

TEST(MotorAlgebra, ProductIsTheGeometricProduct) {
  RC_CLAUSE("MOTOR-3");
  RC_CLAUSE("DQ-2");
  Rng rng;
  // Small integers: every product and sum is exact, so any sign error shows as an inequality.
  for (int i = 0; i < 500; ++i) {
    const auto a = rng.integer_motor<double>(), b = rng.integer_motor<double>();
    const auto want = even_coefficients(ref::gp(rmv(a), rmv(b)));
    EXPECT_EQ(coefficients(a * b), want);
  }
  // Random reals: within the rounding of 8-term sums.
  both([&](auto tag) {
    using S = decltype(tag);
    for (int i = 0; i < 200; ++i) {
      const auto a = rng.motor<S>(2), b = rng.motor<S>(2);
      const Real scale = norm8(coefficients(a)) * norm8(coefficients(b));
      EXPECT_LE(coefficient_err<S>(coefficients(a * b), even_coefficients(ref::gp(rmv(a), rmv(b))), scale), strict("eps8"));
    }
  });
}

TEST(MotorAlgebra, ReverseAndMotorOneMapMatchTheReference) {
  RC_CLAUSE("MOTOR-1");
  Rng rng;
  for (int i = 0; i < 50; ++i) {
    const auto m = rng.motor<double>(3);
    EXPECT_EQ(coefficients(mp::reverse(m)), even_coefficients(ref::reverse(rmv(m))));
    D<double> d = mp::to_dual_quaternion(m);
    EXPECT_EQ(even_coefficients(cl::MOTOR_1_from_dual_quaternion(rd(d))), coefficients(m));
    EXPECT_EQ(mp::to_dual_quaternion(mp::from_dual_quaternion(d)), d);
  }
}

TEST(MotorAlgebra, PointSandwichIsTheReferenceSandwich) {
  RC_CLAUSE("MOTOR-2");
  RC_CLAUSE("DQ-3");
  both([](auto tag) {
    using S = decltype(tag);
    Rng rng;
    for (int i = 0; i < 200; ++i) {
      const mp::Motor<S> m = mp::normalized(rng.motor<S>(2));
      const V<S> p = rng.vec<S>(10);
      const auto moved = mp::sandwich(m, mp::Point<S>{p[0], p[1], p[2], S(1)});
      EXPECT_EQ(moved.e123, S(1));
      const RMV rm = rmv(m);
      const auto want = ref::pga::point_coordinates(ref::gp(ref::gp(rm, ref::pga::point(rv(p))), ref::reverse(rm)));
      const ref::Vec3<Real> t = cl::DQ_1_translation(rd(mp::to_dual_quaternion(m))).value;
      EXPECT_LE(vec_err(V<S>{moved.e032, moved.e013, moved.e021}, want, std::max({Real(1), norm3(rv(p)), norm3(t)})),
                strict("eps16"));
    }
  });
}

TEST(MotorAlgebra, ExpAndLogMatchTheReferenceClosedForms) {
  RC_CLAUSE("MOTOR-4");
  both([](auto tag) {
    using S = decltype(tag);
    Rng rng;
    // |beta| from 0 through the series threshold (1/16) to pi/2 (what interpolation takes).
    for (const double angle : {0.0, 1e-30, 1e-8, 1e-3, 0.06, 0.0625, 0.07, 0.5, 1.5, 1.5707963}) {
      for (int i = 0; i < 20; ++i) {
        const V<S> axis = rng.vec<S>(1), ideal = rng.vec<S>(4);
        const double len = std::sqrt(double(axis[0]) * axis[0] + double(axis[1]) * axis[1] + double(axis[2]) * axis[2]);
        const mp::Bivector<S> B{S(angle * axis[0] / len), S(angle * axis[1] / len), S(angle * axis[2] / len),
                                ideal[0], ideal[1], ideal[2]};
        const mp::Motor<S> m = mp::exp(B);
        const Real scale = max(Real(1), norm3(rv(ideal)));
        EXPECT_LE(coefficient_err<S>(coefficients(m), even_coefficients(cl::MOTOR_4_exp(rmv(B))), scale), strict("eps32"))
            << angle;
        // log(exp B) = B for |beta| < pi. Checked against B itself: the reference's MOTOR_4_log
        // does not invert its own MOTOR_4_exp (nor the series exp) when the ideal part has a
        // component along beta (reported), so it cannot serve as the expected value here.
        const mp::Bivector<S> L = mp::log(m);
        const std::array<Real, 8> got{0, Real(L.e23), Real(L.e31), Real(L.e12), Real(L.e01), Real(L.e02), Real(L.e03), 0};
        EXPECT_LE(coefficient_err<S>(got, even_coefficients(rmv(B)), scale), strict("eps32")) << angle;
        // And exp(log M) = M through the reference's exp.
        EXPECT_LE(coefficient_err<S>(coefficients(m), even_coefficients(cl::MOTOR_4_exp(rmv(L))), scale), strict("eps32"))
            << angle;
      }
    }
  });
}

// ---- the ABI tables (with the laws of every table of dual-quaternion ops, at the end) -----------------

/// DQS through the motors: SKIN-2, whose blend of the influences' motors is MOTOR-5's (the
/// dual-quaternion ops of the tables, dq_blend among them: RigidLaws.SmokeAgainstReference).
TEST(MotorPga, SmokeAgainstReference) {
  RC_CLAUSE("MOTOR-5");
  RC_CLAUSE("SKIN-2");
  both([](auto tag) {
    using S = decltype(tag);
    Rng rng;
    std::uint8_t st = 9;
    for (int i = 0; i < 40; ++i) {
      const std::array<Q<S>, 2> qs{rng.quat<S>(), rng.quat<S>()};
      const std::array<V<S>, 2> ts{rng.vec<S>(10), rng.vec<S>(10)};
      const std::array<S, 2> ws{S(rng.uniform(0, 1)), S(rng.uniform(0.1, 1))};
      const V<S> p = rng.vec<S>(10);
      V<S> moved;
      ops<S>().skin_dual_quaternion(1, 2, qs.front().data(), ts.front().data(), ws.data(), p.data(), moved.data(), &st);
      const std::vector<ref::Quaternion<Real>> rqs{rq(qs[0]), rq(qs[1])};
      const std::vector<ref::Vec3<Real>> rts{rv(ts[0]), rv(ts[1])};
      const std::vector<Real> rws{Real(ws[0]), Real(ws[1])};
      EXPECT_LE(vec_err(moved, cl::SKIN_2_dual_quaternion<Real>(rqs, rts, rws, rv(p)).value,
                        std::max({Real(1), norm3(rv(p)), norm3(rts[0]), norm3(rts[1])})),
                strict("eps64"));
    }
  });
}

}  // namespace

// The laws that every table of dual-quaternion ops keeps, on motor_pga's tables: MotorPga/RigidLaws/0.*
// (rotorcert/testing/rigid_law_tests.hpp; ctest shows MotorPga.<law><MotorPgaTables>).
struct MotorPgaTables : rotorcert::testing::rigid_laws::AbiTables<&rotorcert_impl_entry_motor_pga> {};
namespace rotorcert::testing::rigid_laws {
INSTANTIATE_TYPED_TEST_SUITE_P(MotorPga, RigidLaws, MotorPgaTables);
}  // namespace rotorcert::testing::rigid_laws
