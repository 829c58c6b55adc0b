#include <rotorcert/render/camera.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace rotorcert::render {

namespace {

constexpr double kPi = 3.14159265358979323846;

Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double norm(const Vec3& a) { return std::sqrt(dot(a, a)); }
Vec3 scaled(const Vec3& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
bool finite(const Vec3& a) { return std::isfinite(a[0]) && std::isfinite(a[1]) && std::isfinite(a[2]); }

void check_camera(const Camera& c) {
  if (!finite(c.eye) || !finite(c.target) || !finite(c.up) || !std::isfinite(c.fov_y) ||
      !std::isfinite(c.near_plane) || !std::isfinite(c.far_plane))
    throw std::invalid_argument("camera: a value is not finite");
  const Vec3 forward = sub(c.target, c.eye);
  if (norm(forward) == 0.0) throw std::invalid_argument("camera: eye and target coincide");
  // Relative test: up within ~1e-9 rad of the view axis gives no usable right vector.
  if (norm(cross(forward, c.up)) <= 1e-9 * norm(forward) * norm(c.up))
    throw std::invalid_argument("camera: up is zero or parallel to the view direction");
  if (!(c.fov_y > 0.0 && c.fov_y < kPi)) throw std::invalid_argument("camera: fov_y outside (0, pi)");
  if (!(c.near_plane > 0.0 && c.near_plane < c.far_plane))
    throw std::invalid_argument("camera: planes must satisfy 0 < near < far");
}

}  // namespace

Aabb bounding_box(std::span<const Vec3> points) {
  if (points.empty()) throw std::invalid_argument("bounding_box: no points");
  Aabb box{points[0], points[0]};
  for (const Vec3& p : points) {
    if (!finite(p)) throw std::invalid_argument("bounding_box: a point is not finite");
    for (std::size_t i = 0; i < 3; ++i) {
      box.min[i] = std::min(box.min[i], p[i]);
      box.max[i] = std::max(box.max[i], p[i]);
    }
  }
  return box;
}

Camera frame_box(const Aabb& box, double aspect, const Framing& framing) {
  if (!finite(box.min) || !finite(box.max)) throw std::invalid_argument("frame_box: box not finite");
  for (std::size_t i = 0; i < 3; ++i)
    if (box.min[i] > box.max[i]) throw std::invalid_argument("frame_box: box min > max");
  if (!(aspect > 0.0) || !std::isfinite(aspect)) throw std::invalid_argument("frame_box: aspect must be positive");
  if (!(framing.margin >= 1.0) || !std::isfinite(framing.margin)) throw std::invalid_argument("frame_box: margin must be >= 1");
  if (!(std::abs(framing.elevation) < kPi / 2)) throw std::invalid_argument("frame_box: elevation outside (-pi/2, pi/2)");
  if (!(framing.fov_y > 0.0 && framing.fov_y < kPi)) throw std::invalid_argument("frame_box: fov_y outside (0, pi)");

  const Vec3 centre = scaled({box.min[0] + box.max[0], box.min[1] + box.max[1], box.min[2] + box.max[2]}, 0.5);
  const double radius = std::max(0.5 * norm(sub(box.max, box.min)), 1e-3) * framing.margin;
  // The narrower of the two fields of view decides: a sphere of radius r seen under half-angle a
  // fills it at distance r / sin(a).
  const double half_x = std::atan(aspect * std::tan(framing.fov_y / 2));
  const double half = std::min(framing.fov_y / 2, half_x);
  const double distance = radius / std::sin(half);
  const double ce = std::cos(framing.elevation);
  const Vec3 direction{std::sin(framing.azimuth) * ce, std::sin(framing.elevation), std::cos(framing.azimuth) * ce};

  Camera c;
  c.eye = {centre[0] + distance * direction[0], centre[1] + distance * direction[1], centre[2] + distance * direction[2]};
  c.target = centre;
  c.up = {0.0, 1.0, 0.0};
  c.fov_y = framing.fov_y;
  // The sphere lies between distance - radius and distance + radius; the near plane stays at
  // least 1% of the distance from the eye so that the depth buffer keeps its precision.
  c.near_plane = std::max(distance - 1.5 * radius, 0.01 * distance);
  c.far_plane = distance + 1.5 * radius;
  return c;
}

Mat4 view_matrix(const Camera& camera) {
  check_camera(camera);
  const Vec3 f = scaled(sub(camera.target, camera.eye), 1.0 / norm(sub(camera.target, camera.eye)));
  Vec3 s = cross(f, camera.up);
  s = scaled(s, 1.0 / norm(s));
  const Vec3 u = cross(s, f);
  Mat4 m{};
  // Rows s, u, -f (column-major storage: element (r, c) at m[4c + r]).
  for (std::size_t c = 0; c < 3; ++c) {
    m[4 * c + 0] = s[c];
    m[4 * c + 1] = u[c];
    m[4 * c + 2] = -f[c];
  }
  m[12] = -dot(s, camera.eye);
  m[13] = -dot(u, camera.eye);
  m[14] = dot(f, camera.eye);
  m[15] = 1.0;
  return m;
}

Mat4 projection_matrix(const Camera& camera, double aspect) {
  check_camera(camera);
  if (!(aspect > 0.0) || !std::isfinite(aspect)) throw std::invalid_argument("projection_matrix: aspect must be positive");
  const double f = 1.0 / std::tan(camera.fov_y / 2);
  const double n = camera.near_plane, fa = camera.far_plane;
  Mat4 m{};
  m[0] = f / aspect;
  m[5] = f;
  m[10] = (fa + n) / (n - fa);
  m[11] = -1.0;
  m[14] = 2.0 * fa * n / (n - fa);
  return m;
}

std::optional<Vec3> project_to_pixel(const Camera& camera, int width, int height, const Vec3& p) {
  if (width <= 0 || height <= 0) throw std::invalid_argument("project_to_pixel: image size must be positive");
  const Mat4 view = view_matrix(camera);
  const Mat4 proj = projection_matrix(camera, static_cast<double>(width) / height);
  std::array<double, 4> e{}, clip{};
  for (std::size_t r = 0; r < 4; ++r) e[r] = view[r] * p[0] + view[4 + r] * p[1] + view[8 + r] * p[2] + view[12 + r];
  for (std::size_t r = 0; r < 4; ++r) clip[r] = proj[r] * e[0] + proj[4 + r] * e[1] + proj[8 + r] * e[2] + proj[12 + r] * e[3];
  if (!(clip[3] > 0.0)) return std::nullopt;
  const double nx = clip[0] / clip[3], ny = clip[1] / clip[3], nz = clip[2] / clip[3];
  // OpenGL's viewport transform, with y flipped because image rows run top to bottom.
  return Vec3{(nx + 1.0) * 0.5 * width, (1.0 - ny) * 0.5 * height, (nz + 1.0) * 0.5};
}

}  // namespace rotorcert::render
