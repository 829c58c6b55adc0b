#include <rotorcert/engine/runner.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
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
    out.assign(op.outputs.size(), {});
    for (std::size_t a = 0; a < op.outputs.size(); ++a) out[a].assign(n * op.outputs[a].stride + 1, S(0));
    status.assign(n + 1, 0xEE);  // a value no implementation writes: shows an element left untouched
    in_ptrs.clear();
    out_ptrs.clear();
    for (auto& v : in) in_ptrs.push_back(v.empty() ? nullptr : v.data());
    for (auto& v : out) out_ptrs.push_back(v.data());
    (void)k;
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

std::string join_values(const std::vector<Real>& v, bool hexfloat, ref::Format f) {
  std::string s = "[";
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + (hexfloat ? hex(v[i], f) : dec(v[i]));
  return s + "]";
}

std::string describe_inputs(const AbiOp& op, const Case& c, ref::Format f) {
  std::string s;
  for (std::size_t a = 0; a < op.inputs.size(); ++a)
    s += (a ? " " : "") + op.inputs[a].name + "=" + join_values(c.inputs[a], true, f);
  if (op.nway) s += " k=" + std::to_string(c.k);
  return s;
}

Quat quat(const std::vector<Real>& a) { return {a[3], a[0], a[1], a[2]}; }
ref::DualQuaternion<Real> dq(const std::vector<Real>& a) { return {{a[3], a[0], a[1], a[2]}, {a[7], a[4], a[5], a[6]}}; }

Real norm(const std::vector<Real>& v) {
  Real s(0);
  for (const Real& x : v) s += x * x;
  return sqrt(s);
}

/// The error of one output array in the unit of its measure (radians, relative, ...).
Real measure(Measure m, const std::vector<Real>& got, const std::vector<Real>& want, const Real& scale,
             const Real& tiny) {
  using std::max;
  switch (m) {
    case Measure::rotation: return clause::METRIC_1_rotation_distance(quat(got), quat(want));
    case Measure::quaternion: {
      Real worst(0);
      for (int i = 0; i < 4; ++i) worst = max(worst, Real(abs(got[i] - want[i])));
      const Real relative = worst / norm(want);
      if (mpfr::isnan(relative)) return relative;
      return max(clause::METRIC_1_rotation_distance(quat(got), quat(want)), relative);
    }
    case Measure::unit_rotation:
      return max(clause::METRIC_1_rotation_distance(quat(got), quat(want)), clause::METRIC_6_norm_defect(quat(got)));
    case Measure::vector:
      return clause::METRIC_3_vector_error<Real>({got[0], got[1], got[2]}, {want[0], want[1], want[2]}, tiny);
    case Measure::point: {
      std::vector<Real> d{got[0] - want[0], got[1] - want[1], got[2] - want[2]};
      return norm(d) / scale;
    }
    case Measure::bivector: return clause::METRIC_5_bivector_error<Real>({got[0], got[1], got[2]}, {want[0], want[1], want[2]});
    case Measure::matrix: {
      ref::Mat3<Real> a, b;
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
    case Measure::unit_rigid: {
      const auto e = clause::METRIC_7_rigid_error(dq(got), dq(want));
      const auto g = dq(got);
      const auto t = clause::dual_quaternion_translation(dq(want));
      const Real orthogonality = abs(ref::dot(g.real, g.dual)) / max(Real(1), sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]));
      return max(max(e.rotation, e.translation), max(clause::METRIC_6_norm_defect(g.real), orthogonality));
    }
  }
  return ref::ScalarTraits<Real>::nan();
}

bool all_nan(const std::vector<Real>& v) {
  return std::all_of(v.begin(), v.end(), [](const Real& x) { return mpfr::isnan(x); });
}

/// Strict and loose bars for one case, in eps units (the unit errors are compared in).
ref::Bars bars_for(const spec::ToleranceClass& tc, const AbiOp& op, const Case& c, const Real& eps) {
  if (tc.kind == "exact") return {0, 0};
  if (tc.kind == "formula") {  // inherited-mat: 16 eps + 2 delta / 256 eps + 8 delta, delta of the input
    Real delta(0);
    if (op.name == "from_matrix") {
      const auto& m = c.inputs[0];
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          Real s(0);
          for (int r = 0; r < 3; ++r) s += m[i * 3 + r] * m[j * 3 + r];
          const Real d = s - Real(i == j ? 1 : 0);
          delta += d * d;
        }
      delta = sqrt(delta);
    }
    return {(Real(16) + Real(2) * delta / eps).toDouble(), (Real(256) + Real(8) * delta / eps).toDouble()};
  }
  const auto strict = tc.strict_value(), loose = tc.loose_value();
  if (!strict || !loose) return {0, 0};  // a class without numeric bars accepts no numeric error
  return {strict->toDouble(), loose->toDouble()};
}

struct Judge {
  ClauseResult& result;
  ref::Verdict worst_verdict = ref::Verdict::pass;

  /// Keeps the worst case: the highest verdict, then the largest error (NaN counts as infinite).
  void record(ref::Verdict v, double error, const AbiOp& op, const Case& c, ref::Format f, const std::string& detail) {
    ++result.cases;
    if (v == ref::Verdict::fail) ++result.failures;
    if (std::isfinite(error)) result.errors.push_back(error);
    const double key = std::isnan(error) ? INFINITY : error;
    const double worst_key = std::isnan(result.worst_error) ? INFINITY : result.worst_error;
    const bool first = result.worst_op.empty();
    if (first || static_cast<int>(v) > static_cast<int>(worst_verdict) || (v == worst_verdict && key > worst_key)) {
      worst_verdict = v;
      result.worst_error = error;
      result.worst_op = op.name;
      result.worst_label = c.label;
      result.worst_input = describe_inputs(op, c, f);
      result.worst_detail = detail;
    }
  }
};

template <class S>
void run_check(const rc_impl& table, const spec::Spec& spec, const spec::ToleranceClass& tc, const Check& check,
               Judge& judge) {
  const ref::Format f = format_of(table);
  const Real eps = ref::format_epsilon<Real>(f);
  const AbiOp& op = *find_abi_op(check.op);
  std::map<std::size_t, std::vector<const Case*>> groups;  // n-way calls share one k
  for (const Case& c : check.cases) groups[c.k].push_back(&c);
  for (const auto& [k, cases] : groups) {
    Buffers<S> buf;
    buf.fill(op, cases, k);
    const int rc = call(table, op.name, cases.size(), k, buf.in_ptrs, buf.out_ptrs, buf.status.data());

    // EXP-2: feed log's output to exp and compare with the input rotation.
    Buffers<S> second;
    if (check.log_exp_round_trip && rc == 0) {
      const AbiOp& exp_op = *find_abi_op("exp");
      std::vector<Case> logs;
      for (std::size_t i = 0; i < cases.size(); ++i) logs.push_back(Case{{buf.output(op, 0, i)}, 0, "log output"});
      std::vector<const Case*> ptrs;
      for (const Case& c : logs) ptrs.push_back(&c);
      second.fill(exp_op, ptrs, 0);
      call(table, "exp", ptrs.size(), 0, second.in_ptrs, second.out_ptrs, second.status.data());
    }

    for (std::size_t i = 0; i < cases.size(); ++i) {
      const Case& c = *cases[i];
      if (rc != 0) {
        judge.record(ref::Verdict::fail, NAN, op, c, f, "the batch call returned " + std::to_string(rc));
        continue;
      }
      const std::uint8_t st = buf.status[i];
      if (check.log_exp_round_trip) {
        const std::vector<Real> got = second.output(*find_abi_op("exp"), 0, i);
        const bool ok = st == RC_OK && second.status[i] == RC_OK;
        const Real e = ok ? clause::METRIC_1_rotation_distance(quat(got), quat(c.inputs[0])) / eps
                          : ref::ScalarTraits<Real>::nan();
        const double err = e.toDouble();
        const auto b = bars_for(tc, op, c, eps);
        judge.record(ref::clause::TOL_1_verdict(err, b), err, op, c, f,
                     "exp(log q) = " + join_values(got, false, f) + ", q = " + join_values(c.inputs[0], false, f));
        continue;
      }
      const ReferenceResult want = op.reference(c.inputs, c.k);
      std::vector<std::vector<Real>> got;
      for (std::size_t a = 0; a < op.outputs.size(); ++a) got.push_back(buf.output(op, a, i));
      auto got_text = [&] {
        std::string s;
        for (std::size_t a = 0; a < got.size(); ++a) s += (a ? " " : "") + join_values(got[a], false, f);
        return s;
      };
      if (st != RC_OK && st != RC_DOMAIN_ERROR) {
        judge.record(ref::Verdict::fail, NAN, op, c, f, "status byte " + std::to_string(st) + " is neither OK nor DOMAIN_ERROR");
        continue;
      }
      if (want.status == ref::Status::domain_error) {
        const bool nan_out = std::all_of(got.begin(), got.end(), all_nan);
        if (st == RC_DOMAIN_ERROR && nan_out) {
          judge.record(ref::Verdict::pass, 0, op, c, f, "DOMAIN_ERROR with NaN outputs, as required");
        } else {
          judge.record(ref::Verdict::fail, NAN, op, c, f,
                       std::string("expected DOMAIN_ERROR with all outputs NaN, got ") +
                           (st == RC_OK ? "OK" : "DOMAIN_ERROR") + " " + got_text());
        }
        continue;
      }
      if (st == RC_DOMAIN_ERROR) {
        judge.record(ref::Verdict::fail, NAN, op, c, f, "spurious DOMAIN_ERROR on an input inside the domain");
        continue;
      }
      const Real scale = op.scale(c.inputs, c.k);
      Real e(0);
      std::string detail;
      for (std::size_t a = 0; a < op.outputs.size(); ++a) {
        const Real ea = measure(op.outputs[a].measure, got[a], want.outputs[a], scale, ref::format_min_normal<Real>(f));
        if (mpfr::isnan(ea) || ea > e || mpfr::isnan(e)) e = ea;
        detail += (a ? "; " : "") + op.outputs[a].name + " expected " + join_values(want.outputs[a], false, f) +
                  " got " + join_values(got[a], false, f);
      }
      const double err = (e / eps).toDouble();
      const auto b = bars_for(tc, op, c, eps);
      judge.record(ref::clause::TOL_1_verdict(err, b), err, op, c, f, detail);
    }
  }
  (void)spec;
}

}  // namespace

const char* to_string(Outcome o) {
  switch (o) {
    case Outcome::pass: return "PASS";
    case Outcome::quality_warning: return "QUALITY_WARNING";
    case Outcome::fail: return "FAIL";
    case Outcome::not_supported: return "NOT_SUPPORTED";
  }
  return "FAIL";
}

ref::Format format_of(const rc_impl& table) {
  return table.scalar == RC_SCALAR_FLOAT32 ? ref::Format::binary32 : ref::Format::binary64;
}

std::vector<std::string> claimed_clauses(const rc_impl& table) {
  std::vector<std::string> ids;
  for (int i = 0; table.clauses && table.clauses[i]; ++i) ids.emplace_back(table.clauses[i]);
  return ids;
}

ClauseResult run_clause(const rc_impl& table, const spec::Spec& spec, const std::string& clause_id,
                        const CaseOptions& options) {
  ClauseResult result;
  result.clause = clause_id;
  const spec::Clause* cl = spec.find_clause(clause_id);
  if (cl == nullptr) {
    result.outcome = Outcome::fail;
    result.worst_detail = "no clause " + clause_id + " in the spec";
    return result;
  }
  result.level = cl->level;
  result.tolerance = cl->tolerance;
  const auto checks = checks_for_clause(spec, clause_id, format_of(table), options,
                                        [&](const std::string& op) { return supports(table, op); });
  if (checks.empty()) {
    result.outcome = Outcome::not_supported;
    return result;
  }
  Judge judge{result};
  for (const Check& check : checks) {
    const spec::ToleranceClass& tc = spec.lookup(check.tolerance.empty() ? cl->tolerance : check.tolerance);
    if (table.scalar == RC_SCALAR_FLOAT32) run_check<float>(table, spec, tc, check, judge);
    else run_check<double>(table, spec, tc, check, judge);
  }
  result.outcome = judge.worst_verdict == ref::Verdict::pass              ? Outcome::pass
                   : judge.worst_verdict == ref::Verdict::quality_warning ? Outcome::quality_warning
                                                                          : Outcome::fail;
  return result;
}

}  // namespace rotorcert::engine
