// CPU skinning of a SkinnedMesh with the skinning transforms a PoseJob computed with the same
// method (ozz-animation style job: inputs, outputs, validate(), run()). Arithmetic that the
// suite does (the LBS matrix blend, the stretch of pose_job.hpp) is done in the method's
// format: binary32 for a float table, as a vertex shader would; outputs are binary64 arrays.
//
// Vertex v with influences (j_k, w_k), k = 1..4, W = sum w_k, skinning transforms
// x -> R_j K_j x + t_j:
//   LBS: A_j = to_matrix(q_j) K_j (one to_matrix call for every joint), M = sum (w_k/W) A_jk,
//        T = sum (w_k/W) t_jk;  position M v + T, normal M n normalised (M's linear part, not
//        its inverse transpose: equal for rotations, the usual shader shortcut otherwise).
//   DQS: two-phase skinning (Kavan et al. 2008, Section 4.2) with the stretch first:
//        v_s = sum (w_k/W) K_jk v (v itself when no influence is stretched), then the blended
//        dual quaternion sigma = dq_blend(sigma_jk, w_k) applied by dq_apply_point; normals
//        n_s likewise, rotated by dq_apply_point of (real part of sigma, 0) and normalised.
//        Tables without dq_blend/dq_apply_point: skin_dual_quaternion with q = real part and
//        t = translation of each sigma_j (read back in the method's format), normals with t = 0.
#pragma once

#include <string>
#include <vector>

#include <rotorcert/render/method.hpp>
#include <rotorcert/render/pose_job.hpp>
#include <rotorcert/render/scene.hpp>

namespace rotorcert::render {

/// Posed vertices, one per mesh vertex.
struct SkinOutput {
  std::vector<Vec3> positions;
  std::vector<Vec3> normals;  // unit
};

struct SkinJob {
  // Inputs.
  SkinningMethod method;
  const SkinnedMesh* mesh = nullptr;
  const std::vector<JointTransform>* skinning = nullptr;  // PoseJob::skinning of the same method
  // Output: resized by run().
  SkinOutput* output = nullptr;
  // Why validate() or run() failed.
  std::string message;

  /// Empty when the job can run (joint indices in range, transforms of the method's kind, ...).
  std::string validate() const;
  /// false, with `message` set, when the job is invalid or the method fails an element.
  bool run();
};

}  // namespace rotorcert::render
