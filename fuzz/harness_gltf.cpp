// libFuzzer harness: the glTF loading path of render_check (rotorcert::render::load_gltf_memory):
// .gltf JSON (embedded data: URIs) or .glb bytes must load or throw GltfError, never crash, read
// out of bounds, hang or throw anything else. Small limits keep every input cheap: the size
// checks themselves (file, vertices, joints, keyframes) are part of what is fuzzed.
// A loaded scene's animation rotations are whatever the file says (non-unit, NaN): the loader
// must not reject or crash on them; judging what the renderer does with them is render_check's.
#include <cstdint>

#include <rotorcert/render/gltf_load.hpp>

#include "parser_harness.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace rotorcert;
  render::GltfLimits limits;
  limits.max_file_bytes = 1u << 20;
  limits.max_vertices = 1u << 12;
  limits.max_joints = 64;
  limits.max_keyframes = 1u << 12;
  fuzz::expect_only<render::GltfError>("gltf", "load_gltf_memory",
                                       [&] { (void)render::load_gltf_memory(data, size, limits, "fuzz.gltf"); });
  return 0;
}
