// Seeded benchmark inputs: valid values typical of animation data, written into the ABI arrays
// of an op (op_layout.hpp). The distribution of each Gen is documented in inputs.cpp.
#pragma once

#include <cstddef>
#include <cstdint>

#include "op_layout.hpp"

namespace rotorcert::bench {

/// Every benchmark's generator starts from this seed, so the same op, n and k always get the
/// same values: every implementation of an op is timed on identical data, and the glm
/// baselines on the slerp inputs.
inline constexpr std::uint64_t kSeed = 20261122;

/// Rotation angle (radians) between an element's keyframe neighbours (near_quat, near_dq) and
/// between the influences of a blend or skin cluster: at most a quarter turn, as between
/// consecutive keys or the poses of one joint in two clips.
inline constexpr double kNeighbourAngle = 1.5707963267948966;

/// Influences per element of the n-way ops (blends, skinning), as in real-time skinning.
inline constexpr std::size_t kInfluences = 4;

/// Fills the op's input arrays in[0 .. n_in) (ABI layout, scalar S; array_scalars() each) for
/// n elements of k influences. Values are drawn in double and rounded to S.
template <class S>
void fill_inputs(const OpSpec& op, std::size_t n, std::size_t k, S* const* in);

extern template void fill_inputs<float>(const OpSpec&, std::size_t, std::size_t, float* const*);
extern template void fill_inputs<double>(const OpSpec&, std::size_t, std::size_t, double* const*);

}  // namespace rotorcert::bench
