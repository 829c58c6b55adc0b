// Value types of the render check: vectors, quaternions, 4x4 matrices and TRS transforms, in
// binary64 and in the layouts glTF 2.0 uses, so that data read from a file keeps its order.
#pragma once

#include <array>

namespace rotorcert::render {

/// [x, y, z].
using Vec3 = std::array<double, 3>;

/// Quaternion [x, y, z, w]: glTF order (LAYOUT-1 order too); w is the scalar part.
using Quat = std::array<double, 4>;

/// 4x4 matrix, column-major as glTF stores it: element (row r, column c) is m[4 * c + r], so
/// m[12], m[13], m[14] hold the translation of an affine transform.
using Mat4 = std::array<double, 16>;

/// A local transform as glTF nodes define it: M = T * R * S (scale first, then rotate, then
/// translate). Defaults are the identity transform.
struct Trs {
  Vec3 translation{0.0, 0.0, 0.0};
  Quat rotation{0.0, 0.0, 0.0, 1.0};
  Vec3 scale{1.0, 1.0, 1.0};
};

}  // namespace rotorcert::render
