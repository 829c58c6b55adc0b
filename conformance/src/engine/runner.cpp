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
    case Measure::canonical_rotation: {
      // MAT-2: q and -q are one rotation, but from_matrix has one answer, w > 0. A result on the
      // other side of the reference (negative dot product) is off by |w_ref|: within the bar (a
      // half turn, w near 0) either sign passes, beyond it the wrong sign fails.
      const Real rotation =
          max(clause::METRIC_1_rotation_distance(quat(got), quat(want)), clause::METRIC_6_norm_defect(quat(got)));
      const Real dot = got[0] * want[0] + got[1] * want[1] + got[2] * want[2] + got[3] * want[3];
      return dot < 0 ? max(rotation, Real(abs(want[3]))) : rotation;
    }
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

}  // namespace

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

namespace {

/// Runs one check: observe in batches (or one at a time), judge each case.
template <class Record>
void run_check(const rc_impl& table, const spec::ToleranceClass& tc, const Check& check, const RunHooks& hooks,
               Record record) {
  const ref::Format f = format_of(table);
  const AbiOp& op = *find_abi_op(check.op);
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
      for (std::size_t i = 0; i < cases.size(); ++i) logs.push_back(Case{{got[i].outputs.at(0)}, 0, "log output"});
      std::vector<const Case*> ptrs;
      for (const Case& c : logs) ptrs.push_back(&c);
      if (hooks.before_call) hooks.before_call(exp_op, ptrs);
      const std::vector<Observed> second = observe(table, exp_op, ptrs, 0);
      for (std::size_t i = 0; i < cases.size(); ++i)
        record(judge_round_trip(tc, *cases[i], got[i], second[i], f), op, *cases[i]);
      continue;
    }
    for (std::size_t i = 0; i < cases.size(); ++i)
      record(judge_case(op, tc, *cases[i], got[i], f, hooks.convention), op, *cases[i]);
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

std::vector<Observed> observe(const rc_impl& table, const AbiOp& op, const std::vector<const Case*>& cases,
                              std::size_t k) {
  std::vector<Observed> result(cases.size());
  auto run = [&](auto tag) {
    using S = decltype(tag);
    Buffers<S> buf;
    buf.fill(op, cases, k);
    std::fenv_t judge_environment;
    if (call_environment_set) {
      std::fegetenv(&judge_environment);
      std::fesetenv(&call_environment);
    }
    const int rc = call(table, op.name, cases.size(), k, buf.in_ptrs, buf.out_ptrs, buf.status.data());
    if (call_environment_set) std::fesetenv(&judge_environment);
    for (std::size_t i = 0; i < cases.size(); ++i) {
      result[i].call_rc = rc;
      result[i].status = buf.status[i];
      for (std::size_t a = 0; a < op.outputs.size(); ++a) result[i].outputs.push_back(buf.output(op, a, i));
    }
  };
  if (table.scalar == RC_SCALAR_FLOAT32) run(float{});
  else run(double{});
  return result;
}

CaseVerdict judge_round_trip(const spec::ToleranceClass& tc, const Case& c, const Observed& log_got,
                             const Observed& exp_got, ref::Format f) {
  const Real eps = ref::format_epsilon<Real>(f);
  const AbiOp& op = *find_abi_op("log");
  if (log_got.call_rc != 0 || exp_got.call_rc != 0)
    return {ref::Verdict::fail, NAN, "the batch call returned " + std::to_string(log_got.call_rc ? log_got.call_rc : exp_got.call_rc)};
  const std::vector<Real>& got = exp_got.outputs.at(0);
  const bool ok = log_got.status == RC_OK && exp_got.status == RC_OK;
  const Real e = ok ? clause::METRIC_1_rotation_distance(quat(got), quat(c.inputs[0])) / eps
                    : ref::ScalarTraits<Real>::nan();
  const double err = e.toDouble();
  return {ref::clause::TOL_1_verdict(err, bars_for(tc, op, c, eps)), err,
          "exp(log q) = " + join_values(got, false, f) + ", q = " + join_values(c.inputs[0], false, f)};
}

CaseVerdict judge_case(const AbiOp& op, const spec::ToleranceClass& tc, const Case& c, const Observed& obs,
                       ref::Format f, const Convention* convention) {
  const Real eps = ref::format_epsilon<Real>(f);
  if (obs.call_rc != 0) return {ref::Verdict::fail, NAN, "the batch call returned " + std::to_string(obs.call_rc)};
  const std::vector<std::vector<Real>>& got = obs.outputs;
  auto got_text = [&] {
    std::string s;
    for (std::size_t a = 0; a < got.size(); ++a) s += (a ? " " : "") + join_values(got[a], false, f);
    return s;
  };
  const std::uint8_t st = obs.status;
  if (st != RC_OK && st != RC_DOMAIN_ERROR)
    return {ref::Verdict::fail, NAN, "status byte " + std::to_string(st) + " is neither OK nor DOMAIN_ERROR"};
  ReferenceResult want = op.reference(convention ? convention->map_inputs(op, c.inputs) : c.inputs, c.k);
  if (convention && want.status == ref::Status::ok) want.outputs = convention->map_outputs(op, want.outputs);
  if (want.status == ref::Status::domain_error) {
    if (st == RC_DOMAIN_ERROR && std::all_of(got.begin(), got.end(), all_nan))
      return {ref::Verdict::pass, 0, "DOMAIN_ERROR with NaN outputs, as required"};
    return {ref::Verdict::fail, NAN,
            std::string("expected DOMAIN_ERROR with all outputs NaN, got ") + (st == RC_OK ? "OK" : "DOMAIN_ERROR") + " " +
                got_text()};
  }
  if (st == RC_DOMAIN_ERROR) return {ref::Verdict::fail, NAN, "spurious DOMAIN_ERROR on an input inside the domain"};
  const Real scale = op.scale(c.inputs, c.k);
  Real e(0);
  std::string detail;
  for (std::size_t a = 0; a < op.outputs.size(); ++a) {
    const Real ea = measure(op.outputs[a].measure, got[a], want.outputs[a], scale, ref::format_min_normal<Real>(f));
    if (mpfr::isnan(ea) || ea > e || mpfr::isnan(e)) e = ea;
    detail += (a ? "; " : "") + op.outputs[a].name + " expected " + join_values(want.outputs[a], false, f) + " got " +
              join_values(got[a], false, f);
  }
  const double err = (e / eps).toDouble();
  return {ref::clause::TOL_1_verdict(err, bars_for(tc, op, c, eps)), err, detail};
}

void ClauseJudge::record(const CaseVerdict& v, const AbiOp& op, const Case& c, ref::Format f) {
  ++result.cases;
  if (v.verdict == ref::Verdict::fail) ++result.failures;
  if (std::isfinite(v.error)) {
    result.errors[op.name].push_back(v.error);
    auto [it, fresh] = result.worst_by_op.try_emplace(op.name);
    if (fresh || v.error > it->second.error) it->second = {v.error, c.label, describe_inputs(op, c, f), v.detail};
  }
  // The worst case: the highest verdict, then the largest error (NaN counts as infinite).
  const double key = std::isnan(v.error) ? INFINITY : v.error;
  const double worst_key = std::isnan(result.worst_error) ? INFINITY : result.worst_error;
  const bool first = result.worst_op.empty();
  if (first || static_cast<int>(v.verdict) > static_cast<int>(worst_verdict) ||
      (v.verdict == worst_verdict && key > worst_key)) {
    worst_verdict = v.verdict;
    result.worst_error = v.error;
    result.worst_op = op.name;
    result.worst_label = c.label;
    result.worst_input = describe_inputs(op, c, f);
    result.worst_detail = v.detail;
  }
}

void ClauseJudge::finish() {
  result.outcome = worst_verdict == ref::Verdict::pass              ? Outcome::pass
                   : worst_verdict == ref::Verdict::quality_warning ? Outcome::quality_warning
                                                                    : Outcome::fail;
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
  return ids;
}

ClauseResult run_clause(const rc_impl& table, const spec::Spec& spec, const std::string& clause_id,
                        const CaseOptions& options, const RunHooks& hooks) {
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
  for (const Check& check : checks)
    run_check(table, class_of(spec, *cl, check), check, hooks,
              [&](const CaseVerdict& v, const AbiOp& op, const Case& c) { judge.record(v, op, c, f); });
  judge.finish();
  return result;
}

std::vector<std::string> detect_conventions(const rc_impl& table, const spec::Spec& spec, const std::string& clause_id,
                                            const CaseOptions& options) {
  std::vector<std::string> found;
  const spec::Clause* cl = spec.find_clause(clause_id);
  if (cl == nullptr) return found;
  const auto checks = supported_checks(table, spec, clause_id, options);
  auto fails = [&](const Check& check, const Convention* convention) {
    RunHooks hooks;
    hooks.convention = convention;
    bool failed = false;
    run_check(table, class_of(spec, *cl, check), check, hooks, [&](const CaseVerdict& v, const AbiOp&, const Case&) {
      if (v.verdict == ref::Verdict::fail) failed = true;
    });
    return failed;
  };
  std::vector<bool> failed_as_specified;
  for (const Check& check : checks) failed_as_specified.push_back(fails(check, nullptr));
  // A convention explains the clause when every check that failed as specified is one it
  // applies to and passes under it, and every other check it applies to still passes: it must
  // account for the failure and contradict nothing. (The EXP-2 round trip is convention-free.)
  for (const Convention& convention : conventions()) {
    bool explains = true, covers = false;
    for (std::size_t i = 0; i < checks.size() && explains; ++i) {
      const Check& check = checks[i];
      const bool applies = !check.log_exp_round_trip && convention.applies(*find_abi_op(check.op));
      if (!applies) {
        explains = !failed_as_specified[i];
        continue;
      }
      if (fails(check, &convention)) explains = false;
      else covers = covers || failed_as_specified[i];
    }
    if (explains && covers) found.push_back(convention.id);
  }
  return found;
}

}  // namespace rotorcert::engine
