// The plugin entry point of the external library: its one binary64 table, named my_rotations,
// taken from the rotation code it compiles (rotor_m2's table, whose non-plugin build defines
// rotorcert_impl_entry_rotor_m2). With MY_ROTATIONS_PLANTED_DEFECT, compose(a, b) returns b a:
// the bug COMPOSE-1 exists to catch.
#include <cstddef>
#include <cstdint>

#include <rotorcert/impl_abi.h>

extern "C" const rc_impl* rotorcert_impl_entry_rotor_m2(std::uint32_t abi_version, std::uint32_t index);

namespace {

const rc_ops_f64* g_original = nullptr;

#ifdef MY_ROTATIONS_PLANTED_DEFECT
int compose_reversed(std::size_t n, const double* a, const double* b, double* out_q, std::uint8_t* status) {
  return g_original->compose(n, b, a, out_q, status);
}
#endif

const rc_impl* make_table(std::uint32_t abi_version) {
  static rc_impl table;
  static rc_ops_f64 ops;
  for (std::uint32_t i = 0;; ++i) {
    const rc_impl* t = rotorcert_impl_entry_rotor_m2(abi_version, i);
    if (t == nullptr) return nullptr;
    if (t->scalar != RC_SCALAR_FLOAT64) continue;
    table = *t;
    ops = *t->f64;
    g_original = t->f64;
#ifdef MY_ROTATIONS_PLANTED_DEFECT
    ops.compose = compose_reversed;
#endif
    table.name = "my_rotations";
    table.version = "1.0";
    table.description = "an external library certified from its own CMake build";
    table.f64 = &ops;
    return &table;
  }
}

}  // namespace

extern "C" __attribute__((visibility("default"))) const rc_impl* rotorcert_impl_entry(std::uint32_t abi_version,
                                                                                      std::uint32_t index) {
  return index == 0 ? make_table(abi_version) : nullptr;
}
