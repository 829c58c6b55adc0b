// Geometric error of a method's posed character against the reference of the same technique,
// in millimetres, and the volume of closed meshes (the candy-wrapper measure).
//
// Units: glTF scenes are in metres, so 1 scene unit = 1000 mm; for data in other units pass
// `metres_per_unit` (the mocap clips of ../shared/data are in centimetres: 0.01).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <rotorcert/render/pose_job.hpp>
#include <rotorcert/render/skin_job.hpp>
#include <rotorcert/render/types.hpp>

namespace rotorcert::render {

/// ACL's virtual vertex ("shell") distance for characters: 3 cm from the joint.
constexpr double kVirtualVertexMetres = 0.03;

/// Distances |p - p_ref| over the vertices of one frame.
struct VertexError {
  double max_mm = 0.0;
  double sum_mm = 0.0;            // for means over several frames
  std::size_t count = 0;
  std::size_t worst_vertex = 0;
  double max_normal_rad = 0.0;    // largest angle between a normal and the reference normal
  double mean_mm() const { return count == 0 ? 0.0 : sum_mm / static_cast<double>(count); }
};
/// NaN positions count as an infinite error (a method that poisons a vertex fails).
VertexError vertex_error(const SkinOutput& method, const SkinOutput& reference, double metres_per_unit = 1.0);

/// A method's virtual vertices: for each joint, t + R(q/|q|) K (offset e_axis), axis x, y, z, from
/// its global transforms (PoseJob::globals), evaluated in binary64. This measures the pose
/// itself, not the skinning (ACL's error metric).
std::vector<Vec3> virtual_vertices(std::span<const JointTransform> globals, std::span<const std::size_t> joints,
                                   double offset);

struct VirtualVertexError {
  double max_mm = 0.0;
  std::size_t joint = 0;  // skeleton index of the worst joint
  std::size_t axis = 0;   // 0, 1, 2: x, y, z
};
/// Largest |method - reference| over virtual vertices laid out as virtual_vertices() does.
VirtualVertexError virtual_vertex_error(std::span<const Vec3> method, std::span<const Vec3> reference,
                                        std::span<const std::size_t> joints, double metres_per_unit = 1.0);

/// The worst of several frames, and where it occurred.
struct ErrorSummary {
  double max_mm = 0.0;
  double sum_mm = 0.0;
  std::size_t count = 0;
  std::string worst_frame;
  std::size_t worst_vertex = 0;
  double max_normal_rad = 0.0;
  double virtual_max_mm = 0.0;
  std::string virtual_frame;
  std::size_t virtual_joint = 0;
  std::size_t virtual_axis = 0;

  void add(const std::string& frame, const VertexError& e, const VirtualVertexError& v);
  double mean_mm() const { return count == 0 ? 0.0 : sum_mm / static_cast<double>(count); }
};

/// One frame of one method: posed (PoseJob), skinned (SkinJob) and measured against the
/// reference skin and virtual vertices of the same request and the method's technique
/// (reference_pose.hpp). Throws std::runtime_error with the job's message when a job fails.
struct FrameResult {
  SkinOutput skin;
  std::vector<JointTransform> globals;
  VertexError vertex;
  VirtualVertexError virtual_vertex;
};
FrameResult measure_frame(const SkinningMethod& method, const Rig& rig, const SkinnedMesh& mesh,
                          const PoseRequest& request, const SkinOutput& reference_skin,
                          std::span<const Vec3> reference_virtual_vertices, std::span<const std::size_t> joints,
                          double metres_per_unit = 1.0);

/// Enclosed volume by the divergence theorem: V = (1/6) sum over triangles (a, b, c) of
/// a . (b x c), positive for outward-facing (counter-clockwise seen from outside) triangles.
/// Meaningful only for a closed mesh: an open one gives a value that depends on the origin.
/// `closed` is true iff every directed edge (a, b) occurs once and (b, a) occurs once; `parts`
/// holds the volume of each connected part (vertices joined through triangles), in the order of
/// each part's lowest vertex index.
struct MeshVolume {
  double total = 0.0;
  std::vector<double> parts;
  bool closed = false;
  std::size_t open_edges = 0;  // directed edges without their reverse, or repeated
};
MeshVolume mesh_volume(std::span<const Vec3> positions, std::span<const std::uint32_t> indices);

}  // namespace rotorcert::render
