// Capsule skins for skeleton-only files (GLTF-4 of spec/SPEC.md).
#include <rotorcert/render/capsule.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include <rotorcert/render/gltf_load.hpp>
#include <rotorcert/render/transform.hpp>

namespace rotorcert::render {

namespace {

Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Vec3 scaled(const Vec3& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
Vec3 unit(const Vec3& a) { return scaled(a, 1.0 / std::sqrt(dot(a, a))); }

double smoothstep(double s) {
  s = std::clamp(s, 0.0, 1.0);
  return s * s * (3.0 - 2.0 * s);
}

}  // namespace

SkinnedMesh make_capsule_skin(const Skeleton& skeleton, const CapsuleOptions& options) {
  const unsigned segs = std::max(3u, options.segments);
  const unsigned caps = options.cap_rings;
  const unsigned body = std::max(2u, options.body_rings);
  const auto& joints = skeleton.joints;

  // Bind-pose joint positions: the translation of inverse(inverse bind).
  std::vector<Vec3> at(joints.size(), Vec3{0.0, 0.0, 0.0});
  for (std::size_t j = 0; j < joints.size(); ++j) {
    if (!joints[j].skinned) continue;
    const auto bind = inverse(joints[j].inverse_bind);
    if (!bind) throw GltfError("capsule skin: joint " + std::to_string(j) + " (" + joints[j].name + "): inverse bind matrix is singular");
    at[j] = {(*bind)[12], (*bind)[13], (*bind)[14]};
  }
  struct Bone {
    std::size_t parent, child;
    double length;
  };
  std::vector<Bone> bones;
  double longest = 0.0;
  for (std::size_t j = 0; j < joints.size(); ++j) {
    const int p = joints[j].parent;
    if (p < 0 || !joints[j].skinned || !joints[static_cast<std::size_t>(p)].skinned) continue;
    const Vec3 d = sub(at[j], at[static_cast<std::size_t>(p)]);
    const double len = std::sqrt(dot(d, d));
    bones.push_back({static_cast<std::size_t>(p), j, len});
    longest = std::max(longest, len);
  }

  SkinnedMesh mesh;
  mesh.name = "capsules";
  for (const Bone& bone : bones) {
    if (!(bone.length > 1e-6 * longest)) continue;  // a joint on its parent: no direction, no capsule
    const Vec3 origin = at[bone.parent];
    const Vec3 axis = unit(sub(at[bone.child], origin));
    // Any unit vector not parallel to the axis, then an orthonormal frame (e1, e2, axis).
    const Vec3 helper = std::abs(axis[0]) < 0.9 ? Vec3{1.0, 0.0, 0.0} : Vec3{0.0, 1.0, 0.0};
    const Vec3 e1 = unit(cross(axis, helper));
    const Vec3 e2 = cross(axis, e1);
    const double len = bone.length;
    const double r = options.radius_fraction * len;
    const auto base = static_cast<std::uint32_t>(mesh.positions.size());

    auto add_vertex = [&](double along, const Vec3& normal) {
      // along: distance from the parent joint along the axis; the surface point is the axis point
      // plus r * normal.
      const Vec3 c{origin[0] + axis[0] * along, origin[1] + axis[1] * along, origin[2] + axis[2] * along};
      mesh.positions.push_back({c[0] + r * normal[0], c[1] + r * normal[1], c[2] + r * normal[2]});
      mesh.normals.push_back(normal);
      const double wc = smoothstep(along / len);
      mesh.joints.push_back({static_cast<std::uint32_t>(bone.parent), static_cast<std::uint32_t>(bone.child), 0, 0});
      mesh.weights.push_back({1.0 - wc, wc, 0.0, 0.0});
    };
    // Rings from the parent-end pole to the child-end pole: polar angle phi from -pi/2 (parent
    // pole) to +pi/2 (child pole); the cylinder holds phi = 0 at `body` stations.
    struct Ring {
      double along, phi;
    };
    std::vector<Ring> rings;
    for (unsigned i = 1; i <= caps; ++i) rings.push_back({0.0, -std::numbers::pi / 2 + std::numbers::pi / 2 * i / (caps + 1)});
    for (unsigned i = 0; i < body; ++i) rings.push_back({len * i / (body - 1), 0.0});
    for (unsigned i = caps; i >= 1; --i) rings.push_back({len, std::numbers::pi / 2 - std::numbers::pi / 2 * i / (caps + 1)});

    add_vertex(0.0, scaled(axis, -1.0));  // parent pole
    for (const Ring& ring : rings) {
      for (unsigned k = 0; k < segs; ++k) {
        const double a = 2.0 * std::numbers::pi * k / segs;
        const double c = std::cos(ring.phi), s = std::sin(ring.phi);
        const Vec3 radial{e1[0] * std::cos(a) + e2[0] * std::sin(a), e1[1] * std::cos(a) + e2[1] * std::sin(a),
                          e1[2] * std::cos(a) + e2[2] * std::sin(a)};
        add_vertex(ring.along, {radial[0] * c + axis[0] * s, radial[1] * c + axis[1] * s, radial[2] * c + axis[2] * s});
      }
    }
    add_vertex(len, axis);  // child pole

    // Triangles, counter-clockwise seen from outside: (e1, e2, axis) is right-handed, so going
    // around with increasing angle and towards the child end faces outwards with (k, k+1 next ring).
    const auto nr = static_cast<std::uint32_t>(rings.size());
    auto ring_vertex = [&](std::uint32_t ring, std::uint32_t k) { return base + 1 + ring * segs + k % segs; };
    const std::uint32_t top = base + 1 + nr * segs;
    for (std::uint32_t k = 0; k < segs; ++k) mesh.indices.insert(mesh.indices.end(), {base, ring_vertex(0, k + 1), ring_vertex(0, k)});
    for (std::uint32_t i = 0; i + 1 < nr; ++i)
      for (std::uint32_t k = 0; k < segs; ++k) {
        const std::uint32_t a = ring_vertex(i, k), b = ring_vertex(i, k + 1), c = ring_vertex(i + 1, k + 1), d = ring_vertex(i + 1, k);
        mesh.indices.insert(mesh.indices.end(), {a, b, c, a, c, d});
      }
    for (std::uint32_t k = 0; k < segs; ++k) mesh.indices.insert(mesh.indices.end(), {top, ring_vertex(nr - 1, k), ring_vertex(nr - 1, k + 1)});
  }
  return mesh;
}

}  // namespace rotorcert::render
