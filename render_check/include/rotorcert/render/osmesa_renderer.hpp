// Off-screen rendering of skinned meshes with OSMesa (Mesa's software OpenGL, on its llvmpipe
// driver): an OpenGL 4.5 core context with no window or GPU, so every machine renders the same
// frames. Skinning runs in the vertex shader, as in the paper: linear blend skinning (LBS) with a
// matrix palette, or dual quaternion skinning (DQS) with a dual quaternion palette; a pass-through
// mode draws positions skinned elsewhere (on the CPU, by the reference) through the same shaders
// and rasteriser, so that shader frames and reference frames differ only by what skinning did.
//
// The interface follows ozz-animation's jobs: a RenderJob holds the inputs (pointers/spans into
// the caller's data, which must outlive the call), validate() checks them, and
// OsmesaRenderer::run() validates then renders.
//
// What a frame is: depth test on (less), back-face culling off (glTF meshes may be two-sided),
// no multisampling (so frames are deterministic), a fixed directional light from the upper front
// right (world direction toward the light normalize(0.3, 0.8, 0.5)) plus ambient light:
// colour = mesh colour * (0.25 + 0.75 * max(0, n . l)), with n the interpolated, renormalised
// skinned normal turned toward the viewer on back faces; alpha 255. Everything on the GPU side is
// binary32: palettes, positions and normals are rounded from binary64 when uploaded.
// Frames are reproducible byte for byte on one Mesa build and driver (llvmpipe is Mesa's default
// for OSMesa; GALLIUM_DRIVER could select another): compare frames rendered by the same renderer
// (description() names it), never with frames stored from another machine.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include <rotorcert/render/camera.hpp>
#include <rotorcert/render/image.hpp>
#include <rotorcert/render/scene.hpp>
#include <rotorcert/render/types.hpp>

namespace rotorcert::render {

/// No OpenGL context could be made (OSMesa missing or refusing a 4.5 core profile), or OpenGL
/// failed while rendering (a shader that does not compile, an incomplete framebuffer, a GL error).
class RenderError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A unit dual quaternion sigma = real + eps dual, each part [x, y, z, w] (LAYOUT-1): the rigid
/// motion "rotate by real, then translate by t" has dual = 0.5 * t * real (t the pure quaternion
/// [tx, ty, tz, 0], Hamilton product), so t = 2 * dual * conj(real) (DQ-1).
struct DualQuaternion {
  Quat real{0.0, 0.0, 0.0, 1.0};
  Quat dual{0.0, 0.0, 0.0, 0.0};
};

enum class SkinningMode {
  /// v' = sum_k w_k M_k [p, 1]; normal: normalize(upper 3x3 of sum_k w_k M_k times n). The
  /// palette's M_j = global[j] * inverse_bind[j] (skinning_matrices() of sample.hpp).
  linear_blend,
  /// Dual quaternion skinning (Kavan et al. 2008): the pivot is the first influence of weight > 0;
  /// sigma = sum_k w_k s_k sigma_k with s_k = -1 when dot(real_k, real_pivot) < 0, else +1; then
  /// r = sigma.real / |sigma.real|, d = sigma.dual / |sigma.real|, and
  ///   p' = p + 2 r_v x (r_v x p + r_w p) + 2 (r_w d_v - d_w r_v + r_v x d_v),
  ///   n' = normalize(n + 2 r_v x (r_v x n + r_w n))   (n rotated by r).
  dual_quaternion,
  /// No skinning: `positions` and `normals` of the MeshDraw are drawn as given (joints, weights
  /// and bind-space positions of the mesh are not used; its indices are).
  pass_through,
};

const char* to_string(SkinningMode mode);

/// One mesh in a frame.
struct MeshDraw {
  const SkinnedMesh* mesh = nullptr;  // triangles (and, when skinned here, bind-space vertices)
  SkinningMode mode = SkinningMode::linear_blend;
  /// linear_blend: one matrix per Skeleton::joints entry (the index space of mesh->joints); at
  /// least every joint index the mesh uses must have one.
  std::span<const Mat4> matrices;
  /// dual_quaternion: one per Skeleton::joints entry, as for `matrices`.
  std::span<const DualQuaternion> dual_quaternions;
  /// pass_through: skinned positions and unit normals, one per mesh vertex.
  std::span<const Vec3> positions;
  std::span<const Vec3> normals;
  Rgba8 colour{200, 200, 200, 255};  // material colour (alpha unused: frames are opaque)
};

/// Everything one frame needs.
struct RenderJob {
  std::vector<MeshDraw> meshes;
  Camera camera;
  int width = 512;                    // pixels, 1..kMaxImageSide
  int height = 512;
  Rgba8 background{255, 255, 255, 255};

  static constexpr int kMaxImageSide = 8192;
  /// Palettes are shader storage buffers, so any size up to this (the loader's joint limit is
  /// 1024; the mocap clips have 44 joints, the full character 42).
  static constexpr std::size_t kMaxPaletteSize = 65536;

  /// The first problem found, or nothing when the job can run: a valid camera and image size; at
  /// least one mesh; each mesh with vertices and a multiple of 3 indices, all < the vertex count;
  /// for linear_blend and dual_quaternion, as many normals, joints and weights as positions,
  /// finite values, a positive weight on every vertex, and a palette of at most kMaxPaletteSize
  /// finite entries covering every joint index of the mesh (dual quaternions with a nonzero real
  /// part); for pass_through, finite skinned positions and normals, as many as mesh vertices.
  std::optional<std::string> validate() const;
};

/// An OpenGL 4.5 core context of OSMesa (llvmpipe) with the skinning shaders compiled. Costly to
/// make (context and shader compilation), cheap to reuse: make one and render every frame with it.
/// Not thread-safe: one thread at a time may call run() (each call makes the context current on
/// the calling thread).
class OsmesaRenderer {
 public:
  /// RenderError, saying why, when no 4.5 core context can be made or the shaders do not build.
  OsmesaRenderer();
  ~OsmesaRenderer();
  OsmesaRenderer(const OsmesaRenderer&) = delete;
  OsmesaRenderer& operator=(const OsmesaRenderer&) = delete;

  /// Renders the job: std::invalid_argument with validate()'s message when the job is invalid,
  /// RenderError when OpenGL fails. The image is job.width x job.height, rows top to bottom.
  Image run(const RenderJob& job);

  /// GL_RENDERER and GL_VERSION of the context, e.g. "llvmpipe (LLVM 15.0.6, 256 bits); 4.5
  /// (Core Profile) Mesa 22.3.6", for reports.
  std::string description() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace rotorcert::render
