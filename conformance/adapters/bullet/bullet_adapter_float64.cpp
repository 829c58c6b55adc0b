// The double table of the bullet plugin (bullet_adapter.cpp says why it lives in its own shared
// library): Bullet 3.24 as Debian 12's bullet-float64.pc builds it, -DBT_USE_DOUBLE_PRECISION
// (btScalar = double, btScalar.h:310). The table itself is bullet_table.hpp.
#include "bullet_table.hpp"

static_assert(sizeof(btScalar) == sizeof(double), "bullet-float64.pc defines BT_USE_DOUBLE_PRECISION");

extern "C" __attribute__((visibility("default"))) const rc_impl* rotorcert_adapter_bullet_float64_entry(
    std::uint32_t abi_version, std::uint32_t index) {
  return rotorcert::impl::entry<BulletTable>(abi_version, index);
}
