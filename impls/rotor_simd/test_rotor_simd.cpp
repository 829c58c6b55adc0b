// rotor_simd: every claimed operation on EVERY dispatch target against the MPFR reference.
//
// The lead's generic engine tests the default target; this file forces each target of
// simd_targets in turn (select_target) and runs a fixed input set through it: random unit
// quaternions from a fixed seed, near-identity pairs (angles 1e-7 .. 1e-2), near-antipodal
// pairs, exact dot = 0 ties, non-unit inputs at scales 2^-140 .. 2^120, t in [-0.5, 1.5] (plus
// a few far extrapolations), in calls of n = 1, 7, 64 and 1000 elements (tails included) and
// n = 0. The worst error per op per target must be within the STRICT bar of the clause's
// tolerance class (spec/clauses.json); it is printed in eps units with its input in hexfloat.
// The reference results are computed once and shared by all targets. Those inputs put an edge
// case into nearly every block, so a second set (RotorSimdFastPaths) is ordinary in every lane,
// to exercise the fast paths of slerp, nlerp and QLB (k = 4).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <map>
#include <numbers>
#include <random>
#include <span>
#include <string>
#include <vector>

#include <unistd.h>

#include <gtest/gtest.h>

#include <rotorcert/impl_abi.h>
#include <rotorcert/reference/metrics.hpp>
#include <rotorcert/reference/rotation_ops.hpp>
#include <rotorcert/testing/clause.hpp>
#include <rotorcert/testing/tolerance.hpp>

extern "C" const rc_impl* rotorcert_impl_entry_rotor_simd(std::uint32_t abi, std::uint32_t index);

namespace {

using rotorcert::ref::Format;
using rotorcert::ref::Real;
namespace clause = rotorcert::ref::clause;
namespace ref = rotorcert::ref;
using RQ = ref::Quaternion<Real>;
using RV = ref::Vec3<Real>;
using rotorcert::testing::eps_class_bars;

const rc_impl& impl() {
  static const rc_impl* t = rotorcert_impl_entry_rotor_simd(RC_ABI_VERSION, 0);
  return *t;
}
const rc_ops_f32& ops() { return *impl().f32; }

std::vector<std::string> targets() {
  std::vector<std::string> r;
  for (const char* const* p = impl().simd_targets; *p != nullptr; ++p) r.emplace_back(*p);
  return r;
}

/// Restores the default target when a test ends, whatever it forced.
struct TargetGuard {
  ~TargetGuard() { impl().select_target(nullptr); }
};

// ---- inputs ----------------------------------------------------------------------------------

using F4 = std::array<float, 4>;
using F3 = std::array<float, 3>;

struct Rng {
  std::mt19937_64 g{0x5eed2024};
  double normal() { return std::normal_distribution<double>(0, 1)(g); }
  double uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(g); }
  int pick(int n) { return std::uniform_int_distribution<int>(0, n - 1)(g); }
};

std::array<double, 4> unit_double(Rng& r) {
  std::array<double, 4> q;
  double n = 0;
  for (double& x : q) {
    x = r.normal();
    n += x * x;
  }
  n = std::sqrt(n);
  for (double& x : q) x /= n;
  return q;
}
F4 to_f4(const std::array<double, 4>& q) {
  return {static_cast<float>(q[0]), static_cast<float>(q[1]), static_cast<float>(q[2]), static_cast<float>(q[3])};
}
/// Hamilton product in double, [x, y, z, w] arrays.
std::array<double, 4> mul(const std::array<double, 4>& a, const std::array<double, 4>& b) {
  return {a[3] * b[0] + a[0] * b[3] + a[1] * b[2] - a[2] * b[1], a[3] * b[1] - a[0] * b[2] + a[1] * b[3] + a[2] * b[0],
          a[3] * b[2] + a[0] * b[1] - a[1] * b[0] + a[2] * b[3], a[3] * b[3] - a[0] * b[0] - a[1] * b[1] - a[2] * b[2]};
}
/// a rotated by a rotation of `angle` about a random axis (S^3 distance angle/2).
std::array<double, 4> near(Rng& r, const std::array<double, 4>& a, double angle) {
  std::array<double, 4> axis = unit_double(r);
  const double n = std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
  const double s = std::sin(angle / 2) / n;
  return mul(a, {axis[0] * s, axis[1] * s, axis[2] * s, std::cos(angle / 2)});
}
/// A non-unit copy: every component times 2^e (exact), or times a non-power-of-two factor.
F4 rescale(const F4& q, int e) {
  F4 r;
  for (int i = 0; i < 4; ++i) r[i] = std::ldexp(q[i], e);
  return r;
}

struct PairSet {
  std::vector<F4> a, b;
  std::vector<float> t;
  std::vector<bool> tie;  // a.b = 0 exactly by construction
};

/// Pairs for slerp / nlerp / compose: random, near-identity, near-antipodal, exact ties,
/// non-unit scales; t in [-0.5, 1.5] with the endpoints and a few far extrapolations.
const PairSet& pairs() {
  static const PairSet s = [] {
    PairSet p;
    Rng r;
    auto t_of = [&r](std::size_t i) -> float {
      static const float special[] = {0.0f, 1.0f, 0.5f, -0.5f, 1.5f, 0.25f, 2.0f, -1.0f, 3.0f, 10.0f};
      if (i % 7 == 0) return special[(i / 7) % 10];
      return static_cast<float>(r.uniform(-0.5, 1.5));
    };
    auto add = [&](const F4& a, const F4& b, bool tie = false) {
      p.tie.push_back(tie);
      p.t.push_back(t_of(p.a.size()));
      p.a.push_back(a);
      p.b.push_back(b);
    };
    for (int i = 0; i < 400; ++i) add(to_f4(unit_double(r)), to_f4(unit_double(r)));
    for (int i = 0; i < 300; ++i) {  // near identity: angles 1e-7 .. 1e-2
      const auto a = unit_double(r);
      add(to_f4(a), to_f4(near(r, a, std::pow(10.0, r.uniform(-7, -2)))));
    }
    for (int i = 0; i < 200; ++i) {  // near antipodal: b = -(a rotated a little)
      const auto a = unit_double(r);
      auto b = near(r, a, std::pow(10.0, r.uniform(-7, -1)));
      for (double& x : b) x = -x;
      add(to_f4(a), to_f4(b));
    }
    for (int i = 0; i < 100; ++i) {  // exact ties: dot(a, b) = 0 in exact arithmetic
      const F4 a = to_f4(unit_double(r));
      const F4 ties[3] = {{-a[1], a[0], -a[3], a[2]}, {a[2], a[3], -a[0], -a[1]}, {a[3], -a[2], a[1], -a[0]}};
      add(a, ties[i % 3], true);
    }
    for (int i = 0; i < 100; ++i) {  // non-unit inputs (EDGE-5), including subnormal components
      static const int scales[] = {-140, -126, -60, -7, 3, 60, 120};
      const F4 a = to_f4(unit_double(r));
      const F4 b = to_f4(near(r, unit_double(r), r.uniform(0, 3)));
      F4 sa = rescale(a, scales[r.pick(7)]), sb = rescale(b, scales[r.pick(7)]);
      if (i % 5 == 0)
        for (float& x : sb) x *= 3.7f;
      add(sa, sb);
    }
    // Endpoints 2^-70 .. 2^-80 rad apart, one of them the other's antipode (the hemisphere flip
    // makes them equal but for tiny components): sin(Omega) a's squares underflow (the general
    // kernel's regression, fuzz/corpus/interpolation/regression-simd-slerp-tiny-omega).
    for (int e = 70; e <= 80; e += 2) {
      add({std::ldexp(1.0f, -e), 0, -1, 0}, {0, std::ldexp(1.5f, -e), 1, std::ldexp(1.0f, -e - 20)});
      add({0x1.0a0a0ap-51f, 0x1.5bc07ep-68f, -0x1.d5f97ep+21f, 0x1.de867cp-64f},
          {0x1.2c1a7ep-111f, 0x1.81487ep-98f, 0x1.d7cc7cp-16f, 0x1.917dacp-96f});
    }
    // Exact identities and the spec's examples.
    add({0, 0, 0, 1}, {0, 0, 0, 1});
    add({0, 0, 0, 1}, {1, 0, 0, 0});
    add({0, 0, 0, 1}, {-1, 0, 0, 0});
    add({0, 0, 0, 1}, {0, 0, 0, -1});
    return p;
  }();
  return s;
}

// ---- running an op in chunks of 1, 7, 64 and 1000 --------------------------------------------------

/// Calls f(offset, count) over [0, n) in chunks cycling through 1, 7, 64, 1000; also n = 0.
void in_chunks(std::size_t n, const std::function<void(std::size_t, std::size_t)>& f) {
  static const std::size_t sizes[] = {1, 7, 64, 1000};
  f(0, 0);
  std::size_t i = 0;
  for (int c = 0; i < n; ++c) {
    const std::size_t m = std::min(sizes[c % 4], n - i);
    f(i, m);
    i += m;
  }
}

RQ rq(const float* p) {
  return RQ{Real(double(p[3])), Real(double(p[0])), Real(double(p[1])), Real(double(p[2]))};
}
RV rv(const float* p) { return RV{Real(double(p[0])), Real(double(p[1])), Real(double(p[2]))}; }

std::string hex(const float* p, int n) {
  std::string s = "[";
  char buf[64];
  for (int i = 0; i < n; ++i) {
    std::snprintf(buf, sizeof buf, "%s%a", i ? ", " : "", static_cast<double>(p[i]));
    s += buf;
  }
  return s + "]";
}

double eps_units(const Real& e) { return clause::METRIC_2_eps_units(e, Format::binary32).toDouble(); }

/// Rotation-valued unit output: max(METRIC-1, METRIC-6) in eps units.
double quat_error(const float* got, const RQ& want) {
  const RQ g = rq(got);
  const double m1 = eps_units(clause::METRIC_1_rotation_distance(g, want));
  const double m6 = eps_units(clause::METRIC_6_norm_defect(g));
  if (std::isnan(m1) || std::isnan(m6)) return std::numeric_limits<double>::infinity();
  return std::max(m1, m6);
}

/// Worst case of one op on one target.
struct Worst {
  double eps = 0;
  std::string input;
  void see(double e, const std::string& in) {
    if (!(e <= eps)) {  // NaN counts as worst
      eps = std::isnan(e) ? std::numeric_limits<double>::infinity() : e;
      input = in;
    }
  }
};

void report(const char* op, const std::string& target, const Worst& w, const char* cls) {
  const double strict = eps_class_bars(cls).strict;
  std::printf("  %-10s %-8s worst %8.3f eps (%s strict %g) at %s\n", op, target.c_str(), w.eps, cls, strict,
              w.input.c_str());
  EXPECT_LE(w.eps, strict) << op << " on " << target << " at " << w.input;
}

/// Element-by-element outputs of one op over all targets, to say whether they are identical.
struct CrossTarget {
  std::vector<float> first;
  std::string first_name;
  void see(const std::string& target, const std::vector<float>& out) {
    if (first.empty()) {
      first = out;
      first_name = target;
      return;
    }
    std::size_t differ = 0;
    for (std::size_t i = 0; i < out.size(); ++i)
      if (std::memcmp(&out[i], &first[i], sizeof(float)) != 0) ++differ;
    std::printf("  %-8s vs %-8s: %zu of %zu output floats differ in bits\n", target.c_str(), first_name.c_str(),
                differ, out.size());
  }
};

// ---- per-op runs ------------------------------------------------------------------------------------

/// Statuses must all be OK for the valid inputs used in the accuracy runs.
void expect_all_ok(const std::vector<std::uint8_t>& st, const char* op, const std::string& target) {
  for (std::size_t i = 0; i < st.size(); ++i) ASSERT_EQ(st[i], RC_OK) << op << " on " << target << " element " << i;
}

using InterpFn = int (*)(std::size_t, const float*, const float*, const float*, float*, std::uint8_t*);

/// The expected slerp / nlerp of an exact tie (a.b = 0: no flip, EDGE-3), from the clause
/// formulas. The reference clause functions decide the flip on the dot of their 256-bit
/// ROUNDED normalised inputs, which for a non-unit tie is +-2^-256-ish noise (reported to the
/// lead), so ties are evaluated here with the exact decision.
RQ tie_expected(bool slerp, const RQ& qa, const RQ& qb, const Real& t) {
  const RQ a = ref::normalized(qa), b = ref::normalized(qb);
  if (!slerp) return ref::normalized(a + t * (b - a));
  const Real omega = 2 * atan2(ref::norm(a - b), ref::norm(a + b));
  return (sin((1 - t) * omega) / sin(omega)) * a + (sin(t * omega) / sin(omega)) * b;
}

void check_interp(const char* op, InterpFn fn,
                  ref::Result<RQ> (*reference)(const RQ&, const RQ&, const Real&), const char* cls) {
  TargetGuard guard;
  const PairSet& p = pairs();
  const std::size_t n = p.a.size();
  std::vector<RQ> want(n);
  for (std::size_t i = 0; i < n; ++i) {
    const RQ a = rq(p.a[i].data()), b = rq(p.b[i].data());
    const Real t(double(p.t[i]));
    want[i] = p.tie[i] ? tie_expected(reference == &clause::SLERP_1_slerp<Real>, a, b, t) : reference(a, b, t).value;
  }
  CrossTarget cross;
  for (const std::string& target : targets()) {
    ASSERT_EQ(impl().select_target(target.c_str()), 0);
    ASSERT_STREQ(impl().current_target(), target.c_str());
    std::vector<float> out(n * 4, -7.0f);
    std::vector<std::uint8_t> st(n, 99);
    in_chunks(n, [&](std::size_t i, std::size_t m) {
      ASSERT_EQ(fn(m, p.a[i].data(), p.b[i].data(), &p.t[i], &out[i * 4], &st[i]), 0);
    });
    expect_all_ok(st, op, target);
    Worst w;
    for (std::size_t i = 0; i < n; ++i)
      w.see(quat_error(&out[i * 4], want[i]),
            "a=" + hex(p.a[i].data(), 4) + " b=" + hex(p.b[i].data(), 4) + " t=" + hex(&p.t[i], 1));
    report(op, target, w, cls);
    cross.see(target, out);
  }
}

TEST(RotorSimdTargets, ListAndSelect) {
  TargetGuard guard;
  const std::vector<std::string> names = targets();
  ASSERT_FALSE(names.empty());
  std::printf("  simd_targets:");
  for (const std::string& s : names) std::printf(" %s", s.c_str());
  std::printf("  (default %s)\n", impl().current_target());
  // The default is the best runnable target unless ROTORCERT_SIMD_TARGET says otherwise.
  if (std::getenv("ROTORCERT_SIMD_TARGET") == nullptr) {
    EXPECT_EQ(names.back(), impl().current_target());
  }
  const std::string before = impl().current_target();
  EXPECT_NE(impl().select_target("NOT_A_TARGET"), 0);
  EXPECT_NE(impl().select_target(""), 0);
  EXPECT_EQ(before, impl().current_target()) << "a rejected name must not change the target";
  for (const std::string& s : names) {
    EXPECT_EQ(impl().select_target(s.c_str()), 0);
    EXPECT_EQ(s, impl().current_target());
  }
  EXPECT_EQ(impl().select_target(nullptr), 0);
  EXPECT_EQ(before, impl().current_target());
}

/// ROTORCERT_SIMD_TARGET, read when the library loads: this test re-runs the test binary with
/// the variable set and checks, in the child, that the named target is the current one.
TEST(RotorSimdTargets, EnvironmentVariable) {
  if (const char* expect = std::getenv("ROTORCERT_SIMD_TEST_EXPECT")) {
    EXPECT_STREQ(impl().current_target(), expect);
    impl().select_target(nullptr);  // the default is the environment's target
    EXPECT_STREQ(impl().current_target(), expect);
    return;
  }
  char self[4096] = {};
  ASSERT_GT(readlink("/proc/self/exe", self, sizeof self - 1), 0);
  const std::string exe = self;
  const std::vector<std::string> names = targets();
  for (const std::string& name : {names.front(), names.size() > 1 ? names[names.size() - 2] : names.front()}) {
    const std::string cmd = "ROTORCERT_SIMD_TARGET=" + name + " ROTORCERT_SIMD_TEST_EXPECT=" + name +
                            " " + exe + " --gtest_filter=RotorSimdTargets.EnvironmentVariable > /dev/null 2>&1";
    EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
  }
  // An unknown name falls back to Highway's choice (the best target).
  const std::string cmd = "ROTORCERT_SIMD_TARGET=BOGUS ROTORCERT_SIMD_TEST_EXPECT=" + names.back() +
                          " " + exe + " --gtest_filter=RotorSimdTargets.EnvironmentVariable > /dev/null 2>&1";
  EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
}

TEST(RotorSimdAccuracy, Slerp) {
  RC_CLAUSE("SLERP-1");
  RC_CLAUSE("SLERP-4");
  RC_CLAUSE("EDGE-2");
  RC_CLAUSE("EDGE-5");
  check_interp("slerp", ops().slerp, &clause::SLERP_1_slerp<Real>, "eps16");
}

TEST(RotorSimdAccuracy, Nlerp) {
  RC_CLAUSE("NLERP-1");
  check_interp("nlerp", ops().nlerp, &clause::NLERP_1_nlerp<Real>, "eps16");
}

TEST(RotorSimdAccuracy, SlerpEndpointsAndVelocity) {
  RC_CLAUSE("SLERP-3");
  RC_CLAUSE("SLERP-5");
  TargetGuard guard;
  const PairSet& p = pairs();
  const std::size_t n = 600;  // random, near-identity and near-antipodal pairs
  for (const std::string& target : targets()) {
    ASSERT_EQ(impl().select_target(target.c_str()), 0);
    // SLERP-3: t = 0 gives a, t = 1 gives b' (with its sign); SLERP-5: the distance between
    // slerp(t1) and slerp(t2) is |t1 - t2| d(a, b').
    const float ts[4] = {0.0f, 1.0f, 0.25f, 0.75f};
    std::vector<float> out(4 * 4);
    std::vector<std::uint8_t> st(4);
    Worst ends, velocity;
    for (std::size_t i = 0; i < n; ++i) {
      const F4 as[4] = {p.a[i], p.a[i], p.a[i], p.a[i]}, bs[4] = {p.b[i], p.b[i], p.b[i], p.b[i]};
      ASSERT_EQ(ops().slerp(4, as[0].data(), bs[0].data(), ts, out.data(), st.data()), 0);
      const RQ a = rq(p.a[i].data()), b = rq(p.b[i].data());
      const RQ bp = ref::dot(a, b) < 0 ? -b : b;
      const RQ s0 = rq(&out[0]), s1 = rq(&out[4]), s2 = rq(&out[8]), s3 = rq(&out[12]);
      const std::string in = "a=" + hex(p.a[i].data(), 4) + " b=" + hex(p.b[i].data(), 4);
      ends.see(std::max(eps_units(clause::METRIC_1_rotation_distance(s0, a)),
                        eps_units(clause::METRIC_1_rotation_distance(s1, bp))),
               in);
      EXPECT_GT(ref::dot(s1, bp), 0) << "slerp(a, b, 1) must be b', not -b': " << in;
      EXPECT_GT(ref::dot(s0, a), 0) << in;
      const Real dab = clause::METRIC_1_rotation_distance(a, bp);
      velocity.see(eps_units(abs(clause::METRIC_1_rotation_distance(s2, s3) - Real(0.5) * dab)), in);
    }
    report("slerp-ends", target, ends, "eps16");
    report("slerp-vel", target, velocity, "eps16");
  }
}

TEST(RotorSimdAccuracy, Compose) {
  RC_CLAUSE("COMPOSE-1");
  TargetGuard guard;
  const PairSet& p = pairs();
  const std::size_t n = p.a.size();
  std::vector<RQ> want(n);
  // COMPOSE-1 defines the exact product, of norm |a||b|; where that is outside the normal
  // binary32 range it is not representable and the element is skipped.
  std::vector<bool> in_range(n);
  for (std::size_t i = 0; i < n; ++i) {
    const RQ a = rq(p.a[i].data()), b = rq(p.b[i].data());
    want[i] = clause::COMPOSE_1_compose(a, b).value;
    const Real norm = ref::norm(a) * ref::norm(b);
    in_range[i] = norm > Real(std::ldexp(1.0, -100)) && norm < Real(std::ldexp(1.0, 100));
  }
  CrossTarget cross;
  for (const std::string& target : targets()) {
    ASSERT_EQ(impl().select_target(target.c_str()), 0);
    std::vector<float> out(n * 4);
    std::vector<std::uint8_t> st(n);
    in_chunks(n, [&](std::size_t i, std::size_t m) {
      ASSERT_EQ(ops().compose(m, p.a[i].data(), p.b[i].data(), &out[i * 4], &st[i]), 0);
    });
    expect_all_ok(st, "compose", target);
    Worst w;
    for (std::size_t i = 0; i < n; ++i)  // METRIC-1 (the product of non-unit inputs is not unit)
      if (in_range[i]) w.see(eps_units(clause::METRIC_1_rotation_distance(rq(&out[i * 4]), want[i])),
            "a=" + hex(p.a[i].data(), 4) + " b=" + hex(p.b[i].data(), 4));
    report("compose", target, w, "eps8");
    cross.see(target, out);
  }
}

/// Quaternions for the unary ops: the pairs' a and b.
std::vector<F4> singles() {
  const PairSet& p = pairs();
  std::vector<F4> q(p.a);
  q.insert(q.end(), p.b.begin(), p.b.end());
  q.push_back({0x1p-149f, -0.0f, 0.0f, 0.0f});  // EDGE-8: subnormal, -0
  q.push_back({3e38f, 3e38f, -3e38f, 1.0f});   // sum of squares overflows
  q.push_back({0, 0, 0, -7});
  return q;
}

TEST(RotorSimdAccuracy, Normalize) {
  RC_CLAUSE("NORM-1");
  RC_CLAUSE("EDGE-8");
  TargetGuard guard;
  const std::vector<F4> q = singles();
  const std::size_t n = q.size();
  std::vector<RQ> want(n);
  for (std::size_t i = 0; i < n; ++i) want[i] = clause::NORM_1_normalize(rq(q[i].data())).value;
  CrossTarget cross;
  for (const std::string& target : targets()) {
    ASSERT_EQ(impl().select_target(target.c_str()), 0);
    std::vector<float> out(n * 4);
    std::vector<std::uint8_t> st(n);
    in_chunks(n, [&](std::size_t i, std::size_t m) { ASSERT_EQ(ops().normalize(m, q[i].data(), &out[i * 4], &st[i]), 0); });
    expect_all_ok(st, "normalize", target);
    Worst w;
    for (std::size_t i = 0; i < n; ++i) w.see(quat_error(&out[i * 4], want[i]), hex(q[i].data(), 4));
    report("normalize", target, w, "eps4");
    cross.see(target, out);
  }
}

/// Vectors to rotate: random directions at scales 2^-140 .. 2^100, plus 0.
std::vector<F3> vectors(std::size_t n) {
  Rng r;
  std::vector<F3> v(n);
  static const int scales[] = {0, 0, 0, 0, 5, -20, 100, -140};
  for (std::size_t i = 0; i < n; ++i)
    for (float& x : v[i]) x = static_cast<float>(std::ldexp(r.normal(), scales[i % 8]));
  v[0] = {0, 0, 0};
  return v;
}

/// METRIC-3 in eps units with the scale of SPEC section 3, s = max(|v_ref|, tiny), tiny =
/// 2^-126: a vector with subnormal components cannot be rotated to relative precision in
/// binary32 (its image is rounded to the subnormal grid). clause::METRIC_3_vector_error has no
/// floor (reported to the lead), and APPLY-1's s = |x| has none either.
double vector_error(const RV& v, const RV& want) {
  Real d(0), r(0);
  for (int i = 0; i < 3; ++i) {
    d += (v[i] - want[i]) * (v[i] - want[i]);
    r += want[i] * want[i];
  }
  const Real s = r == 0 ? Real(1) : max(sqrt(r), Real(std::ldexp(1.0, -126)));
  return eps_units(sqrt(d) / s);
}

TEST(RotorSimdAccuracy, ApplyVectorAndBivector) {
  RC_CLAUSE("APPLY-1");
  RC_CLAUSE("APPLY-2");
  RC_CLAUSE("EDGE-4");
  TargetGuard guard;
  const std::vector<F4> q = singles();
  const std::size_t n = q.size();
  const std::vector<F3> v = vectors(n);
  std::vector<RV> want(n), want_b(n);
  for (std::size_t i = 0; i < n; ++i) {
    want[i] = clause::APPLY_1_apply_vector(rq(q[i].data()), rv(v[i].data())).value;
    want_b[i] = clause::APPLY_2_apply_bivector(rq(q[i].data()), rv(v[i].data())).value;
  }
  CrossTarget cross;
  for (const std::string& target : targets()) {
    ASSERT_EQ(impl().select_target(target.c_str()), 0);
    std::vector<float> out(n * 3), outb(n * 3), outneg(n * 3);
    std::vector<std::uint8_t> st(n);
    std::vector<F4> neg(q);
    for (F4& x : neg)
      for (float& c : x) c = -c;
    in_chunks(n, [&](std::size_t i, std::size_t m) {
      ASSERT_EQ(ops().apply_vector(m, q[i].data(), v[i].data(), &out[i * 3], &st[i]), 0);
      ASSERT_EQ(ops().apply_bivector(m, q[i].data(), v[i].data(), &outb[i * 3], &st[i]), 0);
      ASSERT_EQ(ops().apply_vector(m, neg[i].data(), v[i].data(), &outneg[i * 3], &st[i]), 0);
    });
    expect_all_ok(st, "apply", target);
    Worst w, wb;
    for (std::size_t i = 0; i < n; ++i) {
      const std::string in = "q=" + hex(q[i].data(), 4) + " v=" + hex(v[i].data(), 3);
      w.see(vector_error(rv(&out[i * 3]), want[i]), in);
      wb.see(vector_error(rv(&outb[i * 3]), want_b[i]), in);
    }
    report("apply_vec", target, w, "eps8");
    report("apply_biv", target, wb, "eps8");
    // EDGE-4: q and -q give bit-identical vectors (the formula is even in q).
    EXPECT_EQ(0, std::memcmp(out.data(), outneg.data(), out.size() * sizeof(float)));
    cross.see(target, out);
  }
}

TEST(RotorSimdAccuracy, ToMatrix) {
  RC_CLAUSE("MAT-1");
  TargetGuard guard;
  const std::vector<F4> q = singles();
  const std::size_t n = q.size();
  std::vector<ref::Mat3<Real>> want(n);
  for (std::size_t i = 0; i < n; ++i) want[i] = clause::MAT_1_to_matrix(rq(q[i].data())).value;
  CrossTarget cross;
  for (const std::string& target : targets()) {
    ASSERT_EQ(impl().select_target(target.c_str()), 0);
    std::vector<float> out(n * 9);
    std::vector<std::uint8_t> st(n);
    in_chunks(n, [&](std::size_t i, std::size_t m) { ASSERT_EQ(ops().to_matrix(m, q[i].data(), &out[i * 9], &st[i]), 0); });
    expect_all_ok(st, "to_matrix", target);
    Worst w;
    for (std::size_t i = 0; i < n; ++i) {
      ref::Mat3<Real> m;
      for (int e = 0; e < 9; ++e) m[e] = Real(double(out[i * 9 + e]));
      w.see(eps_units(clause::METRIC_4_matrix_error(m, want[i])), hex(q[i].data(), 4));
    }
    report("to_matrix", target, w, "eps8");
    cross.see(target, out);
  }
}

/// Whether every component of an exact result is zero or a normal binary32 magnitude: beyond that
/// the format cannot hold it to relative precision (EDGE-5's headroom), so the accuracy runs of
/// ops whose outputs scale with 1/|q| leave such inputs out.
bool within_normal_range(const RQ& r) {
  const Real big{double(std::numeric_limits<float>::max())}, tiny{std::ldexp(1.0, -126)};  // braces: not a declaration
  for (const Real& c : {r.w, r.x, r.y, r.z})
    if (c != 0 && (abs(c) > big || abs(c) < tiny)) return false;
  return true;
}

TEST(RotorSimdAccuracy, Inverse) {
  RC_CLAUSE("INV-1");
  RC_CLAUSE("EDGE-5");
  TargetGuard guard;
  std::vector<F4> q;
  std::vector<RQ> want;
  for (const F4& x : singles()) {
    const RQ r = clause::INV_1_inverse(rq(x.data())).value;
    if (!within_normal_range(r)) continue;
    q.push_back(x);
    want.push_back(r);
  }
  q.push_back({0, 0, 0, 1});  // EDGE-1: the identity's inverse is the identity, exactly
  want.push_back(clause::INV_1_inverse(rq(q.back().data())).value);
  const std::size_t n = q.size();
  CrossTarget cross;
  for (const std::string& target : targets()) {
    ASSERT_EQ(impl().select_target(target.c_str()), 0);
    std::vector<float> out(n * 4);
    std::vector<std::uint8_t> st(n);
    in_chunks(n, [&](std::size_t i, std::size_t m) { ASSERT_EQ(ops().inverse(m, q[i].data(), &out[i * 4], &st[i]), 0); });
    expect_all_ok(st, "inverse", target);
    Worst w;
    for (std::size_t i = 0; i < n; ++i) {
      // INV-1's measure: max_i |q_i - r_i| / |r|, componentwise.
      const RQ g = rq(&out[i * 4]);
      const Real e = max(max(abs(g.w - want[i].w), abs(g.x - want[i].x)), max(abs(g.y - want[i].y), abs(g.z - want[i].z)));
      w.see(eps_units(e / ref::norm(want[i])), hex(q[i].data(), 4));
    }
    report("inverse", target, w, "eps4");
    for (int c = 0; c < 4; ++c)  // by value: the conjugate's -0 is the identity's 0
      EXPECT_EQ(out[(n - 1) * 4 + c], q.back()[c]) << "EDGE-1 on " << target;
    cross.see(target, out);
  }
}

TEST(RotorSimdAccuracy, ToAxisAngle) {
  RC_CLAUSE("AXANG-1");
  RC_CLAUSE("EDGE-8");
  TargetGuard guard;
  std::vector<F4> q = singles();
  q.push_back({0, 0, 0, 1});                // angle 0, axis +z
  q.push_back({0, 0, 0, -1});               // angle 2 pi, axis +z
  q.push_back({0x1p-140f, 0, 0, -1});       // EDGE-8: a subnormal v beside w = -1 keeps its axis
  q.push_back({3e-30f, -4e-30f, 0, 5e10f}); // |v| 2^-133 |w|: the half angle below 2^-100
  const std::size_t n = q.size();
  std::vector<ref::AxisAngle<Real>> want(n);
  for (std::size_t i = 0; i < n; ++i) want[i] = clause::AXANG_1_to_axis_angle(rq(q[i].data())).value;
  CrossTarget cross;
  for (const std::string& target : targets()) {
    ASSERT_EQ(impl().select_target(target.c_str()), 0);
    std::vector<float> angle(n), axis(n * 3);
    std::vector<std::uint8_t> st(n);
    in_chunks(n, [&](std::size_t i, std::size_t m) {
      ASSERT_EQ(ops().to_axis_angle(m, q[i].data(), &angle[i], &axis[i * 3], &st[i]), 0);
    });
    expect_all_ok(st, "to_axis_angle", target);
    Worst wa, wu;
    for (std::size_t i = 0; i < n; ++i) {
      wa.see(eps_units(abs(Real(double(angle[i])) - want[i].angle)), hex(q[i].data(), 4));
      wu.see(vector_error(rv(&axis[i * 3]), want[i].axis), hex(q[i].data(), 4));
    }
    report("angle", target, wa, "eps16");
    report("axis", target, wu, "eps16");
    cross.see(target, angle);
  }
}

TEST(RotorSimdAccuracy, FromAxisAngle) {
  RC_CLAUSE("AXANG-2");
  RC_CLAUSE("EDGE-1");
  TargetGuard guard;
  Rng r;
  const std::size_t n = 1200;
  std::vector<F3> axis = vectors(n);
  axis[0] = {0, 0, 1};  // vectors() starts with 0, a DOMAIN_ERROR here
  std::vector<float> angle(n);
  for (std::size_t i = 0; i < n; ++i)  // |angle| <= 16 in SIMD; beyond (every 7th here, up to 1e38) in binary64
    angle[i] = static_cast<float>(i % 7 == 0 ? std::copysign(std::pow(10.0, r.uniform(1.2, 38)), r.uniform(-1, 1))
                                             : r.uniform(-16, 16));
  angle[1] = 0;                          // EDGE-1: the identity, exactly
  angle[2] = 16.000002f, angle[3] = -16;  // either side of the binary64 switch
  std::vector<RQ> want(n);
  for (std::size_t i = 0; i < n; ++i) want[i] = clause::AXANG_2_from_axis_angle(Real(double(angle[i])), rv(axis[i].data())).value;
  CrossTarget cross;
  for (const std::string& target : targets()) {
    ASSERT_EQ(impl().select_target(target.c_str()), 0);
    std::vector<float> out(n * 4);
    std::vector<std::uint8_t> st(n);
    in_chunks(n, [&](std::size_t i, std::size_t m) {
      ASSERT_EQ(ops().from_axis_angle(m, &angle[i], axis[i].data(), &out[i * 4], &st[i]), 0);
    });
    expect_all_ok(st, "from_axis_angle", target);
    Worst w;
    for (std::size_t i = 0; i < n; ++i) w.see(quat_error(&out[i * 4], want[i]), "angle=" + hex(&angle[i], 1) + " axis=" + hex(axis[i].data(), 3));
    report("from_axang", target, w, "eps16");
    const float identity[4] = {0, 0, 0, 1};
    for (int c = 0; c < 4; ++c) EXPECT_EQ(out[4 + c], identity[c]) << "EDGE-1 on " << target;  // -0 == 0
    cross.see(target, out);
  }
}

TEST(RotorSimdAccuracy, LogAndExp) {
  RC_CLAUSE("LOG-1");
  RC_CLAUSE("LOG-2");
  RC_CLAUSE("EXP-1");
  RC_CLAUSE("EXP-2");
  TargetGuard guard;
  const std::vector<F4> q = singles();
  const std::size_t n = q.size();
  // exp inputs: logs of the quaternions, random |v| up to 3 pi / 2, tiny |v|, and |v| up to 20.
  Rng r;
  std::vector<F3> v(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double len = i % 4 == 0 ? std::pow(10.0, r.uniform(-9, -2)) : i % 9 == 0 ? r.uniform(5, 20) : r.uniform(0, 4.72);
    const double x = r.normal(), y = r.normal(), z = r.normal(), s = len / std::sqrt(x * x + y * y + z * z);
    v[i] = {static_cast<float>(x * s), static_cast<float>(y * s), static_cast<float>(z * s)};
  }
  v[0] = {0, 0, 0};
  std::vector<RV> want_log(n);
  std::vector<RQ> want_exp(n);
  for (std::size_t i = 0; i < n; ++i) {
    want_log[i] = clause::LOG_1_log(rq(q[i].data())).value;
    want_exp[i] = clause::EXP_1_exp(rv(v[i].data())).value;
  }
  for (const std::string& target : targets()) {
    ASSERT_EQ(impl().select_target(target.c_str()), 0);
    std::vector<float> lg(n * 3), ex(n * 4), round_trip(n * 4);
    std::vector<std::uint8_t> st(n);
    in_chunks(n, [&](std::size_t i, std::size_t m) {
      ASSERT_EQ(ops().log(m, q[i].data(), &lg[i * 3], &st[i]), 0);
      ASSERT_EQ(ops().exp(m, v[i].data(), &ex[i * 4], &st[i]), 0);
    });
    expect_all_ok(st, "log/exp", target);
    in_chunks(n, [&](std::size_t i, std::size_t m) { ASSERT_EQ(ops().exp(m, &lg[i * 3], &round_trip[i * 4], &st[i]), 0); });
    Worst wl, we, wr;
    for (std::size_t i = 0; i < n; ++i) {
      wl.see(eps_units(clause::METRIC_5_bivector_error(rv(&lg[i * 3]), want_log[i])), hex(q[i].data(), 4));
      we.see(quat_error(&ex[i * 4], want_exp[i]), hex(v[i].data(), 3));
      wr.see(eps_units(clause::METRIC_1_rotation_distance(rq(&round_trip[i * 4]), rq(q[i].data()))), hex(q[i].data(), 4));
    }
    report("log", target, wl, "eps16");
    report("exp", target, we, "eps16");
    report("exp(log)", target, wr, "eps16");
    // LOG-2: log(-1) = (0, 0, pi) exactly, for every negative w and signed zeros.
    const F4 cut[3] = {{0, 0, 0, -1}, {-0.0f, 0, -0.0f, -3}, {0x1p-149f * 0, -0.0f, -0.0f, -0x1p-140f}};
    float out[9];
    std::uint8_t s3[3];
    ASSERT_EQ(ops().log(3, cut[0].data(), out, s3), 0);
    for (int i = 0; i < 3; ++i) {
      EXPECT_EQ(out[i * 3 + 0], 0.0f);
      EXPECT_EQ(out[i * 3 + 1], 0.0f);
      EXPECT_EQ(out[i * 3 + 2], std::numbers::pi_v<float>);
    }
  }
}

struct BlendSet {
  std::size_t k;
  std::vector<float> q, w;  // n * k influences, n * k weights
};

/// Blends of k = 1 .. 8 influences: spread-out and clustered influences with random signs,
/// zero leading weights (pivot not first), ties against the pivot, huge and tiny weights.
BlendSet blends(std::size_t k, std::size_t n) {
  Rng r;
  r.g.seed(1000 + k);
  BlendSet s{k, {}, {}};
  for (std::size_t i = 0; i < n; ++i) {
    const auto center = unit_double(r);
    const double spread = i % 3 == 0 ? 3.0 : i % 3 == 1 ? 0.5 : 1e-4;
    const double wscale = i % 11 == 0 ? 1e30 : i % 13 == 0 ? 1e-30 : 1.0;
    for (std::size_t j = 0; j < k; ++j) {
      auto q = near(r, center, r.uniform(0, spread));
      if (r.pick(2)) for (double& x : q) x = -x;
      F4 f = to_f4(q);
      if (i % 7 == 3 && j < 2) {  // exact tie between influences 0 and 1, (+-1/2, ...) family:
        // exactly unit, so the reference's normalisation is exact and its tie decision too
        const F4 h{r.pick(2) ? 0.5f : -0.5f, r.pick(2) ? 0.5f : -0.5f, r.pick(2) ? 0.5f : -0.5f, 0.5f};
        f = j == 0 ? h : F4{-s.q[i * k * 4 + 1], s.q[i * k * 4], -s.q[i * k * 4 + 3], s.q[i * k * 4 + 2]};
      }
      if (i % 17 == 5) f = rescale(f, 40);  // non-unit influence
      s.q.insert(s.q.end(), f.begin(), f.end());
      float wt = static_cast<float>(r.uniform(0, 1) * wscale);
      if (i % 5 == 1 && j + 1 < k) wt = j % 2 ? 0.0f : -0.0f;  // pivot is a later influence
      s.w.push_back(wt);
    }
    if (s.w[i * k + k - 1] == 0) s.w[i * k + k - 1] = 0.5f;  // some weight positive
  }
  return s;
}

void check_blend(const char* op, bool qlb) {
  TargetGuard guard;
  for (std::size_t k : {1u, 2u, 3u, 4u, 8u}) {
    const std::size_t n = k == 2 ? 1100 : 300;
    const BlendSet s = blends(k, n);
    std::vector<RQ> want(n);
    for (std::size_t i = 0; i < n; ++i) {
      std::vector<RQ> qs;
      std::vector<Real> ws;
      for (std::size_t j = 0; j < k; ++j) {
        qs.push_back(rq(&s.q[(i * k + j) * 4]));
        ws.push_back(Real(double(s.w[i * k + j])));
      }
      want[i] = (qlb ? clause::QLB_1_blend<Real>(qs, ws) : clause::LOGBLEND_1_blend<Real>(qs, ws)).value;
    }
    for (const std::string& target : targets()) {
      ASSERT_EQ(impl().select_target(target.c_str()), 0);
      std::vector<float> out(n * 4);
      std::vector<std::uint8_t> st(n);
      const auto fn = qlb ? ops().blend_qlb : ops().blend_log;
      in_chunks(n, [&](std::size_t i, std::size_t m) {
        ASSERT_EQ(fn(m, k, &s.q[i * k * 4], &s.w[i * k], &out[i * 4], &st[i]), 0);
      });
      expect_all_ok(st, op, target);
      Worst w;
      for (std::size_t i = 0; i < n; ++i)
        w.see(quat_error(&out[i * 4], want[i]),
              "k=" + std::to_string(k) + " q=" + hex(&s.q[i * k * 4], 4 * int(k)) + " w=" + hex(&s.w[i * k], int(k)));
      report(op, target + "/k" + std::to_string(k), w, "eps32");
    }
  }
}

TEST(RotorSimdAccuracy, BlendQlb) {
  RC_CLAUSE("QLB-1");
  check_blend("qlb", true);
}

TEST(RotorSimdAccuracy, BlendLog) {
  RC_CLAUSE("LOGBLEND-1");
  check_blend("log_blend", false);
}

// ---- edge outcomes on every target --------------------------------------------------------------

bool all_nan(const float* p, int n) {
  for (int i = 0; i < n; ++i)
    if (!std::isnan(p[i])) return false;
  return true;
}

TEST(RotorSimdEdges, DomainErrors) {
  RC_CLAUSE("EDGE-6");
  RC_CLAUSE("EDGE-7");
  RC_CLAUSE("EDGE-9");
  TargetGuard guard;
  const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
  // Bad inputs interleaved with good ones, so every block mixes lanes of both kinds.
  std::vector<F4> q;
  std::vector<bool> bad;
  const F4 bads[] = {{0, 0, 0, 0}, {-0.0f, 0, -0.0f, 0}, {inf, 0, 0, 1}, {0, nan, 0, 1}, {0, 0, 0, -inf}};
  for (int i = 0; i < 40; ++i) {
    q.push_back(i % 2 ? bads[(i / 2) % 5] : F4{0.5f, 0.5f, 0.5f, 0.5f});
    bad.push_back(i % 2 == 1);
  }
  const std::size_t n = q.size();
  std::vector<float> t(n, 0.3f);
  t[4] = nan;  // non-finite t
  std::vector<bool> bad_t(bad);
  bad_t[4] = true;
  std::vector<F3> v(n, F3{1, 2, 3});
  v[6] = {0, inf, 0};
  std::vector<bool> bad_v(bad);
  bad_v[6] = true;
  for (const std::string& target : targets()) {
    ASSERT_EQ(impl().select_target(target.c_str()), 0);
    std::vector<float> o(n * 9);
    std::vector<std::uint8_t> st(n);
    auto check = [&](const char* op, const std::vector<bool>& expect, int width) {
      for (std::size_t i = 0; i < n; ++i) {
        EXPECT_EQ(st[i], expect[i] ? RC_DOMAIN_ERROR : RC_OK) << op << " " << target << " element " << i;
        EXPECT_EQ(all_nan(&o[i * width], width), bool(expect[i])) << op << " " << target << " element " << i;
      }
    };
    ops().normalize(n, q[0].data(), o.data(), st.data());
    check("normalize", bad, 4);
    ops().to_matrix(n, q[0].data(), o.data(), st.data());
    check("to_matrix", bad, 9);
    ops().log(n, q[0].data(), o.data(), st.data());
    check("log", bad, 3);
    ops().compose(n, q[0].data(), q[0].data(), o.data(), st.data());
    check("compose", bad, 4);
    ops().apply_vector(n, q[0].data(), v[0].data(), o.data(), st.data());
    check("apply_vector", bad_v, 3);
    ops().slerp(n, q[0].data(), q[0].data(), t.data(), o.data(), st.data());
    check("slerp", bad_t, 4);
    ops().nlerp(n, q[0].data(), q[0].data(), t.data(), o.data(), st.data());
    check("nlerp", bad_t, 4);
    std::vector<float> ev(n * 3, 0.25f);
    ev[5] = nan;
    std::vector<bool> bad_e(n, false);
    bad_e[1] = true;
    ops().exp(n, ev.data(), o.data(), st.data());
    check("exp", bad_e, 4);
    // EDGE-9 and EDGE-6 in blends of 3: negative, NaN, Inf weight; all zero; zero quaternion
    // with weight 0.
    const std::size_t k = 3;
    std::vector<float> bq, bw;
    std::vector<bool> bad_b;
    for (int i = 0; i < 24; ++i) {
      for (int j = 0; j < 3; ++j) {
        const F4 g{0.1f * j, 0.2f, 0.3f, 0.9f};
        const F4 x = (i % 8 == 5 && j == 2) ? F4{0, 0, 0, 0} : g;
        bq.insert(bq.end(), x.begin(), x.end());
      }
      float w[3] = {0.5f, 0.25f, 0.25f};
      switch (i % 8) {
        case 1: w[1] = -1e-30f; break;
        case 2: w[2] = nan; break;
        case 3: w[0] = inf; break;
        case 4: w[0] = w[1] = w[2] = 0; break;
        case 5: w[2] = 0; break;  // zero quaternion with weight 0: still DOMAIN_ERROR
        case 6: w[0] = -0.0f; break;  // -0 counts as 0: fine
        default: break;
      }
      bw.insert(bw.end(), w, w + 3);
      bad_b.push_back(i % 8 >= 1 && i % 8 <= 5);
    }
    for (bool qlb : {true, false}) {
      std::vector<std::uint8_t> bs(24);
      (qlb ? ops().blend_qlb : ops().blend_log)(24, k, bq.data(), bw.data(), o.data(), bs.data());
      for (std::size_t i = 0; i < 24; ++i) {
        EXPECT_EQ(bs[i], bad_b[i] ? RC_DOMAIN_ERROR : RC_OK) << (qlb ? "qlb " : "log_blend ") << target << " " << i;
        EXPECT_EQ(all_nan(&o[i * 4], 4), bool(bad_b[i])) << target << " " << i;
      }
      // An empty influence set (k = 0) is DOMAIN_ERROR.
      std::uint8_t s1 = 0;
      float o1[4] = {};
      (qlb ? ops().blend_qlb : ops().blend_log)(1, 0, bq.data(), bw.data(), o1, &s1);
      EXPECT_EQ(s1, RC_DOMAIN_ERROR);
      EXPECT_TRUE(all_nan(o1, 4));
    }
  }
}

TEST(RotorSimdEdges, IdentityAndTies) {
  RC_CLAUSE("EDGE-1");
  RC_CLAUSE("EDGE-3");
  TargetGuard guard;
  const F4 one{0, 0, 0, 1};
  for (const std::string& target : targets()) {
    ASSERT_EQ(impl().select_target(target.c_str()), 0);
    float o[9];
    std::uint8_t s;
    // 0x1.264p+0: extrapolated, (0, 0, 0, 1/t) normalised gave 1 - 2^-24 before unit_of_scaled
    // kept pure scalars exact (found by Properties.EDGE_1).
    for (float t : {0.0f, 0.3f, 1.0f, -2.5f, 7.0f, 0x1.264p+0f}) {
      ops().slerp(1, one.data(), one.data(), &t, o, &s);
      EXPECT_EQ(F4({o[0], o[1], o[2], o[3]}), one) << target << " slerp t=" << t;
      ops().nlerp(1, one.data(), one.data(), &t, o, &s);
      EXPECT_EQ(F4({o[0], o[1], o[2], o[3]}), one) << target << " nlerp t=" << t;
    }
    ops().compose(1, one.data(), one.data(), o, &s);
    EXPECT_EQ(F4({o[0], o[1], o[2], o[3]}), one);
    ops().log(1, one.data(), o, &s);
    EXPECT_TRUE(o[0] == 0 && o[1] == 0 && o[2] == 0);
    const float zero3[3] = {0, 0, 0};
    ops().exp(1, zero3, o, &s);
    EXPECT_EQ(F4({o[0], o[1], o[2], o[3]}), one);
    const float v[3] = {0x1.8p-140f, 3.5f, -1e30f};
    ops().apply_vector(1, one.data(), v, o, &s);
    EXPECT_TRUE(o[0] == v[0] && o[1] == v[1] && o[2] == v[2]) << target;
    ops().to_matrix(1, one.data(), o, &s);
    for (int e = 0; e < 9; ++e) EXPECT_EQ(o[e], e % 4 == 0 ? 1.0f : 0.0f) << target;
    // EDGE-3: dot = +-0 does not flip: slerp(1, i, 1/2) = (1 + i)/sqrt 2, slerp(1, -i, 1/2) =
    // (1 - i)/sqrt 2; an exact antipode flips (constant interpolation).
    const F4 i_pos{1, 0, 0, 0}, i_neg{-1, 0, 0, 0}, minus_one{0, 0, 0, -1};
    const float half = 0.5f;
    const double strict = eps_class_bars("eps16").strict;
    for (const F4& b : {i_pos, i_neg}) {
      ops().slerp(1, one.data(), b.data(), &half, o, &s);
      const RQ want = clause::SLERP_1_slerp(rq(one.data()), rq(b.data()), Real(0.5)).value;
      EXPECT_LE(quat_error(o, want), strict) << target;
      EXPECT_EQ(o[0] > 0, b[0] > 0) << target << ": the tie must not flip";
    }
    ops().slerp(1, one.data(), minus_one.data(), &half, o, &s);
    EXPECT_EQ(F4({o[0], o[1], o[2], o[3]}), one);
  }
}


// ---- the fast paths (rotor_simd.cpp section 2d) ------------------------------------------------
//
// The inputs above put an edge case into nearly every block, so their blocks mostly take the
// general kernels. The inputs here are ordinary in EVERY lane (unit quaternions rounded to
// binary32, hemisphere dots away from 0, t in [0, 1], positive weights), so every block, the
// padded tails included, takes the slerp / nlerp / QLB (k = 4) fast paths: their polynomial
// slerp, their lane order and their exactness for identities are checked here.

struct OrdinaryPairs {
  std::vector<F4> a, b;
  std::vector<float> t;
  std::vector<bool> exact_identity;  // a = b' = +-1: the result must be exactly (0, 0, 0, 1)
};

/// |a.b| of the float inputs, in double (exact for binary32 products and these sums' sizes).
double abs_dot(const F4& a, const F4& b) {
  double s = 0;
  for (int i = 0; i < 4; ++i) s += double(a[i]) * double(b[i]);
  return std::fabs(s);
}

const OrdinaryPairs& ordinary_pairs() {
  static const OrdinaryPairs s = [] {
    OrdinaryPairs p;
    Rng r;
    r.g.seed(0xfa57);
    for (int i = 0; p.a.size() < 1500; ++i) {
      const auto a = unit_double(r);
      std::array<double, 4> b;
      bool identity = false;
      switch (i % 6) {
        case 0:
        case 1: b = unit_double(r); break;                                       // any angle, any sign
        case 2: b = near(r, a, std::pow(10.0, r.uniform(-7, -2))); break;        // EDGE-2 small angles
        case 3:                                                                  // near antipode: flip
          b = near(r, a, std::pow(10.0, r.uniform(-4, -0.3)));
          for (double& x : b) x = -x;
          break;
        case 4: b = near(r, a, r.uniform(2.8, std::numbers::pi - 1e-4)); break;  // Omega near pi/2
        default: b = a; break;                                                   // Omega = 0
      }
      F4 fa = to_f4(a), fb = to_f4(b);
      if (i % 6 == 5 && i % 4 == 1) {  // identities, and an exact antipode of one (EDGE-1, EDGE-3)
        fa = {0, 0, 0, 1};
        fb = (i % 8 == 1) ? F4{0, 0, 0, -1} : F4{0, 0, 0, 1};
        identity = true;
      }
      if (abs_dot(fa, fb) < 0x1p-16) continue;  // the fast paths leave near-ties to the general kernels
      static const float special[] = {0.0f, 1.0f, 0.5f, 0x1p-30f, 1.0f - 0x1p-24f};
      p.t.push_back(i % 7 == 0 ? special[(i / 7) % 5] : static_cast<float>(r.uniform(0, 1)));
      p.a.push_back(fa);
      p.b.push_back(fb);
      p.exact_identity.push_back(identity);
    }
    return p;
  }();
  return s;
}

/// Ordinary pairs that are all keyframe neighbours, Omega <= pi/4 (rotation angles up to a
/// quarter turn, either sign of b), so that whole blocks take slerp's shorter series without
/// angle halving; includes angles just below pi/4, tiny ones and exact identities.
const OrdinaryPairs& neighbour_pairs() {
  static const OrdinaryPairs s = [] {
    OrdinaryPairs p;
    Rng r;
    r.g.seed(0x2e1);
    for (int i = 0; p.a.size() < 1500; ++i) {
      const auto a = unit_double(r);
      const double angle = i % 5 == 0   ? std::numbers::pi / 2 * (1 - std::pow(10.0, r.uniform(-6, -3)))
                           : i % 5 == 1 ? std::pow(10.0, r.uniform(-7, -2))
                                        : r.uniform(0, std::numbers::pi / 2);
      auto b = near(r, a, angle);
      if (r.pick(2))
        for (double& x : b) x = -x;
      F4 fa = to_f4(a), fb = to_f4(b);
      const bool identity = i % 37 == 3;
      if (identity) fa = {0, 0, 0, 1}, fb = {0, 0, 0, i % 2 ? -1.0f : 1.0f};
      static const float special[] = {0.0f, 1.0f, 0.5f, 0x1p-30f, 1.0f - 0x1p-24f};
      p.t.push_back(i % 7 == 0 ? special[(i / 7) % 5] : static_cast<float>(r.uniform(0, 1)));
      p.a.push_back(fa);
      p.b.push_back(fb);
      p.exact_identity.push_back(identity);
    }
    return p;
  }();
  return s;
}

void check_interp_fast(const char* op, InterpFn fn, ref::Result<RQ> (*reference)(const RQ&, const RQ&, const Real&),
                       const OrdinaryPairs& p, const char* set) {
  TargetGuard guard;
  const std::size_t n = p.a.size();
  std::vector<RQ> want(n);
  for (std::size_t i = 0; i < n; ++i) want[i] = reference(rq(p.a[i].data()), rq(p.b[i].data()), Real(double(p.t[i]))).value;
  for (const std::string& target : targets()) {
    ASSERT_EQ(impl().select_target(target.c_str()), 0);
    std::vector<float> out(n * 4, -7.0f);
    std::vector<std::uint8_t> st(n, 99);
    in_chunks(n, [&](std::size_t i, std::size_t m) {
      ASSERT_EQ(fn(m, p.a[i].data(), p.b[i].data(), &p.t[i], &out[i * 4], &st[i]), 0);
    });
    expect_all_ok(st, op, target);
    Worst w;
    for (std::size_t i = 0; i < n; ++i) {
      const std::string in = "a=" + hex(p.a[i].data(), 4) + " b=" + hex(p.b[i].data(), 4) + " t=" + hex(&p.t[i], 1);
      w.see(quat_error(&out[i * 4], want[i]), in);
      if (p.exact_identity[i]) {
        EXPECT_EQ(F4({out[i * 4], out[i * 4 + 1], out[i * 4 + 2], out[i * 4 + 3]}), F4({0, 0, 0, 1}))
            << op << " " << target << " " << in << " -> " << hex(&out[i * 4], 4);
      }
      // SLERP-3 / NLERP-1 endpoints carry the sign: t = 0 is a, t = 1 is b' (not -b').
      if (p.t[i] == 0.0f || p.t[i] == 1.0f) {
        const RQ end = p.t[i] == 0.0f ? rq(p.a[i].data()) : want[i];
        EXPECT_GT(ref::dot(rq(&out[i * 4]), end), 0) << op << " " << target << " " << in;
      }
    }
    report(op, target + "/" + set, w, "eps16");
  }
}

TEST(RotorSimdFastPaths, Slerp) {
  RC_CLAUSE("SLERP-1");
  RC_CLAUSE("SLERP-3");
  RC_CLAUSE("EDGE-1");
  RC_CLAUSE("EDGE-2");
  RC_CLAUSE("EDGE-3");
  check_interp_fast("slerp", ops().slerp, &clause::SLERP_1_slerp<Real>, ordinary_pairs(), "fast");
  check_interp_fast("slerp", ops().slerp, &clause::SLERP_1_slerp<Real>, neighbour_pairs(), "fast-near");
}

TEST(RotorSimdFastPaths, Nlerp) {
  RC_CLAUSE("NLERP-1");
  RC_CLAUSE("EDGE-1");
  RC_CLAUSE("EDGE-2");
  check_interp_fast("nlerp", ops().nlerp, &clause::NLERP_1_nlerp<Real>, ordinary_pairs(), "fast");
  check_interp_fast("nlerp", ops().nlerp, &clause::NLERP_1_nlerp<Real>, neighbour_pairs(), "fast-near");
}

TEST(RotorSimdFastPaths, BlendQlbFourInfluences) {
  RC_CLAUSE("QLB-1");
  RC_CLAUSE("EDGE-1");
  TargetGuard guard;
  constexpr std::size_t k = 4, n = 1000;
  Rng r;
  r.g.seed(0xb1e4d);
  std::vector<float> q, w;
  std::vector<bool> identity(n, false);
  for (std::size_t i = 0; i < n; ++i) {
    const auto center = unit_double(r);
    const double spread = i % 3 == 0 ? 3.0 : i % 3 == 1 ? 0.5 : 1e-4;
    identity[i] = i % 50 == 7;  // a weighted sum of +-identities: exactly (0, 0, 0, 1) out
    F4 first{};
    for (std::size_t j = 0; j < k; ++j) {
      F4 f;
      do {
        auto qj = near(r, center, r.uniform(0, spread));
        if (r.pick(2))
          for (double& x : qj) x = -x;
        f = identity[i] ? F4{0, 0, 0, r.pick(2) ? 1.0f : -1.0f} : to_f4(qj);
        if (identity[i] && j == 0) f[3] = 1.0f;
      } while (j > 0 && abs_dot(f, first) < 0x1p-16);  // hemisphere signs clear of ties
      if (j == 0) first = f;
      q.insert(q.end(), f.begin(), f.end());
      w.push_back(static_cast<float>(r.uniform(0.05, 1)));
    }
  }
  std::vector<RQ> want(n);
  for (std::size_t i = 0; i < n; ++i) {
    std::vector<RQ> qs;
    std::vector<Real> ws;
    for (std::size_t j = 0; j < k; ++j) {
      qs.push_back(rq(&q[(i * k + j) * 4]));
      ws.push_back(Real(double(w[i * k + j])));
    }
    want[i] = clause::QLB_1_blend<Real>(qs, ws).value;
  }
  for (const std::string& target : targets()) {
    ASSERT_EQ(impl().select_target(target.c_str()), 0);
    std::vector<float> out(n * 4);
    std::vector<std::uint8_t> st(n);
    in_chunks(n, [&](std::size_t i, std::size_t m) {
      ASSERT_EQ(ops().blend_qlb(m, k, &q[i * k * 4], &w[i * k], &out[i * 4], &st[i]), 0);
    });
    expect_all_ok(st, "qlb", target);
    Worst worst;
    for (std::size_t i = 0; i < n; ++i) {
      const std::string in = "q=" + hex(&q[i * k * 4], 4 * int(k)) + " w=" + hex(&w[i * k], int(k));
      worst.see(quat_error(&out[i * 4], want[i]), in);
      if (identity[i]) {
        EXPECT_EQ(F4({out[i * 4], out[i * 4 + 1], out[i * 4 + 2], out[i * 4 + 3]}), F4({0, 0, 0, 1}))
            << target << " " << in << " -> " << hex(&out[i * 4], 4);
      }
    }
    report("qlb", target + "/fast/k4", worst, "eps32");
  }
}

// Blocks of ordinary lanes with one unusual lane in most blocks (every fifth element; blocks
// are 4, 8 or 16 elements): the fast path must decline such a block as a whole, and the
// general kernel must then give every lane its defined result, the ordinary ones included.
// Unusual: domain errors (EDGE-6, EDGE-7, EDGE-9), extrapolation, non-unit inputs, exact ties.

TEST(RotorSimdFastPaths, InterpBlocksWithOneUnusualLane) {
  RC_CLAUSE("SLERP-1");
  RC_CLAUSE("SLERP-4");
  RC_CLAUSE("NLERP-1");
  RC_CLAUSE("EDGE-3");
  RC_CLAUSE("EDGE-5");
  RC_CLAUSE("EDGE-6");
  RC_CLAUSE("EDGE-7");
  TargetGuard guard;
  const OrdinaryPairs& ord = ordinary_pairs();
  const std::size_t n = 400;
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  std::vector<F4> a(ord.a.begin(), ord.a.begin() + n), b(ord.b.begin(), ord.b.begin() + n);
  std::vector<float> t(ord.t.begin(), ord.t.begin() + n);
  std::vector<bool> domain_error(n, false), tie(n, false);
  for (std::size_t i = 2; i < n; i += 5) {
    switch ((i / 5) % 7) {
      case 0: t[i] = nan, domain_error[i] = true; break;
      case 1: a[i] = {0, -0.0f, 0, 0}, domain_error[i] = true; break;
      case 2: b[i] = {inf, 0, 0, 1}, domain_error[i] = true; break;
      case 3: t[i] = (i % 2) ? 1.5f : -0.25f; break;  // extrapolation
      case 4: a[i] = rescale(a[i], 40); break;        // non-unit
      case 5: b[i] = {-a[i][1], a[i][0], -a[i][3], a[i][2]}, tie[i] = true; break;  // a.b = 0 exactly
      default: b[i] = rescale(b[i], -70); break;
    }
  }
  for (const bool slerp : {true, false}) {
    const InterpFn fn = slerp ? ops().slerp : ops().nlerp;
    const auto reference = slerp ? &clause::SLERP_1_slerp<Real> : &clause::NLERP_1_nlerp<Real>;
    std::vector<RQ> want(n);
    for (std::size_t i = 0; i < n; ++i) {
      if (domain_error[i]) continue;
      const RQ qa = rq(a[i].data()), qb = rq(b[i].data());
      const Real ti = Real(double(t[i]));
      want[i] = tie[i] ? tie_expected(slerp, qa, qb, ti) : reference(qa, qb, ti).value;
    }
    for (const std::string& target : targets()) {
      ASSERT_EQ(impl().select_target(target.c_str()), 0);
      std::vector<float> out(n * 4, -7.0f);
      std::vector<std::uint8_t> st(n, 99);
      in_chunks(n, [&](std::size_t i, std::size_t m) {
        ASSERT_EQ(fn(m, a[i].data(), b[i].data(), &t[i], &out[i * 4], &st[i]), 0);
      });
      Worst w;
      for (std::size_t i = 0; i < n; ++i) {
        const std::string in = "a=" + hex(a[i].data(), 4) + " b=" + hex(b[i].data(), 4) + " t=" + hex(&t[i], 1);
        EXPECT_EQ(st[i], domain_error[i] ? RC_DOMAIN_ERROR : RC_OK) << target << " " << in;
        if (domain_error[i]) {
          EXPECT_TRUE(all_nan(&out[i * 4], 4)) << target << " " << in;
        } else {
          w.see(quat_error(&out[i * 4], want[i]), in);
        }
      }
      report(slerp ? "slerp" : "nlerp", target + "/mixed", w, "eps16");
    }
  }
}

TEST(RotorSimdFastPaths, QlbBlocksWithOneUnusualLane) {
  RC_CLAUSE("QLB-1");
  RC_CLAUSE("EDGE-5");
  RC_CLAUSE("EDGE-6");
  RC_CLAUSE("EDGE-7");
  RC_CLAUSE("EDGE-9");
  TargetGuard guard;
  constexpr std::size_t k = 4, n = 400;
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  Rng r;
  r.g.seed(0x0dd1a9e);
  std::vector<float> q, w;
  for (std::size_t i = 0; i < n; ++i) {  // ordinary: unit influences near a centre, weights > 0
    const auto center = unit_double(r);
    for (std::size_t j = 0; j < k; ++j) {
      const F4 f = to_f4(near(r, center, r.uniform(0, 1.0)));
      q.insert(q.end(), f.begin(), f.end());
      w.push_back(static_cast<float>(r.uniform(0.05, 1)));
    }
  }
  std::vector<bool> domain_error(n, false);
  for (std::size_t i = 2; i < n; i += 5) {
    float* qi = &q[i * k * 4];
    float* wi = &w[i * k];
    switch ((i / 5) % 10) {
      case 0: wi[1] = -0.5f, domain_error[i] = true; break;
      case 1: wi[2] = nan, domain_error[i] = true; break;
      case 2: wi[0] = inf, domain_error[i] = true; break;
      case 3: std::fill(qi + 12, qi + 16, 0.0f), wi[3] = 0, domain_error[i] = true; break;  // zero q, weight 0
      case 4: qi[4] = nan, domain_error[i] = true; break;
      case 5: std::fill(wi, wi + k, 0.0f), domain_error[i] = true; break;
      case 6: wi[0] = 0; break;                                   // the pivot is influence 1
      case 7: wi[0] = -0.0f; break;                               // -0 counts as 0
      case 8: for (int c = 8; c < 12; ++c) qi[c] = std::ldexp(qi[c], 50); break;  // non-unit
      default: for (std::size_t j = 0; j < k; ++j) wi[j] *= 1e30f; break;          // huge weights
    }
  }
  std::vector<RQ> want(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (domain_error[i]) continue;
    std::vector<RQ> qs;
    std::vector<Real> ws;
    for (std::size_t j = 0; j < k; ++j) {
      qs.push_back(rq(&q[(i * k + j) * 4]));
      ws.push_back(Real(double(w[i * k + j])));
    }
    want[i] = clause::QLB_1_blend<Real>(qs, ws).value;
  }
  for (const std::string& target : targets()) {
    ASSERT_EQ(impl().select_target(target.c_str()), 0);
    std::vector<float> out(n * 4, -7.0f);
    std::vector<std::uint8_t> st(n, 99);
    in_chunks(n, [&](std::size_t i, std::size_t m) {
      ASSERT_EQ(ops().blend_qlb(m, k, &q[i * k * 4], &w[i * k], &out[i * 4], &st[i]), 0);
    });
    Worst worst;
    for (std::size_t i = 0; i < n; ++i) {
      const std::string in = "q=" + hex(&q[i * k * 4], 4 * int(k)) + " w=" + hex(&w[i * k], int(k));
      EXPECT_EQ(st[i], domain_error[i] ? RC_DOMAIN_ERROR : RC_OK) << target << " " << in;
      if (domain_error[i]) {
        EXPECT_TRUE(all_nan(&out[i * 4], 4)) << target << " " << in;
      } else {
        worst.see(quat_error(&out[i * 4], want[i]), in);
      }
    }
    report("qlb", target + "/mixed/k4", worst, "eps32");
  }
}

// ---- dispatch: a short tail runs on the one-lane or the narrowest target ---------------------

/// Lanes of binary32 vectors per x86 Highway target (SCALAR and EMU128 are not SIMD targets).
std::size_t lanes_of(const std::string& target) {
  static const std::map<std::string, std::size_t> lanes = {
      {"SSSE3", 4}, {"SSE4", 4}, {"AVX2", 8}, {"AVX3", 16}, {"AVX3_DL", 16}, {"AVX3_ZEN4", 16}};
  const auto it = lanes.find(target);
  return it == lanes.end() ? 0 : it->second;
}

/// The default target's batch of two full blocks and a tail of `tail` elements against the full
/// blocks computed on `wide` and the tail on `tail_target`, each forced.
void check_split(const std::string& wide, const std::string& tail_target, std::size_t tail) {
  const std::size_t full = 2 * lanes_of(wide), n = full + tail;
  Rng r;
  const std::size_t k = 4;
  std::vector<float> a, b, t, v, q, w;
  for (std::size_t i = 0; i < n; ++i) {
    const F4 qa = rescale(to_f4(unit_double(r)), int(i % 5) - 2), qb = to_f4(near(r, unit_double(r), 2.0));
    a.insert(a.end(), qa.begin(), qa.end());
    b.insert(b.end(), qb.begin(), qb.end());
    t.push_back(static_cast<float>(r.uniform(-0.5, 1.5)));
    for (int c = 0; c < 3; ++c) v.push_back(static_cast<float>(r.uniform(-2, 2)));
    for (std::size_t j = 0; j < k; ++j) {
      const F4 f = to_f4(near(r, unit_double(r), 1.0));
      q.insert(q.end(), f.begin(), f.end());
      w.push_back(static_cast<float>(r.uniform(0.05, 1)));
    }
  }
  struct Op {
    const char* name;
    std::size_t width;  // output floats per element
    std::function<void(std::size_t first, std::size_t count, float* out, std::uint8_t* st)> call;
  };
  const std::vector<Op> ops_under_test = {
      {"normalize", 4, [&](std::size_t i, std::size_t m, float* o, std::uint8_t* s) { ASSERT_EQ(ops().normalize(m, &a[4 * i], o, s), 0); }},
      {"compose", 4, [&](std::size_t i, std::size_t m, float* o, std::uint8_t* s) { ASSERT_EQ(ops().compose(m, &a[4 * i], &b[4 * i], o, s), 0); }},
      {"apply_vector", 3, [&](std::size_t i, std::size_t m, float* o, std::uint8_t* s) { ASSERT_EQ(ops().apply_vector(m, &a[4 * i], &v[3 * i], o, s), 0); }},
      {"to_matrix", 9, [&](std::size_t i, std::size_t m, float* o, std::uint8_t* s) { ASSERT_EQ(ops().to_matrix(m, &a[4 * i], o, s), 0); }},
      {"log", 3, [&](std::size_t i, std::size_t m, float* o, std::uint8_t* s) { ASSERT_EQ(ops().log(m, &a[4 * i], o, s), 0); }},
      {"exp", 4, [&](std::size_t i, std::size_t m, float* o, std::uint8_t* s) { ASSERT_EQ(ops().exp(m, &v[3 * i], o, s), 0); }},
      {"slerp", 4, [&](std::size_t i, std::size_t m, float* o, std::uint8_t* s) { ASSERT_EQ(ops().slerp(m, &a[4 * i], &b[4 * i], &t[i], o, s), 0); }},
      {"nlerp", 4, [&](std::size_t i, std::size_t m, float* o, std::uint8_t* s) { ASSERT_EQ(ops().nlerp(m, &a[4 * i], &b[4 * i], &t[i], o, s), 0); }},
      {"blend_qlb", 4, [&](std::size_t i, std::size_t m, float* o, std::uint8_t* s) { ASSERT_EQ(ops().blend_qlb(m, k, &q[4 * k * i], &w[k * i], o, s), 0); }},
      {"blend_log", 4, [&](std::size_t i, std::size_t m, float* o, std::uint8_t* s) { ASSERT_EQ(ops().blend_log(m, k, &q[4 * k * i], &w[k * i], o, s), 0); }},
  };
  for (const Op& op : ops_under_test) {
    std::vector<float> got(n * op.width), want(n * op.width);
    std::vector<std::uint8_t> got_st(n, 99), want_st(n, 99);
    ASSERT_EQ(impl().select_target(nullptr), 0);
    op.call(0, n, got.data(), got_st.data());
    ASSERT_EQ(impl().select_target(wide.c_str()), 0);
    op.call(0, full, want.data(), want_st.data());
    ASSERT_EQ(impl().select_target(tail_target.c_str()), 0);
    op.call(full, n - full, want.data() + full * op.width, want_st.data() + full);
    for (std::size_t i = 0; i < n; ++i) {
      EXPECT_EQ(got_st[i], want_st[i]) << op.name << " element " << i;
      EXPECT_EQ(0, std::memcmp(&got[i * op.width], &want[i * op.width], op.width * sizeof(float)))
          << op.name << " element " << i << " of " << n << ": not the bits of " << (i < full ? wide : tail_target);
    }
  }
}

// With the default target, the n mod L elements after the last full block of L lanes run on the
// one-lane SCALAR target when they are one or two (a single-element call costs a padded block on
// any SIMD target), else on the narrowest SIMD target; the full blocks on the default one. Bit
// for bit: the full blocks as the default target computes them, the tail as its target computes
// it alone; a wrong offset, width or choice of target in the split would move or mix elements.
TEST(RotorSimdDispatch, TheTailOfADefaultBatchRunsOnTheOneLaneOrTheNarrowestTarget) {
  const TargetGuard guard;
  if (const char* env = std::getenv("ROTORCERT_SIMD_TARGET"); env != nullptr && *env != '\0')
    GTEST_SKIP() << "ROTORCERT_SIMD_TARGET=" << env << " forces every element onto one target";
  ASSERT_EQ(impl().select_target(nullptr), 0);
  const std::string wide = impl().current_target();
  std::string narrow;
  bool has_scalar = false;
  for (const std::string& t : targets()) {
    if (lanes_of(t) != 0 && (narrow.empty() || lanes_of(t) <= lanes_of(narrow))) narrow = t;
    has_scalar = has_scalar || t == "SCALAR";
  }
  if (lanes_of(wide) == 0 || narrow.empty()) GTEST_SKIP() << "default target " << wide << " is not an x86 SIMD target";
  ASSERT_TRUE(has_scalar) << "rotor_simd lists no SCALAR target";
  for (const std::size_t tail : {std::size_t{1}, std::size_t{2}, std::size_t{3}}) {
    const std::string tail_target = tail <= 2 ? "SCALAR" : lanes_of(narrow) < lanes_of(wide) ? narrow : wide;
    std::printf("  default %s, a tail of %zu on %s\n", wide.c_str(), tail, tail_target.c_str());
    check_split(wide, tail_target, tail);
  }
}

}  // namespace
