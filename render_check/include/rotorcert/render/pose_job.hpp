// Posing a skeleton with one implementation (ozz-animation style: a job is a struct of inputs
// and outputs with validate() and run()). The implementation computes every rotation and
// rigid motion: keyframe interpolation, the pose blend, the hierarchy and the skinning
// transforms (method.hpp says which ops). What no rotation can express -- scale, shear, the
// non-rotation part of a node `matrix` or of an inverse bind matrix -- is carried by the suite
// as a binary64 3x3 "stretch" K applied before the rotation, so that every transform is
//
//     x -> R(q) K x + t.
//
// Rigid rigs (the built-in characters, the mocap clips) have K = I on every joint's global
// transform; only their binary32 inverse bind matrices carry a stretch of a few 1e-8.
//
// Hierarchy, per joint j with parent p (parents first, Skeleton invariant), local (q, t, K_l):
//   quaternion methods (LBS):  q_j = compose(q_p, q), t_j = t_p + apply_vector(q_p, K_p t)
//   dual-quaternion methods (DQS):  sigma_j = dq_compose(sigma_p, dq_from_rotation_translation(q, K_p t))
//   both:  K_j = R(q)^T K_p R(q) K_l   (suite, binary64; K_j = c K_l when K_p = c I)
// Skinning transform of joint j = global_j * inverse bind_j, the inverse bind decomposed as
// (q_b, K_b, t_b) by prepare_rig, with the same formulas. No result is renormalised between
// ops: drift of the norm along the chain is part of what is measured.
//
// Batching: one ABI call per op per hierarchy depth level (all joints of a level together), and
// one call per op for the keyframes and for the skinning transforms.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <rotorcert/render/method.hpp>
#include <rotorcert/render/scene.hpp>
#include <rotorcert/render/types.hpp>

namespace rotorcert::render {

/// 3x3 matrix, column-major: element (row r, column c) is m[3 * c + r] (LAYOUT-1).
using Mat3 = std::array<double, 9>;

Mat3 identity3();

/// x -> R(rotation) * stretch * x + translation. Values in binary64; those a float method
/// computed are binary32 values. For dual-quaternion methods `motion` holds the method's own
/// dual quaternion [real xyzw, dual xyzw] (not renormalised), `rotation` its real part, and
/// `translation` = vector part of 2 dual real* / |real|^2, evaluated in binary64 by the suite.
struct JointTransform {
  Quat rotation{0.0, 0.0, 0.0, 1.0};
  Vec3 translation{0.0, 0.0, 0.0};
  Mat3 stretch = identity3();
  bool stretched = false;  // false: stretch is exactly the identity and is skipped
  std::array<double, 8> motion{0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0};
  bool has_motion = false;
};

/// Per-skeleton inputs prepared once and shared by every method and by the reference, so that
/// all of them pose exactly the same data.
struct Rig {
  const Skeleton* skeleton = nullptr;
  std::vector<int> depth;                            // per joint: 0 for roots
  std::vector<std::vector<std::size_t>> levels;      // joints of each depth, ascending
  std::vector<std::optional<JointTransform>> matrix_local;  // joints given by a node `matrix`
  std::vector<JointTransform> inverse_bind;          // per joint (identity for non-skin joints)
};

/// Depth levels, and the decompositions (q, K, t) of node matrices and inverse bind matrices:
/// q = the nearest rotation of the linear part L (MAT-2/MAT-3 of the MPFR reference, rounded to
/// binary64), K = R(q)^T L at the reference precision rounded to binary64 (K is kept exactly
/// when it is the identity), t = the translation column. Requires the reference precision
/// (rotorcert::ref::use_reference_precision()); throws std::invalid_argument for a linear part
/// with det <= 0 (a mirror has no rotation) or non-finite entries. The Rig keeps a pointer to
/// `skeleton`, which must outlive it.
Rig prepare_rig(const Skeleton& skeleton);

/// A clip sampled at a time (clamped to the clip as sample.hpp does); no clip: the rest pose.
struct PoseSample {
  const Clip* clip = nullptr;
  double time = 0.0;
};

/// One sample, or two blended with weight alpha on b ((1 - alpha, alpha) for (a, b)).
struct PoseRequest {
  PoseSample a;
  std::optional<PoseSample> b;
  double alpha = 0.0;
};

/// Poses `rig` for `request` with `method`.
///   LINEAR rotation channels: the method's slerp(k_i, k_i+1, s), or for a table without slerp
///     the real part of dq_sclerp of the two rotation-only dual quaternions (equal to slerp);
///     a time on a keyframe gives the keyframe exactly (GLTF-2).
///   STEP: the keyframe. CUBICSPLINE: the Hermite sum of sample.hpp in binary64 (suite), then
///     the method's normalize (DQS without normalize: dq_normalize of (q, 0)).
///   Translation and scale channels: sample.hpp in binary64 (suite).
///   Pose blend (method.pose_blend()): LBS blends local rotations by blend_qlb, else nlerp, and
///     lerps translations and scales (suite); DQS blends the local rigid motions (rotation and
///     K_p-stretched translation) by dq_blend (DLB), else dq_sclerp, and lerps scales.
struct PoseJob {
  // Inputs.
  SkinningMethod method;
  const Rig* rig = nullptr;
  PoseRequest request;
  // Outputs: resized to the joint count by run().
  std::vector<JointTransform>* globals = nullptr;   // global transform of every joint
  std::vector<JointTransform>* skinning = nullptr;  // global * inverse bind; optional
  // Why validate() or run() failed.
  std::string message;

  /// Empty when the job can run; otherwise what is wrong (missing ops, no outputs, ...).
  std::string validate() const;
  /// false, with `message` set, when the job is invalid or the method fails an element.
  bool run();
};

/// The suite's binary64 plumbing of a pose, shared by PoseJob and the reference pose so that
/// both read the clips the same way.
namespace pose_math {

/// Where time t falls in a channel, by the rules of GLTF-2 (sample.hpp): on keyframe k (before
/// the first, after the last, exactly on a keyframe time, or STEP), or between k and k + 1 at
/// s = (t - t_k) / td in (0, 1).
struct KeyLocation {
  enum Kind { key, linear, cubic } kind = key;
  std::size_t k = 0;
  double s = 0.0;
  double td = 0.0;
};
KeyLocation locate(const Channel& channel, double t);

/// Rotation keyframe k (CUBICSPLINE: the value v_k of its triplet); identity for an empty channel.
Quat key_quat(const Channel& channel, std::size_t k);

/// The Hermite sum of GLTF-2 for a rotation channel at a `cubic` location, NOT normalised (the
/// method's normalize, or the reference's, does that).
Quat hermite_rotation(const Channel& channel, const KeyLocation& at);

// 3x3 products on column-major arrays (m[3 c + r]) of any scalar: binary64 here, the 256-bit
// Real in the reference pose (reference_pose.cpp), so that both walk the rig with one formula.
template <class T>
std::array<T, 9> mul3(const std::array<T, 9>& a, const std::array<T, 9>& b) {
  std::array<T, 9> r{};
  for (std::size_t c = 0; c < 3; ++c)
    for (std::size_t row = 0; row < 3; ++row)
      r[3 * c + row] = a[row] * b[3 * c] + a[3 + row] * b[3 * c + 1] + a[6 + row] * b[3 * c + 2];
  return r;
}
template <class T>
std::array<T, 3> mul3v(const std::array<T, 9>& a, const std::array<T, 3>& v) {
  return {a[0] * v[0] + a[3] * v[1] + a[6] * v[2], a[1] * v[0] + a[4] * v[1] + a[7] * v[2],
          a[2] * v[0] + a[5] * v[1] + a[8] * v[2]};
}
template <class T>
std::array<T, 9> transpose3(const std::array<T, 9>& a) {
  return {a[0], a[3], a[6], a[1], a[4], a[7], a[2], a[5], a[8]};
}
/// The rotation matrix of q/|q|.
Mat3 rotation3(const Quat& q);
/// c I for some c (off-diagonal entries zero, diagonal entries equal).
bool is_scalar_matrix(const Mat3& a);
/// The translation of a dual quaternion [real xyzw, dual xyzw]: vector part of
/// 2 dual real* / |real|^2 (DQ-1 after DQ-4), in binary64.
Vec3 dq_translation(const std::array<double, 8>& d);

}  // namespace pose_math
}  // namespace rotorcert::render
