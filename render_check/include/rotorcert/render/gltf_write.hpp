// Writing a Scene as a glTF 2.0 JSON document with one embedded buffer (a base64 data: URI), so
// that characters built in memory (character.hpp) reach the render check through the same loader
// (gltf_load.hpp) as files. The output is deterministic byte for byte: the same Scene gives the
// same string on every run and platform (keys sorted, numbers printed by nlohmann::json).
//
// What is written, and how load_gltf_memory reads it back:
//   - joint j of the skeleton as node j (name, children in ascending index, translation/rotation/
//     scale when not the default, or `matrix`); the loader numbers nodes depth-first from the
//     roots, so joint indices survive the round trip when the joints are in that preorder (as
//     make_character builds them); Joint::node is not written, the node of joint j is j;
//   - one skin: joints = Skeleton::skin_joints, inverse bind matrices as a FLOAT MAT4 accessor;
//   - each SkinnedMesh as a glTF mesh of one TRIANGLES primitive on node SkinnedMesh::node with
//     that skin: POSITION and NORMAL (FLOAT VEC3), JOINTS_0 (UNSIGNED_BYTE VEC4 for skins of at
//     most 256 joints, else UNSIGNED_SHORT; skeleton indices mapped to skin indices), WEIGHTS_0
//     (FLOAT VEC4), indices (UNSIGNED_SHORT below 65536 vertices, else UNSIGNED_INT);
//   - each Clip as an animation: one sampler per channel, times and values as FLOAT accessors.
// Every number that goes into an accessor is rounded to binary32 (glTF has no binary64
// accessors); node transforms are JSON numbers and keep binary64. A scene whose accessor data are
// already binary32 values therefore loads back identically.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>

#include <rotorcert/render/scene.hpp>

namespace rotorcert::render {

/// A scene that glTF cannot express as this writer writes it: a parent after its child, a mesh
/// joint outside the skin, two meshes on one node, a number that is not finite in binary32, an
/// empty mesh or channel, per-vertex arrays of different lengths, a value count that does not
/// match the keyframes (three per keyframe for CUBICSPLINE).
class GltfWriteError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The scene as a .gltf JSON document (UTF-8, no trailing newline).
std::string write_gltf(const Scene& scene);

/// write_gltf(scene) written to `file` (replaced if it exists); GltfWriteError when it cannot be.
void write_gltf_file(const Scene& scene, const std::filesystem::path& file);

}  // namespace rotorcert::render
