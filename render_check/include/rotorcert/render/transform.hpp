// Transform arithmetic in binary64 on the types of types.hpp: TRS to matrix, products, inverses.
// This is plumbing for posing a skeleton, not an implementation under test.
#pragma once

#include <optional>

#include <rotorcert/render/types.hpp>

namespace rotorcert::render {

Mat4 identity_matrix();

/// a * b (apply b first).
Mat4 multiply(const Mat4& a, const Mat4& b);

/// The rotation matrix of q / |q| (q need not be exactly unit).
Mat4 rotation_matrix(const Quat& q);

/// T * R * S of a glTF node.
Mat4 trs_matrix(const Trs& trs);

/// The inverse of m, or nothing when m is singular or the inverse is not finite.
std::optional<Mat4> inverse(const Mat4& m);

/// m * [p, 1] (the homogeneous w of an affine m is 1 and is not divided by).
Vec3 transform_point(const Mat4& m, const Vec3& p);

/// m * [v, 0]: the linear part only.
Vec3 transform_vector(const Mat4& m, const Vec3& v);

}  // namespace rotorcert::render
