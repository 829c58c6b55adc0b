#include <rotorcert/engine/fast_oracle.hpp>

#include <cfloat>
#include <cmath>
#include <functional>
#include <map>
#include <span>

#include <rotorcert/engine/declarations.hpp>
#include <rotorcert/reference/bounded_from_matrix.hpp>
#include <rotorcert/reference/rigid_ops.hpp>
#include <rotorcert/reference/rotation_ops.hpp>

#include "rigid_scales.hpp"

namespace rotorcert::engine {
namespace {

using ref::Bounded;
using BQuat = ref::Quaternion<Bounded>;
using BV3 = ref::Vec3<Bounded>;
using BDQ = ref::DualQuaternion<Bounded>;
using BoundedArray = std::vector<Bounded>;
namespace clause = ref::clause;

FastOracleMutation g_mutation = FastOracleMutation::none;

// ---- ABI layout <-> reference types, as in abi_ops.cpp, in Bounded ----------------------------

BQuat quat(const BoundedArray& a, std::size_t i = 0) { return {a[i * 4 + 3], a[i * 4], a[i * 4 + 1], a[i * 4 + 2]}; }
BV3 vec3(const BoundedArray& a, std::size_t i = 0) { return {a[i * 3], a[i * 3 + 1], a[i * 3 + 2]}; }
BDQ dq(const BoundedArray& a, std::size_t i = 0) {
  return {{a[i * 8 + 3], a[i * 8], a[i * 8 + 1], a[i * 8 + 2]}, {a[i * 8 + 7], a[i * 8 + 4], a[i * 8 + 5], a[i * 8 + 6]}};
}
template <class V, class F>
std::vector<V> many(const BoundedArray& a, std::size_t k, F unpack) {
  std::vector<V> r;
  for (std::size_t i = 0; i < k; ++i) r.push_back(unpack(a, i));
  return r;
}

ref::Mat3<Bounded> mat3(const BoundedArray& a) {
  ref::Mat3<Bounded> m;
  std::copy(a.begin(), a.begin() + 9, m.begin());
  return m;
}
BoundedArray flat(const BQuat& q) { return {q.x, q.y, q.z, q.w}; }
BoundedArray flat(const BV3& v) { return {v[0], v[1], v[2]}; }
BoundedArray flat(const BDQ& d) { return {d.real.x, d.real.y, d.real.z, d.real.w, d.dual.x, d.dual.y, d.dual.z, d.dual.w}; }
BoundedArray flat(const ref::Mat3<Bounded>& m) { return {m.begin(), m.end()}; }
BoundedArray flat(const Bounded& s) { return {s}; }

template <class V>
FastReference one(const ref::Result<V>& r) {
  return {r.status, {flat(r.value)}};
}
FastReference pair(const ref::Result<ref::RotationTranslation<Bounded>>& r) {
  return {r.status, {flat(r.value.q), flat(r.value.t)}};
}

using FastFn = std::function<FastReference(const BoundedValues& in, std::size_t k)>;

/// The closed-form ops: the same clause templates as abi_ops.cpp's MPFR lambdas (DQ-8's and
/// DQ-9's branches at |r_v| = 0 and b = 0 are decided wherever the bound keeps away from 0, every
/// case the suite generates: conformance_test_fast_oracle).
const std::map<std::string, FastFn>& fast_ops() {
  static const std::map<std::string, FastFn> ops = {
      {"normalize", [](const BoundedValues& in, std::size_t) { return one(clause::NORM_1_normalize(quat(in[0]))); }},
      {"compose",
       [](const BoundedValues& in, std::size_t) { return one(clause::COMPOSE_1_compose(quat(in[0]), quat(in[1]))); }},
      {"inverse", [](const BoundedValues& in, std::size_t) { return one(clause::INV_1_inverse(quat(in[0]))); }},
      {"apply_vector",
       [](const BoundedValues& in, std::size_t) { return one(clause::APPLY_1_apply_vector(quat(in[0]), vec3(in[1]))); }},
      {"apply_bivector",
       [](const BoundedValues& in, std::size_t) { return one(clause::APPLY_2_apply_bivector(quat(in[0]), vec3(in[1]))); }},
      {"apply_trivector",
       [](const BoundedValues& in, std::size_t) { return one(clause::APPLY_3_apply_trivector(quat(in[0]), in[1][0])); }},
      {"to_matrix", [](const BoundedValues& in, std::size_t) { return one(clause::MAT_1_to_matrix(quat(in[0]))); }},
      {"from_matrix", [](const BoundedValues& in, std::size_t) { return one(clause::MAT_2_from_matrix_verified(mat3(in[0]))); }},
      {"to_axis_angle",
       [](const BoundedValues& in, std::size_t) {
         const auto r = clause::AXANG_1_to_axis_angle(quat(in[0]));
         return FastReference{r.status, {flat(r.value.angle), flat(r.value.axis)}};
       }},
      {"to_angle",
       [](const BoundedValues& in, std::size_t) {
         const auto r = clause::AXANG_1_to_axis_angle(quat(in[0]));
         return FastReference{r.status, {flat(r.value.angle)}};
       }},
      {"to_axis",
       [](const BoundedValues& in, std::size_t) {
         const auto r = clause::AXANG_1_to_axis_angle(quat(in[0]));
         return FastReference{r.status, {flat(r.value.axis)}};
       }},
      {"from_axis_angle",
       [](const BoundedValues& in, std::size_t) { return one(clause::AXANG_2_from_axis_angle(in[0][0], vec3(in[1]))); }},
      {"sqrt", [](const BoundedValues& in, std::size_t) { return one(clause::SQRT_1_sqrt(quat(in[0]))); }},
      {"log", [](const BoundedValues& in, std::size_t) { return one(clause::LOG_1_log(quat(in[0]))); }},
      {"exp", [](const BoundedValues& in, std::size_t) { return one(clause::EXP_1_exp(vec3(in[0]))); }},
      {"slerp",
       [](const BoundedValues& in, std::size_t) {
         return one(clause::SLERP_1_slerp(quat(in[0]), quat(in[1]), in[2][0]));
       }},
      {"nlerp",
       [](const BoundedValues& in, std::size_t) {
         return one(clause::NLERP_1_nlerp(quat(in[0]), quat(in[1]), in[2][0]));
       }},
      {"blend_qlb",
       [](const BoundedValues& in, std::size_t k) {
         const auto qs = many<BQuat>(in[0], k, [](const BoundedArray& a, std::size_t i) { return quat(a, i); });
         return one(clause::QLB_1_blend(std::span<const BQuat>(qs), std::span<const Bounded>(in[1])));
       }},
      {"blend_log",
       [](const BoundedValues& in, std::size_t k) {
         const auto qs = many<BQuat>(in[0], k, [](const BoundedArray& a, std::size_t i) { return quat(a, i); });
         return one(clause::LOGBLEND_1_blend(std::span<const BQuat>(qs), std::span<const Bounded>(in[1])));
       }},
      {"dq_from_rotation_translation",
       [](const BoundedValues& in, std::size_t) {
         return one(clause::DQ_1_from_rotation_translation(quat(in[0]), vec3(in[1])));
       }},
      {"dq_compose", [](const BoundedValues& in, std::size_t) { return one(clause::DQ_2_compose(dq(in[0]), dq(in[1]))); }},
      {"dq_apply_point",
       [](const BoundedValues& in, std::size_t) { return one(clause::DQ_3_apply_point(dq(in[0]), vec3(in[1]))); }},
      {"dq_normalize", [](const BoundedValues& in, std::size_t) { return one(clause::DQ_4_normalize(dq(in[0]))); }},
      {"dq_sclerp",
       [](const BoundedValues& in, std::size_t) { return one(clause::DQ_5_sclerp(dq(in[0]), dq(in[1]), in[2][0])); }},
      {"dq_blend",
       [](const BoundedValues& in, std::size_t k) {
         const auto ds = many<BDQ>(in[0], k, [](const BoundedArray& a, std::size_t i) { return dq(a, i); });
         return one(clause::DQ_6_dlb(std::span<const BDQ>(ds), std::span<const Bounded>(in[1])));
       }},
      {"skin_linear",
       [](const BoundedValues& in, std::size_t k) {
         const auto qs = many<BQuat>(in[0], k, [](const BoundedArray& a, std::size_t i) { return quat(a, i); });
         const auto ts = many<BV3>(in[1], k, [](const BoundedArray& a, std::size_t i) { return vec3(a, i); });
         return one(clause::SKIN_1_linear_blend(std::span<const BQuat>(qs), std::span<const BV3>(ts),
                                                std::span<const Bounded>(in[2]), vec3(in[3])));
       }},
      {"skin_dual_quaternion",
       [](const BoundedValues& in, std::size_t k) {
         const auto qs = many<BQuat>(in[0], k, [](const BoundedArray& a, std::size_t i) { return quat(a, i); });
         const auto ts = many<BV3>(in[1], k, [](const BoundedArray& a, std::size_t i) { return vec3(a, i); });
         return one(clause::SKIN_2_dual_quaternion(std::span<const BQuat>(qs), std::span<const BV3>(ts),
                                                   std::span<const Bounded>(in[2]), vec3(in[3])));
       }},
      {"rotate_about_axis",
       [](const BoundedValues& in, std::size_t) {
         return one(clause::AXIS_1_rotate_about_line(vec3(in[0]), vec3(in[1]), in[2][0], vec3(in[3])));
       }},
      {"rotate_about_axis",
       [](const BoundedValues& in, std::size_t) {
         return one(clause::AXIS_1_rotate_about_line(vec3(in[0]), vec3(in[1]), in[2][0], vec3(in[3])));
       }},
      {"rigid_compose",
       [](const BoundedValues& in, std::size_t) {
         return pair(clause::RIGID_1_compose(quat(in[0]), vec3(in[1]), quat(in[2]), vec3(in[3])));
       }},
      {"rigid_apply",
       [](const BoundedValues& in, std::size_t) {
         return one(clause::RIGID_2_apply(quat(in[0]), vec3(in[1]), vec3(in[2])));
       }},
      {"rigid_inverse",
       [](const BoundedValues& in, std::size_t) { return pair(clause::RIGID_3_inverse(quat(in[0]), vec3(in[1]))); }},
      {"dq_to_rotation_translation",
       [](const BoundedValues& in, std::size_t) { return pair(clause::DQ_7_to_rotation_translation(dq(in[0]))); }},
      {"dq_log",
       [](const BoundedValues& in, std::size_t) {
         const auto r = clause::DQ_8_log(dq(in[0]));
         BoundedArray xi = flat(r.value.real);
         for (const Bounded& x : flat(r.value.dual)) xi.push_back(x);
         return FastReference{r.status, {xi}};
       }},
      {"dq_exp",
       [](const BoundedValues& in, std::size_t) {
         const BV3 r{in[0][0], in[0][1], in[0][2]}, d{in[0][3], in[0][4], in[0][5]};
         return one(clause::DQ_9_exp(ref::DualVector<Bounded>{r, d}));
       }},
  };
  return ops;
}

}  // namespace

void set_fast_oracle_mutation(FastOracleMutation m) { g_mutation = m; }

bool has_fast_reference(const std::string& op) { return fast_ops().count(op) != 0; }

/// An input of the format, or a perturbed one (fuzz oracle): exact in long double, or the nearest
/// long double with its rounding as the bound.
Bounded bounded_value(const Real& x) {
  // Most inputs are values of the format, which a double holds exactly: mpfr_get_d and an
  // in-place comparison settle those without mpfr_get_ld or a temporary mpreal (most of this
  // function's time before).
  const double d = mpfr_get_d(x.mpfr_srcptr(), MPFR_RNDN);
  if (std::isfinite(d) ? mpfr_cmp_d(x.mpfr_srcptr(), d) == 0 : !mpfr_number_p(x.mpfr_srcptr()))
    return {static_cast<long double>(d), 0};  // (a NaN or an infinity is exact too)
  const long double v = x.toLDouble();
  if (!std::isfinite(v) || Real(v) == x) return {v, 0};
  return Bounded::result(v, 0, 0.5L);
}

BoundedValues bounded_values(const Values& v) {
  BoundedValues out(v.size());
  for (std::size_t a = 0; a < v.size(); ++a) {
    out[a].reserve(v[a].size());
    for (const Real& x : v[a]) out[a].push_back(bounded_value(x));
  }
  return out;
}

namespace {

std::optional<FastReference> evaluate(const AbiOp& op, const FastFn& fn, const BoundedValues& in, std::size_t k) {
  const ref::BoundedScope scope;
  FastReference r = fn(in, k);
  if (!scope.decided()) return std::nullopt;
  if (r.status != ref::Status::ok) r.outputs.assign(op.outputs.size(), {});
  if (g_mutation == FastOracleMutation::bound_too_small)
    for (auto& arr : r.outputs)
      for (Bounded& y : arr) y = Bounded(y.value(), std::ldexp(y.bound(), -40));
  if (g_mutation == FastOracleMutation::wrong_term && !r.outputs.empty() && !r.outputs[0].empty()) {
    Bounded& y = r.outputs[0][0];  // off by 2^-50 of its size: a term dropped in a formula
    y = Bounded(y.value() + std::ldexp(std::fabs(y.value()) + 1, -50), y.bound());
  }
  return r;
}

}  // namespace

std::optional<FastReference> fast_reference(const AbiOp& op, const Values& inputs, std::size_t k) {
  const auto it = fast_ops().find(op.name);
  if (it == fast_ops().end()) return std::nullopt;  // (before converting the inputs)
  return evaluate(op, it->second, bounded_values(inputs), k);
}

std::optional<FastReference> fast_reference(const AbiOp& op, const BoundedValues& in, std::size_t k) {
  const auto it = fast_ops().find(op.name);
  if (it == fast_ops().end()) return std::nullopt;
  return evaluate(op, it->second, in, k);
}

namespace {

/// y widened by 2^-240 of its size: an interval that holds the exact value then holds MPFR's
/// 256-bit one too, and one that holds MPFR's holds the exact one.
Bounded widened_to_hold_mpfr(const Bounded& y) {
  return Bounded(y.value(), y.bound() + std::ldexp(std::fabs(y.value()), -240) + Bounded::kTiny);
}

}  // namespace

FastReference fast_reference_from(const AbiOp& op, const ReferenceResult& r) {
  FastReference f{r.status, {}};
  if (r.status != ref::Status::ok) {
    f.outputs.assign(op.outputs.size(), {});  // as evaluate() leaves them
    return f;
  }
  f.outputs = bounded_values(r.outputs);
  for (BoundedArray& arr : f.outputs)
    for (Bounded& y : arr)
      if (std::isfinite(y.value())) y = widened_to_hold_mpfr(y);
  return f;
}

Values fast_values(const FastReference& r) {
  Values v(r.outputs.size());
  for (std::size_t a = 0; a < r.outputs.size(); ++a)
    for (const Bounded& y : r.outputs[a]) v[a].push_back(Real(y.value()));
  return v;
}

std::optional<std::vector<Values>> fast_roundings(const FastReference& r, ref::Format f, std::size_t max_candidates) {
  // Rounding is monotone: every point of [v - e, v + e], the exact reference included, rounds to
  // the rounding of one of its ends. (long double -> float/double conversions round to nearest
  // even, as round_to does.) Where the ends round to neighbouring values of the format, those two
  // are the only candidates; an interval wider than that is not decided here.
  std::vector<Values> candidates(1, Values(r.outputs.size()));
  for (std::size_t a = 0; a < r.outputs.size(); ++a)
    for (const Bounded& y : r.outputs[a]) {
      const long double lo = y.value() - y.bound() * (1 + 4 * Bounded::kU);
      const long double hi = y.value() + y.bound() * (1 + 4 * Bounded::kU);
      bool adjacent;  // the two ends round to neighbours: one rounding point between them
      Real rlo, rhi;
      if (f == ref::Format::binary32) {
        const float l = static_cast<float>(lo), h = static_cast<float>(hi);
        adjacent = std::nextafter(l, INFINITY) == h;
        rlo = Real(l), rhi = Real(h);
      } else {
        const double l = static_cast<double>(lo), h = static_cast<double>(hi);
        adjacent = std::nextafter(l, INFINITY) == h;
        rlo = Real(l), rhi = Real(h);
      }
      if (rlo == rhi) {
        for (Values& c : candidates) c[a].push_back(rlo);
        continue;
      }
      if (!adjacent) return std::nullopt;  // a bound wider than an ulp: more than two roundings
      if (candidates.size() * 2 > max_candidates) return std::nullopt;
      std::vector<Values> both = candidates;
      for (Values& c : candidates) c[a].push_back(rlo);
      for (Values& c : both) c[a].push_back(rhi);
      candidates.insert(candidates.end(), both.begin(), both.end());
    }
  return candidates;
}

namespace {

/// The scale of a case (AbiOp::scale) in Bounded arithmetic, for the ops whose scale is a
/// reference computation (rigid_scales.hpp: DQ-8's log, DQ-7's translation) rather than a max of
/// input lengths, which MPFR forms cheaply. Widened by 2^-240 of its size, so that it holds MPFR's
/// value as well as the exact one. nullopt for the other ops and where the bounds do not decide.
std::optional<Bounded> fast_scale(const AbiOp& op, const Case& c) {
  const bool log = op.name == "dq_log";
  if (!log && op.name != "dq_to_rotation_translation") return std::nullopt;
  const BoundedValues in = bounded_values(c.inputs);
  const ref::BoundedScope scope;
  const Bounded s = log ? rigid_scales::dq_log_scale(dq(in[0])) : rigid_scales::dq_translation_scale(dq(in[0]));
  if (!scope.decided() || !std::isfinite(s.value())) return std::nullopt;
  return widened_to_hold_mpfr(s);
}

}  // namespace

std::optional<FastCase> fast_case(const AbiOp& op, const spec::ToleranceClass& tc, const Case& c, ref::Format f) {
  if (tc.kind != "eps" && tc.kind != "formula") return std::nullopt;
  const Real eps = ref::format_epsilon<Real>(f);
  std::optional<Bounded> scale = fast_scale(op, c);
  if (!scale) scale = bounded_value(op.scale(c.inputs, c.k));
  return FastCase{bars_for(tc, op, c, eps), *scale, bounded_value(ref::format_min_normal<Real>(f)), eps.toLDouble()};
}

namespace {

/// Values of the format (an observation or an input) as exact Bounded values; false where one is
/// not finite.
bool exact_values(const std::vector<Real>& xs, BoundedArray& out) {
  out.clear();
  for (const Real& x : xs) {
    const long double v = x.toLDouble();  // a value of the format: exact
    if (!std::isfinite(v)) return false;
    out.push_back(Bounded(v, 0));
  }
  return true;
}

}  // namespace

FastVerdicts fast_verdicts_of_error(const FastCase& fc, const Bounded& e) {
  // The exact error lies in [e - bound, e + bound]; MPFR's err (that error over eps, rounded to
  // double) lies between the roundings of the two ends, and TOL_1_verdict is monotone.
  const long double spread = e.bound() * (1 + 4 * Bounded::kU);
  const long double lo = (e.value() - spread) / fc.eps * (1 - 4 * Bounded::kU);
  const long double hi = (e.value() + spread) / fc.eps * (1 + 4 * Bounded::kU);
  const double lo_down = std::nextafter(static_cast<double>(lo), -INFINITY);
  const double hi_up = std::nextafter(static_cast<double>(hi), INFINITY);
  return FastVerdicts{ref::clause::TOL_1_verdict(std::max(lo_down, 0.0), fc.bars),
                      ref::clause::TOL_1_verdict(hi_up, fc.bars)};
}

std::optional<FastVerdicts> fast_verdicts(const AbiOp& op, const FastCase& fc, const Observed& obs,
                                          const FastReference& want) {
  // Only a plain numeric judgement is taken from the fast level; a wrong status or a domain error
  // is MPFR's to judge.
  if (obs.call_rc != 0 || !obs.fault.empty() || obs.status != RC_OK || want.status != ref::Status::ok)
    return std::nullopt;
  BoundedValues got(obs.outputs.size());
  for (std::size_t a = 0; a < obs.outputs.size(); ++a)
    if (!exact_values(obs.outputs[a], got[a])) return std::nullopt;
  return fast_verdicts_of_values(op, fc, got, want);
}

std::optional<FastVerdicts> fast_verdicts_of_values(const AbiOp& op, const FastCase& fc, const BoundedValues& got,
                                                    const FastReference& want) {
  if (want.status != ref::Status::ok) return std::nullopt;
  for (const BoundedArray& arr : got)
    for (const Bounded& x : arr)
      if (!std::isfinite(x.value())) return std::nullopt;
  const ref::BoundedScope scope;
  const Bounded e = output_error_bounded(op, got, want.outputs, fc.scale, fc.tiny);
  if (!scope.decided() || !std::isfinite(e.value())) return std::nullopt;
  return fast_verdicts_of_error(fc, e);
}

std::optional<BoundedValues> rounded_intervals(const FastReference& r, ref::Format f) {
  if (r.status != ref::Status::ok) return std::nullopt;
  constexpr long double u = Bounded::kU;
  BoundedValues got(r.outputs.size());
  for (std::size_t a = 0; a < r.outputs.size(); ++a)
    for (const Bounded& y : r.outputs[a]) {
      const long double lo = y.value() - y.bound() * (1 + 4 * u), hi = y.value() + y.bound() * (1 + 4 * u);
      const long double rlo = f == ref::Format::binary32 ? static_cast<long double>(static_cast<float>(lo))
                                                         : static_cast<long double>(static_cast<double>(lo));
      const long double rhi = f == ref::Format::binary32 ? static_cast<long double>(static_cast<float>(hi))
                                                         : static_cast<long double>(static_cast<double>(hi));
      if (!std::isfinite(rlo) || !std::isfinite(rhi)) return std::nullopt;
      // [rlo, rhi] as mid +- half: the halvings are exact (long double's range is far wider than
      // the formats'), the sum and the difference round once each.
      const long double mid = rlo / 2 + rhi / 2, half = (rhi - rlo) / 2;
      got[a].push_back(Bounded(mid, half * (1 + 2 * u) + std::fabs(mid) * 2 * u + Bounded::kTiny));
    }
  return got;
}

std::optional<FastVerdicts> fast_verdicts_of_rounding(const AbiOp& op, const FastCase& fc, const FastReference& r,
                                                      ref::Format f, const FastReference& want) {
  if (want.status != ref::Status::ok) return std::nullopt;
  const std::optional<BoundedValues> got = rounded_intervals(r, f);
  if (!got) return std::nullopt;
  const ref::BoundedScope scope;
  const Bounded e = output_error_bounded(op, *got, want.outputs, fc.scale, fc.tiny);
  if (!scope.decided() || !std::isfinite(e.value())) return std::nullopt;
  return fast_verdicts_of_error(fc, e);
}

std::optional<FastVerdicts> fast_round_trip_verdicts(const FastCase& fc, const Case& c, const Observed& log_got,
                                                     const Observed& exp_got) {
  // judge_round_trip: METRIC-1 between exp's output and the input q, over eps, against the bars.
  if (log_got.call_rc != 0 || exp_got.call_rc != 0 || !log_got.fault.empty() || !exp_got.fault.empty() ||
      log_got.status != RC_OK || exp_got.status != RC_OK)
    return std::nullopt;
  BoundedArray got, q;
  if (!exact_values(exp_got.outputs.at(0), got) || !exact_values(c.inputs.at(0), q)) return std::nullopt;
  const ref::BoundedScope scope;
  Bounded e = clause::METRIC_1_rotation_distance(quat(got), quat(q));
  if (!scope.decided() || !std::isfinite(e.value())) return std::nullopt;
  if (g_mutation == FastOracleMutation::wrong_term) e = Bounded(e.value() / 2, e.bound() / 2);  // a lost factor 2
  return fast_verdicts_of_error(fc, e);
}

bool may_be_acceptable(const AbiOp& op, const Case& c, ref::Format f) {
  for (const AcceptableConvention& a : acceptable_conventions()) {
    if (a.outside_domain || a.declared_only || !a.applies(op)) continue;
    const std::optional<bool> relevant = a.relevant.of_input(op, c, f);
    if (!relevant || *relevant) return true;
  }
  return false;
}

std::optional<std::vector<AcceptableAnswer>> fast_acceptable_answers(const AbiOp& op, const Case& c,
                                                                     const BoundedValues& in,
                                                                     const FastReference& want, ref::Format f) {
  std::vector<AcceptableAnswer> answers;
  for (const AcceptableConvention& a : acceptable_conventions()) {
    if (a.outside_domain || a.declared_only || !a.applies(op)) continue;
    std::optional<bool> relevant = a.relevant.of_input(op, c, f);
    if (!relevant && a.fast_relevant && want.status == ref::Status::ok) {  // read from the spec's answer
      const ref::BoundedScope scope;
      const bool r = a.fast_relevant(op, c, want.outputs, f);
      if (scope.decided()) relevant = r;
    }
    if (relevant && !*relevant) continue;
    // endpoint_sign's error is defined only under SLERP-3's signed measure.
    if (a.id == "endpoint_sign" && relevant && op.outputs.at(0).measure != Measure::signed_unit_rotation) continue;
    if (!relevant) return std::nullopt;  // relevance undecided: MPFR's to judge
    if (a.id != "hemisphere_tie") {
      if (!a.fast_error) return std::nullopt;  // no fast form: MPFR's to judge
      answers.push_back({a.id, std::nullopt, [&a, &op, &c, &in, &want, f](const BoundedValues& got) {
                           return a.fast_error(op, c, in, got, want.outputs, f);
                         }});
      continue;
    }
    if (op.name == "slerp" || op.name == "nlerp") {
      // As the convention's error: the interpolation of the normalised inputs with the spec's flip
      // (decided on the exact inputs) reversed, measured as METRIC-1 and METRIC-6.
      if (op.outputs.at(0).measure != Measure::unit_rotation) return std::nullopt;
      const ref::BoundedScope scope;
      const BQuat other =
          hemisphere_tie_other_branch(op.name == "slerp", quat(in[0]), quat(in[1]), in[2][0], hemisphere_rule_flips_b(c));
      if (!scope.decided()) return std::nullopt;
      answers.push_back({a.id, FastReference{ref::Status::ok, {flat(other)}}, {}});
      continue;
    }
    const std::optional<Values> flipped = hemisphere_tie_flipped_inputs(op, c, f);
    if (!flipped) continue;  // no influence at an exact tie: the convention's error is undefined
    std::optional<FastReference> r = fast_reference(op, bounded_values(*flipped), c.k);
    if (!r) return std::nullopt;
    if (r->status != ref::Status::ok) continue;  // (undefined too)
    answers.push_back({a.id, std::move(*r), {}});
  }
  return answers;
}

}  // namespace rotorcert::engine
