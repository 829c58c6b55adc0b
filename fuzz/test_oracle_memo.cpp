// The fuzz oracle's memo (fuzz/README.md, "The memo") keeps, per element, the results already
// judged not to be a finding, keyed by their bits. These tests show that it cannot hide one: a
// table whose result changes from one call to the next, or with the element's place in the
// batch, is judged again and its wrong result is found. The table is a correct built-in one
// (rotor_m2, binary64) whose compose writes a wrong w (off by 1/4: far beyond COMPOSE-1's bars)
// whenever the test asks it to.
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

/// rotor_m2 (binary64) but for compose: the same claims, so the oracle checks it on compose.
const rc_impl& flaky_table() {
  static const rc_ops_f64 ops = [] {
    rc_ops_f64 o = *base().f64;
    o.compose = flaky_compose;
    return o;
  }();
  static const rc_impl table = [] {
    rc_impl t = base();
    t.f64 = &ops;
    return t;
  }();
  return table;
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
    found.emplace_back(f.table == &flaky_table() ? "flaky" : f.table->name, f.element);
  });
  EXPECT_EQ(run, static_cast<int>(tables.size())) << "every table is eligible on compose";
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
