#include <rotorcert/engine/cases.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <limits>
#include <random>
#include <optional>
#include <set>

#include <rotorcert/reference/mat3_domain.hpp>
#include <rotorcert/reference/rigid_ops.hpp>
#include <rotorcert/reference/rotation_ops.hpp>

#include "../selfcheck/ops.hpp"

namespace rotorcert::engine {
namespace {

using Quat = ref::Quaternion<Real>;
using V3 = ref::Vec3<Real>;

// Which ABI ops judge which clause. Edge clauses apply to every op whose inputs they concern.
const std::map<std::string, std::vector<std::string>>& clause_ops() {
  static const std::vector<std::string> quaternion_ops = {
      "normalize", "compose", "inverse", "apply_vector", "apply_bivector", "apply_trivector", "to_matrix",
      "to_axis_angle", "log", "slerp", "nlerp", "blend_qlb", "blend_log", "to_angle", "to_axis", "sqrt"};
  static const std::vector<std::string> rigid_ops = {"dq_from_rotation_translation", "dq_compose", "dq_apply_point",
                                                    "dq_normalize", "dq_sclerp", "dq_blend",
                                                    "dq_to_rotation_translation", "dq_log"};
  // Rigid transforms as rotation + translation (RIGID-1 .. RIGID-3): quaternion inputs, vectors.
  static const std::vector<std::string> rotation_translation_ops = {"rigid_compose", "rigid_apply", "rigid_inverse"};
  static const std::vector<std::string> weighted_ops = {"blend_qlb", "blend_log", "dq_blend", "skin_linear",
                                                        "skin_dual_quaternion"};
  auto join = [](std::vector<std::string> a, const std::vector<std::string>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
  };
  static const std::map<std::string, std::vector<std::string>> table = {
      {"QUAT-2", {"apply_vector"}},
      {"NORM-1", {"normalize"}},
      {"COMPOSE-1", {"compose"}},
      {"INV-1", {"inverse"}},
      {"APPLY-1", {"apply_vector"}},
      {"APPLY-2", {"apply_bivector"}},
      {"APPLY-3", {"apply_trivector"}},
      {"MAT-1", {"to_matrix"}},
      {"MAT-2", {"from_matrix"}},
      {"MAT-3", {"from_matrix"}},
      {"AXANG-1", {"to_axis_angle"}},
      {"AXANG-2", {"from_axis_angle"}},
      {"AXANG-3", {"to_angle"}},
      {"AXANG-4", {"to_axis"}},
      {"SQRT-1", {"sqrt"}},
      {"LOG-1", {"log"}},
      {"LOG-2", {"log"}},
      {"EXP-1", {"exp"}},
      {"EXP-2", {"log", "exp"}},  // a round trip through both, see checks_for_clause_impl
      {"SLERP-1", {"slerp"}},
      {"SLERP-2", {"slerp"}},
      {"SLERP-3", {"slerp"}},
      {"SLERP-4", {"slerp"}},
      {"SLERP-5", {"slerp"}},
      {"NLERP-1", {"nlerp"}},
      {"QLB-1", {"blend_qlb"}},
      {"LOGBLEND-1", {"blend_log"}},
      {"DQ-1", {"dq_from_rotation_translation"}},
      {"DQ-2", {"dq_compose"}},
      {"DQ-3", {"dq_apply_point"}},
      {"DQ-4", {"dq_normalize"}},
      {"DQ-5", {"dq_sclerp"}},
      {"DQ-6", {"dq_blend"}},
      {"DQ-7", {"dq_to_rotation_translation"}},
      {"DQ-8", {"dq_log"}},
      {"DQ-9", {"dq_exp"}},
      {"RIGID-1", {"rigid_compose"}},
      {"RIGID-2", {"rigid_apply"}},
      {"RIGID-3", {"rigid_inverse"}},
      {"AXIS-1", {"rotate_about_axis"}},
      {"SKIN-1", {"skin_linear"}},
      {"SKIN-2", {"skin_dual_quaternion"}},
      {"SKIN-3", {"skin_linear", "skin_dual_quaternion"}},
      {"EDGE-1", {"normalize", "compose", "inverse", "apply_vector", "to_matrix", "from_matrix", "log", "exp", "slerp",
                  "nlerp", "blend_qlb", "blend_log", "dq_compose", "dq_normalize", "dq_sclerp", "dq_blend", "dq_log",
                  "dq_exp"}},
      {"EDGE-2", {"compose", "to_axis_angle", "log", "exp", "slerp", "nlerp", "blend_qlb", "blend_log", "dq_sclerp"}},
      {"EDGE-3", {"slerp", "nlerp", "blend_qlb", "dq_sclerp", "dq_blend"}},
      {"EDGE-4", {"compose", "inverse", "apply_vector", "to_matrix", "slerp", "nlerp", "blend_qlb", "dq_apply_point"}},
      {"EDGE-5", join(join(quaternion_ops, rotation_translation_ops),
                      {"dq_apply_point", "dq_normalize", "dq_sclerp", "dq_blend", "from_axis_angle", "rotate_about_axis",
                       "dq_to_rotation_translation", "dq_log"})},
      {"EDGE-6", join(join(join(quaternion_ops, rigid_ops), rotation_translation_ops), {"from_axis_angle", "rotate_about_axis"})},
      {"EDGE-7", join(join(join(quaternion_ops, rigid_ops), rotation_translation_ops),
                      {"from_matrix", "from_axis_angle", "exp", "rotate_about_axis", "skin_linear", "skin_dual_quaternion",
                       "dq_exp"})},
      {"EDGE-8", {"normalize", "apply_vector", "to_matrix", "slerp", "nlerp", "log", "to_angle", "to_axis", "sqrt"}},
      {"EDGE-9", weighted_ops},
  };
  return table;
}

/// Deterministic generator for one (seed, clause, op): the same triple gives the same cases.
class Gen {
 public:
  Gen(std::uint64_t seed, const std::string& clause, const std::string& op, ref::Format format) : format_(format) {
    std::uint64_t h = 1469598103934665603ull ^ seed;  // FNV-1a over clause and op
    for (char c : clause + "/" + op) h = (h ^ static_cast<unsigned char>(c)) * 1099511628211ull;
    rng_.seed(h);
  }

  ref::Format format() const { return format_; }
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng_); }
  int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }
  double normal() { return std::normal_distribution<double>(0.0, 1.0)(rng_); }
  Real round(const Real& x) const { return round_to(format_, x); }

  /// Uniform on S^3 (normalised Gaussian), normalised exactly, then rounded to the format.
  Quat unit_quaternion() {
    const Quat q{Real(normal()), Real(normal()), Real(normal()), Real(normal())};
    return rounded(ref::normalized(q));
  }
  /// A unit vector, exact, not rounded.
  V3 direction() {
    V3 v{Real(normal()), Real(normal()), Real(normal())};
    const Real n = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    return {v[0] / n, v[1] / n, v[2] / n};
  }
  /// A unit vector, rounded to the format.
  V3 unit_vector() {
    const V3 d = direction();
    return {round(d[0]), round(d[1]), round(d[2])};
  }
  /// A vector of length 10^U(lo, hi), rounded.
  V3 vector(double lo_exp10, double hi_exp10) {
    const V3 d = direction();
    const Real len = pow(Real(10), Real(uniform(lo_exp10, hi_exp10)));
    return {round(d[0] * len), round(d[1] * len), round(d[2] * len)};
  }
  /// Exact rotation by angle about a unit axis (not rounded).
  static Quat rotation(const Real& angle, const V3& axis) {
    const Real h = angle / Real(2);
    return {cos(h), sin(h) * axis[0], sin(h) * axis[1], sin(h) * axis[2]};
  }
  /// b = a * (rotation by `angle` about a random axis), rounded.
  Quat near(const Quat& a, const Real& angle) { return rounded(a * rotation(angle, direction())); }
  Quat rounded(const Quat& q) const { return {round(q.w), round(q.x), round(q.y), round(q.z)}; }
  /// A unit dual quaternion of a random rotation and a translation of length up to 10^hi.
  ref::DualQuaternion<Real> rigid(double hi_exp10) {
    const Quat q = ref::normalized(Quat{Real(normal()), Real(normal()), Real(normal()), Real(normal())});
    const V3 d = direction();
    const Real len = pow(Real(10), Real(uniform(-1, hi_exp10)));
    const auto r = ref::clause::DQ_1_from_rotation_translation(q, V3{d[0] * len, d[1] * len, d[2] * len});
    return {rounded(r.value.real), rounded(r.value.dual)};
  }

 private:
  std::mt19937_64 rng_;
  ref::Format format_;
};

std::vector<Real> flat(const Quat& q) { return {q.x, q.y, q.z, q.w}; }
std::vector<Real> flat(const V3& v) { return {v[0], v[1], v[2]}; }
std::vector<Real> flat(const ref::DualQuaternion<Real>& d) {
  return {d.real.x, d.real.y, d.real.z, d.real.w, d.dual.x, d.dual.y, d.dual.z, d.dual.w};
}
void append(std::vector<Real>& a, const std::vector<Real>& b) { a.insert(a.end(), b.begin(), b.end()); }

/// Positive weights, rounded, the first one positive (it is the pivot).
std::vector<Real> weights(Gen& g, std::size_t k) {
  std::vector<Real> w;
  for (std::size_t i = 0; i < k; ++i) w.push_back(g.round(Real(g.uniform(i == 0 ? 0.05 : 0.0, 1.0))));
  return w;
}

/// One ordinary random input for `op` (influence count k for n-way ops).
Case random_case(Gen& g, const std::string& op, std::size_t k = 0) {
  Case c;
  c.label = "random";
  c.flags = {"Random"};
  auto q = [&] { return flat(g.unit_quaternion()); };
  auto t01 = [&] { return std::vector<Real>{g.round(Real(g.uniform(0, 1)))}; };
  if (op == "normalize" || op == "inverse" || op == "to_matrix" || op == "to_axis_angle" || op == "log" ||
      op == "to_angle" || op == "to_axis" || op == "sqrt") {
    c.inputs = {q()};
  } else if (op == "compose") {
    c.inputs = {q(), q()};
  } else if (op == "apply_vector" || op == "apply_bivector") {
    c.inputs = {q(), flat(g.vector(-3, 3))};
  } else if (op == "apply_trivector") {
    c.inputs = {q(), {g.round(Real(g.uniform(-10, 10)))}};
  } else if (op == "from_matrix") {
    const Quat u = ref::normalized(Quat{Real(g.normal()), Real(g.normal()), Real(g.normal()), Real(g.normal())});
    const auto m = ref::clause::MAT_1_to_matrix(u).value;
    std::vector<Real> mm;
    for (const Real& x : m) mm.push_back(g.round(x));
    c.inputs = {mm};
  } else if (op == "from_axis_angle") {
    // A unit axis (rounded): a non-unit axis is an EDGE-5 input (Robust), and many APIs document
    // a unit axis as their precondition (DECL-1).
    c.inputs = {{g.round(Real(g.uniform(-7, 7)))}, flat(g.unit_vector())};
  } else if (op == "exp") {
    const V3 d = g.direction();
    const Real len(g.uniform(0, 3));
    c.inputs = {{g.round(d[0] * len), g.round(d[1] * len), g.round(d[2] * len)}};
  } else if (op == "slerp" || op == "nlerp") {
    c.inputs = {q(), q(), t01()};
  } else if (op == "blend_qlb" || op == "blend_log") {
    c.k = k ? k : std::size_t(g.integer(1, 5));
    std::vector<Real> qs;
    for (std::size_t i = 0; i < c.k; ++i) append(qs, q());
    c.inputs = {qs, weights(g, c.k)};
  } else if (op == "dq_from_rotation_translation") {
    c.inputs = {q(), flat(g.vector(-1, 3))};
  } else if (op == "dq_compose") {
    c.inputs = {flat(g.rigid(3)), flat(g.rigid(3))};
  } else if (op == "dq_to_rotation_translation" || op == "dq_log") {
    c.inputs = {flat(g.rigid(3))};
  } else if (op == "dq_exp") {
    // A screw: rotation part of any length up to 3 (beyond pi/2 included), a translation part of
    // length 10^U(-1, 3).
    const V3 d = g.direction();
    const Real len(g.uniform(0, 3));
    std::vector<Real> xi = {g.round(d[0] * len), g.round(d[1] * len), g.round(d[2] * len)};
    append(xi, flat(g.vector(-1, 3)));
    c.inputs = {xi};
  } else if (op == "rigid_compose") {
    c.inputs = {q(), flat(g.vector(-1, 3)), q(), flat(g.vector(-1, 3))};
  } else if (op == "rigid_apply") {
    c.inputs = {q(), flat(g.vector(-1, 3)), flat(g.vector(-1, 3))};
  } else if (op == "rigid_inverse") {
    c.inputs = {q(), flat(g.vector(-1, 3))};
  } else if (op == "dq_apply_point") {
    c.inputs = {flat(g.rigid(3)), flat(g.vector(-1, 3))};
  } else if (op == "dq_normalize") {
    // Non-unit and with a dual part not orthogonal to the real part: what DQ-4 must repair.
    auto d = g.rigid(2);
    const Real s(std::ldexp(1.0, g.integer(-3, 3)));
    std::vector<Real> v = flat(d);
    for (int i = 0; i < 8; ++i) v[i] = g.round(v[i] * s);
    for (int i = 4; i < 8; ++i) v[i] = g.round(v[i] + v[i - 4] * Real(g.uniform(-0.5, 0.5)));
    c.inputs = {v};
  } else if (op == "dq_sclerp") {
    c.inputs = {flat(g.rigid(2)), flat(g.rigid(2)), t01()};
  } else if (op == "dq_blend") {
    c.k = k ? k : std::size_t(g.integer(1, 4));
    std::vector<Real> ds;
    for (std::size_t i = 0; i < c.k; ++i) append(ds, flat(g.rigid(2)));
    c.inputs = {ds, weights(g, c.k)};
  } else if (op == "rotate_about_axis") {
    c.inputs = {flat(g.vector(-1, 1)), flat(g.unit_vector()), {g.round(Real(g.uniform(-7, 7)))}, flat(g.vector(-1, 2))};
  } else if (op == "skin_linear" || op == "skin_dual_quaternion") {
    c.k = k ? k : std::size_t(g.integer(1, 4));
    std::vector<Real> qs, ts;
    for (std::size_t i = 0; i < c.k; ++i) {
      append(qs, q());
      append(ts, flat(g.vector(-1, 1)));
    }
    c.inputs = {qs, ts, weights(g, c.k), flat(g.vector(-1, 1))};
  }
  return c;
}

/// Indices of the input arrays of `op` that hold quaternions (stride 4) or dual quaternions (8).
std::vector<std::size_t> arrays_with_stride(const std::string& op, int stride) {
  std::vector<std::size_t> r;
  const AbiOp* d = find_abi_op(op);
  for (std::size_t i = 0; d && i < d->inputs.size(); ++i)
    if (d->inputs[i].stride == stride) r.push_back(i);
  return r;
}

/// The case with its label (prose, for people) and its test-vector flags (data: the vocabulary of
/// conformance/src/vectors/flags.cpp, in any order).
Case labelled(Case c, std::string label, std::vector<std::string> flags) {
  c.label = std::move(label);
  c.flags = std::move(flags);
  return c;
}

/// Flags of a non-unit input scaled by 2^e: beyond +-10 its |q|^2 leaves the format (EDGE-5).
std::vector<std::string> scale_flags(int e) {
  std::vector<std::string> f = {"NonUnit"};
  if (e > 10) f.push_back("HugeScale");
  if (e < -10) f.push_back("TinyScale");
  return f;
}

/// Replaces every quaternion of every quaternion array by q, every dual quaternion by d.
Case with_all(Case c, const std::string& op, const std::vector<Real>& q, const std::vector<Real>& d) {
  for (std::size_t i : arrays_with_stride(op, 4))
    for (std::size_t j = 0; j < c.inputs[i].size(); j += 4) std::copy(q.begin(), q.end(), c.inputs[i].begin() + j);
  for (std::size_t i : arrays_with_stride(op, 8))
    for (std::size_t j = 0; j < c.inputs[i].size(); j += 8) std::copy(d.begin(), d.end(), c.inputs[i].begin() + j);
  return c;
}

/// The angle of the i-th of n strata of a logarithmic sweep over [1e-9, pi]: every decade is
/// sampled, with no gap (LEVEL-1 ordinary inputs: every angle, dense at the ends).
Real swept_angle(Gen& g, int i, int n) {
  const double lo = -9.0, hi = std::log10(M_PI);
  const double u = (static_cast<double>(i) + g.uniform(0, 1)) / static_cast<double>(std::max(1, n));
  return std::min(Real(ref::ScalarTraits<Real>::pi()), pow(Real(10), Real(lo + (hi - lo) * u)));
}
/// 10^U(-9, -1): how far short of a full turn (or of an antipode) the near-2pi families go.
Real shortfall(Gen& g, int i, int n) {
  const double u = (static_cast<double>(i) + g.uniform(0, 1)) / static_cast<double>(std::max(1, n));
  return pow(Real(10), Real(-9.0 + 8.0 * u));
}

/// The dot product a.b as the format computes it (4 products, 3 sums, in order).
Real format_dot(const std::vector<Real>& a, const std::vector<Real>& b, ref::Format f) {
  if (f == ref::Format::binary32) {
    float s = 0;
    for (int i = 0; i < 4; ++i) s += mpfr_get_flt(a[i].mpfr_srcptr(), MPFR_RNDN) * mpfr_get_flt(b[i].mpfr_srcptr(), MPFR_RNDN);
    return Real(s);
  }
  double s = 0;
  for (int i = 0; i < 4; ++i) s += mpfr_get_d(a[i].mpfr_srcptr(), MPFR_RNDN) * mpfr_get_d(b[i].mpfr_srcptr(), MPFR_RNDN);
  return Real(s);
}

/// A rotation the format holds: the exact rotation by `angle` about a random axis, rounded.
Quat rounded_rotation(Gen& g, const Real& angle) { return g.rounded(Gen::rotation(angle, g.direction())); }

/// An ordinary pair (a, b') whose rotation distance is near a full turn: b = -a (rotated by a
/// tiny angle), the near-antipodal class. Every other pair is an exact antipode whose dot
/// product, rounded in the format, is below -1 where such an a exists (the acos(-1 - delta)
/// NaN class: after the hemisphere flip an acos-based slerp sees a dot above 1).
std::pair<Quat, Quat> near_antipodal_pair(Gen& g, int i, int n) {
  const Quat a = g.unit_quaternion();
  // The first: the identity and its negation, the antipode every animation has (a key and the
  // same key with the other sign).
  if (i == 0) return {Quat{Real(1), Real(0), Real(0), Real(0)}, Quat{Real(-1), Real(0), Real(0), Real(0)}};
  if (i % 2 == 0) {
    for (int tries = 0; tries < 64; ++tries) {
      const Quat c = g.unit_quaternion();
      const std::vector<Real> fc = flat(c), fm = flat(-c);
      if (format_dot(fc, fm, g.format()) < Real(-1)) return {c, -c};
    }
    return {a, -a};
  }
  return {a, g.rounded(-(a * Gen::rotation(shortfall(g, i, n), g.direction())))};
}

/// Puts the rotations a and b into the first two quaternion slots of `op`'s case: the influences 0
/// and 1 of a blend, or the two inputs of an interpolation; for dual-quaternion ops the real parts
/// of two rigid motions (translations drawn here), DQ-4 normalised and rounded.
void set_pair(Gen& g, Case& c, const std::string& op, const Quat& a, const Quat& b) {
  const bool nway = find_abi_op(op)->nway;
  if (op == "dq_blend" || op == "dq_sclerp") {
    auto d0 = g.rigid(1), d1 = g.rigid(1);
    d0.real = a;
    d1.real = b;
    std::vector<Real> f0 = flat(ref::clause::DQ_4_normalize(d0).value), f1 = flat(ref::clause::DQ_4_normalize(d1).value);
    for (auto* v : {&f0, &f1})
      for (Real& x : *v) x = g.round(x);
    if (nway) {
      std::copy(f0.begin(), f0.end(), c.inputs[0].begin());
      std::copy(f1.begin(), f1.end(), c.inputs[0].begin() + 8);
    } else {
      c.inputs[0] = f0;
      c.inputs[1] = f1;
    }
    return;
  }
  const auto fa = flat(a), fb = flat(b);
  if (nway) {
    std::copy(fa.begin(), fa.end(), c.inputs[0].begin());
    std::copy(fb.begin(), fb.end(), c.inputs[0].begin() + 4);
  } else {
    c.inputs[0] = fa;
    c.inputs[1] = fb;
  }
}

/// The ordinary families of LEVEL-1 for an operation clause (Core .. Skinning): a logarithmic
/// angle sweep over [1e-9, pi], rotations near a full turn (1e-9 .. 1e-1 short of 2 pi), and for
/// pairs and blends near-antipodal pairs (rounded dot below -1 included), near-identical pairs
/// at every scale of the format, and influences of unequal scales.
void add_ordinary_families(std::vector<Case>& cases, Gen& g, const std::string& op, int n) {
  const Real pi = ref::ScalarTraits<Real>::pi();
  const bool single = op == "normalize" || op == "inverse" || op == "to_matrix" || op == "to_axis_angle" ||
                      op == "log" || op == "apply_vector" || op == "to_angle" || op == "to_axis" || op == "sqrt";
  auto rotation_case = [&](const Real& angle, const char* what, const char* flag) {
    Case c = random_case(g, op);
    if (single) {
      c.inputs[0] = flat(rounded_rotation(g, angle));
    } else if (op == "exp") {
      const V3 d = g.direction();
      const Real h = angle / Real(2);
      c.inputs[0] = {g.round(d[0] * h), g.round(d[1] * h), g.round(d[2] * h)};
    } else if (op == "from_axis_angle") {
      c.inputs[0] = {g.round(angle)};
    } else if (op == "from_matrix") {
      const auto m = ref::clause::MAT_1_to_matrix(Gen::rotation(angle, g.direction())).value;
      c.inputs[0].clear();
      for (const Real& x : m) c.inputs[0].push_back(g.round(x));
    } else if (op == "compose") {
      c.inputs[0] = flat(rounded_rotation(g, angle));
      c.inputs[1] = flat(rounded_rotation(g, angle));
    } else if (op == "rigid_compose") {
      c.inputs[0] = flat(rounded_rotation(g, angle));
      c.inputs[2] = flat(rounded_rotation(g, angle));
    } else if (op == "rigid_apply" || op == "rigid_inverse") {
      c.inputs[0] = flat(rounded_rotation(g, angle));
    } else if (op == "dq_exp") {
      const V3 d = g.direction();
      const Real h = angle / Real(2);
      c.inputs[0][0] = g.round(d[0] * h), c.inputs[0][1] = g.round(d[1] * h), c.inputs[0][2] = g.round(d[2] * h);
    } else if (op == "dq_to_rotation_translation" || op == "dq_log") {
      // The rigid motion of that rotation and a random translation, DQ-1 exactly, then rounded.
      const V3 d = g.direction();
      const Real len = pow(Real(10), Real(g.uniform(-1, 3)));
      const auto r = ref::clause::DQ_1_from_rotation_translation(Gen::rotation(angle, g.direction()),
                                                                 V3{d[0] * len, d[1] * len, d[2] * len});
      c.inputs[0] = flat(ref::DualQuaternion<Real>{g.rounded(r.value.real), g.rounded(r.value.dual)});
    }
    c.label = what;
    c.flags = {flag};
    return c;
  };
  const bool rotation_valued = single || op == "exp" || op == "from_axis_angle" || op == "from_matrix" || op == "compose" ||
                               op == "dq_to_rotation_translation" || op == "dq_log" || op == "dq_exp" ||
                               op == "rigid_compose" || op == "rigid_apply" || op == "rigid_inverse";
  if (rotation_valued) {
    // One angle per decade whatever n is (2e-9, 2e-8, ..., 2): no decade is left to chance.
    for (int k = -9; k <= 0; ++k) cases.push_back(rotation_case(Real(2) * pow(Real(10), Real(k)), "angle sweep 1e-9 .. pi", "AngleSweep"));
    for (int i = 0; i < n; ++i) cases.push_back(rotation_case(swept_angle(g, i, n), "angle sweep 1e-9 .. pi", "AngleSweep"));
    for (int i = 0; i < n; ++i)
      cases.push_back(rotation_case(Real(2) * pi - shortfall(g, i, n), "near a full turn: 2 pi - 1e-9 .. 1e-1", "NearFullTurn"));
    return;
  }
  if (op == "slerp" || op == "nlerp") {
    for (int i = -10; i < n; ++i) {  // i < 0: one pair distance per decade, 2e-9 .. 2
      Case c = random_case(g, op);
      const Quat a = g.unit_quaternion();
      c.inputs[0] = flat(a);
      const Real distance = i < 0 ? Real(2) * pow(Real(10), Real(i + 1)) : swept_angle(g, i, n);
      c.inputs[1] = flat(g.rounded(a * Gen::rotation(distance, g.direction())));
      c.label = "pair distance sweep 1e-9 .. pi";
      c.flags = {"AngleSweep"};
      cases.push_back(c);
    }
    for (int i = 0; i < n; ++i) {
      Case c = random_case(g, op);
      const auto [a, b] = near_antipodal_pair(g, i, n);
      c.inputs[0] = flat(a);
      c.inputs[1] = flat(b);
      c.label = i % 2 == 0 ? "exact antipode (rounded dot below -1 where possible)" : "near-antipodal pair";
      c.flags = {i % 2 == 0 ? "Antipodal" : "NearAntipodal"};
      cases.push_back(c);
    }
    // Near-identical pairs at every scale of the format: b = a rotated by 2^-j, j = 1 .. p + 2.
    const int p = g.format() == ref::Format::binary32 ? 24 : 53;
    for (int i = 0; i < n; ++i) {
      Case c = random_case(g, op);
      const Quat a = g.unit_quaternion();
      const Real angle = Real(std::ldexp(g.uniform(1, 2), -1 - (i % (p + 2))));
      c.inputs[0] = flat(a);
      c.inputs[1] = flat(g.rounded(a * Gen::rotation(angle, g.direction())));
      c.label = "near-identical pair, distance 2^-" + std::to_string(1 + (i % (p + 2)));
      c.flags = {"NearIdentical"};
      cases.push_back(c);
    }
    return;
  }
  if (op == "blend_qlb" || op == "blend_log" || op == "dq_blend") {
    for (int i = 0; i < n; ++i) {
      Case c = random_case(g, op, 2);
      const auto [a, b] = near_antipodal_pair(g, i, n);
      set_pair(g, c, op, a, b);
      c.label = "near-antipodal influences";
      c.flags = {"NearAntipodal"};
      cases.push_back(c);
    }
    return;
  }
  if (op == "dq_sclerp") {
    for (int i = 0; i < n; ++i) {
      Case c = random_case(g, op);
      const auto [a, b] = near_antipodal_pair(g, i, n);
      set_pair(g, c, op, a, b);
      c.label = "near-antipodal real parts";
      c.flags = {"NearAntipodal"};
      cases.push_back(c);
    }
  }
}

void add_families(std::vector<Case>& cases, Gen& g, const std::string& clause, const std::string& op, int n) {
  const bool f32 = g.format() == ref::Format::binary32;
  auto repeat = [&](auto make) {
    for (int i = 0; i < n; ++i) cases.push_back(make(i));
  };
  auto random = [&](std::size_t k = 0) { return random_case(g, op, k); };
  const Real pi = ref::ScalarTraits<Real>::pi();

  if (clause == "NORM-1") {
    repeat([&](int) {
      Case c = random();
      const Real s(std::ldexp(g.uniform(0.5, 1.0), g.integer(-8, 8)));
      for (Real& x : c.inputs[0]) x = g.round(x * s);
      return labelled(c, "non-unit scale 2^-8..2^8", {"NonUnit"});
    });
  } else if (clause == "MAT-2") {
    repeat([&](int) { return random(); });
    // Half turns (w = 0) and near half turns: the branch where naive trace-based extraction fails.
    repeat([&](int) {
      const Quat u = Gen::rotation(pi - Real(g.uniform(0, 1e-3)), g.direction());
      const auto m = ref::clause::MAT_1_to_matrix(u).value;
      Case c;
      c.inputs = {{}};
      for (const Real& x : m) c.inputs[0].push_back(g.round(x));
      c.label = "near half turn";
      c.flags = {"NearHalfTurn"};
      return c;
    });
  } else if (clause == "MAT-3") {
    repeat([&](int i) {
      Case c = random();
      if (i % 4 == 3) {  // a reflection: det < 0 is outside the domain
        for (int r = 0; r < 3; ++r) c.inputs[0][r] = -c.inputs[0][r];
        return labelled(c, "reflection (det < 0)", {"Reflection"});
      }
      const double size = std::pow(10.0, g.uniform(-6, -2));
      for (Real& x : c.inputs[0]) x = g.round(x + Real(g.uniform(-size, size)));
      return labelled(c, "perturbed rotation", {"NonOrthogonalMatrix"});
    });
    // Singular values spread over the format's exponent range: M = U diag(2^a, 2^b, +-2^c) V^T,
    // U and V random or with components in {-1, 0, 1} (rotations of the cube, which keep the
    // scales in separate entries). A polar iteration that forms X^-T overflows; a determinant of
    // the matrix scaled as a whole underflows (fuzz findings conversions/regression-rotor-from-
    // matrix-spurious-domain-error-*). Only inputs whose det sign the format decides (outside
    // MAT-3's band |det| <= 8u per(|M|)), so that the status is judged; delta of such an input is
    // large, so the bar asks a unit rotation and the status, nothing finer.
    const int top = f32 ? 120 : 1000;
    auto cube_or_random = [&]() {
      if (g.integer(0, 1) == 0) return g.unit_quaternion();
      Quat q{Real(g.integer(-1, 1)), Real(g.integer(-1, 1)), Real(g.integer(-1, 1)), Real(g.integer(-1, 1))};
      if (q.w == 0 && q.x == 0 && q.y == 0 && q.z == 0) q.w = 1;
      const Real norm = sqrt(ref::dot(q, q));
      return Quat{q.w / norm, q.x / norm, q.y / norm, q.z / norm};
    };
    repeat([&](int i) {
      for (;;) {
        const auto u = ref::clause::MAT_1_to_matrix(cube_or_random()).value;
        const auto v = ref::clause::MAT_1_to_matrix(cube_or_random()).value;
        const std::array<int, 3> e{g.integer(-top, top), g.integer(-top, top), g.integer(-top, top)};
        const bool reflection = i % 4 == 3;
        Case c = random();
        for (int r = 0; r < 3; ++r)
          for (int col = 0; col < 3; ++col) {
            Real sum(0);
            for (int k = 0; k < 3; ++k)
              sum += u[std::size_t(k * 3 + r)] * Real(std::ldexp(k == 2 && reflection ? -1.0 : 1.0, e[std::size_t(k)])) *
                     v[std::size_t(k * 3 + col)];
            c.inputs[0][std::size_t(col * 3 + r)] = g.round(sum);
          }
        if (numerically_singular(c.inputs[0], g.format())) continue;
        const std::string what = "singular values 2^" + std::to_string(e[0]) + ", 2^" + std::to_string(e[1]) + ", " +
                                 (reflection ? "-2^" : "2^") + std::to_string(e[2]);
        return reflection ? labelled(c, what, {"SpreadSingularValues", "Reflection"}) : labelled(c, what, {"SpreadSingularValues"});
      }
    });
  } else if (clause == "AXANG-1" || clause == "AXANG-3" || clause == "AXANG-4" || clause == "SQRT-1") {
    repeat([&](int) { return random(); });
    // Angles above 2 pi - 1 (w < -cos(1/2)): where GLM 0.9.9.8's angle() returns the wrong branch.
    repeat([&](int) {
      Case c;
      c.inputs = {flat(g.rounded(Gen::rotation(Real(g.uniform(2 * M_PI - 1, 2 * M_PI)), g.direction())))};
      c.label = "angle in (2pi - 1, 2pi)";
      c.flags = {"AngleNear2Pi"};
      return c;
    });
    if (clause == "SQRT-1") {
      // q^ = -1: s = (0, 0, 1, 0), the +z of LOG-2 (another unit pure quaternion: ACC-1 minus_one_axis).
      for (double s : {1.0, 0.5, 3.0})
        cases.push_back(Case{{{Real(0), Real(0), Real(0), g.round(Real(-s))}}, 0, "negative real quaternion", {"NegativeReal"}});
      cases.push_back(Case{{{Real(-0.0), Real(0), Real(-0.0), Real(-1)}}, 0, "-1 with -0 components", {"NegativeZero", "NegativeReal"}});
    }
  } else if (clause == "DQ-7" || clause == "DQ-8") {
    repeat([&](int) { return random(); });
    // DQ-4 first: a real part off unit (within the ordinary 2^-6) and a dual part with a component
    // along the real part, which carries no translation and must be removed.
    repeat([&](int) {
      Case c = random();
      const Real s(1.0 + g.uniform(-0.01, 0.01));
      std::vector<Real>& v = c.inputs[0];
      for (int i = 0; i < 8; ++i) v[i] = g.round(v[i] * s);
      for (int i = 4; i < 8; ++i) v[i] = g.round(v[i] + v[i - 4] * Real(g.uniform(-0.5, 0.5)));
      return labelled(c, "dual part not orthogonal to the real part", {"NonUnit"});  // DQ-4 repairs it
    });
    if (clause == "DQ-8") {
      // The branch cut r = -1: xi = (pi t/|t|, t/2), and (pi (0, 0, 1), 0) without a translation
      // (another log of sigma with |xi_r| = pi: ACC-1 minus_one_axis).
      repeat([&](int i) {
        const V3 t = i % 4 == 0 ? V3{Real(0), Real(0), Real(0)} : g.vector(-1, 3);
        const auto r = ref::clause::DQ_1_from_rotation_translation(Quat{Real(-1), Real(0), Real(0), Real(0)}, t).value;
        Case c{{flat(ref::DualQuaternion<Real>{g.rounded(r.real), g.rounded(r.dual)})}, 0, "", {}};
        return labelled(c, i % 4 == 0 ? "real part -1, no translation" : "real part -1 (the branch cut)", {"NegativeReal"});
      });
    }
  } else if (clause == "DQ-9") {
    repeat([&](int) { return random(); });
    repeat([&](int i) {
      Case c = random();
      if (i % 2 == 0) {  // a pure translation: xi_r = 0, exp = (1, (0, xi_d)) exactly
        for (int j = 0; j < 3; ++j) c.inputs[0][std::size_t(j)] = Real(0);
        return labelled(c, "pure translation (xi_r = 0)", {"PureTranslation"});
      }
      const V3 d = g.direction();  // beyond a half turn of the rotor: |xi_r| in (pi, 3 pi)
      const Real len(g.uniform(M_PI, 3 * M_PI));
      for (int j = 0; j < 3; ++j) c.inputs[0][std::size_t(j)] = g.round(d[std::size_t(j)] * len);
      return labelled(c, "|xi_r| in (pi, 3 pi)", {"LargeAngle"});
    });
  } else if (clause == "LOG-2") {
    for (double s : {1.0, 0.5, 3.0})
      cases.push_back(Case{{{Real(0), Real(0), Real(0), g.round(Real(-s))}}, 0, "negative real quaternion", {"NegativeReal"}});
    cases.push_back(Case{{{Real(-0.0), Real(0), Real(-0.0), Real(-1)}}, 0, "-1 with -0 components", {"NegativeZero", "NegativeReal"}});
  } else if (clause == "SLERP-2") {
    repeat([&](int) { return random(); });
  } else if (clause == "SLERP-3") {
    repeat([&](int i) {
      Case c = random();
      c.inputs[2] = {Real(i % 2)};
      return labelled(c, i % 2 ? "t = 1" : "t = 0", {"Endpoint"});
    });
  } else if (clause == "SLERP-4") {
    repeat([&](int i) {
      Case c = random();
      c.inputs[2] = {g.round(Real(i % 2 ? g.uniform(1, 2) : g.uniform(-1, 0)))};
      return labelled(c, "t outside [0, 1]", {"TOutsideUnitInterval"});
    });
  } else if (clause == "SLERP-5") {
    // Half the pairs obtuse (a.b < 0), so the hemisphere rule is always exercised.
    for (int p = 0; p < std::max(2, n / 9); ++p) {
      Case base = random();
      Real d(0);
      for (int i = 0; i < 4; ++i) d += base.inputs[0][i] * base.inputs[1][i];
      const bool obtuse = p % 2 == 1;
      if ((d < 0) != obtuse)
        for (Real& x : base.inputs[1]) x = -x;
      for (int j = 0; j <= 8; ++j) {
        Case c = base;
        c.inputs[2] = {Real(j) / Real(8)};
        cases.push_back(labelled(c, obtuse ? "t = j/8 on one obtuse pair" : "t = j/8 on one pair",
                                  obtuse ? std::vector<std::string>{"TSweep", "ObtusePair"} : std::vector<std::string>{"TSweep"}));
      }
    }
  } else if (clause == "SKIN-3") {
    repeat([&](int i) {
      if (i % 2 == 0) return labelled(random(1), "single influence", {"SingleInfluence"});
      Case c = random(3);
      // Copy influence 0 (rotation and translation) over the others.
      for (std::size_t a : {std::size_t(0), std::size_t(1)}) {
        const std::size_t stride = c.inputs[a].size() / c.k;
        for (std::size_t j = 1; j < c.k; ++j)
          for (std::size_t s = 0; s < stride; ++s) c.inputs[a][j * stride + s] = c.inputs[a][s];
      }
      return labelled(c, "equal influences", {"EqualInfluences"});
    });
  } else if (clause == "EDGE-1") {
    const std::vector<Real> id = {Real(0), Real(0), Real(0), Real(1)};
    const std::vector<Real> did = {Real(0), Real(0), Real(0), Real(1), Real(0), Real(0), Real(0), Real(0)};
    Case c = with_all(random(2), op, id, did);
    if (op == "exp") c.inputs[0] = {Real(0), Real(0), Real(0)};
    if (op == "dq_exp") c.inputs[0] = std::vector<Real>(6, Real(0));
    if (op == "from_matrix") c.inputs[0] = {Real(1), Real(0), Real(0), Real(0), Real(1), Real(0), Real(0), Real(0), Real(1)};
    if (op == "apply_vector") c.inputs[1] = flat(g.vector(-1, 1));
    cases.push_back(labelled(c, "identity", {"Identity"}));
  } else if (clause == "EDGE-2") {
    repeat([&](int) {
      Case c = random(2);
      const Real angle = pow(Real(10), Real(g.uniform(-9, -3)));
      const Quat a = g.unit_quaternion();
      if (op == "log" || op == "to_axis_angle") {
        c.inputs[0] = flat(g.rounded(Gen::rotation(angle, g.direction())));
      } else if (op == "exp") {
        const V3 d = g.direction();
        c.inputs[0] = {g.round(d[0] * angle / 2), g.round(d[1] * angle / 2), g.round(d[2] * angle / 2)};
      } else if (op == "compose") {
        c.inputs[0] = flat(g.rounded(Gen::rotation(angle, g.direction())));
        c.inputs[1] = flat(g.rounded(Gen::rotation(angle, g.direction())));
      } else if (op == "blend_qlb" || op == "blend_log") {
        for (std::size_t j = 0; j < c.k; ++j) {
          const auto b = flat(g.near(a, angle));
          std::copy(b.begin(), b.end(), c.inputs[0].begin() + j * 4);
        }
      } else if (op == "dq_sclerp") {
        const auto d = g.rigid(1);
        c.inputs[0] = flat(d);
        auto e = d;
        e.real = g.near(d.real, angle);
        c.inputs[1] = flat(e);  // a dual part that no longer matches exactly: still a valid rigid motion
        c.inputs[1] = flat(ref::clause::DQ_4_normalize(e).value);
        for (Real& x : c.inputs[1]) x = g.round(x);
      } else {  // slerp, nlerp
        c.inputs[0] = flat(a);
        c.inputs[1] = flat(g.near(a, angle));
      }
      return labelled(c, "angle 1e-9 .. 1e-3", {"SmallAngle"});
    });
  } else if (clause == "EDGE-3") {
    repeat([&](int i) {
      Case c = random(2);
      const Quat a = g.unit_quaternion();
      // (x, y, z, w) and (-y, x, -w, z) have a dot product of exactly 0 in any arithmetic: the
      // products pair up and cancel. A half turn between them: the tie of the hemisphere rule.
      Quat b{a.z, -a.y, a.x, -a.w};
      if (i % 3 == 2) b = -a;  // exact antipode: flips, constant interpolation
      set_pair(g, c, op, a, b);
      return labelled(c, i % 3 == 2 ? "exact antipode" : "dot exactly 0", {i % 3 == 2 ? "Antipodal" : "HemisphereTie"});
    });
  } else if (clause == "EDGE-4") {
    repeat([&](int) {
      Case c = random(2);
      for (std::size_t i : arrays_with_stride(op, 4))
        for (Real& x : c.inputs[i]) x = -x;
      for (std::size_t i : arrays_with_stride(op, 8))
        for (Real& x : c.inputs[i]) x = -x;
      return labelled(c, "negated quaternions", {"Negated"});
    });
  } else if (clause == "EDGE-5") {
    const int extreme = f32 ? 100 : 900;  // |q|^2 overflows / underflows the format
    repeat([&](int i) {
      Case c = random(2);
      if (op == "compose" && i % 4 == 3) {
        // Unbalanced factors: a's largest component just below the overflow threshold (so |a|
        // itself overflows), b scaled down by as much, the product of order 1. A compose that
        // forms |a| unscaled returns Inf * 0 = NaN (fuzz finding rotor_m1-compose-norm-overflow).
        const int top = f32 ? 127 : 1023;
        Real big(0);
        for (int j = 0; j < 4; ++j) big = std::max(big, Real(abs(c.inputs[0][j])));
        const Real sa = Real(std::ldexp(g.uniform(1.9, 1.99), top)) / big;
        const Real sb(std::ldexp(g.uniform(1.0, 2.0), -top));
        for (Real& x : c.inputs[0]) x = g.round(x * sa);
        for (Real& x : c.inputs[1]) x = g.round(x * sb);
        return labelled(c, "unbalanced factors: |a| at the overflow threshold, b scaled by 2^-" + std::to_string(top),
                        {"NonUnit", "HugeScale", "TinyScale", "UnbalancedScale"});
      }
      if (op == "from_axis_angle" || op == "rotate_about_axis") {
        // A non-unit axis: ordinary lengths 0.1..10, and lengths near the overflow and
        // underflow thresholds (AXANG-2, AXIS-1 normalise u/|u|).
        const std::size_t axis = op == "from_axis_angle" ? 1 : 1;
        const int e = (i % 3 == 0) ? g.integer(-3, 3) : (i % 3 == 1 ? extreme : -extreme);
        const Real s(std::ldexp(g.uniform(1.0, 2.0), e));
        for (Real& x : c.inputs[axis]) x = g.round(x * s);
        return labelled(c, "non-unit axis, scale 2^" + std::to_string(e), scale_flags(e));
      }
      const std::vector<std::size_t> quaternion_arrays = arrays_with_stride(op, 4);
      if (i % 6 == 5 && op != "compose" && !find_abi_op(op)->nway && !quaternion_arrays.empty()) {
        // Components of very different scales: the vector part 2^-x, the scalar part 2^x (x the
        // extreme exponent), so that q/|q| flushes the vector part to zero although it alone fixes
        // the axis and the plane (fuzz finding regression-rotor-tiny-vector-part-*: rotor_gen's
        // sqrt of (2^-815 (1, -1, 1), -2^760) was +z).
        const std::size_t a = quaternion_arrays.front();
        const Real small(std::ldexp(1.0, -extreme));
        for (int j = 0; j < 3; ++j) c.inputs[a][std::size_t(j)] = g.round(c.inputs[a][std::size_t(j)] * small);
        const double w = std::ldexp(g.uniform(1.0, 2.0), extreme);
        c.inputs[a][3] = g.round(Real(g.uniform(0.0, 1.0) < 0.5 ? -w : w));
        return labelled(c, "vector part 2^-" + std::to_string(extreme) + " beside a scalar part 2^" + std::to_string(extreme),
                        {"NonUnit", "HugeScale", "TinyScale", "UnbalancedScale"});
      }
      if (find_abi_op(op)->nway && i % 2 == 1) {
        // Influences of unequal scales, each its own power of two (ordinary 2^-4 .. 2^5 or
        // extreme): every influence means its normalised rotation or motion, and its weight is
        // not scaled by its norm (QLB-1, DQ-6).
        const int stride = find_abi_op(op)->inputs[0].stride;
        for (std::size_t j = 0; j < c.k; ++j) {
          const int e = (i % 6 == 1) ? g.integer(-4, 4) : (j % 2 ? extreme : -extreme) / 2;
          const Real s(std::ldexp(g.uniform(1.0, 2.0), e));
          for (int x = 0; x < stride; ++x) c.inputs[0][j * stride + x] = g.round(c.inputs[0][j * stride + x] * s);
        }
        return labelled(c, i % 6 == 1 ? "influences of unequal scales 2^-4 .. 2^5" : "influences of unequal extreme scales",
                        i % 6 == 1 ? std::vector<std::string>{"NonUnit", "UnequalScales"}
                                   : std::vector<std::string>{"NonUnit", "HugeScale", "TinyScale", "UnequalScales"});
      }
      // COMPOSE-1 is defined on the unnormalised inputs (an EDGE-5 exception): its exact product
      // must stay representable, so each factor gets half the extreme exponent.
      const int far = op == "compose" ? extreme / 2 : extreme;
      const int e = (i % 3 == 0) ? g.integer(-10, 10) : (i % 3 == 1 ? far : -far);
      const Real s(std::ldexp(g.uniform(1.0, 2.0), e));
      for (std::size_t a : quaternion_arrays)
        for (Real& x : c.inputs[a]) x = g.round(x * s);
      for (std::size_t a : arrays_with_stride(op, 8))
        for (Real& x : c.inputs[a]) x = g.round(x * s);
      return labelled(c, "non-unit scale 2^" + std::to_string(e), scale_flags(e));
    });
  } else if (clause == "EDGE-6") {
    for (std::size_t a : arrays_with_stride(op, 4)) {
      Case c = random(2);
      std::fill(c.inputs[a].begin(), c.inputs[a].begin() + 4, Real(0));
      cases.push_back(labelled(c, "zero quaternion in " + find_abi_op(op)->inputs[a].name, {"ZeroQuaternion"}));
      Case m = random(2);
      for (int j = 0; j < 4; ++j) m.inputs[a][j] = Real(j % 2 ? -0.0 : 0.0);
      cases.push_back(labelled(m, "quaternion of +-0 in " + find_abi_op(op)->inputs[a].name, {"NegativeZero", "ZeroQuaternion"}));
    }
    for (std::size_t a : arrays_with_stride(op, 8)) {
      Case c = random(2);
      std::fill(c.inputs[a].begin(), c.inputs[a].begin() + 4, Real(0));
      cases.push_back(labelled(c, "zero real part in " + find_abi_op(op)->inputs[a].name, {"ZeroRealPart"}));
    }
    // AXANG-2, AXIS-1: a zero axis has no direction, even for a zero angle.
    const AbiOp& d = *find_abi_op(op);
    for (std::size_t a = 0; a < d.inputs.size(); ++a) {
      if (!is_axis_input(d, d.inputs[a])) continue;
      for (int signs = 0; signs < 2; ++signs) {
        Case c = random(2);
        for (int j = 0; j < 3; ++j) c.inputs[a][std::size_t(j)] = Real(signs && j != 1 ? -0.0 : 0.0);
        cases.push_back(labelled(c, std::string(signs ? "axis of +-0 in " : "zero axis in ") + d.inputs[a].name,
                                  signs ? std::vector<std::string>{"NegativeZero", "ZeroAxis"} : std::vector<std::string>{"ZeroAxis"}));
      }
      if (d.name == "from_axis_angle") {  // inputs {angle, axis}: the identity's angle does not help
        Case z = random(2);
        for (int j = 0; j < 3; ++j) z.inputs[a][std::size_t(j)] = Real(0);
        z.inputs[0] = {Real(0)};
        cases.push_back(labelled(z, "zero axis in " + d.inputs[a].name + ", angle 0", {"ZeroAxis"}));
      }
    }
  } else if (clause == "EDGE-7") {
    // NaN, +Inf and -Inf in every component of the first element of every input: a library that
    // reads one component by another path (2 acos(w) beside v / |v|) drops a NaN in some
    // components only, and a random position would find it by luck.
    const AbiOp* d = find_abi_op(op);
    const Real specials[3] = {ref::ScalarTraits<Real>::nan(), Real("inf"), -Real("inf")};
    for (std::size_t a = 0; a < d->inputs.size(); ++a)
      for (std::size_t at = 0; at < std::size_t(d->inputs[a].stride); ++at)
        for (int s = 0; s < 3; ++s) {
          Case c = random(2);
          if (at >= c.inputs[a].size()) continue;
          c.inputs[a][at] = specials[s];
          const std::string where =
              d->inputs[a].stride == 1 ? d->inputs[a].name : d->inputs[a].name + "[" + std::to_string(at) + "]";
          cases.push_back(labelled(c, std::string(s == 0 ? "NaN" : s == 1 ? "+Inf" : "-Inf") + " in " + where,
                                   {s == 0 ? "NaN" : "Infinity"}));
        }
  } else if (clause == "EDGE-8") {
    repeat([&](int i) {
      Case c = random();
      // Components that are subnormal in the format (and -0): a naive |q|^2 underflows to 0.
      const int lowest = f32 ? -149 : -1074;
      for (std::size_t a : arrays_with_stride(op, 4))
        for (std::size_t j = 0; j < c.inputs[a].size(); ++j) {
          const int m = g.integer(0, 7);
          c.inputs[a][j] = (j + i) % 4 == 0 ? Real(-0.0) : Real(std::ldexp(double(m + 1), lowest + g.integer(0, 10)));
        }
      if (i % 4 == 3) {
        // A subnormal vector part beside a normal scalar part of either sign: a rotation within a
        // few ulp of +-1, whose axis B/|B| must still be accurate (fuzz finding
        // rotor-log-subnormal-vector-part-near-minus-1).
        for (std::size_t a : arrays_with_stride(op, 4)) c.inputs[a][3] = Real((i / 4) % 2 ? 1.0 : -1.0);
        return labelled(c, "subnormal vector part, scalar part +-1", {"Subnormal", "NegativeZero", "SubnormalAxis"});
      }
      return labelled(c, "subnormal and -0 components", {"Subnormal", "NegativeZero"});
    });
  } else if (clause == "EDGE-9") {
    const AbiOp* d = find_abi_op(op);
    std::size_t w = 0;
    for (std::size_t a = 0; a < d->inputs.size(); ++a)
      if (d->inputs[a].name == "w") w = a;
    const char* labels[] = {"negative weight", "NaN weight", "+Inf weight", "all weights zero"};
    const std::vector<std::string> flags[] = {
        {"DegenerateWeights", "NegativeWeight"}, {"NaN", "DegenerateWeights"}, {"Infinity", "DegenerateWeights"},
        {"DegenerateWeights", "ZeroWeights"}};
    for (int kind = 0; kind < 4; ++kind) {
      Case c = random(3);
      if (kind == 0) c.inputs[w][1] = Real(-0.25);
      if (kind == 1) c.inputs[w][2] = ref::ScalarTraits<Real>::nan();
      if (kind == 2) c.inputs[w][0] = Real("inf");
      if (kind == 3) std::fill(c.inputs[w].begin(), c.inputs[w].end(), Real(0));
      cases.push_back(labelled(c, labels[kind], flags[kind]));
    }
    Case empty = random(1);
    empty.k = 0;
    for (const Array& arr : d->inputs)
      if (arr.per_influence) empty.inputs[&arr - d->inputs.data()].clear();
    cases.push_back(labelled(empty, "no influences (k = 0)", {"DegenerateWeights", "NoInfluences"}));
  } else {
    // The operation's own clause: ordinary random inputs, obtuse pairs included by construction.
    repeat([&](int) { return random(); });
    if (clause == "QLB-1" || clause == "LOGBLEND-1" || clause == "DQ-6") {
      // The pivot is the first influence with a positive weight, not the first influence: a zero
      // first weight, and a third influence on whose hemisphere the two candidate pivots disagree.
      repeat([&](int) {
        for (;;) {
          Case c = random(3);
          const int stride = op == "dq_blend" ? 8 : 4;
          auto real = [&](std::size_t j) {
            const auto& v = c.inputs[0];
            return Quat{v[j * stride + 3], v[j * stride], v[j * stride + 1], v[j * stride + 2]};
          };
          const int s01 = ref::hemisphere_sign(real(1), real(0)), s02 = ref::hemisphere_sign(real(2), real(0));
          const int s12 = ref::hemisphere_sign(real(2), real(1));
          if (s01 * s02 == s12 || s01 == 0 || s02 == 0 || s12 == 0) continue;
          c.inputs[1][0] = Real(0);
          return labelled(c, "first weight 0: pivot is the second influence", {"ZeroFirstWeight"});
        }
      });
    }
  }
  // LEVEL-1: the operation clauses of Core .. Rigid also see the angle sweep, the rotations near
  // a full turn and, for pairs and blends, the antipodal, near-identical and unequal-scale pairs.
  static const std::set<std::string> ordinary = {"APPLY-1", "MAT-1", "MAT-2", "AXANG-1", "AXANG-2", "AXANG-3",
                                                 "AXANG-4", "COMPOSE-1", "LOG-1", "EXP-1", "SQRT-1", "SLERP-1",
                                                 "SLERP-2", "NLERP-1", "QLB-1", "LOGBLEND-1", "DQ-5", "DQ-6", "DQ-7",
                                                 "DQ-8", "DQ-9", "RIGID-1", "RIGID-2", "RIGID-3"};
  if (ordinary.count(clause)) add_ordinary_families(cases, g, op, n);
}

/// Example op (spec/examples.json) -> ABI op, for the examples that an implementation can run.
const std::map<std::string, std::string>& example_ops() {
  static const std::map<std::string, std::string> m = {
      {"normalize", "normalize"}, {"compose", "compose"}, {"inverse", "inverse"},
      {"apply_vector", "apply_vector"}, {"apply_bivector", "apply_bivector"}, {"apply_trivector", "apply_trivector"},
      {"to_matrix", "to_matrix"}, {"from_matrix", "from_matrix"}, {"to_axis_angle", "to_axis_angle"},
      {"from_axis_angle", "from_axis_angle"}, {"log", "log"}, {"exp", "exp"}, {"slerp", "slerp"},
      {"rotor_interp", "slerp"}, {"nlerp", "nlerp"}, {"qlb", "blend_qlb"}, {"log_blend", "blend_log"},
      {"dq_from_rt", "dq_from_rotation_translation"}, {"dq_compose", "dq_compose"},
      {"dq_apply_point", "dq_apply_point"}, {"dq_normalize", "dq_normalize"}, {"dq_sclerp", "dq_sclerp"},
      {"dq_dlb", "dq_blend"}, {"axis_rotation", "rotate_about_axis"}, {"lbs_vertex", "skin_linear"},
      {"dqs_vertex", "skin_dual_quaternion"}, {"to_angle", "to_angle"}, {"to_axis", "to_axis"}, {"sqrt", "sqrt"},
      {"dq_to_rt", "dq_to_rotation_translation"}, {"dq_log", "dq_log"}, {"dq_exp", "dq_exp"},
      {"rigid_compose", "rigid_compose"}, {"rigid_apply", "rigid_apply"}, {"rigid_inverse", "rigid_inverse"}};
  return m;
}

/// The inputs of a worked example in ABI layout, rounded to the format; nullopt when rounding
/// changes its meaning (a finite value that overflows to infinity, a nonzero one that underflows
/// to zero: a binary64 example exported to binary32 must not silently become another case).
std::optional<Case> example_case(const spec::Spec& spec, const spec::Example& ex, const std::string& op,
                                 ref::Format format) {
  const conformance::Inputs in(ex.in, ex.json_path + "/in", &spec);
  Case c;
  c.label = "example " + ex.id;
  c.flags = {"WorkedExample"};
  auto q = [](const Quat& x) { return flat(x); };
  auto qs = [&](const std::string& key) {
    std::vector<Real> r;
    for (const Quat& x : in.quats(key)) append(r, flat(x));
    return r;
  };
  auto vs = [&](const std::string& key) {
    std::vector<Real> r;
    for (const V3& x : in.vec3s(key)) append(r, flat(x));
    return r;
  };
  auto s = [&](const std::string& key) { return std::vector<Real>{in.scalar(key)}; };
  if (op == "normalize" || op == "inverse" || op == "to_matrix" || op == "to_axis_angle" || op == "log" ||
      op == "to_angle" || op == "to_axis" || op == "sqrt")
    c.inputs = {q(in.quat("q"))};
  else if (op == "compose") c.inputs = {q(in.quat("a")), q(in.quat("b"))};
  else if (op == "apply_vector") c.inputs = {q(in.quat("q")), flat(in.vec3("v"))};
  else if (op == "apply_bivector") c.inputs = {q(in.quat("q")), flat(in.vec3("b"))};
  else if (op == "apply_trivector") c.inputs = {q(in.quat("q")), s("s")};
  else if (op == "from_matrix") { const auto m = in.mat3("m"); c.inputs = {{m.begin(), m.end()}}; }
  else if (op == "from_axis_angle") c.inputs = {s("theta"), flat(in.vec3("axis"))};
  else if (op == "exp") c.inputs = {flat(in.vec3("v"))};
  else if (op == "slerp" || op == "nlerp") c.inputs = {q(in.quat("a")), q(in.quat("b")), s("t")};
  else if (op == "blend_qlb" || op == "blend_log") { c.inputs = {qs("qs"), in.scalars("ws")}; c.k = c.inputs[1].size(); }
  else if (op == "dq_from_rotation_translation") c.inputs = {q(in.quat("q")), flat(in.vec3("t"))};
  else if (op == "dq_compose") c.inputs = {flat(in.dq("a")), flat(in.dq("b"))};
  else if (op == "dq_apply_point") c.inputs = {flat(in.dq("d")), flat(in.vec3("p"))};
  else if (op == "dq_normalize" || op == "dq_to_rotation_translation" || op == "dq_log") c.inputs = {flat(in.dq("d"))};
  else if (op == "dq_exp") c.inputs = {in.scalars("xi")};
  else if (op == "rigid_compose") c.inputs = {q(in.quat("qa")), flat(in.vec3("ta")), q(in.quat("qb")), flat(in.vec3("tb"))};
  else if (op == "rigid_apply") c.inputs = {q(in.quat("q")), flat(in.vec3("t")), flat(in.vec3("p"))};
  else if (op == "rigid_inverse") c.inputs = {q(in.quat("q")), flat(in.vec3("t"))};
  else if (op == "dq_sclerp") c.inputs = {flat(in.dq("a")), flat(in.dq("b")), s("t")};
  else if (op == "dq_blend") {
    std::vector<Real> ds;
    for (const auto& d : in.dqs("ds")) append(ds, flat(d));
    c.inputs = {ds, in.scalars("ws")};
    c.k = c.inputs[1].size();
  } else if (op == "rotate_about_axis") c.inputs = {flat(in.vec3("c")), flat(in.vec3("u")), s("theta"), flat(in.vec3("p"))};
  else if (op == "skin_linear" || op == "skin_dual_quaternion") {
    c.inputs = {qs("qs"), vs("ts"), in.scalars("ws"), flat(in.vec3("v"))};
    c.k = c.inputs[2].size();
  }
  for (auto& arr : c.inputs)
    for (Real& x : arr) {
      const Real r = round_to(format, x);
      if ((mpfr::isfinite(x) && !mpfr::isfinite(r)) || (x != 0 && r == 0)) return std::nullopt;
      x = r;
    }
  return c;
}

}  // namespace

std::string main_clause_of(const std::string& op) {
  for (const auto& [clause, ops] : clause_ops())
    if (clause.rfind("EDGE-", 0) != 0 && clause != "SKIN-3" && ops.size() == 1 && ops[0] == op) return clause;
  return {};
}

Real round_to(ref::Format format, const Real& x) {
  if (format == ref::Format::binary32) return Real(mpfr_get_flt(x.mpfr_srcptr(), MPFR_RNDN));
  return Real(mpfr_get_d(x.mpfr_srcptr(), MPFR_RNDN));
}

bool numerically_singular(const std::vector<Real>& m, ref::Format format) {
  if (m.size() != 9) return false;
  for (const Real& x : m)
    if (!mpfr::isfinite(x)) return false;
  ref::Mat3<Real> a;
  std::copy(m.begin(), m.end(), a.begin());
  return ref::clause::MAT_3_numerically_singular(a, ref::format_epsilon<Real>(format) / Real(2));
}

std::string robust_clause_of(const AbiOp& op, const Case& c, ref::Format f) {
  // Ordinary magnitudes: quaternions, axes and dual real parts near unit (within 2^-6: drift
  // from a few roundings of unit inputs), except for the operations whose clause is about
  // non-unit input (NORM-1, COMPOSE-1, INV-1, DQ-4: within 2^-16 .. 2^16); vectors, points and
  // translations below 2^32; no subnormal component.
  const bool wide = op.name == "normalize" || op.name == "compose" || op.name == "inverse" || op.name == "dq_normalize";
  const Real lo = wide ? Real(std::ldexp(1.0, -16)) : Real(1) - Real(std::ldexp(1.0, -6));
  const Real hi = wide ? Real(std::ldexp(1.0, 16)) : Real(1) + Real(std::ldexp(1.0, -6));
  const Real far(std::ldexp(1.0, 32));
  const Real min_normal = ref::format_min_normal<Real>(f);  // below it: subnormal in the format
  for (const auto& a : c.inputs)
    for (const Real& x : a)
      if (!mpfr::isfinite(x)) return "EDGE-7";
  for (std::size_t a = 0; a < op.inputs.size() && a < c.inputs.size(); ++a)
    if (op.inputs[a].name == "w" && op.inputs[a].per_influence) {
      const auto& w = c.inputs[a];
      if (c.k == 0 || w.empty() || std::any_of(w.begin(), w.end(), [](const Real& x) { return x < 0; }) ||
          std::all_of(w.begin(), w.end(), [](const Real& x) { return x == 0; }))
        return "EDGE-9";
    }
  std::string kind;
  auto note = [&](const char* k) {
    // The most specific kind wins: zero (EDGE-6) over subnormal (EDGE-8) over scale (EDGE-5).
    const std::string order = "EDGE-6 EDGE-8 EDGE-5";
    if (kind.empty() || order.find(k) < order.find(kind)) kind = k;
  };
  for (std::size_t a = 0; a < op.inputs.size() && a < c.inputs.size(); ++a) {
    const Array& arr = op.inputs[a];
    const auto& v = c.inputs[a];
    for (const Real& x : v)
      if (x != 0 && abs(x) < min_normal) note("EDGE-8");
    const bool axis = is_axis_input(op, arr);
    if (arr.stride == 4 || arr.stride == 8 || axis) {
      const std::size_t block = static_cast<std::size_t>(arr.stride);
      const std::size_t part = arr.stride == 8 ? 4 : block;  // the real part of a dual quaternion
      for (std::size_t j = 0; j + block <= v.size(); j += block) {
        const Real n = block_norm(v, j, part);
        if (n == 0) note("EDGE-6");
        else if (n < lo || n > hi) note("EDGE-5");
        if (arr.stride == 8 && block_norm(v, j + 4, 4) > far * n) note("EDGE-5");
      }
    } else if (arr.stride == 3 || arr.stride == 1) {
      for (const Real& x : v)
        if (abs(x) > far) note("EDGE-5");
    }
  }
  return kind;
}

std::string tolerance_for(const spec::Spec& spec, const std::string& clause, const std::string& op) {
  const spec::Clause* cl = spec.find_clause(clause);
  if (cl == nullptr) return {};
  if (clause.rfind("EDGE-", 0) == 0 && cl->tolerance != "exact") {
    // An edge clause applied to an op judges numbers with the looser of the two classes; an
    // "outcome" clause (status and NaN pattern only) judges any number with the op's class.
    const auto* mc = spec.find_clause(main_clause_of(op));
    if (mc && spec.lookup(mc->tolerance).kind == "eps" &&
        (cl->tolerance == "outcome" ||
         spec.lookup(mc->tolerance).strict_value() > spec.lookup(cl->tolerance).strict_value()))
      return mc->tolerance;
  }
  return cl->tolerance;
}

std::vector<std::string> ops_for_clause(const std::string& clause) {
  const auto& t = clause_ops();
  const auto it = t.find(clause);
  return it == t.end() ? std::vector<std::string>{} : it->second;
}

std::vector<Check> checks_for_clause_impl(const spec::Spec& spec, const std::string& clause, ref::Format format,
                                          const CaseOptions& options, const std::vector<std::string>& supported_ops) {
  std::vector<Check> checks;
  const spec::Clause* cl = spec.find_clause(clause);
  if (cl == nullptr) return checks;
  for (const std::string& op : supported_ops) {
    Check check;
    check.clause = clause;
    check.op = op;
    if (clause == "EXP-2") {
      // exp(log q) = q through the implementation: one check, on log's inputs, needing both ops.
      const auto has = [&](const char* name) {
        return std::find(supported_ops.begin(), supported_ops.end(), name) != supported_ops.end();
      };
      if (op != "log" || !has("exp")) continue;
      check.log_exp_round_trip = true;
      Gen g(options.seed, clause, op, format);
      for (int i = 0; i < options.cases_per_family; ++i) check.cases.push_back(random_case(g, "log"));
      add_ordinary_families(check.cases, g, "log", options.cases_per_family);
      checks.push_back(check);
      continue;
    }
    Gen g(options.seed, clause, op, format);
    const bool robust = cl->level == "Robust";
    const AbiOp& abi = *find_abi_op(op);
    if (options.worked_examples) {
      for (const spec::Example& ex : spec.examples) {
        const auto it = example_ops().find(ex.op);
        if (it == example_ops().end() || it->second != op) continue;
        if (ex.clause != clause && !robust) continue;
        const std::optional<Case> c = example_case(spec, ex, op, format);
        if (!c) continue;
        // LEVEL-1: an example whose input is not ordinary is judged by the Robust clause of its
        // kind (EDGE-5 .. EDGE-9), not by its operation clause.
        const std::string home = robust_clause_of(abi, *c, format);
        if (ex.clause == clause) {
          if (robust || home.empty()) check.cases.push_back(*c);
        } else if (home == clause) {
          const spec::Clause* of = spec.find_clause(ex.clause);
          if (of != nullptr && of->level != "Robust") check.cases.push_back(*c);
        }
      }
    }
    add_families(check.cases, g, clause, op, options.cases_per_family);
    if (!robust)  // Core .. Skinning judge ordinary inputs only (LEVEL-1)
      check.cases.erase(std::remove_if(check.cases.begin(), check.cases.end(),
                                       [&](const Case& c) { return !robust_clause_of(abi, c, format).empty(); }),
                        check.cases.end());
    if (const std::string tc = tolerance_for(spec, clause, op); tc != cl->tolerance) check.tolerance = tc;
    if (!check.cases.empty()) checks.push_back(std::move(check));
  }
  return checks;
}

}  // namespace rotorcert::engine
