// Sampling clips as glTF 2.0 Appendix C ("Animation sampler interpolation modes") defines it, and
// posing the skeleton (GLTF-2 of spec/SPEC.md). The rotation interpolation of LINEAR channels is a
// parameter so that the render check can plug in each implementation's slerp or nlerp.
#pragma once

#include <functional>
#include <vector>

#include <rotorcert/render/scene.hpp>

namespace rotorcert::render {

/// Interpolates rotation a (s = 0) to b (s = 1); s in [0, 1).
using QuatInterpolation = std::function<Quat(const Quat& a, const Quat& b, double s)>;

/// glTF's slerp in binary64 as SLERP-1 defines it: a and b normalised first (finite nonzero
/// inputs), the shorter arc (b negated when a.b < 0), angle from atan2 so that nearly equal
/// keyframes interpolate accurately; a/|a| at s = 0.
Quat slerp(const Quat& a, const Quat& b, double s);

/// The channel's value at time t: translation/scale in [0..2], rotation [x,y,z,w] in [0..3].
/// t before the first keyframe gives the first value, after the last the last value; at a
/// keyframe time exactly, that keyframe's value (for CUBICSPLINE the value v_k, not a tangent).
/// STEP holds v_k on [t_k, t_k+1); LINEAR is lerp (translation/scale) or `interp` (rotation);
/// CUBICSPLINE is the Hermite spline with tangents scaled by t_k+1 - t_k, rotations normalised.
std::array<double, 4> sample_channel(const Channel& channel, double t,
                                     const QuatInterpolation& interp = slerp);

/// Local transforms of every joint at time t: rest transforms overridden by the clip's channels;
/// t is clamped to [clip.start, clip.end].
std::vector<Trs> sample_pose(const Skeleton& skeleton, const Clip& clip, double t,
                             const QuatInterpolation& interp = slerp);

/// The rest pose (every joint's rest transform).
std::vector<Trs> rest_pose(const Skeleton& skeleton);

/// Global joint matrices: global[j] = global[parent] * local[j] (joint.matrix when the node has one).
std::vector<Mat4> global_matrices(const Skeleton& skeleton, const std::vector<Trs>& local);

/// Skinning matrices: global[j] * inverse_bind[j].
std::vector<Mat4> skinning_matrices(const Skeleton& skeleton, const std::vector<Mat4>& global);

}  // namespace rotorcert::render
