// Loading skinned, animated glTF 2.0 (.gltf with data: URIs or external files, and .glb) through
// tinygltf, followed by the validation of GLTF-3 (spec/SPEC.md): tinygltf parses, this code checks
// every index, accessor range, component type and value before reading it. Every malformed input
// ends in GltfError; nothing is read out of bounds.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>

#include <rotorcert/render/scene.hpp>

namespace rotorcert::render {

/// Caps on what a file may ask for, checked before anything of that size is allocated.
struct GltfLimits {
  std::size_t max_file_bytes = 256u << 20;  // the file, and each external buffer
  std::size_t max_vertices = 1u << 22;      // over all primitives
  std::size_t max_joints = 1024;            // glTF nodes (every node is a joint)
  std::size_t max_keyframes = 1u << 22;     // over all channels of all animations
  std::size_t max_triangles = 1u << 23;     // over all primitives
  std::size_t max_json_depth = 64;          // nesting of JSON arrays and objects
};

/// A malformed or unsupported file. what() names the file and the glTF object, e.g.
/// "rigged_simple.gltf: animation 0 sampler 2: keyframe 5 rotation is NaN".
class GltfError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Loads a .gltf or .glb file (by content, not extension); external buffers are read from the
/// file's directory, external images are never read (a missing image is not an error).
Scene load_gltf_file(const std::filesystem::path& file, const GltfLimits& limits = {});

/// Loads a .gltf (JSON) or .glb document held in memory; `name` prefixes error messages. External
/// buffer files are refused (only data: URIs and the GLB BIN chunk).
Scene load_gltf_memory(const std::uint8_t* data, std::size_t size, const GltfLimits& limits = {},
                       const std::string& name = "<memory>");

}  // namespace rotorcert::render
