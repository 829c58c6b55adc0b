// What the glTF loader produces (GLTF-1 of spec/SPEC.md): one skeleton holding every node of the
// file, the triangle meshes skinned to it, and the animation clips. All numbers are binary64;
// layouts are those of types.hpp (quaternions [x, y, z, w], matrices column-major).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <rotorcert/render/types.hpp>

namespace rotorcert::render {

/// One node of the file's hierarchy. Every glTF node is a joint of the skeleton, so that
/// non-joint ancestors (a Z-up root, an armature node) take part in the global transforms as
/// glTF requires; the joints a skin names are listed in Skeleton::skin_joints.
struct Joint {
  std::string name;             // node name, or "node <i>" when the node has none
  int parent = -1;              // index into Skeleton::joints, always < this joint's index; -1: root
  std::size_t node = 0;         // index of the node in the glTF file
  Trs rest;                     // local rest transform (node translation/rotation/scale)
  std::optional<Mat4> matrix;   // set when the node gives `matrix` instead of TRS; such a node is
                                // never animated (glTF forbids it) and `rest` is then the identity
  Mat4 inverse_bind{};          // inverse bind matrix (column-major); identity for non-skin nodes
  bool skinned = false;         // named by a skin (or the skeleton of a skeleton-only file)
};

/// Joints in topological order: parents before children (checked acyclic, one parent per node).
struct Skeleton {
  std::vector<Joint> joints;
  /// Skeleton indices of the joints that skins name, in the order of the file's skin(s); for a
  /// skeleton-only file (no mesh, no skin) every joint, with inverse binds from the rest pose.
  std::vector<std::size_t> skin_joints;
};

/// A triangle mesh skinned to the Skeleton: vertex v is placed at
///   sum_k weights[v][k] * skinning_matrix[joints[v][k]] * positions[v]
/// with skinning_matrix = global joint matrix * inverse bind (sample.hpp). An unskinned glTF mesh
/// is bound rigidly to its node (weight 1), so one formula serves every mesh.
struct SkinnedMesh {
  std::string name;
  std::size_t node = 0;                               // glTF node that instantiates it
  std::vector<Vec3> positions;                        // bind-space positions
  std::vector<Vec3> normals;                          // unit, one per position (computed when absent)
  std::vector<std::array<std::uint32_t, 4>> joints;   // Skeleton::joints indices
  std::vector<std::array<double, 4>> weights;         // >= 0, sum 1 (GLTF-3)
  std::vector<std::uint32_t> indices;                 // 3 per triangle, counter-clockwise front faces
  std::size_t triangle_count() const { return indices.size() / 3; }
};

enum class ChannelPath { translation, rotation, scale };
enum class Interpolation { step, linear, cubicspline };

/// One animation channel: keyframes of one property of one joint.
struct Channel {
  std::size_t joint = 0;          // Skeleton::joints index
  ChannelPath path = ChannelPath::rotation;
  Interpolation interpolation = Interpolation::linear;
  std::vector<double> times;      // seconds, finite, non-decreasing, at least one
  /// Keyframe values, `width()` numbers per element (3: translation/scale, 4: rotation [x,y,z,w]).
  /// STEP and LINEAR: one element per keyframe. CUBICSPLINE: three per keyframe as glTF stores
  /// them: in-tangent a_k, value v_k, out-tangent b_k.
  std::vector<double> values;
  std::size_t width() const { return path == ChannelPath::rotation ? 4 : 3; }
};

/// One glTF animation.
struct Clip {
  std::string name;               // animation name, or "animation <i>"
  double start = 0.0;             // earliest keyframe time over the channels
  double end = 0.0;               // latest keyframe time over the channels
  std::vector<Channel> channels;
  double duration() const { return end - start; }
};

struct Scene {
  std::string name;               // the file name (or the name given to load_gltf_memory)
  Skeleton skeleton;
  std::vector<SkinnedMesh> meshes;
  std::vector<Clip> clips;
  bool generated_skin = false;    // meshes come from make_capsule_skin (skeleton-only file)
  /// Inputs the loader repaired (GLTF-3): non-unit rotations normalised, weights renormalised,
  /// channels and primitives skipped. Every repair is counted; the first messages are kept.
  std::size_t warning_count = 0;
  std::vector<std::string> warnings;

  std::size_t vertex_count() const;
  std::size_t triangle_count() const;
};

}  // namespace rotorcert::render
