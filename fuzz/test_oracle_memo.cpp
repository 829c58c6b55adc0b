// The fuzz oracle's memo (fuzz/README.md, "The memo") keeps, per element, the results already
// judged not to be a finding, keyed by their bits. These tests show that it cannot hide one: a
// table whose result changes from one call to the next, or with the element's place in the
// batch, is judged again and its wrong result is found. The table is a correct built-in one
// (rotor_m2, binary64) whose compose writes a wrong w (off by 1/4: far beyond COMPOSE-1's bars)
// whenever the test asks it to.
//
// The oracle decides how much of an element is judged (its perturbations) only when a result is
// not surely within the bar (fuzz/README.md, "The fast oracle"). FuzzOracleJudgement shows that
// the decision is still taken where it matters: a wrong slerp at an ill-conditioned t is judged on
// its status alone, at an ordinary t on its numbers.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include <rotorcert/registry.hpp>
#include <rotorcert/testing/clause.hpp>

#include "decode.hpp"
#include "families.hpp"
#include "oracle.hpp"

namespace {

using rotorcert::engine::Case;
using rotorcert::fuzz::Decoded;
using rotorcert::fuzz::Finding;
using rotorcert::ref::Real;

/// Which elements the flaky compose gets wrong on its next calls (none: it is rotor_m2's own).
std::vector<bool> g_wrong_elements;

const rc_impl& base() {
  const rc_impl* t = rotorcert::impl::find_builtin("rotor_m2", RC_SCALAR_FLOAT64);
  if (t == nullptr) throw std::runtime_error("rotor_m2 (binary64) is not built in");
  return *t;
}

int flaky_compose(std::size_t n, const double* a, const double* b, double* out_q, std::uint8_t* status) {
  const int rc = base().f64->compose(n, a, b, out_q, status);
  for (std::size_t e = 0; e < n && e < g_wrong_elements.size(); ++e)
    if (g_wrong_elements[e]) out_q[4 * e] += 0.25;
  return rc;
}

/// rotor_m2 (binary64) with one op replaced by `Fn`: the same claims, so the oracle checks it on
/// that op.
template <auto Slot, auto Fn>
const rc_impl& rotor_m2_with() {
  static const rc_ops_f64 ops = [] {
    rc_ops_f64 o = *base().f64;
    o.*Slot = Fn;
    return o;
  }();
  static const rc_impl table = [] {
    rc_impl t = base();
    t.f64 = &ops;
    return t;
  }();
  return table;
}

const rc_impl& flaky_table() { return rotor_m2_with<&rc_ops_f64::compose, flaky_compose>(); }

/// What the flaky slerp does to its results: nothing, add 1/4 to every w, or that and answer
/// DOMAIN_ERROR.
enum class SlerpFault { none, wrong_w, wrong_w_and_domain_error };
SlerpFault g_slerp_fault = SlerpFault::none;

int flaky_slerp(std::size_t n, const double* a, const double* b, const double* t, double* out_q, std::uint8_t* status) {
  const int rc = base().f64->slerp(n, a, b, t, out_q, status);
  for (std::size_t e = 0; e < n && g_slerp_fault != SlerpFault::none; ++e) {
    out_q[4 * e + 3] += 0.25;
    if (g_slerp_fault == SlerpFault::wrong_w_and_domain_error) status[e] = RC_DOMAIN_ERROR;
  }
  return rc;
}

const rc_impl& flaky_slerp_table() { return rotor_m2_with<&rc_ops_f64::slerp, flaky_slerp>(); }

/// One slerp(a, b, t) in binary64, a and b ordinary rotations.
Decoded slerp_batch(double t) {
  Case c;
  c.k = 0;
  c.inputs = {{Real(0.25), Real(-0.5), Real(0.75), Real(0.5)}, {Real(0.5), Real(0.5), Real(-0.5), Real(0.5)}, {Real(t)}};
  const auto& ops = rotorcert::fuzz::families().at("interpolation");
  const std::vector<std::uint8_t> bytes =
      rotorcert::fuzz::encode(ops, "slerp", rotorcert::ref::Format::binary64, std::vector<Case>(1, c));
  Decoded d;
  if (!rotorcert::fuzz::decode(bytes.data(), bytes.size(), ops, d)) throw std::runtime_error("not decoded");
  return d;
}

/// One batch of `n` copies of compose(a, b), a and b ordinary rotations, in binary64.
Decoded compose_batch(std::size_t n) {
  Case c;
  c.k = 0;
  c.inputs = {{Real(0.25), Real(-0.5), Real(0.75), Real(0.5)}, {Real(0.5), Real(0.5), Real(-0.5), Real(0.5)}};
  const auto& ops = rotorcert::fuzz::families().at("compose_apply");
  const std::vector<std::uint8_t> bytes =
      rotorcert::fuzz::encode(ops, "compose", rotorcert::ref::Format::binary64, std::vector<Case>(n, c));
  Decoded d;
  if (!rotorcert::fuzz::decode(bytes.data(), bytes.size(), ops, d)) throw std::runtime_error("not decoded");
  return d;
}

using Found = std::vector<std::pair<std::string, std::size_t>>;

/// The findings of one check() of `d` on `tables`, as (table, element) pairs.
Found findings(const Decoded& d, const std::vector<const rc_impl*>& tables) {
  Found found;
  const int run = rotorcert::fuzz::check(d, tables, [&](const Decoded&, const Finding& f) {
    const bool flaky = f.table == &flaky_table() || f.table == &flaky_slerp_table();
    found.emplace_back(flaky ? "flaky" : f.table->name, f.element);
  });
  EXPECT_EQ(run, static_cast<int>(tables.size())) << "every table is eligible on the op";
  return found;
}

}  // namespace

TEST(FuzzOracleMemo, AResultThatChangesBetweenCallsIsJudgedAgain) {
  RC_CLAUSE("COMPOSE-1");
  rotorcert::fuzz::init();
  const Decoded d = compose_batch(1);
  const rc_impl* flaky = &flaky_table();
  g_wrong_elements = {false};
  EXPECT_EQ(findings(d, {flaky}), Found{}) << "rotor_m2's own compose is right";
  EXPECT_EQ(findings(d, {flaky}), Found{}) << "the same result again, now from the memo";
  g_wrong_elements = {true};
  EXPECT_EQ(findings(d, {flaky}), (Found{{"flaky", 0}})) << "a new result for a remembered element is judged";
  EXPECT_EQ(findings(d, {flaky}), (Found{{"flaky", 0}})) << "a result found wrong is never cleared";
  g_wrong_elements = {false};
  EXPECT_EQ(findings(d, {flaky}), Found{});
}

TEST(FuzzOracleMemo, AResultClearedForOneTableIsJudgedAgainForAnotherThatDiffers) {
  RC_CLAUSE("COMPOSE-1");
  rotorcert::fuzz::init();
  const Decoded d = compose_batch(1);
  const rc_impl* right = &base();
  const rc_impl* flaky = &flaky_table();
  g_wrong_elements = {true};
  // rotor_m2 runs first and clears its result; the flaky table's differs in its bits.
  EXPECT_EQ(findings(d, {right, flaky}), (Found{{"flaky", 0}}));
  EXPECT_EQ(findings(d, {right, flaky}), (Found{{"flaky", 0}}));
  g_wrong_elements = {false};
}

TEST(FuzzOracleMemo, AnElementWrongOnlyAtOnePlaceInTheBatchIsFound) {
  RC_CLAUSE("COMPOSE-1");
  rotorcert::fuzz::init();
  // Three equal elements share one memo entry; the table gets the last one wrong (a SIMD tail).
  const Decoded d = compose_batch(3);
  const rc_impl* flaky = &flaky_table();
  g_wrong_elements = {false, false, true};
  EXPECT_EQ(findings(d, {flaky}), (Found{{"flaky", 2}}));
  g_wrong_elements = {false};
}

TEST(FuzzOracleJudgement, AWrongResultAtAnIllConditionedInputIsJudgedOnItsStatus) {
  RC_CLAUSE("SLERP-1");
  RC_CLAUSE("SLERP-4");
  rotorcert::fuzz::init();
  const rc_impl* flaky = &flaky_slerp_table();
  // t = 2^80: one unit roundoff of the angle moves the exact result by 2^80 u, far beyond the
  // strict bar (SLERP-4), so only the status is judged; t = 0.3 is ordinary.
  const Decoded ill = slerp_batch(0x1p80), ordinary = slerp_batch(0.3);
  g_slerp_fault = SlerpFault::none;
  EXPECT_EQ(findings(ill, {flaky}), Found{}) << "rotor_m2's own slerp";
  EXPECT_EQ(findings(ordinary, {flaky}), Found{}) << "rotor_m2's own slerp";
  g_slerp_fault = SlerpFault::wrong_w;
  EXPECT_EQ(findings(ill, {flaky}), Found{}) << "ill-conditioned: the numbers are not judged, the status is OK";
  EXPECT_EQ(findings(ordinary, {flaky}), (Found{{"flaky", 0}})) << "ordinary: the numbers are judged";
  g_slerp_fault = SlerpFault::wrong_w_and_domain_error;
  EXPECT_EQ(findings(ill, {flaky}), (Found{{"flaky", 0}})) << "ill-conditioned: DOMAIN_ERROR inside the domain";
  g_slerp_fault = SlerpFault::none;
}
