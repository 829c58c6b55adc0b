// The expected pose and skin: the same PoseRequest on the same Rig computed with the MPFR
// reference at 256 bits (NUM-2; call rotorcert::ref::use_reference_precision() first). It reads
// the clips and the rig exactly as PoseJob does (pose_job.hpp: the same binary64 keyframes,
// lerped translations and scales, Hermite sums and stretch decompositions) and replaces every
// op of the method by the reference clause function:
//   keyframes   SLERP_1 (LINEAR), NORM_1 of the Hermite sum (CUBICSPLINE)
//   pose blend  QLB_1 of the two rotations (rules qlb and nlerp: equal for two influences),
//               DQ_6_dlb or DQ_5_sclerp of the two local rigid motions (rules dlb, sclerp)
//   hierarchy   COMPOSE_1 and APPLY_1 (a dual-quaternion chain DQ_2 of DQ_1 is the same rigid
//               motion, so one reference pose serves both techniques)
//   LBS vertex  sum (w_k/W) (A_k v + t_k), A_k = MAT_1(q_k) K_k  (SKIN-1 with the stretch)
//   DQS vertex  DQ_3(DQ_6_dlb(DQ_1(q_k, t_k), w), sum (w_k/W) K_k v)  (SKIN-2, two-phase)
// LBS and DQS are different deformations: each method is compared with the reference of its
// own technique.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include <rotorcert/reference/quaternion.hpp>
#include <rotorcert/reference/result.hpp>
#include <rotorcert/reference/scalar.hpp>
#include <rotorcert/render/method.hpp>
#include <rotorcert/render/pose_job.hpp>
#include <rotorcert/render/skin_job.hpp>

namespace rotorcert::render {

/// x -> R(rotation) K x + translation at the reference precision (rotation not necessarily
/// unit: its rotation is that of q/|q|, as in APPLY-1 and MAT-1).
struct RefTransform {
  ref::Quaternion<ref::Real> rotation;
  ref::Vec3<ref::Real> translation;
  ref::Mat3<ref::Real> stretch;  // column-major
  bool stretched = false;
};

struct ReferencePose {
  std::vector<RefTransform> globals;   // every joint
  std::vector<RefTransform> skinning;  // global * inverse bind, every joint
};

/// The 256-bit pose. `blend` is the rule of the method being compared (SkinningMethod::
/// pose_blend()); it matters only when request.b is set (none is then std::invalid_argument).
ReferencePose reference_pose(const Rig& rig, const PoseRequest& request, PoseBlend blend = PoseBlend::qlb);

/// The expected position of vertex v, unrounded.
ref::Vec3<ref::Real> reference_position(const ReferencePose& pose, const SkinnedMesh& mesh, std::size_t v,
                                        Technique technique);

/// Every vertex: positions and unit normals rounded to binary64.
SkinOutput reference_skin(const ReferencePose& pose, const SkinnedMesh& mesh, Technique technique);

/// ACL-style virtual vertices of `joints`: for each joint, t + R K (offset e_x), (offset e_y),
/// (offset e_z) in that order (offset in scene units), rounded to binary64.
std::vector<Vec3> reference_virtual_vertices(const ReferencePose& pose, std::span<const std::size_t> joints,
                                             double offset);

/// The transforms rounded to binary64 (for display and for comparisons at joint level).
std::vector<JointTransform> to_binary64(const std::vector<RefTransform>& transforms);

}  // namespace rotorcert::render
