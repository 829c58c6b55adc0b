// Building an implementation's rc_impl tables and its entry point from C++ structs.
//
// An implementation struct provides, besides its operations (impl.hpp):
//   using Scalar = float | double;
//   static constexpr const char* name, version, description;
//   static constexpr std::uint32_t levels;          // RC_LEVEL_* bits
//   static constexpr const char* const clauses[];   // NULL-terminated
// and optionally the SIMD dispatch hooks simd_targets / select_target / current_target, and the
// declarations of ABI version 2 (DECL-1), each a NULL-terminated array of "op:id" strings:
//   static constexpr const char* const preconditions[], conventions[];
// The operations of ABI version 3 (to_angle, to_axis, sqrt, dq_to_rotation_translation) and 4
// (dq_log, dq_exp, rigid_compose, rigid_apply, rigid_inverse) are element functions like the others;
// table() puts them in f32_v3 / f64_v3 and f32_v4 / f64_v4.
#pragma once

#include <cstdint>

#include "impl.hpp"

namespace rotorcert::impl {

template <class Impl>
const rc_impl* table(std::uint32_t abi_version = RC_ABI_VERSION) {
  using S = typename Impl::Scalar;
  static const Ops<S> ops = make_ops<Impl>();
  static const Ops3<S> ops3 = make_ops3<Impl>();
  static const Ops4<S> ops4 = make_ops4<Impl>();
  static const rc_impl t = [] {
    rc_impl r{};
    r.abi_version = RC_ABI_VERSION;
    r.name = Impl::name;
    r.version = Impl::version;
    r.description = Impl::description;
    r.levels = Impl::levels;
    r.clauses = Impl::clauses;
    if constexpr (std::is_same_v<S, float>) {
      r.scalar = RC_SCALAR_FLOAT32;
      r.f32 = &ops;
      r.f32_v3 = &ops3;
      r.f32_v4 = &ops4;
    } else {
      r.scalar = RC_SCALAR_FLOAT64;
      r.f64 = &ops;
      r.f64_v3 = &ops3;
      r.f64_v4 = &ops4;
    }
    if constexpr (requires { Impl::simd_targets; }) {
      r.simd_targets = Impl::simd_targets;
      r.select_target = &Impl::select_target;
      r.current_target = &Impl::current_target;
    }
    if constexpr (requires { Impl::preconditions; }) r.preconditions = Impl::preconditions;
    if constexpr (requires { Impl::conventions; }) r.conventions = Impl::conventions;
    return r;
  }();
  // An older host gets the same table stamped with the version it asked for: it reads the prefix
  // of that version (the appended fields are there, unread), and a host that checks the stamp
  // against its own RC_ABI_VERSION accepts it.
  static const rc_impl v3 = [] {
    rc_impl r = t;
    r.abi_version = 3;
    return r;
  }();
  static const rc_impl v2 = [] {
    rc_impl r = t;
    r.abi_version = 2;
    return r;
  }();
  static const rc_impl v1 = [] {
    rc_impl r = t;
    r.abi_version = 1;
    return r;
  }();
  return abi_version >= 4 ? &t : abi_version == 3 ? &v3 : abi_version == 2 ? &v2 : &v1;
}

/// The body of an entry point: the index-th of the given implementation structs. A newer table is
/// an older one with fields appended, so it answers every version it contains.
template <class... Impls>
const rc_impl* entry(std::uint32_t abi_version, std::uint32_t index) {
  if (abi_version < RC_ABI_VERSION_MIN || abi_version > RC_ABI_VERSION) return nullptr;
  const rc_impl* tables[] = {table<Impls>(abi_version)...};
  return index < sizeof...(Impls) ? tables[index] : nullptr;
}

}  // namespace rotorcert::impl

/// Defines the implementation's static entry point rotorcert_impl_entry_<id>; the plugin
/// build of the same file (ROTORCERT_PLUGIN defined) also exports rotorcert_impl_entry.
#ifdef ROTORCERT_PLUGIN
#define ROTORCERT_DEFINE_ENTRY(id, ...)                                                            \
  extern "C" const rc_impl* rotorcert_impl_entry_##id(std::uint32_t abi, std::uint32_t index) {  \
    return ::rotorcert::impl::entry<__VA_ARGS__>(abi, index);                                     \
  }                                                                                                \
  extern "C" __attribute__((visibility("default"))) const rc_impl* rotorcert_impl_entry(          \
      std::uint32_t abi, std::uint32_t index) {                                                    \
    return rotorcert_impl_entry_##id(abi, index);                                                  \
  }
#else
#define ROTORCERT_DEFINE_ENTRY(id, ...)                                                            \
  extern "C" const rc_impl* rotorcert_impl_entry_##id(std::uint32_t abi, std::uint32_t index) {  \
    return ::rotorcert::impl::entry<__VA_ARGS__>(abi, index);                                     \
  }
#endif
