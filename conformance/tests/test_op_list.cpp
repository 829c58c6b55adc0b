// The op list (impls/include/rotorcert/abi_op_list.h) and what is derived from it or described
// beside it agree: the engine's AbiOp table (entry i is OpId i, the same arrays under the same
// names), the spec and the engine's cases (each clause a row names exists and is judged by that
// op; the first is the op's main clause, at the row's level), the
// table structs (static_asserts in op_id.hpp) and a call through with_slot / invoke_slot reaching
// the slot the row names with its arrays in order. The vectors packages' tables are checked
// against `rotorcert list --ops --json` by conformance_abi_tables_match.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <type_traits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <rotorcert/engine/abi_op.hpp>
#include <rotorcert/engine/cases.hpp>
#include <rotorcert/spec/spec.hpp>

namespace {

using namespace rotorcert;

/// The array names of a row's parameter list, "(const S* a, const S* b)" -> {"a", "b"}.
std::vector<std::string> names(std::string_view params) {
  std::vector<std::string> r;
  std::string cur;
  for (char c : params) {
    if (std::isalnum(static_cast<unsigned char>(c)) || c == '_') cur += c;
    else if (c == ',' || c == ')') r.push_back(cur), cur.clear();
    else cur.clear();
  }
  return r;
}

std::vector<std::string> names(const std::vector<engine::Array>& arrays) {
  std::vector<std::string> r;
  for (const engine::Array& a : arrays) r.push_back(a.name);
  return r;
}

TEST(OpList, EngineTableHasOneEntryPerRowWithTheRowsArrays) {
  const auto& ops = engine::abi_ops();
  ASSERT_EQ(ops.size(), kOpCount);
  for (std::size_t i = 0; i < kOpCount; ++i) {
    const OpInfo& row = kOps[i];
    SCOPED_TRACE(std::string(row.name));
    EXPECT_EQ(ops[i].name, row.name);
    EXPECT_EQ(ops[i].id, static_cast<OpId>(i));
    EXPECT_EQ(names(ops[i].inputs), names(row.input_params));
    EXPECT_EQ(names(ops[i].outputs), names(row.output_params));
    EXPECT_EQ(ops[i].nway, row.kind != OpKind::ELEM);
    EXPECT_EQ(op_id(row.name), static_cast<OpId>(i));
  }
  EXPECT_FALSE(op_id("not_an_op").has_value());
}

TEST(OpList, EveryClauseARowNamesJudgesThatOpAndTheFirstIsItsMainClauseAtItsLevel) {
  const spec::Spec s = spec::load_spec(spec::resolve_spec_dir());
  for (const OpInfo& row : kOps) {
    const std::string op(row.name);
    std::istringstream ids{std::string(row.clauses)};
    std::vector<std::string> clauses;
    for (std::string id; ids >> id;) clauses.push_back(id);
    ASSERT_FALSE(clauses.empty()) << op;
    for (const std::string& id : clauses) {
      SCOPED_TRACE(op + " " + id);
      ASSERT_NE(s.find_clause(id), nullptr) << "the op list names a clause spec/clauses.json lacks";
      const auto judging = engine::ops_for_clause(id);
      EXPECT_NE(std::find(judging.begin(), judging.end(), op), judging.end()) << "the engine does not judge it by this op";
    }
    EXPECT_EQ(engine::main_clause_of(op), clauses.front());
    std::string level = s.find_clause(clauses.front())->level;
    for (char& c : level) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    EXPECT_EQ(level, row.level) << op;
  }
}

// A table whose every slot records which slot ran and what it got, filled from the list: a call
// through with_slot and invoke_slot must reach exactly the row's slot and hand it n, k (n-way
// kinds), the input arrays, the output arrays and the status, in the row's order.
struct Recorded {
  OpId slot = OpId::count_;
  std::vector<std::uintptr_t> args;
};
Recorded recorded;

template <class P>
std::uintptr_t as_word(P p) {
  if constexpr (std::is_pointer_v<P>) return reinterpret_cast<std::uintptr_t>(p);
  else return static_cast<std::uintptr_t>(p);
}

template <class Fn, OpId Id> struct Recorder;
template <class... P, OpId Id>
struct Recorder<int (*)(std::size_t, P...), Id> {
  static int run(std::size_t n, P... p) {
    recorded = {Id, {n, as_word(p)...}};
    return 7;
  }
};

TEST(OpList, InvokeSlotReachesTheRowsSlotWithItsArraysInOrder) {
  rc_ops_f64 v1{};
  rc_ops3_f64 v3{};
  rc_ops4_f64 v4{};
#define RC_RECORDING_SLOT(name, since, ...) v##since.name = &Recorder<decltype(v##since.name), OpId::name>::run;
  RC_ABI_OPS(RC_RECORDING_SLOT, double)
#undef RC_RECORDING_SLOT
  rc_impl table{};
  table.abi_version = RC_ABI_VERSION;
  table.scalar = RC_SCALAR_FLOAT64;
  table.f64 = &v1;
  table.f64_v3 = &v3;
  table.f64_v4 = &v4;

  double arrays[8] = {};
  const double* in[4] = {arrays + 0, arrays + 1, arrays + 2, arrays + 3};
  double* out[2] = {arrays + 4, arrays + 5};
  std::uint8_t status[1] = {};
  const SlotArgs<double> a{3, 5, in, out, status};
  for (const OpId id : all_ops()) {
    const OpInfo& row = op_info(id);
    SCOPED_TRACE(std::string(row.name));
    recorded = {};
    ASSERT_TRUE(has_op(table, id));
    EXPECT_EQ(with_slot<double>(table, id, [&](auto fn) { return fn == nullptr ? -1 : invoke_slot(fn, a); }), 7);
    EXPECT_EQ(recorded.slot, id);
    std::vector<std::uintptr_t> want = {3};
    if (row.kind != OpKind::ELEM) want.push_back(5);
    for (int i = 0; i < row.inputs; ++i) want.push_back(reinterpret_cast<std::uintptr_t>(in[i]));
    for (int i = 0; i < row.outputs; ++i) want.push_back(reinterpret_cast<std::uintptr_t>(out[i]));
    want.push_back(reinterpret_cast<std::uintptr_t>(status));
    EXPECT_EQ(recorded.args, want);
  }

  // An older table's memory ends before the structs added after its version: never read.
  table.abi_version = 3;
  EXPECT_TRUE(has_op(table, OpId::sqrt));
  EXPECT_FALSE(has_op(table, OpId::dq_log));
  table.abi_version = 1;
  EXPECT_TRUE(has_op(table, OpId::skin_dual_quaternion));
  EXPECT_FALSE(has_op(table, OpId::to_angle));
  // The other scalar type's slots are not this table's.
  EXPECT_FALSE(with_slot<float>(table, OpId::normalize, [](auto fn) { return fn != nullptr; }));
}

}  // namespace
