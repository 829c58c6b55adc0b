// Vertex, virtual-vertex and volume measures (vertex_error.hpp).
#include <rotorcert/render/vertex_error.hpp>

#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <stdexcept>

#include <rotorcert/render/transform.hpp>

namespace rotorcert::render {

namespace {

double distance(const Vec3& a, const Vec3& b) {
  const double d = std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
  return std::isnan(d) ? std::numeric_limits<double>::infinity() : d;
}

/// Angle between two vectors by atan2(|a x b|, a . b): accurate at small angles (METRIC-1's
/// reason for avoiding acos).
double angle(const Vec3& a, const Vec3& b) {
  const Vec3 c{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  const double r = std::atan2(std::hypot(c[0], c[1], c[2]), a[0] * b[0] + a[1] * b[1] + a[2] * b[2]);
  return std::isnan(r) ? std::numeric_limits<double>::infinity() : r;
}

}  // namespace

VertexError vertex_error(const SkinOutput& method, const SkinOutput& reference, double metres_per_unit) {
  if (method.positions.size() != reference.positions.size() || method.normals.size() != reference.normals.size())
    throw std::invalid_argument("vertex_error: different vertex counts");
  VertexError e;
  const double mm = 1000.0 * metres_per_unit;
  for (std::size_t v = 0; v < method.positions.size(); ++v) {
    const double d = mm * distance(method.positions[v], reference.positions[v]);
    e.sum_mm += d;
    ++e.count;
    if (v == 0 || d > e.max_mm) {
      e.max_mm = d;
      e.worst_vertex = v;
    }
    e.max_normal_rad = std::max(e.max_normal_rad, angle(method.normals[v], reference.normals[v]));
  }
  return e;
}

std::vector<Vec3> virtual_vertices(std::span<const JointTransform> globals, std::span<const std::size_t> joints,
                                   double offset) {
  std::vector<Vec3> out;
  out.reserve(3 * joints.size());
  for (std::size_t j : joints) {
    const JointTransform& g = globals[j];
    const Mat3 r = pose_math::rotation3(g.rotation);
    const Mat3 a = g.stretched ? pose_math::mul3(r, g.stretch) : r;
    for (std::size_t axis = 0; axis < 3; ++axis) {
      Vec3 e{0.0, 0.0, 0.0};
      e[axis] = offset;
      const Vec3 x = pose_math::mul3v(a, e);
      out.push_back({x[0] + g.translation[0], x[1] + g.translation[1], x[2] + g.translation[2]});
    }
  }
  return out;
}

VirtualVertexError virtual_vertex_error(std::span<const Vec3> method, std::span<const Vec3> reference,
                                        std::span<const std::size_t> joints, double metres_per_unit) {
  if (method.size() != reference.size() || method.size() != 3 * joints.size())
    throw std::invalid_argument("virtual_vertex_error: sizes do not match");
  VirtualVertexError e;
  for (std::size_t i = 0; i < method.size(); ++i) {
    const double d = 1000.0 * metres_per_unit * distance(method[i], reference[i]);
    if (d > e.max_mm || i == 0) {
      e.max_mm = d;
      e.joint = joints[i / 3];
      e.axis = i % 3;
    }
  }
  return e;
}

void ErrorSummary::add(const std::string& frame, const VertexError& e, const VirtualVertexError& v) {
  if (count == 0 || e.max_mm > max_mm) {
    max_mm = e.max_mm;
    worst_frame = frame;
    worst_vertex = e.worst_vertex;
  }
  sum_mm += e.sum_mm;
  count += e.count;
  max_normal_rad = std::max(max_normal_rad, e.max_normal_rad);
  if (virtual_frame.empty() || v.max_mm > virtual_max_mm) {
    virtual_max_mm = v.max_mm;
    virtual_frame = frame;
    virtual_joint = v.joint;
    virtual_axis = v.axis;
  }
}

FrameResult measure_frame(const SkinningMethod& method, const Rig& rig, const SkinnedMesh& mesh,
                          const PoseRequest& request, const SkinOutput& reference_skin,
                          std::span<const Vec3> reference_virtual_vertices, std::span<const std::size_t> joints,
                          double metres_per_unit) {
  FrameResult r;
  std::vector<JointTransform> skinning;
  PoseJob pose{method, &rig, request, &r.globals, &skinning, {}};
  if (!pose.run()) throw std::runtime_error("pose: " + pose.message);
  SkinJob skin{method, &mesh, &skinning, &r.skin, {}};
  if (!skin.run()) throw std::runtime_error("skin: " + skin.message);
  r.vertex = vertex_error(r.skin, reference_skin, metres_per_unit);
  const double offset = kVirtualVertexMetres / metres_per_unit;
  r.virtual_vertex = virtual_vertex_error(virtual_vertices(r.globals, joints, offset), reference_virtual_vertices, joints,
                                          metres_per_unit);
  return r;
}

MeshVolume mesh_volume(std::span<const Vec3> positions, std::span<const std::uint32_t> indices) {
  MeshVolume r;
  const std::size_t nv = positions.size();
  // Connected parts: union-find over the triangles' vertices.
  std::vector<std::size_t> root(nv);
  std::iota(root.begin(), root.end(), std::size_t{0});
  auto find = [&](std::size_t x) {
    while (root[x] != x) x = root[x] = root[root[x]];
    return x;
  };
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
  for (std::size_t t = 0; t + 2 < indices.size(); t += 3)
    for (std::size_t k = 0; k < 3; ++k) {
      const std::uint32_t a = indices[t + k], b = indices[t + (k + 1) % 3];
      if (a >= nv || b >= nv) throw std::invalid_argument("mesh_volume: index out of range");
      ++edges[{a, b}];
      const std::size_t ra = find(a), rb = find(b);
      if (ra != rb) root[std::max(ra, rb)] = std::min(ra, rb);  // the lowest index is the part's root
    }
  for (const auto& [e, count] : edges) {
    const auto rev = edges.find({e.second, e.first});
    if (count != 1 || rev == edges.end() || rev->second != 1) ++r.open_edges;
  }
  r.closed = !indices.empty() && r.open_edges == 0;
  std::map<std::size_t, double> part;
  for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
    const Vec3 &a = positions[indices[t]], &b = positions[indices[t + 1]], &c = positions[indices[t + 2]];
    // 6 times the tetrahedron's volume; the division by 6 is done once, on the sums.
    const double v = a[0] * (b[1] * c[2] - b[2] * c[1]) + a[1] * (b[2] * c[0] - b[0] * c[2]) +
                     a[2] * (b[0] * c[1] - b[1] * c[0]);
    part[find(indices[t])] += v;
    r.total += v;
  }
  r.total /= 6.0;
  for (const auto& [root_index, v] : part) r.parts.push_back(v / 6.0);
  return r;
}

}  // namespace rotorcert::render
