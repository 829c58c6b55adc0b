// One frame of the render check's pipeline (pose_job.hpp + skin_job.hpp of render_check/) for
// one skinning method, on native scalar arrays, for timing (REPORT-2's frame benchmarks;
// ozz-animation style job: inputs, outputs, validate(), prepare(), run()).
//
// A frame: clip A sampled at time_a and clip B at time_b, the two poses blended with weight
// alpha on B, global transforms built level by level, skinning transforms (global * inverse
// bind), and every vertex of every mesh skinned (position and normal). Every rotation and
// rigid motion is computed by the method's table through its batched ABI ops (impl_abi.h), with
// the ops method.hpp assigns to the technique, so that the frame is the render check's frame:
//
//   keys      slerp(k_i, k_i+1, s) over all rotation channels of a clip (one call per clip);
//             DQS tables without slerp: dq_sclerp of rotation-only dual quaternions [q, 0].
//             A time on a keyframe (or past the ends, or STEP) is slerp(k_i, k_i+1, 0), where
//             PoseJob takes the keyframe itself: the same rotation to rounding.
//   blend     LBS: blend_qlb (k = 2, weights 1 - alpha, alpha) of every joint's local rotation,
//             else nlerp(a, b, alpha); translations lerped by the suite.
//             DQS: dq_from_rotation_translation of every local (q, t) of A and B (one call),
//             then dq_blend (k = 2), else dq_sclerp(a, b, alpha).
//   hierarchy one call per op per depth level: LBS compose(q_p, q) and apply_vector(q_p, t)
//             (t_j = t_p + that, suite); DQS dq_compose(sigma_p, sigma).
//   skinning  global * inverse bind with the same ops (DQS: the inverse binds' dual quaternions
//             are made once by prepare() with the method's dq_from_rotation_translation).
//   vertices  LBS: to_matrix of every skinning rotation (one call), then the suite's blend of
//             the 3x4 matrices [R K | t] of the 4 influences in the method's format, applied to
//             the position and the normal: the same loop for every method, as a vertex shader
//             would do it (method.hpp: "the suite blends the 3x4 matrices"), not the table's
//             skin_linear, which takes (q, t) per influence and so makes 4 matrices per vertex.
//             DQS: likewise the suite's loop over the table's skinning dual quaternions, as
//             Kavan et al.'s shader does it (2008, Algorithm 1): each influence signed against
//             the pivot (DQ-6), the weighted sum, its rotation and translation (DQ-3) applied
//             to the position and the rotation to the normal. Not the table's dq_blend (k = 4)
//             + dq_apply_point per vertex: their batch layout takes the 4 influences' dual
//             quaternions inline per element, and gathering them (32 scalars a vertex) cost
//             more than the whole LBS vertex loop; the table's DLB per element is timed by
//             the op benchmark dq_blend (k = 4) against blend_qlb, and the render check
//             (SkinJob) still skins with it.
//             Both loops run SIMD across vertices (vertex_kernels.hpp: Highway, the CPU's best
//             target, one vertex per lane, the palette gathered per lane, as a GPU runs the
//             shader), so that neither technique is timed on slower suite code than the other.
// Normals are not renormalised (a shader does that per fragment); PoseJob/SkinJob's are.
//
// Rigid rigs only: every joint's global stretch K must be the identity (no rest scale other
// than 1, no scale channel value other than 1, no stretched node matrix); prepare() refuses
// others, saying why. The few-1e-8 stretches of binary32 inverse bind matrices are applied as
// SkinJob applies them: LBS multiplies the joint's matrix by K_b (suite, per joint per frame);
// DQS blends the stretched bind-space positions and normals, sum (w_k/W) K_b v, which for a
// rigid rig do not change from frame to frame and so are made once by prepare().
// CUBICSPLINE rotation and translation channels are refused too (the built-in characters and
// the mocap clips are LINEAR).
//
// What run() does besides the ABI calls (all in the method's scalar type, in the timed path):
// locating the keys (pose_math::locate, on the channel's binary64 times), gathering keyframes,
// scattering the slerp results into the joints' slots, lerping translations, gathering parents
// and influences, building the matrix palette, the two vertex loops, and checking every status
// byte. run() allocates nothing.
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <rotorcert/render/method.hpp>
#include <rotorcert/render/pose_job.hpp>
#include <rotorcert/render/scene.hpp>
#include <rotorcert/render/skin_job.hpp>

namespace rotorcert::bench {

class FrameJob {
 public:
  // Inputs, fixed by prepare().
  render::SkinningMethod method;
  const render::Scene* scene = nullptr;  // every mesh of it is skinned
  const render::Rig* rig = nullptr;      // render::prepare_rig(scene->skeleton)
  const render::Clip* clip_a = nullptr;
  const render::Clip* clip_b = nullptr;  // may be clip_a
  double alpha = 0.3;                    // weight of B in the pose blend
  // Inputs of one frame (clamped to each clip as PoseJob does).
  double time_a = 0.0;
  double time_b = 0.0;
  /// false: stop after the skinning transforms (LBS: after to_matrix and the matrix palette;
  /// DQS: after dq_compose with the inverse binds), leaving the vertices as they were: the
  /// part of the frame that depends on the rotation library alone.
  bool skin_vertices = true;
  // Why validate(), prepare() or run() failed.
  std::string message;

  FrameJob();
  ~FrameJob();
  FrameJob(FrameJob&&) noexcept;
  FrameJob& operator=(FrameJob&&) noexcept;

  /// Empty when prepare() can run; otherwise why not (missing inputs or ops, no pose blend,
  /// a non-rigid rig, CUBICSPLINE channels, a joint index out of range, ...).
  std::string validate() const;
  /// Lays out the native arrays (keyframes in ABI layout, rest pose, inverse binds, vertices,
  /// influences) for the inputs above. false, with `message`, when validate() fails or an op
  /// fails while preparing.
  bool prepare();
  /// One frame at (time_a, time_b). false, with `message`, when not prepared or an op returns
  /// nonzero or a non-OK status.
  bool run();

  std::size_t joint_count() const;
  std::size_t vertex_count() const;  // over every mesh
  std::size_t level_count() const;   // hierarchy depth levels: ABI calls per op in the hierarchy
  std::size_t rotation_channels() const;  // of clip A plus clip B

  /// The last frame's vertices of mesh `m` in binary64 (normals as computed, not normalised).
  render::SkinOutput output(std::size_t m) const;

  struct Pipeline;  // the scalar-typed arrays and code (frame_job.cpp)

 private:
  std::unique_ptr<Pipeline> p_;
};

/// FrameJob against the render check's pipeline (PoseJob + SkinJob of the same method and
/// request) at some frames: the largest vertex distance in mm and normal angle in radians over
/// every mesh and frame, and where.
struct FrameAgreement {
  double max_mm = 0.0;
  double max_normal_rad = 0.0;
  std::string worst;    // "mesh m vertex v at t_a = .., t_b = .."
  std::string failure;  // non-empty: a job failed, nothing was compared
};
/// Runs `job` (prepared) and PoseJob + SkinJob at each (time_a, time_b) of `times`;
/// `metres_per_unit` converts scene units to millimetres (vertex_error.hpp).
FrameAgreement compare_with_render_check(FrameJob& job, const std::vector<std::pair<double, double>>& times,
                                         double metres_per_unit);

}  // namespace rotorcert::bench
