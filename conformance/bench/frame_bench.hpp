// frame/<scene>/<impl>/<float|double>/<LBS|DQS>: the frame pipeline of every skinning method
// (frame_job.hpp) on the built-in characters and the mocap clips, and frame_pose/<same>: the
// frame without the vertices (README.md, "Frame pipeline").
#pragma once

#include "register.hpp"

namespace rotorcert::bench {

/// Registers the frame benchmarks; `quick`: the medium and full characters and one mocap clip.
/// Loads the scenes now (a scene that cannot be loaded or posed is skipped with a line on stderr).
void register_frame_benchmarks(const RunConfig& config, bool quick);

}  // namespace rotorcert::bench
