#include <rotorcert/engine/runner.hpp>
#include <rotorcert/engine/hygiene.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <random>
#include <set>
#include <sstream>

#include <rotorcert/reference/metrics.hpp>
#include <rotorcert/reference/tolerance.hpp>

namespace rotorcert::engine {
namespace {

using Quat = ref::Quaternion<Real>;
namespace clause = ref::clause;

/// The implementation's arrays of one group of cases (same k), in its scalar type S.
template <class S>
struct Buffers {
  std::vector<std::vector<S>> in, out;
  std::vector<std::uint8_t> status;
  std::vector<const void*> in_ptrs;
  std::vector<void*> out_ptrs;

  void fill(const AbiOp& op, const std::vector<const Case*>& cases, std::size_t k) {
    const std::size_t n = cases.size();
    in.assign(op.inputs.size(), {});
    for (std::size_t a = 0; a < op.inputs.size(); ++a)
      for (const Case* c : cases)
        for (const Real& x : c->inputs[a]) in[a].push_back(static_cast<S>(to_native<S>(x)));
    // Outputs start as a finite value no answer has, so that an output left unwritten fails (a 0
    // would pass as the log of the identity); kGuard slots past every array stay so unless the
    // implementation writes past the end (overrun()).
    out.assign(op.outputs.size(), {});
    for (std::size_t a = 0; a < op.outputs.size(); ++a) out[a].assign(n * op.outputs[a].stride + kGuard, unwritten());
    status.assign(n + kGuard, kUnwrittenStatus);  // a value no implementation writes: shows an element left untouched
    in_ptrs.clear();
    out_ptrs.clear();
    for (auto& v : in) in_ptrs.push_back(v.empty() ? nullptr : v.data());
    for (auto& v : out) out_ptrs.push_back(v.data());
    (void)k;
  }
  static constexpr std::size_t kGuard = 16;
  static constexpr std::uint8_t kUnwrittenStatus = 0xEE;
  static S unwritten() { return S(-0x1.5p+100); }

  /// Where the implementation wrote past the end of an output or the status array, or "".
  std::string overrun(const AbiOp& op, std::size_t n) const {
    for (std::size_t a = 0; a < op.outputs.size(); ++a) {
      const std::size_t end = n * static_cast<std::size_t>(op.outputs[a].stride);
      const S canary = unwritten();
      for (std::size_t i = end; i < out[a].size(); ++i)
        if (std::memcmp(&out[a][i], &canary, sizeof(S)) != 0)
          return "wrote past the end of " + op.outputs[a].name + " (scalar " + std::to_string(i - end) +
                 " after the last of " + std::to_string(n) + " elements)";
    }
    for (std::size_t i = n; i < status.size(); ++i)
      if (status[i] != kUnwrittenStatus)
        return "wrote past the end of the status array (byte " + std::to_string(i - n) + " after the last of " +
               std::to_string(n) + " elements)";
    return {};
  }
  template <class T>
  static T to_native(const Real& x) {
    if constexpr (std::is_same_v<T, float>) return mpfr_get_flt(x.mpfr_srcptr(), MPFR_RNDN);
    else return mpfr_get_d(x.mpfr_srcptr(), MPFR_RNDN);
  }
  /// Output array a of case i as exact values.
  std::vector<Real> output(const AbiOp& op, std::size_t a, std::size_t i) const {
    const int s = op.outputs[a].stride;
    std::vector<Real> r;
    for (int j = 0; j < s; ++j) r.push_back(Real(out[a][i * s + j]));
    return r;
  }
};

std::string hex(const Real& x, ref::Format f) {
  char buf[64];
  if (f == ref::Format::binary32) std::snprintf(buf, sizeof buf, "%a", double(mpfr_get_flt(x.mpfr_srcptr(), MPFR_RNDN)));
  else std::snprintf(buf, sizeof buf, "%a", mpfr_get_d(x.mpfr_srcptr(), MPFR_RNDN));
  return buf;
}

std::string dec(const Real& x) { return x.toString("%.12Rg"); }

}  // namespace

std::string join_values(const std::vector<Real>& v, bool hexfloat, ref::Format f) {
  std::string s = "[";
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + (hexfloat ? hex(v[i], f) : dec(v[i]));
  return s + "]";
}

namespace {

template <class T>
ref::Quaternion<T> quat(const std::vector<T>& a) { return {a[3], a[0], a[1], a[2]}; }
template <class T>
ref::DualQuaternion<T> dq(const std::vector<T>& a) { return {{a[3], a[0], a[1], a[2]}, {a[7], a[4], a[5], a[6]}}; }

template <class T>
T norm(const std::vector<T>& v) {
  T s(0);
  for (const T& x : v) s += x * x;
  return sqrt(s);
}

/// The error of one output array in the unit of its measure (radians, relative, ...).
template <class T>
T measure(Measure m, const std::vector<T>& got, const std::vector<T>& want, const T& scale, const T& tiny) {
  using std::max;
  switch (m) {
    case Measure::rotation: return clause::METRIC_1_rotation_distance(quat(got), quat(want));
    case Measure::quaternion: {
      T worst(0);
      for (int i = 0; i < 4; ++i) worst = max(worst, T(abs(got[i] - want[i])));
      const T relative = worst / norm(want);
      if (ref::ScalarTraits<T>::is_nan(relative)) return relative;
      return max(clause::METRIC_1_rotation_distance(quat(got), quat(want)), relative);
    }
    case Measure::unit_rotation:
      return max(clause::METRIC_1_rotation_distance(quat(got), quat(want)), clause::METRIC_6_norm_defect(quat(got)));
    case Measure::signed_unit_rotation: {
      T worst(0);
      for (int i = 0; i < 4; ++i) worst = max(worst, T(abs(got[i] - want[i])));
      if (ref::ScalarTraits<T>::is_nan(worst)) return worst;
      return max(max(clause::METRIC_1_rotation_distance(quat(got), quat(want)), clause::METRIC_6_norm_defect(quat(got))),
                 worst);
    }
    case Measure::canonical_rotation: {
      // MAT-2: q and -q are one rotation, but from_matrix has one answer, w > 0. A result on the
      // other side of the reference (negative dot product) is off by |w_ref|: within the bar (a
      // half turn, w near 0) either sign passes, beyond it the wrong sign fails.
      const T rotation =
          max(clause::METRIC_1_rotation_distance(quat(got), quat(want)), clause::METRIC_6_norm_defect(quat(got)));
      const T dot = got[0] * want[0] + got[1] * want[1] + got[2] * want[2] + got[3] * want[3];
      return dot < 0 ? max(rotation, T(abs(want[3]))) : rotation;
    }
    case Measure::vector:
      return clause::METRIC_3_vector_error<T>({got[0], got[1], got[2]}, {want[0], want[1], want[2]}, tiny);
    case Measure::point: {  // every component of the array: a point, or DQ-8's dual vector
      std::vector<T> d;
      for (std::size_t i = 0; i < want.size() && i < got.size(); ++i) d.push_back(got[i] - want[i]);
      return norm(d) / scale;
    }
    case Measure::bivector: return clause::METRIC_5_bivector_error<T>({got[0], got[1], got[2]}, {want[0], want[1], want[2]});
    case Measure::matrix: {
      ref::Mat3<T> a, b;
      std::copy(got.begin(), got.end(), a.begin());
      std::copy(want.begin(), want.end(), b.begin());
      return clause::METRIC_4_matrix_error(a, b);
    }
    case Measure::angle: return abs(got[0] - want[0]);
    case Measure::scalar: return want[0] == 0 ? abs(got[0]) : abs((got[0] - want[0]) / want[0]);
    case Measure::rigid: {
      const auto e = clause::METRIC_7_rigid_error(dq(got), dq(want));
      return max(e.rotation, e.translation);
    }
    case Measure::dual_parts: {
      T real(0), dual(0);
      for (int i = 0; i < 4; ++i) real = max(real, T(abs(got[i] - want[i])));
      for (int i = 4; i < 8; ++i) {
        const T d = got[i] - want[i];
        dual += d * d;  // a square of one value: ref::Bounded then knows the sum is >= 0
      }
      if (ref::ScalarTraits<T>::is_nan(real) || ref::ScalarTraits<T>::is_nan(dual)) return ref::ScalarTraits<T>::nan();
      return max(max(real, T(sqrt(dual) / scale)), clause::METRIC_6_norm_defect(dq(got).real));
    }
    case Measure::unit_rigid: {
      const auto e = clause::METRIC_7_rigid_error(dq(got), dq(want));
      const auto g = dq(got);
      const auto t = clause::dual_quaternion_translation(dq(want));
      const T orthogonality = abs(ref::dot(g.real, g.dual)) / max(T(1), sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]));
      return max(max(e.rotation, e.translation), max(clause::METRIC_6_norm_defect(g.real), orthogonality));
    }
  }
  return ref::ScalarTraits<T>::nan();
}

bool all_nan(const std::vector<Real>& v) {
  return std::all_of(v.begin(), v.end(), [](const Real& x) { return mpfr::isnan(x); });
}

}  // namespace

/// Strict and loose bars for one case, in eps units (the unit errors are compared in).
ref::Bars bars_for(const spec::ToleranceClass& tc, const AbiOp& op, const Case& c, const Real& eps) {
  if (tc.kind == "exact") return {0, 0};
  if (tc.kind == "formula") {  // inherited-mat: 16 eps + 2 delta / 256 eps + 8 delta, delta of the input
    const Real delta = op.name == "from_matrix" ? orthogonality_defect(c.inputs[0]) : Real(0);
    return {(Real(16) + Real(2) * delta / eps).toDouble(), (Real(256) + Real(8) * delta / eps).toDouble()};
  }
  // The bars of the other classes are constant expressions: parsed once per thread and class.
  static thread_local std::map<std::string, ref::Bars> parsed;
  const std::string key = tc.kind + '\n' + tc.strict.value_or("") + '\n' + tc.loose.value_or("");
  if (const auto it = parsed.find(key); it != parsed.end()) return it->second;
  const auto strict = tc.strict_value(), loose = tc.loose_value();
  // A class without numeric bars accepts no numeric error.
  const ref::Bars bars = strict && loose ? ref::Bars{strict->toDouble(), loose->toDouble()} : ref::Bars{0, 0};
  parsed.emplace(key, bars);
  return bars;
}

namespace {

/// Runs one check: observe in batches (or one at a time), judge each case.
template <class Record>
void run_check(const rc_impl& table, const spec::ToleranceClass& tc, const Check& check, const RunHooks& hooks,
               Record record) {
  const ref::Format f = format_of(table);
  const Declarations declared = declarations_of(table);
  const AbiOp& op = judged_op(check.clause, check.op);
  std::vector<std::vector<const Case*>> batches;
  if (hooks.one_at_a_time) {
    for (const Case& c : check.cases) batches.push_back({&c});
  } else {
    std::map<std::size_t, std::vector<const Case*>> groups;  // n-way calls share one k
    for (const Case& c : check.cases) groups[c.k].push_back(&c);
    for (auto& [k, cases] : groups) batches.push_back(std::move(cases));
  }
  for (const auto& cases : batches) {
    const std::size_t k = cases.front()->k;
    if (hooks.before_call) hooks.before_call(op, cases);
    const std::vector<Observed> got = observe(table, op, cases, k);
    if (check.log_exp_round_trip) {
      // EXP-2: feed log's output to exp and compare with the input rotation.
      const AbiOp& exp_op = *find_abi_op("exp");
      std::vector<Case> logs;
      for (std::size_t i = 0; i < cases.size(); ++i) logs.push_back(Case{{got[i].outputs.at(0)}, 0, "log output", {}});
      std::vector<const Case*> ptrs;
      for (const Case& c : logs) ptrs.push_back(&c);
      if (hooks.before_call) hooks.before_call(exp_op, ptrs);
      const std::vector<Observed> second = observe(table, exp_op, ptrs, 0);
      for (std::size_t i = 0; i < cases.size(); ++i)
        record(judge_round_trip(tc, *cases[i], got[i], second[i], f), op, *cases[i]);
      continue;
    }
    for (std::size_t i = 0; i < cases.size(); ++i)
      record(judge_case(op, tc, *cases[i], got[i], f, hooks.convention, &declared), op, *cases[i]);
  }
}

std::vector<Check> supported_checks(const rc_impl& table, const spec::Spec& spec, const std::string& clause_id,
                                    const CaseOptions& options) {
  return checks_for_clause(spec, clause_id, format_of(table), options,
                           [&](const std::string& op) { return supports(table, op); });
}

const spec::ToleranceClass& class_of(const spec::Spec& spec, const spec::Clause& cl, const Check& check) {
  return spec.lookup(check.tolerance.empty() ? cl.tolerance : check.tolerance);
}

}  // namespace

std::string hexfloat(const Real& x, ref::Format f) { return hex(x, f); }

std::string describe_inputs(const AbiOp& op, const Case& c, ref::Format f) {
  std::string s;
  for (std::size_t a = 0; a < op.inputs.size(); ++a)
    s += (a ? " " : "") + op.inputs[a].name + "=" + join_values(c.inputs[a], true, f);
  if (op.nway) s += " k=" + std::to_string(c.k);
  return s;
}

namespace {
bool call_environment_set = false;
std::fenv_t call_environment;
}  // namespace

void set_call_environment(const std::fenv_t& env) {
  call_environment = env;
  call_environment_set = true;
}

namespace {
/// The table's batch call on filled buffers, in the call environment when one is set (the
/// judge's own environment restored after it): what observe and call_raw both run.
template <class S>
int call_in_environment(const rc_impl& table, const AbiOp& op, std::size_t n, std::size_t k, Buffers<S>& buf) {
  std::fenv_t judge_environment;
  if (call_environment_set) {
    std::fegetenv(&judge_environment);
    std::fesetenv(&call_environment);
  }
  const int rc = call(table, op.name, n, k, buf.in_ptrs, buf.out_ptrs, buf.status.data());
  if (call_environment_set) std::fesetenv(&judge_environment);
  return rc;
}
}  // namespace

std::vector<Observed> observe(const rc_impl& table, const AbiOp& op, const std::vector<const Case*>& cases,
                              std::size_t k) {
  std::vector<Observed> result(cases.size());
  auto run = [&](auto tag) {
    using S = decltype(tag);
    Buffers<S> buf;
    buf.fill(op, cases, k);
    const int rc = call_in_environment(table, op, cases.size(), k, buf);
    const std::string fault = buf.overrun(op, cases.size());
    for (std::size_t i = 0; i < cases.size(); ++i) {
      result[i].call_rc = rc;
      result[i].fault = fault;
      result[i].status = buf.status[i];
      for (std::size_t a = 0; a < op.outputs.size(); ++a) result[i].outputs.push_back(buf.output(op, a, i));
    }
  };
  if (table.scalar == RC_SCALAR_FLOAT32) run(float{});
  else run(double{});
  return result;
}

RawCall call_raw(const rc_impl& table, const AbiOp& op, const std::vector<const Case*>& cases, std::size_t k) {
  RawCall r;
  auto bytes = [](const auto& v) {
    const auto* p = reinterpret_cast<const unsigned char*>(v.data());
    return std::vector<unsigned char>(p, p + v.size() * sizeof(v[0]));
  };
  auto run = [&](auto tag) {
    using S = decltype(tag);
    Buffers<S> buf;
    buf.fill(op, cases, k);
    r.scalar_size = sizeof(S);
    for (const auto& v : buf.in) r.in_before.push_back(bytes(v));
    r.call_rc = call_in_environment(table, op, cases.size(), k, buf);
    r.fault = buf.overrun(op, cases.size());
    for (const auto& v : buf.in) r.in_after.push_back(bytes(v));
    for (const auto& v : buf.out) r.out.push_back(bytes(v));
    r.status.assign(buf.status.begin(), buf.status.begin() + long(cases.size()));
  };
  if (table.scalar == RC_SCALAR_FLOAT32) run(float{});
  else run(double{});
  return r;
}

namespace {
std::vector<Real> values_of(const std::vector<unsigned char>& bytes, std::size_t from, std::size_t count, std::size_t size) {
  std::vector<Real> v;
  for (std::size_t i = from; i < from + count && (i + 1) * size <= bytes.size(); ++i) {
    if (size == sizeof(float)) {
      float x;
      std::memcpy(&x, bytes.data() + i * size, size);
      v.emplace_back(x);
    } else {
      double x;
      std::memcpy(&x, bytes.data() + i * size, size);
      v.emplace_back(x);
    }
  }
  return v;
}
}  // namespace

std::vector<Real> RawCall::output(const AbiOp& op, std::size_t a, std::size_t i) const {
  const std::size_t s = static_cast<std::size_t>(op.outputs[a].stride);
  return values_of(out[a], i * s, s, scalar_size);
}

std::vector<Real> RawCall::input(const AbiOp& op, std::size_t a, std::size_t i, std::size_t k, bool after) const {
  const std::size_t s = static_cast<std::size_t>(op.inputs[a].stride) * (op.inputs[a].per_influence ? k : 1);
  return values_of(after ? in_after[a] : in_before[a], i * s, s, scalar_size);
}

bool RawCall::same_element(const AbiOp& op, std::size_t i, const RawCall& other, std::size_t j) const {
  if (call_rc != other.call_rc || status.at(i) != other.status.at(j)) return false;
  for (std::size_t a = 0; a < op.outputs.size(); ++a) {
    const std::size_t n = static_cast<std::size_t>(op.outputs[a].stride) * scalar_size;
    if (std::memcmp(out[a].data() + i * n, other.out[a].data() + j * n, n) != 0) return false;
  }
  return true;
}

CaseVerdict judge_round_trip(const spec::ToleranceClass& tc, const Case& c, const Observed& log_got,
                             const Observed& exp_got, ref::Format f) {
  const Real eps = ref::format_epsilon<Real>(f);
  const AbiOp& op = *find_abi_op("log");
  if (log_got.call_rc != 0 || exp_got.call_rc != 0)
    return {ref::Verdict::fail, NAN, "the batch call returned " + std::to_string(log_got.call_rc ? log_got.call_rc : exp_got.call_rc)};
  if (!log_got.fault.empty() || !exp_got.fault.empty())
    return {ref::Verdict::fail, NAN, (log_got.fault.empty() ? "exp " + exp_got.fault : "log " + log_got.fault)};
  const std::vector<Real>& got = exp_got.outputs.at(0);
  const bool ok = log_got.status == RC_OK && exp_got.status == RC_OK;
  const Real e = ok ? clause::METRIC_1_rotation_distance(quat(got), quat(c.inputs[0])) / eps
                    : ref::ScalarTraits<Real>::nan();
  const double err = e.toDouble();
  return {ref::clause::TOL_1_verdict(err, bars_for(tc, op, c, eps)), err,
          "exp(log q) = " + join_values(got, false, f) + ", q = " + join_values(c.inputs[0], false, f)};
}

namespace {

/// The largest error over the output arrays; NaN wins.
template <class T>
T largest_output_error(const AbiOp& op, const std::vector<std::vector<T>>& got, const std::vector<std::vector<T>>& want,
                       const T& scale, const T& tiny) {
  using Traits = ref::ScalarTraits<T>;
  T e(0);
  for (std::size_t a = 0; a < op.outputs.size(); ++a) {
    const T ea = measure(op.outputs[a].measure, got[a], want[a], scale, tiny);
    if constexpr (std::is_same_v<T, Real>) {
      if (Traits::is_nan(ea) || Traits::is_nan(e) || ea > e) e = ea;
    } else {  // Bounded: max is continuous, a comparison of two nearby errors would be undecided
      if (Traits::is_nan(ea)) return ea;  // the fast level leaves NaN errors to MPFR
      e = max(e, ea);
    }
  }
  return e;
}

}  // namespace

Real output_error(const AbiOp& op, const Values& got, const Values& want, const Case& c, ref::Format f) {
  return largest_output_error(op, got, want, op.scale(c.inputs, c.k), ref::format_min_normal<Real>(f));
}

ref::Bounded output_error_bounded(const AbiOp& op, const std::vector<std::vector<ref::Bounded>>& got,
                                  const std::vector<std::vector<ref::Bounded>>& want, const ref::Bounded& scale,
                                  const ref::Bounded& tiny) {
  return largest_output_error(op, got, want, scale, tiny);
}

namespace {

CaseVerdict judge_against(const AbiOp& op, const spec::ToleranceClass& tc, const Case& c, const Observed& obs,
                          ref::Format f, const ReferenceResult* precomputed, const Convention* convention,
                          const Declarations* declared, bool with_detail) {
  const Real eps = ref::format_epsilon<Real>(f);
  if (declared != nullptr && convention == nullptr)
    if (const Precondition* p = violated_precondition(*declared, op, c, f)) {
      CaseVerdict v{ref::Verdict::pass, 0, "outside the declared precondition " + p->id + ": " + p->description};
      v.grade = Grade::excluded;
      v.precondition = p->id;
      return v;
    }
  auto status_fail = [](std::string detail) {
    CaseVerdict v{ref::Verdict::fail, NAN, std::move(detail)};
    v.status_mismatch = true;
    return v;
  };
  if (obs.call_rc != 0) return status_fail("the batch call returned " + std::to_string(obs.call_rc));
  if (!obs.fault.empty()) return status_fail(obs.fault);
  const std::vector<std::vector<Real>>& got = obs.outputs;
  auto got_text = [&] {
    std::string s;
    for (std::size_t a = 0; a < got.size(); ++a) s += (a ? " " : "") + join_values(got[a], false, f);
    return s;
  };
  const std::uint8_t st = obs.status;
  if (st != RC_OK && st != RC_DOMAIN_ERROR)
    return status_fail("status byte " + std::to_string(st) + " is neither OK nor DOMAIN_ERROR");
  ReferenceResult computed;
  if (precomputed == nullptr) {
    computed = op.reference(convention ? convention->map_inputs(op, c.inputs) : c.inputs, c.k);
    if (convention && computed.status == ref::Status::ok) computed.outputs = convention->map_outputs(op, computed.outputs);
  }
  const ReferenceResult& want = precomputed ? *precomputed : computed;
  if (want.status == ref::Status::domain_error) {
    if (st == RC_DOMAIN_ERROR && std::all_of(got.begin(), got.end(), all_nan))
      return {ref::Verdict::pass, 0, "DOMAIN_ERROR with NaN outputs, as required"};
    // RESULT-2: a library without a status channel signals the error in band, every output
    // component NaN or infinite (IEEE's invalid and divide-by-zero answers); never a number.
    const auto non_finite = [](const std::vector<Real>& v) {
      return std::none_of(v.begin(), v.end(), [](const Real& x) { return mpfr::isfinite(x); });
    };
    if (st == RC_OK && std::all_of(got.begin(), got.end(), non_finite))
      return {ref::Verdict::pass, 0, "OK with every output non-finite: the domain error signalled in band (RESULT-2)"};
    // ACC-1 outside the domain: an OK output that is a defined answer a correct library may give
    // (EDGE-6: zero_sentinel, algebraic_product) is ACCEPTABLE; anything else fails the status.
    if (st == RC_OK && convention == nullptr)
      for (const AcceptableConvention& a : acceptable_conventions()) {
        if (!a.outside_domain || !a.applies(op) || !a.relevant(op, c, want.outputs, f)) continue;
        const bool is_declared = declared != nullptr && declared->has_convention(op.name, a.id);
        if (a.declared_only && !is_declared) continue;
        const std::optional<Real> alt = a.error(op, c, got, want.outputs, f);
        if (!alt) continue;
        const double alt_err = (*alt / eps).toDouble();
        const ref::Verdict v = ref::clause::TOL_1_verdict(alt_err, a.bars ? *a.bars : bars_for(tc, op, c, eps));
        if (v == ref::Verdict::fail) continue;
        CaseVerdict acceptable{v, alt_err, "expected DOMAIN_ERROR, got OK " + got_text() + " (" + a.id + ": " + a.description + ")"};
        acceptable.grade = Grade::acceptable;
        acceptable.convention = a.id;
        acceptable.declared = is_declared;
        return acceptable;
      }
    return status_fail(std::string("expected DOMAIN_ERROR with all outputs NaN, got ") +
                       (st == RC_OK ? "OK" : "DOMAIN_ERROR") + " " + got_text());
  }
  if (st == RC_DOMAIN_ERROR) return status_fail("spurious DOMAIN_ERROR on an input inside the domain");
  const Real e = output_error(op, got, want.outputs, c, f);
  const double err = (e / eps).toDouble();
  const ref::Bars bars = bars_for(tc, op, c, eps);
  const ref::Verdict v0 = ref::clause::TOL_1_verdict(err, bars);
  std::string detail;
  if (with_detail || v0 != ref::Verdict::pass)
    for (std::size_t a = 0; a < op.outputs.size(); ++a)
      detail += (a ? "; " : "") + op.outputs[a].name + " expected " + join_values(want.outputs[a], false, f) + " got " +
                join_values(got[a], false, f);
  CaseVerdict verdict{v0, err, detail};
  if (verdict.verdict == ref::Verdict::pass || convention != nullptr || tc.kind == "exact") return verdict;
  // ACC-1: a numeric FAIL that is the same rotation under a convention a correct library may
  // choose is ACCEPTABLE (a pass if the table declares that convention); so is a QUALITY_WARNING
  // that is a clean PASS under one (MAT-2's −q near a half turn, off by |w| of the reference).
  for (const AcceptableConvention& a : acceptable_conventions()) {
    if (a.outside_domain || !a.applies(op)) continue;
    const bool is_declared = declared != nullptr && declared->has_convention(op.name, a.id);
    if (a.declared_only && !is_declared) continue;
    if (!a.relevant(op, c, want.outputs, f)) continue;  // the fast oracle relies on this (may_be_acceptable)
    const std::optional<Real> alt = a.error(op, c, got, want.outputs, f);
    if (!alt) continue;
    const double alt_err = (*alt / eps).toDouble();
    const ref::Verdict v = ref::clause::TOL_1_verdict(alt_err, bars);
    if (v == ref::Verdict::fail || (verdict.verdict == ref::Verdict::quality_warning && v != ref::Verdict::pass)) continue;
    CaseVerdict acceptable{v, alt_err, detail + " (" + a.id + ": " + a.description + ")"};
    acceptable.grade = Grade::acceptable;
    acceptable.convention = a.id;
    acceptable.declared = is_declared;
    return acceptable;
  }
  return verdict;
}

}  // namespace

CaseVerdict judge_case(const AbiOp& op, const spec::ToleranceClass& tc, const Case& c, const Observed& got,
                       ref::Format f, const Convention* convention, const Declarations* declared) {
  return judge_against(op, tc, c, got, f, nullptr, convention, declared, true);
}

CaseVerdict judge_case_against(const AbiOp& op, const spec::ToleranceClass& tc, const Case& c, const Observed& got,
                               ref::Format f, const ReferenceResult& want, bool detail) {
  return judge_against(op, tc, c, got, f, &want, nullptr, nullptr, detail);
}

void ClauseJudge::record(const CaseVerdict& v, const AbiOp& op, const Case& c, ref::Format f) {
  if (v.grade == Grade::excluded) {
    ++result.excluded[v.precondition];
    return;
  }
  ++result.cases;
  if (v.verdict == ref::Verdict::fail) ++result.failures;
  if (std::isfinite(v.error)) {
    result.errors[op.name].push_back(v.error);
    auto [it, fresh] = result.worst_by_op.try_emplace(op.name);
    if (fresh || v.error > it->second.error) it->second = {v.error, c.label, describe_inputs(op, c, f), v.detail};
  }
  if (static_cast<int>(v.verdict) > static_cast<int>(worst_verdict)) worst_verdict = v.verdict;
  if (v.grade == Grade::acceptable) {
    auto it = std::find_if(result.acceptable.begin(), result.acceptable.end(),
                           [&](const ClauseResult::Acceptable& a) { return a.convention == v.convention; });
    if (it == result.acceptable.end()) {
      result.acceptable.push_back({v.convention, v.declared, 0, op.name, c.label, describe_inputs(op, c, f), v.detail});
      it = result.acceptable.end() - 1;
    }
    ++it->count;
    return;
  }
  if (v.status_mismatch) {
    if (result.status_failures++ == 0) {
      result.status_op = op.name;
      result.status_label = c.label;
      result.status_input = describe_inputs(op, c, f);
      result.status_detail = v.detail;
    }
    return;
  }
  // The numeric headline candidate: the highest verdict, then the largest error (a NaN output
  // counts as infinite), among validly graded inputs.
  const double key = std::isnan(v.error) ? INFINITY : v.error;
  const double best_key = std::isnan(numeric.error) ? INFINITY : numeric.error;
  if (numeric.op.empty() || static_cast<int>(v.verdict) > static_cast<int>(numeric_verdict) ||
      (v.verdict == numeric_verdict && key > best_key)) {
    numeric_verdict = v.verdict;
    numeric = Numeric{{v.error, c.label, describe_inputs(op, c, f), v.detail}, op.name};
  }
}

void ClauseJudge::finish() {
  // REPORT-1 headline: the largest numeric error among valid inputs; the first status failure
  // only where it alone decides the FAIL (no numeric FAIL) or nothing numeric was measured.
  const bool status_headline =
      result.status_failures > 0 && (numeric.op.empty() || numeric_verdict != ref::Verdict::fail);
  if (status_headline) {
    result.worst_error = NAN;
    result.worst_op = result.status_op;
    result.worst_label = result.status_label;
    result.worst_input = result.status_input;
    result.worst_detail = result.status_detail;
  } else if (!numeric.op.empty()) {
    result.worst_error = numeric.error;
    result.worst_op = numeric.op;
    result.worst_label = numeric.label;
    result.worst_input = numeric.input;
    result.worst_detail = numeric.detail;
  } else if (!result.acceptable.empty()) {
    const auto& a = result.acceptable.front();
    result.worst_error = 0;
    result.worst_op = a.op;
    result.worst_label = a.label;
    result.worst_input = a.input;
    result.worst_detail = a.detail;
  }
  result.outcome = worst_verdict == ref::Verdict::pass              ? Outcome::pass
                   : worst_verdict == ref::Verdict::quality_warning ? Outcome::quality_warning
                                                                    : Outcome::fail;
  if (result.outcome == Outcome::fail || result.excluded.empty()) return;
  std::string which;
  std::size_t n = 0;
  for (const auto& [id, count] : result.excluded) {
    which += (which.empty() ? "" : ", ") + id + " (" + std::to_string(count) + ")";
    n += count;
  }
  if (result.cases == 0) {
    result.outcome = Outcome::not_supported;
    result.note = "every input lies outside a declared precondition: " + which;
  } else if (result.level == "Robust") {
    result.outcome = Outcome::not_supported;
    result.note = std::to_string(n) + " input(s) outside declared preconditions, which Robust requires to be handled: " +
                  which + " (DECL-1)";
  } else {
    result.note = std::to_string(n) + " input(s) outside declared preconditions not judged: " + which + " (DECL-1)";
  }
}

const char* to_string(Outcome o) {
  switch (o) {
    case Outcome::pass: return "PASS";
    case Outcome::quality_warning: return "QUALITY_WARNING";
    case Outcome::fail: return "FAIL";
    case Outcome::not_supported: return "NOT_SUPPORTED";
    case Outcome::crash: return "CRASH";
    case Outcome::timeout: return "TIMEOUT";
  }
  return "FAIL";
}

bool parse_outcome(const std::string& code, Outcome& out) {
  for (Outcome o : {Outcome::pass, Outcome::quality_warning, Outcome::fail, Outcome::not_supported, Outcome::crash,
                    Outcome::timeout})
    if (code == to_string(o)) {
      out = o;
      return true;
    }
  return false;
}

ref::Format format_of(const rc_impl& table) {
  return table.scalar == RC_SCALAR_FLOAT32 ? ref::Format::binary32 : ref::Format::binary64;
}

std::vector<std::string> claimed_clauses(const rc_impl& table) {
  std::vector<std::string> ids;
  for (int i = 0; table.clauses && table.clauses[i]; ++i) ids.emplace_back(table.clauses[i]);
  // HYG-1 .. HYG-3 are every C-ABI table's contract, not a feature it offers: judged whether or
  // not the table lists them (old plugins included).
  for (const char* id : {"HYG-1", "HYG-2", "HYG-3"})
    if (std::find(ids.begin(), ids.end(), id) == ids.end()) ids.emplace_back(id);
  return ids;
}

namespace {

/// One value of the format k ulps away from x (k may be negative); x itself if x is 0 or the
/// step leaves the finite range (the search never invents zeros, subnormals or infinities).
Real ulp_step(const Real& x, long k, ref::Format f) {
  if (x == 0 || !mpfr::isfinite(x)) return x;
  if (f == ref::Format::binary32) {
    float v = mpfr_get_flt(x.mpfr_srcptr(), MPFR_RNDN);
    const float ulp = std::nextafter(std::fabs(v), INFINITY) - std::fabs(v);
    const float r = v + static_cast<float>(k) * ulp;
    return std::isfinite(r) && std::fpclassify(r) == FP_NORMAL ? Real(r) : x;
  }
  const double v = mpfr_get_d(x.mpfr_srcptr(), MPFR_RNDN);
  const double ulp = std::nextafter(std::fabs(v), INFINITY) - std::fabs(v);
  const double r = v + static_cast<double>(k) * ulp;
  return std::isfinite(r) && std::fpclassify(r) == FP_NORMAL ? Real(r) : x;
}

/// The search keeps the start's input class: a quaternion, axis or unit dual quaternion that was
/// unit (within 64 eps) in the start is projected back onto the unit sphere exactly and rounded
/// (a rounded unit quaternion is within 2 eps of unit), so the walk explores rounding, not scale.
void keep_unit_blocks(const AbiOp& op, const Case& start, Case& n, ref::Format f) {
  const Real band = Real(64) * ref::format_epsilon<Real>(f);
  for (std::size_t a = 0; a < op.inputs.size(); ++a) {
    const Array& arr = op.inputs[a];
    const bool axis = is_axis_input(op, arr);
    const std::size_t stride = static_cast<std::size_t>(arr.stride);
    if (arr.stride != 4 && arr.stride != 8 && !axis) continue;
    const std::size_t part = arr.stride == 8 ? 4 : stride;
    for (std::size_t j = 0; j + stride <= n.inputs[a].size(); j += stride) {
      const Real was = block_norm(start.inputs[a], j, part);
      if (!mpfr::isfinite(was) || abs(was - Real(1)) > band) continue;
      auto& v = n.inputs[a];
      const Real now = block_norm(v, j, part);
      if (now == 0 || !mpfr::isfinite(now)) continue;
      if (arr.stride == 8) {
        // DQ-4 projection: r/|r|, d/|r| - (r.d/|r|^3) r.
        Real rd(0);
        for (std::size_t i = 0; i < 4; ++i) rd += v[j + i] * v[j + 4 + i];
        std::vector<Real> r(v.begin() + long(j), v.begin() + long(j + 4));
        for (std::size_t i = 0; i < 4; ++i) {
          v[j + 4 + i] = round_to(f, v[j + 4 + i] / now - rd / (now * now * now) * r[i]);
          v[j + i] = round_to(f, r[i] / now);
        }
      } else {
        for (std::size_t i = j; i < j + part; ++i) v[i] = round_to(f, v[i] / now);
      }
    }
  }
}

/// Whether a hemisphere tie (ACC-1 hemisphere_tie) is at stake in this input.
bool is_tie(const AbiOp& op, const Case& c, ref::Format f) {
  for (const AcceptableConvention& a : acceptable_conventions())
    if (a.id == "hemisphere_tie" && a.applies(op)) {
      const ReferenceResult want = op.reference(c.inputs, c.k);
      return want.status == ref::Status::ok && a.relevant(op, c, want.outputs, f);
    }
  return false;
}

/// The worst-case search of one check (CaseOptions::search_budget): starting from the input
/// with the largest valid numeric error, generations of neighbours (each input component moved
/// by +-2^j ulps, j random, one to three components at a time) are evaluated in one batch; the
/// best neighbour replaces the start when its error is larger. Deterministic in the seed; the
/// final input is recorded as one more case of the clause when it beats its start.
template <class Record>
std::size_t search_worst(const rc_impl& table, const spec::ToleranceClass& tc, const Check& check, const Case& start,
                         double start_error, bool ordinary_only, const CaseOptions& options, const RunHooks& hooks,
                         Record record) {
  const ref::Format f = format_of(table);
  const AbiOp& op = *find_abi_op(check.op);
  const Declarations declared = declarations_of(table);
  std::uint64_t h = 1469598103934665603ull ^ (options.seed * 0x9E3779B97F4A7C15ull);
  for (char ch : "search/" + check.op + "/" + start.label) h = (h ^ static_cast<unsigned char>(ch)) * 1099511628211ull;
  std::mt19937_64 rng(h);
  const int batch = 8;
  const int generations = std::max(1, options.search_budget / batch);
  Case best = start;
  double best_error = start_error;
  CaseVerdict best_verdict;
  std::size_t spent = 0;
  for (int g = 0; g < generations; ++g) {
    std::vector<Case> neighbours;
    for (int b = 0; b < batch; ++b) {
      Case n = best;
      const int moves = 1 + static_cast<int>(rng() % 3);
      for (int m = 0; m < moves; ++m) {
        const std::size_t a = rng() % n.inputs.size();
        if (n.inputs[a].empty()) continue;
        const std::size_t i = rng() % n.inputs[a].size();
        // Matrices move by a few ulps only (a rotation matrix must stay one to the accuracy of
        // its format, MAT-2); everything else by up to 2^11 ulps.
        const unsigned span = op.inputs[a].stride == 9 ? 3 : 12;
        const long k = (1L << (rng() % span)) * ((rng() & 1) ? 1 : -1);
        n.inputs[a][i] = ulp_step(n.inputs[a][i], k, f);
      }
      keep_unit_blocks(op, start, n, f);
      if (ordinary_only && !robust_clause_of(op, n, f).empty()) continue;
      if (is_tie(op, n, f)) continue;  // a tie has two right answers; the search is for tails
      n.label = "worst-case search from " + start.label;
      neighbours.push_back(std::move(n));
    }
    if (neighbours.empty()) continue;
    std::vector<const Case*> ptrs;
    for (const Case& n : neighbours) ptrs.push_back(&n);
    if (hooks.before_call) hooks.before_call(op, ptrs);
    const std::vector<Observed> got = observe(table, op, ptrs, start.k);
    spent += neighbours.size();
    for (std::size_t i = 0; i < neighbours.size(); ++i) {
      const CaseVerdict v = judge_case(op, tc, neighbours[i], got[i], f, nullptr, &declared);
      if (v.grade != Grade::valid || v.status_mismatch || !std::isfinite(v.error)) continue;
      if (v.error > best_error) {
        best_error = v.error;
        best = neighbours[i];
        best_verdict = v;
      }
    }
  }
  if (best_error > start_error) record(best_verdict, op, best);
  return spent;
}

}  // namespace

ClauseResult run_clause(const rc_impl& table, const spec::Spec& spec, const std::string& clause_id,
                        const CaseOptions& options, const RunHooks& hooks) {
  if (is_hygiene_clause(clause_id)) return run_hygiene_clause(table, spec, clause_id, options);
  ClauseResult result;
  result.clause = clause_id;
  const spec::Clause* cl = spec.find_clause(clause_id);
  if (cl == nullptr) {
    result.outcome = Outcome::fail;
    result.note = "no clause " + clause_id + " in the spec";
    result.worst_detail = result.note;
    return result;
  }
  result.level = cl->level;
  result.tolerance = cl->tolerance;
  const auto checks = supported_checks(table, spec, clause_id, options);
  if (checks.empty()) {
    result.outcome = Outcome::not_supported;
    result.note = "the table provides none of the operations that judge this clause";
    return result;
  }
  const ref::Format f = format_of(table);
  ClauseJudge judge{result};
  for (const Check& check : checks) {
    const spec::ToleranceClass& tc = class_of(spec, *cl, check);
    const Case* worst = nullptr;
    double worst_error = -1;
    run_check(table, tc, check, hooks, [&](const CaseVerdict& v, const AbiOp& op, const Case& c) {
      judge.record(v, op, c, f);
      if (v.grade == Grade::valid && !v.status_mismatch && std::isfinite(v.error) && v.error > worst_error) {
        worst_error = v.error;
        worst = &c;
      }
    });
    // Worst-case search: numeric classes only, never on the EXP-2 round trip or a convention run,
    // nor on the clauses whose inputs are fixed by a relation a step would break (SLERP-3's exact
    // endpoints, SLERP-5's t grid on one pair, SKIN-3's equal influences, EDGE-3's ties).
    static const std::set<std::string> structured = {"SLERP-3", "SLERP-5", "SKIN-3", "EDGE-1", "EDGE-3"};
    if (options.search_budget > 0 && worst != nullptr && tc.kind != "exact" && tc.kind != "outcome" &&
        structured.count(clause_id) == 0 &&
        !check.log_exp_round_trip && hooks.convention == nullptr && !hooks.one_at_a_time &&
        !is_tie(*find_abi_op(check.op), *worst, f)) {
      const bool ordinary_only = cl->level != "Robust";
      result.searched += search_worst(table, tc, check, *worst, worst_error, ordinary_only, options, hooks,
                                      [&](const CaseVerdict& v, const AbiOp& op, const Case& c) { judge.record(v, op, c, f); });
    }
  }
  judge.finish();
  return result;
}

std::vector<std::string> detect_conventions(const rc_impl& table, const spec::Spec& spec, const std::string& clause_id,
                                            const CaseOptions& options) {
  ClauseResult r;
  detect_conventions(table, spec, clause_id, options, r);
  return r.conventions;
}

void detect_conventions(const rc_impl& table, const spec::Spec& spec, const std::string& clause_id,
                        const CaseOptions& options, ClauseResult& result) {
  result.conventions.clear();
  result.diagnoses.clear();
  const spec::Clause* cl = spec.find_clause(clause_id);
  if (cl == nullptr) return;
  const ref::Format f = format_of(table);
  auto checks = supported_checks(table, spec, clause_id, options);
  // Per input (CONV-1): which inputs fail as specified, and which pass under each convention.
  struct Input {
    const Check* check;
    std::size_t index;
    bool failed;
  };
  auto verdicts = [&](const Check& check, const Convention* convention) {
    RunHooks hooks;
    hooks.convention = convention;
    std::vector<bool> failed;
    run_check(table, class_of(spec, *cl, check), check, hooks, [&](const CaseVerdict& v, const AbiOp&, const Case&) {
      failed.push_back(v.grade != Grade::excluded && v.verdict == ref::Verdict::fail);
    });
    return failed;
  };
  // run_check visits cases grouped by k; keep the same order for every run (same check, same order).
  std::vector<std::vector<bool>> as_specified;
  std::size_t failing = 0;
  for (const Check& check : checks) {
    as_specified.push_back(verdicts(check, nullptr));
    failing += static_cast<std::size_t>(std::count(as_specified.back().begin(), as_specified.back().end(), true));
  }
  if (failing == 0) return;
  for (const Convention& convention : conventions()) {
    std::size_t explained = 0, contradicted = 0, covered = 0;
    std::vector<std::string> unexplained;
    for (std::size_t i = 0; i < checks.size(); ++i) {
      const Check& check = checks[i];
      const AbiOp& op = *find_abi_op(check.op);
      const bool applies = !check.log_exp_round_trip && convention.applies(op);
      // The cases in run_check's order (grouped by k).
      std::vector<const Case*> order;
      std::map<std::size_t, std::vector<const Case*>> groups;
      for (const Case& c : check.cases) groups[c.k].push_back(&c);
      for (auto& [k, cs] : groups) order.insert(order.end(), cs.begin(), cs.end());
      if (!applies) {
        for (std::size_t j = 0; j < as_specified[i].size(); ++j)
          if (as_specified[i][j] && unexplained.size() < 3) unexplained.push_back(describe_inputs(op, *order[j], f));
        continue;
      }
      ++covered;
      const std::vector<bool> under = verdicts(check, &convention);
      for (std::size_t j = 0; j < under.size() && j < as_specified[i].size(); ++j) {
        if (as_specified[i][j] && !under[j]) ++explained;
        else if (as_specified[i][j] && unexplained.size() < 3) unexplained.push_back(describe_inputs(op, *order[j], f));
        if (!as_specified[i][j] && under[j]) ++contradicted;
      }
    }
    if (covered == 0 || explained == 0) continue;
    if (explained == failing && contradicted == 0) result.conventions.push_back(convention.id);
    else if (2 * explained >= failing) result.diagnoses.push_back({convention.id, explained, failing, unexplained});
  }
  (void)f;
}

}  // namespace rotorcert::engine
