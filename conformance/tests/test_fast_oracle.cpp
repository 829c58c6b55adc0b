// The two-level oracle's fast level (engine/fast_oracle.hpp; fuzz/README.md, "The fast oracle"): on every case the
// suite generates for every clause (random, edge and worked-example inputs, both formats), the
// exact 256-bit reference lies within every bound of the fast reference, the statuses agree, and
// every verdict the fuzz oracle takes from the fast level (surely PASS, surely not FAIL, surely
// not PASS) is the MPFR judge's. A fast level with a too-small bound or a wrong term is caught.
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include <rotorcert/engine/declarations.hpp>
#include <rotorcert/engine/fast_oracle.hpp>
#include <rotorcert/reference/bounded_from_matrix.hpp>
#include <rotorcert/testing/clause.hpp>

namespace {

using namespace rotorcert;
using engine::Real;

const spec::Spec& the_spec() {
  static const spec::Spec s = spec::load_spec(spec::resolve_spec_dir());
  return s;
}

struct Tally {
  std::size_t cases = 0, decided = 0, bound_violations = 0, status_mismatches = 0;
  std::size_t judged = 0, fast_pass = 0, fast_not_pass = 0, verdict_mismatches = 0;
  std::string first_problem;
  void problem(const std::string& what) {
    if (first_problem.empty()) first_problem = what;
  }
};

/// An observation near `answer`: each value rounded to the format, the first component then
/// moved k eps (of its size, or of 1) and rounded again.
engine::Observed observation_near(const engine::Values& answer, ref::Format f, int k) {
  engine::Observed o;
  o.status = RC_OK;
  o.outputs = answer;
  for (auto& arr : o.outputs)
    for (Real& x : arr) x = engine::round_to(f, x);
  Real& x = o.outputs[0][0];
  x = engine::round_to(f, x + Real(k) * ref::format_epsilon<Real>(f) * (abs(x) + Real(1)));
  return o;
}

/// Runs the fast level against MPFR on the suite's cases; per op.
std::map<std::string, Tally> compare(int cases_per_family, bool judge) {
  std::map<std::string, Tally> by_op;
  engine::CaseOptions options;
  options.cases_per_family = cases_per_family;
  for (const spec::Clause& clause : the_spec().clauses) {
    if (clause.level == "Meta") continue;
    for (const ref::Format f : {ref::Format::binary32, ref::Format::binary64}) {
      const auto checks =
          engine::checks_for_clause(the_spec(), clause.id, f, options, [](const std::string&) { return true; });
      for (const engine::Check& check : checks) {
        if (check.log_exp_round_trip || !engine::has_fast_reference(check.op)) continue;
        const engine::AbiOp& op = engine::judged_op(check.clause, check.op);
        const spec::ToleranceClass& tc =
            the_spec().lookup(check.tolerance.empty() ? engine::tolerance_for(the_spec(), check.clause, check.op)
                                                      : check.tolerance);
        Tally& t = by_op[check.op];
        for (const engine::Case& c : check.cases) {
          ++t.cases;
          const engine::ReferenceResult want = op.reference(c.inputs, c.k);
          const auto fast = engine::fast_reference(op, c.inputs, c.k);
          if (!fast) continue;
          ++t.decided;
          const std::string where = clause.id + " " + check.op + " [" + c.label + "] " +
                                    engine::describe_inputs(op, c, f);
          if (fast->status != want.status) {
            ++t.status_mismatches;
            t.problem("status differs: " + where);
            continue;
          }
          if (want.status != ref::Status::ok) continue;
          for (std::size_t a = 0; a < want.outputs.size(); ++a)
            for (std::size_t i = 0; i < want.outputs[a].size(); ++i) {
              const ref::Bounded& y = fast->outputs[a][i];
              const Real off = abs(want.outputs[a][i] - Real(y.value()));
              if (!(off <= Real(y.bound()))) {
                ++t.bound_violations;
                t.problem("exact value off by " + off.toString("%.3Rg") + " > bound " +
                          Real(y.bound()).toString("%.3Rg") + ": " + where);
              }
            }
          if (!judge) continue;
          const auto fc = engine::fast_case(op, tc, c, f);
          // Observations around the correctly rounded reference: 0, 3, 40 and 2000 eps off in
          // one component, on both sides of the bars.
          for (const int k : {0, 3, 40, 2000}) {
            const engine::Observed o = observation_near(want.outputs, f, k);
            ++t.judged;
            const auto fv = fc ? engine::fast_verdicts(op, *fc, o, *fast) : std::nullopt;
            if (!fv) continue;
            const ref::Verdict v = engine::judge_case_against(op, tc, c, o, f, want, false).verdict;
            // What the oracle takes from the fast level: surely PASS, surely not FAIL, and
            // surely not PASS where no acceptable convention applies.
            const bool wrong = (fv->worst == ref::Verdict::pass && v != ref::Verdict::pass) ||
                               (fv->worst != ref::Verdict::fail && v == ref::Verdict::fail) ||
                               (fv->best != ref::Verdict::pass && !engine::may_be_acceptable(op, c, f) &&
                                v == ref::Verdict::pass);
            t.fast_pass += fv->worst == ref::Verdict::pass ? 1 : 0;
            t.fast_not_pass += fv->best != ref::Verdict::pass ? 1 : 0;
            if (wrong) {
              ++t.verdict_mismatches;
              t.problem("fast verdicts " + std::to_string(static_cast<int>(fv->best)) + ".." +
                        std::to_string(static_cast<int>(fv->worst)) + ", MPFR " + std::to_string(static_cast<int>(v)) +
                        " at " + std::to_string(k) + " eps off: " + where);
            }
          }
        }
      }
    }
  }
  return by_op;
}

TEST(FastOracle, BoundsHoldAndPassesAgreeWithMpfrOnTheSuitesCases) {
  RC_CLAUSE("NUM-2");
  const auto by_op = compare(32, true);
  ASSERT_FALSE(by_op.empty());
  for (const auto& [op, t] : by_op) {
    EXPECT_EQ(t.bound_violations, 0u) << op << ": " << t.first_problem;
    EXPECT_EQ(t.status_mismatches, 0u) << op << ": " << t.first_problem;
    EXPECT_EQ(t.verdict_mismatches, 0u) << op << ": " << t.first_problem;
    // A fast level that declines everything would agree trivially: most cases must be decided.
    EXPECT_GE(t.decided * 2, t.cases) << op << ": the fast level decided " << t.decided << " of " << t.cases;
    std::printf("%-28s cases %5zu  fast-decided %5zu  observations %5zu  fast PASS %5zu  fast not PASS %5zu\n",
                op.c_str(), t.cases, t.decided, t.judged, t.fast_pass, t.fast_not_pass);
  }
}

TEST(FastOracle, ATooSmallBoundIsCaught) {
  RC_CLAUSE("NUM-2");
  engine::set_fast_oracle_mutation(engine::FastOracleMutation::bound_too_small);
  const auto by_op = compare(2, false);
  engine::set_fast_oracle_mutation(engine::FastOracleMutation::none);
  std::size_t violations = 0;
  for (const auto& [op, t] : by_op) violations += t.bound_violations;
  EXPECT_GT(violations, 0u);
}

TEST(FastOracle, AWrongTermIsCaught) {
  RC_CLAUSE("NUM-2");
  engine::set_fast_oracle_mutation(engine::FastOracleMutation::wrong_term);
  const auto by_op = compare(2, false);
  engine::set_fast_oracle_mutation(engine::FastOracleMutation::none);
  std::size_t caught = 0;
  for (const auto& [op, t] : by_op) caught += t.bound_violations > 0 ? 1 : 0;
  EXPECT_EQ(caught, by_op.size()) << "every op's wrong term must be caught";
}

/// EXP-2 (exp(log q) = q through the implementation) at the fast level against judge_round_trip:
/// exp's output as q rounded to the format and moved by 0 .. 2000 eps in one component, on both
/// sides of the bars. Returns the number of disagreements (surely PASS or surely not FAIL where
/// MPFR says otherwise) and counts the observations the fast level decided.
std::size_t round_trip_disagreements(std::size_t& decided, std::string& first) {
  std::size_t wrong = 0;
  engine::CaseOptions options;
  options.cases_per_family = 32;
  const engine::AbiOp& log_op = *engine::find_abi_op("log");
  for (const ref::Format f : {ref::Format::binary32, ref::Format::binary64}) {
    const auto checks = engine::checks_for_clause(the_spec(), "EXP-2", f, options, [](const std::string&) { return true; });
    for (const engine::Check& check : checks) {
      if (!check.log_exp_round_trip) continue;
      const spec::ToleranceClass& tc = the_spec().lookup(engine::tolerance_for(the_spec(), "EXP-2", "log"));
      for (const engine::Case& c : check.cases) {
        const auto fc = engine::fast_case(log_op, tc, c, f);
        if (!fc) continue;
        engine::Observed log_got;  // only its status and call matter to the round trip's judge
        log_got.status = RC_OK;
        const Real eps = ref::format_epsilon<Real>(f);
        for (const int k : {0, 3, 10, 20, 40, 200, 400, 2000}) {
          engine::Observed exp_got;
          exp_got.status = RC_OK;
          exp_got.outputs = {c.inputs.at(0)};
          for (Real& x : exp_got.outputs[0]) x = engine::round_to(f, x);
          Real& x = exp_got.outputs[0][3];
          x = engine::round_to(f, x + Real(k) * eps * (abs(x) + Real(1)));
          const auto fv = engine::fast_round_trip_verdicts(*fc, c, log_got, exp_got);
          if (!fv) continue;
          ++decided;
          const ref::Verdict v = engine::judge_round_trip(tc, c, log_got, exp_got, f).verdict;
          if ((fv->worst == ref::Verdict::pass && v != ref::Verdict::pass) ||
              (fv->worst != ref::Verdict::fail && v == ref::Verdict::fail)) {
            ++wrong;
            if (first.empty())
              first = "EXP-2 [" + c.label + "] " + std::to_string(k) + " eps off: fast worst " +
                      std::to_string(static_cast<int>(fv->worst)) + ", MPFR " + std::to_string(static_cast<int>(v));
          }
        }
      }
    }
  }
  return wrong;
}

TEST(FastOracle, RoundTripVerdictsAgreeWithMpfr) {
  RC_CLAUSE("EXP-2");
  std::size_t decided = 0;
  std::string first;
  EXPECT_EQ(round_trip_disagreements(decided, first), 0u) << first;
  EXPECT_GT(decided, 0u) << "the fast level decided no round trip";
  std::printf("EXP-2 round trip: %zu observations decided at the fast level\n", decided);
}

TEST(FastOracle, AWrongRoundTripDistanceIsCaught) {
  RC_CLAUSE("EXP-2");
  engine::set_fast_oracle_mutation(engine::FastOracleMutation::wrong_term);  // halves the distance
  std::size_t decided = 0;
  std::string first;
  const std::size_t wrong = round_trip_disagreements(decided, first);
  engine::set_fast_oracle_mutation(engine::FastOracleMutation::none);
  EXPECT_GT(wrong, 0u);
}

/// Every fast acceptable answer (engine::fast_acceptable_answers) on the suite's cases
/// (`cases_per_family` per family) of the ops with a fast reference, where `take(op, c, f)` holds
/// and the reference is OK, formed as the fuzz oracle forms it: against the fast reference, or
/// MPFR's where that is undecided. visit(op, tc, c, f, want, answer, convention, where), with the
/// answer's AcceptableConvention (nullptr if none has its id).
template <class Take, class Visit>
void for_each_acceptable_answer(int cases_per_family, Take take, Visit visit) {
  engine::CaseOptions options;
  options.cases_per_family = cases_per_family;
  for (const spec::Clause& clause : the_spec().clauses) {
    if (clause.level == "Meta") continue;
    for (const ref::Format f : {ref::Format::binary32, ref::Format::binary64}) {
      for (const engine::Check& check :
           engine::checks_for_clause(the_spec(), clause.id, f, options, [](const std::string&) { return true; })) {
        if (check.log_exp_round_trip || !engine::has_fast_reference(check.op)) continue;
        const engine::AbiOp& op = engine::judged_op(check.clause, check.op);
        const spec::ToleranceClass& tc =
            the_spec().lookup(check.tolerance.empty() ? engine::tolerance_for(the_spec(), check.clause, check.op)
                                                      : check.tolerance);
        for (const engine::Case& c : check.cases) {
          if (!take(op, c, f)) continue;
          const engine::ReferenceResult want = op.reference(c.inputs, c.k);
          if (want.status != ref::Status::ok) continue;
          const auto fast_want = engine::fast_reference(op, c.inputs, c.k).value_or(engine::fast_reference_from(op, want));
          const engine::BoundedValues in = engine::bounded_values(c.inputs);  // outlives the answers
          const auto answers = engine::fast_acceptable_answers(op, c, in, fast_want, f);
          if (!answers) continue;
          for (const engine::AcceptableAnswer& a : *answers) {
            const engine::AcceptableConvention* convention = nullptr;
            for (const engine::AcceptableConvention& x : engine::acceptable_conventions())
              if (x.id == a.convention && x.applies(op)) convention = &x;
            const std::string where = a.convention + " " + clause.id + " " + check.op + " [" + c.label + "] " +
                                      engine::describe_inputs(op, c, f);
            visit(op, tc, c, f, want, a, convention, where);
          }
        }
      }
    }
  }
}

/// ACC-1's conventions at the fast level (engine::fast_acceptable_answers): on the suite's cases
/// where a hemisphere tie is at stake, an observation's verdicts against each fast answer are the
/// convention's own (its MPFR error, `AcceptableConvention::error`): surely PASS where it PASSes,
/// surely not PASS where it does not. Observations: the answer rounded, then 3, 40 and 2000 eps off.
std::size_t acceptable_answer_disagreements(std::size_t& decided, std::string& first) {
  std::size_t wrong = 0;
  for_each_acceptable_answer(
      32, [](const engine::AbiOp& op, const engine::Case& c, ref::Format f) { return engine::hemisphere_tie_at_stake(op, c, f); },
      [&](const engine::AbiOp& op, const spec::ToleranceClass& tc, const engine::Case& c, ref::Format f,
          const engine::ReferenceResult& want, const engine::AcceptableAnswer& a,
          const engine::AcceptableConvention* convention, const std::string& where) {
        if (!a.answer) return;  // a convention's own error: convention_error_violations
        if (convention == nullptr) {
          ++wrong;
          if (first.empty()) first = "an answer of no convention: " + where;
          return;
        }
        const auto fc = engine::fast_case(op, tc, c, f);
        if (!fc) return;
        const Real eps = ref::format_epsilon<Real>(f);
        for (const int k : {0, 3, 40, 2000}) {
          const engine::Observed o = observation_near(engine::fast_values(*a.answer), f, k);
          const auto fv = engine::fast_verdicts(op, *fc, o, *a.answer);
          if (!fv) continue;
          ++decided;
          const std::optional<Real> error = convention->error(op, c, o.outputs, want.outputs, f);
          const ref::Verdict v = error ? ref::clause::TOL_1_verdict((*error / eps).toDouble(), fc->bars) : ref::Verdict::fail;
          if ((fv->worst == ref::Verdict::pass && v != ref::Verdict::pass) ||
              (fv->best != ref::Verdict::pass && v == ref::Verdict::pass)) {
            ++wrong;
            if (first.empty())
              first = "fast " + std::to_string(static_cast<int>(fv->best)) + ".." + std::to_string(static_cast<int>(fv->worst)) +
                      ", MPFR " + std::to_string(static_cast<int>(v)) + " at " + std::to_string(k) + " eps off: " + where;
          }
        }
      });
  return wrong;
}

TEST(FastOracle, AcceptableAnswersAgreeWithTheirConventions) {
  RC_CLAUSE("ACC-1");
  RC_CLAUSE("EDGE-3");
  std::size_t decided = 0;
  std::string first;
  EXPECT_EQ(acceptable_answer_disagreements(decided, first), 0u) << first;
  EXPECT_GT(decided, 0u) << "no observation at a hemisphere tie was decided at the fast level";
  std::printf("ACC-1 at the fast level: %zu observations decided against a convention's answer\n", decided);
}

/// ACC-1's conventions whose fast form is their own error (AcceptableConvention::fast_error): on
/// the suite's cases of every op with a fast reference, for observations around the spec's answer
/// (rounded to the format; 3, 40 and 2000 eps off in one component; each also negated, the other
/// sign of a quaternion), the fast error says nothing exactly where the MPFR error does, and its
/// interval holds the MPFR error (within 2^-200 of its size: MPFR's own rounding).
std::size_t convention_error_violations(std::size_t& decided, std::set<std::string>& conventions, std::string& first) {
  std::size_t wrong = 0;
  for_each_acceptable_answer(
      16, [](const engine::AbiOp&, const engine::Case&, ref::Format) { return true; },
      [&](const engine::AbiOp& op, const spec::ToleranceClass&, const engine::Case& c, ref::Format f,
          const engine::ReferenceResult& want, const engine::AcceptableAnswer& a,
          const engine::AcceptableConvention* convention, const std::string& where) {
        if (a.answer || convention == nullptr) return;  // hemisphere_tie: acceptable_answer_disagreements
        for (const int sign : {1, -1})
          for (const int k : {0, 3, 40, 2000}) {
            engine::Observed o = observation_near(want.outputs, f, k);
            if (sign < 0)
              for (Real& y : o.outputs[0]) y = -y;
            engine::BoundedValues got;
            bool finite = true;
            for (const auto& arr : o.outputs) {
              got.emplace_back();
              for (const Real& y : arr) {
                finite = finite && mpfr::isfinite(y);
                got.back().push_back(ref::Bounded(y.toLDouble(), 0));
              }
            }
            if (!finite) continue;
            const ref::BoundedScope scope;
            const std::optional<ref::Bounded> fe = a.error(got);
            if (!scope.decided()) continue;
            const std::optional<Real> me = convention->error(op, c, o.outputs, want.outputs, f);
            auto report = [&](const std::string& what) {
              ++wrong;
              if (first.empty()) first = what + " (sign " + std::to_string(sign) + ", " + std::to_string(k) + " eps off): " + where;
            };
            if (fe.has_value() != me.has_value()) {
              report(std::string("the fast error ") + (fe ? "says something, MPFR's nothing" : "says nothing, MPFR's something"));
              continue;
            }
            if (!fe || !std::isfinite(fe->value()) || mpfr::isnan(*me)) continue;
            ++decided;
            conventions.insert(a.convention + " (" + op.name + ")");
            const Real off = abs(*me - Real(fe->value()));
            if (!(off <= Real(fe->bound()) + ldexp(abs(*me), -200)))
              report("MPFR error " + me->toString("%.6Rg") + " outside the fast " + Real(fe->value()).toString("%.6Rg") +
                     " +- " + Real(fe->bound()).toString("%.3Rg"));
          }
      });
  return wrong;
}

TEST(FastOracle, ConventionErrorsHoldTheirMpfrValues) {
  RC_CLAUSE("ACC-1");
  RC_CLAUSE("AXANG-1");
  RC_CLAUSE("AXANG-4");
  RC_CLAUSE("SQRT-1");
  RC_CLAUSE("LOG-2");
  RC_CLAUSE("DQ-8");
  std::size_t decided = 0;
  std::set<std::string> conventions;
  std::string first;
  EXPECT_EQ(convention_error_violations(decided, conventions, first), 0u) << first;
  std::string seen;
  for (const std::string& x : conventions) seen += (seen.empty() ? "" : ", ") + x;
  std::printf("ACC-1 errors at the fast level: %zu observations decided; conventions: %s\n", decided, seen.c_str());
  // Every convention with a fast error is exercised (its op's suite cases reach it).
  for (const char* expected : {"angle_range (to_axis_angle)", "angle_range (to_axis)", "sign (sqrt)", "shorter_arc (log)",
                               "shorter_arc (dq_log)", "sign (from_matrix)", "algebraic_root (sqrt)"})
    EXPECT_TRUE(conventions.count(expected)) << expected << " was never decided at the fast level";
}

/// A scaling by an exact power of two is exact in Bounded arithmetic while the result stays
/// normal: halving an exact angle adds no rounding, so the sine and cosine of a huge exact angle's
/// half keep their libm bound. Without it AXIS-1 at angle 2^1023 (a fuzzed input) carried a bound
/// of 2^959 into the rotor and its point's weight interval held 0: undecided.
TEST(FastOracle, ScalingByAPowerOfTwoIsExactWhileNormal) {
  RC_CLAUSE("AXIS-1");
  using ref::Bounded;
  const Bounded half = Bounded(0x1p1023) / Bounded(2.0);
  EXPECT_TRUE(half.exact());
  EXPECT_EQ(half.value(), 0x1p1022L);
  EXPECT_TRUE((Bounded(3.0) * Bounded(0.5)).exact());
  const Bounded scaled = Bounded(1.5L, 1e-20L) * Bounded(4.0);
  EXPECT_EQ(scaled.value(), 6.0L);
  EXPECT_EQ(scaled.bound(), 4e-20L + Bounded::kTiny) << "the bound scales exactly, with no rounding of its own";
  EXPECT_FALSE((Bounded(std::numeric_limits<long double>::denorm_min() * 3, 0) / Bounded(2.0)).exact())
      << "below the normal range a halving may lose a bit";
  EXPECT_FALSE((Bounded(3.0) * Bounded(3.0)).exact()) << "3 is no power of two: the product is rounded as any";

  const engine::AbiOp& op = *engine::find_abi_op("rotate_about_axis");
  const Real top(0x1p1023), below_top(0x1.fffffffffffffp+1023);
  const engine::Values in{{top, -below_top, Real(0x1p1022)}, {top, -below_top, Real(0x1p1022)}, {top},
                          {-below_top, Real(0x1p1022), top}};
  const auto fast = engine::fast_reference(op, in, 0);
  ASSERT_TRUE(fast.has_value()) << "rotate_about_axis at angle 2^1023 is undecided at the fast level";
  const engine::ReferenceResult want = op.reference(in, 0);
  ASSERT_EQ(fast->status, want.status);
  for (std::size_t i = 0; i < 3; ++i)
    EXPECT_LE(abs(want.outputs[0][i] - Real(fast->outputs[0][i].value())), Real(fast->outputs[0][i].bound())) << i;
}

/// MAT-2's eigenvector at the fast level is proved, not trusted (reference/bounded_from_matrix.hpp):
/// from an approximation 1e-6 off, the bounds still hold the exact eigenvector and are that wide,
/// not wider than needed; from an eigenvector of another eigenvalue there is no proof.
TEST(FastOracle, FromMatrixEigenvectorIsProvedFromAPoorStartAndRefusedFromAWrongOne) {
  RC_CLAUSE("MAT-2");
  using ref::Bounded;
  // A rotation matrix with every entry nonzero, rounded to binary64, exact as Bounded.
  const ref::Quaternion<Real> rotation = ref::normalized(ref::Quaternion<Real>{Real(0.8), Real(-0.3), Real(0.4), Real(0.2)});
  const auto matrix = ref::clause::MAT_1_to_matrix(rotation).value;
  ref::Mat3<Real> m_real;
  ref::Mat3<Bounded> m_fast;
  for (int i = 0; i < 9; ++i) {
    m_real[i] = Real(matrix[i].toDouble());
    m_fast[i] = Bounded(matrix[i].toDouble());
  }
  const ref::Quaternion<Real> exact = ref::clause::MAT_2_from_matrix(m_real).value;  // w > 0
  const std::array<Real, 4> exact_k_order{exact.x, exact.y, exact.z, exact.w};
  const auto k = ref::clause::detail::from_matrix_k(m_fast);
  ASSERT_TRUE(k.has_value());

  std::array<long double, 4> start;
  for (int i = 0; i < 4; ++i) start[i] = exact_k_order[i].toLDouble() + (i % 2 ? 1e-6L : -1e-6L);
  const auto proved = ref::clause::detail::verified_top_eigenvector(*k, start);
  ASSERT_TRUE(proved.has_value()) << "a start 1e-6 off the top eigenvector must be provable";
  for (int i = 0; i < 4; ++i) {
    const Real off = abs(exact_k_order[i] - Real((*proved)[i].value()));
    EXPECT_LE(off, Real((*proved)[i].bound())) << "component " << i;
    EXPECT_GE((*proved)[i].bound(), 1e-7L) << "component " << i << ": the start's own error must be in the bound";
    EXPECT_LE((*proved)[i].bound(), 1e-4L) << "component " << i << ": a bound too wide to judge with";
  }

  // A vector orthogonal to the top eigenvector: an eigenvector of the triple eigenvalue -1/3.
  const std::array<long double, 4> other{exact.w.toLDouble(), -exact.z.toLDouble(), exact.y.toLDouble(),
                                         -exact.x.toLDouble()};
  EXPECT_FALSE(ref::clause::detail::verified_top_eigenvector(*k, other).has_value());
}

}  // namespace
