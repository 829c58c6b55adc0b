// The ABI's operations as C++ values, all derived from the one list (abi_op_list.h): an OpId per
// row, its facts (name, version, level, clauses, kind, array counts), the table slot of an OpId,
// and one call that works out a slot's arguments from its function-pointer type. Strings name an
// operation only where data enters or leaves (CLI, JSON, vector files): op_id() and op_name().
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <tuple>
#include <string_view>
#include <type_traits>
#include <utility>

#include <rotorcert/impl_abi.h>

namespace rotorcert {

/// The operations in table order: those of rc_ops (v1), then rc_ops3 (v3), then rc_ops4 (v4).
enum class OpId : std::uint8_t {
#define RC_OP_ENUMERATOR(name, ...) name,
  RC_ABI_OPS(RC_OP_ENUMERATOR, S)
#undef RC_OP_ENUMERATOR
      count_
};
inline constexpr std::size_t kOpCount = static_cast<std::size_t>(OpId::count_);

enum class OpKind {
  ELEM,   // n elements
  BLEND,  // n blends of k influences (influence arrays, then k weights)
  SKIN,   // n vertices of k influences (rotation, translation, weight) and the vertex
};

namespace op_list_detail {
/// Arrays in a parenthesised parameter list as the list spells it, "(const S* a, const S* b)".
constexpr int count_arrays(std::string_view params) {
  int n = 1;
  for (char c : params) n += c == ',';
  return n;
}
}  // namespace op_list_detail

/// One row of abi_op_list.h.
struct OpInfo {
  std::string_view name;
  std::uint32_t since;       // the ABI version whose struct holds the slot
  std::string_view level;    // the level of its main clause, in capitals: "CORE", "EXTENDED"
  std::string_view clauses;  // "MAT-2 MAT-3"
  OpKind kind;
  int inputs, outputs;                          // array counts
  std::string_view input_params, output_params;  // "(const S* q, const S* t)", "(S* out_d)"
};

inline constexpr std::array<OpInfo, kOpCount> kOps = {{
#define RC_OP_INFO(name, since, level, clauses, kind, in, out)                                                    \
  {#name, since, #level, clauses, OpKind::kind, op_list_detail::count_arrays(#in),                 \
   op_list_detail::count_arrays(#out), #in, #out},
    RC_ABI_OPS(RC_OP_INFO, S)
#undef RC_OP_INFO
}};

constexpr const OpInfo& op_info(OpId id) { return kOps[static_cast<std::size_t>(id)]; }
constexpr std::string_view op_name(OpId id) { return op_info(id).name; }
constexpr std::size_t op_index(OpId id) { return static_cast<std::size_t>(id); }

/// The op of that slot name, or nothing.
constexpr std::optional<OpId> op_id(std::string_view name) {
  for (std::size_t i = 0; i < kOpCount; ++i)
    if (kOps[i].name == name) return static_cast<OpId>(i);
  return std::nullopt;
}

/// Every OpId, in table order (for range-for).
constexpr std::array<OpId, kOpCount> all_ops() {
  std::array<OpId, kOpCount> r{};
  for (std::size_t i = 0; i < kOpCount; ++i) r[i] = static_cast<OpId>(i);
  return r;
}

// The structs hold the list's slots and nothing else, in its order: a row missing from the struct
// (or one too many) changes its size, a reordered one its offsets.
namespace op_list_detail {
template <class T>
constexpr std::size_t slots_of() {
  return sizeof(T) / sizeof(void (*)());
}
constexpr std::size_t count_since(std::uint32_t v) {
  std::size_t n = 0;
  for (const OpInfo& o : kOps) n += o.since == v;
  return n;
}
}  // namespace op_list_detail
static_assert(op_list_detail::slots_of<rc_ops_f32>() == op_list_detail::count_since(1));
static_assert(op_list_detail::slots_of<rc_ops3_f64>() == op_list_detail::count_since(3));
static_assert(op_list_detail::slots_of<rc_ops4_f32>() == op_list_detail::count_since(4));
static_assert(op_list_detail::count_since(1) + op_list_detail::count_since(3) + op_list_detail::count_since(4) == kOpCount);

// ---- the slot of an OpId ---------------------------------------------------------------------

/// The struct of scalar S that holds the slots added in ABI version `since` (1, 3 or 4), read from
/// the table if it has that scalar type and is at least that version; else nullptr.
template <class S, std::uint32_t Since>
const auto* ops_struct(const rc_impl& t) {
  constexpr bool f32 = std::is_same_v<S, float>;
  static_assert(f32 || std::is_same_v<S, double>);
  const bool here = t.scalar == (f32 ? RC_SCALAR_FLOAT32 : RC_SCALAR_FLOAT64) && t.abi_version >= Since;
  if constexpr (Since == 1) {
    if constexpr (f32) return here ? t.f32 : nullptr;
    else return here ? t.f64 : nullptr;
  } else if constexpr (Since == 3) {
    if constexpr (f32) return here ? t.f32_v3 : nullptr;
    else return here ? t.f64_v3 : nullptr;
  } else {
    static_assert(Since == 4);
    if constexpr (f32) return here ? t.f32_v4 : nullptr;
    else return here ? t.f64_v4 : nullptr;
  }
}

/// Calls f with op `id`'s function pointer of scalar S in the table (its own pointer type; a null
/// pointer of that type when the table lacks it) and returns what f returns. Reading the slot runs
/// none of the implementation's code.
template <class S, class F>
decltype(auto) with_slot(const rc_impl& t, OpId id, F&& f) {
  switch (id) {
#define RC_OP_SLOT_CASE(name, since, ...)                              \
  case OpId::name: {                                                   \
    const auto* o = ops_struct<S, since>(t);                           \
    return f(o != nullptr ? o->name : decltype(o->name){});            \
  }
    RC_ABI_OPS(RC_OP_SLOT_CASE, S)
#undef RC_OP_SLOT_CASE
    case OpId::count_: break;
  }
  return f(static_cast<int (*)(std::size_t)>(nullptr));
}

/// Whether the table has op `id` (a non-NULL slot of its own scalar type).
inline bool has_op(const rc_impl& t, OpId id) {
  auto present = [](auto fn) { return fn != nullptr; };
  if (t.scalar == RC_SCALAR_FLOAT32) return with_slot<float>(t, id, present);
  if (t.scalar == RC_SCALAR_FLOAT64) return with_slot<double>(t, id, present);
  return false;
}

// ---- calling a slot --------------------------------------------------------------------------

/// One call's arrays in the order of the op's row: input arrays, output arrays (scalar S).
template <class S>
struct SlotArgs {
  std::size_t n = 0, k = 0;
  const S* const* in = nullptr;
  S* const* out = nullptr;
  std::uint8_t* status = nullptr;
};

namespace op_list_detail {
template <std::size_t N>
constexpr std::size_t count_set_before(const std::array<bool, N>& flags, std::size_t end) {
  std::size_t n = 0;
  for (std::size_t j = 0; j < end; ++j) n += flags[j];
  return n;
}
/// Which argument parameter I of (P...) gets: inputs (const S*) and outputs (S*) in turn, k for
/// the size_t of n-way kinds, the status bytes for uint8_t*.
template <class S, std::size_t I, class... P>
decltype(auto) argument(const SlotArgs<S>& a) {
  using T = std::tuple_element_t<I, std::tuple<P...>>;
  constexpr std::array<bool, sizeof...(P)> is_in{std::is_same_v<P, const S*>...};
  constexpr std::array<bool, sizeof...(P)> is_out{std::is_same_v<P, S*>...};
  if constexpr (std::is_same_v<T, const S*>) return a.in[count_set_before(is_in, I)];
  else if constexpr (std::is_same_v<T, S*>) return a.out[count_set_before(is_out, I)];
  else if constexpr (std::is_same_v<T, std::size_t>) return a.k;
  else {
    static_assert(std::is_same_v<T, std::uint8_t*>, "a slot parameter the list does not know");
    return a.status;
  }
}
template <class S, class... P, std::size_t... I>
int invoke(int (*fn)(std::size_t, P...), const SlotArgs<S>& a, std::index_sequence<I...>) {
  return fn(a.n, argument<S, I, P...>(a)...);
}
}  // namespace op_list_detail

/// Calls a slot (non-NULL) with the arrays of `a`, its parameters worked out from its type.
template <class S, class... P>
int invoke_slot(int (*fn)(std::size_t, P...), const SlotArgs<S>& a) {
  return op_list_detail::invoke(fn, a, std::index_sequence_for<P...>{});
}

}  // namespace rotorcert
