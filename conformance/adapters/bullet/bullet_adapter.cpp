// bullet_adapter: the dlopen plugin rotorcert_adapter_bullet.so, Bullet 3.24's btQuaternion /
// btMatrix3x3 as Debian 12 ships them (libbullet-dev 3.24+dfsg-2), with two tables named "bullet":
//   index 0, float:  this file, compiled with the flags of bullet.pc, Debian's default build
//                    (no BT_USE_DOUBLE_PRECISION: btScalar = float, btScalar.h:314);
//   index 1, double: bullet_adapter_float64.cpp, compiled with the flags of bullet-float64.pc
//                    (-DBT_USE_DOUBLE_PRECISION: btScalar = double) into the shared library
//                    librotorcert_adapter_bullet_float64.so beside this plugin, which it links.
// Why two shared objects: btQuaternion, btMatrix3x3 and quatRotate are inline functions whose
// mangled names do not depend on btScalar (btQuaternion::normalize(), getAngle(), getAxis(),
// quatRotate(btQuaternion const&, btVector3 const&), ...); in one link the float and double copies
// would be merged into one. Each object is built with hidden visibility, so each binds its own
// copies. The table itself is bullet_table.hpp.
#include "bullet_table.hpp"

static_assert(sizeof(btScalar) == sizeof(float), "bullet.pc (Debian's default build) has btScalar = float");

extern "C" const rc_impl* rotorcert_adapter_bullet_float64_entry(std::uint32_t abi_version, std::uint32_t index);

extern "C" __attribute__((visibility("default"))) const rc_impl* rotorcert_impl_entry(std::uint32_t abi_version,
                                                                                     std::uint32_t index) {
  if (index == 0) return rotorcert::impl::entry<BulletTable>(abi_version, 0);
  if (index == 1) return rotorcert_adapter_bullet_float64_entry(abi_version, 0);
  return nullptr;
}
