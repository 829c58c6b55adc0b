// The camera of the render check: a perspective camera that frames a bounding box from a fixed
// direction, so that one camera, computed once per pose (from the reference's skinned positions,
// say), serves every implementation's frame of that pose and their pixels can be compared.
//
// Conventions: right-handed world coordinates in metres with +Y up, as glTF defines them (the
// built-in characters face +Z). The default view is from the front: the eye is on the +Z side of
// the box, raised by a small elevation angle, looking toward -Z at the box centre, so world +X
// appears on the right of the image and +Y at the top. Matrices are column-major Mat4 (types.hpp)
// with OpenGL's clip conventions: the view matrix maps the eye to the origin looking down -Z;
// the projection maps the visible depth range to normalised device z in [-1, 1] (near -> -1).
// Pixel coordinates: x to the right and y downward from the top-left corner of the image, the
// centre of pixel (i, j) at (i + 0.5, j + 0.5), matching Image (image.hpp).
#pragma once

#include <optional>
#include <span>

#include <rotorcert/render/scene.hpp>
#include <rotorcert/render/types.hpp>

namespace rotorcert::render {

/// Axis-aligned bounding box, min <= max componentwise.
struct Aabb {
  Vec3 min{0.0, 0.0, 0.0};
  Vec3 max{0.0, 0.0, 0.0};
};

/// The box of the points; std::invalid_argument when there are none or one is not finite.
Aabb bounding_box(std::span<const Vec3> points);

/// Perspective camera. Validity (checked by view_matrix and projection_matrix, which throw
/// std::invalid_argument otherwise): finite values, eye != target, up not parallel to the view
/// direction, 0 < fov_y < pi, 0 < near_plane < far_plane.
struct Camera {
  Vec3 eye{0.0, 0.0, 5.0};
  Vec3 target{0.0, 0.0, 0.0};
  Vec3 up{0.0, 1.0, 0.0};
  double fov_y = 0.5235987755982988;  // vertical field of view in radians (30 degrees)
  double near_plane = 0.1;             // distances from the eye, metres
  double far_plane = 100.0;
};

/// Where the framing camera stands. The view direction (target to eye) is
/// (sin(azimuth) cos(elevation), sin(elevation), cos(azimuth) cos(elevation)): azimuth 0 is the
/// front (+Z), positive azimuth turns toward +X; positive elevation looks down from above.
struct Framing {
  double elevation = 0.2617993877991494;  // radians (15 degrees)
  double azimuth = 0.0;                   // radians
  double fov_y = 0.5235987755982988;      // radians (30 degrees)
  double margin = 1.05;                   // >= 1: the bounding sphere's radius is scaled by this
};

/// A camera looking at the centre of `box` from the Framing direction, at the distance where the
/// box's bounding sphere (radius scaled by `margin`) fits both the vertical field of view and the
/// horizontal one of an image of this aspect ratio (width / height); so the whole box is in the
/// frame whatever its orientation. Near and far planes enclose the sphere. A degenerate box (a
/// point) is framed as a sphere of radius 1 mm. std::invalid_argument for a box that is not finite
/// or min > max, aspect <= 0, margin < 1, or elevation outside (-pi/2, pi/2).
Camera frame_box(const Aabb& box, double aspect, const Framing& framing = {});

/// World to eye coordinates (the gluLookAt matrix).
Mat4 view_matrix(const Camera& camera);

/// Eye to clip coordinates (the gluPerspective matrix) for an image of this aspect (width / height).
Mat4 projection_matrix(const Camera& camera, double aspect);

/// Where world point p lands in a width x height image: [x, y, depth] with x, y in pixel
/// coordinates (see above; not clamped to the image) and depth the window depth in [0, 1] for
/// points between the near and far planes. Nothing when p is not in front of the eye (clip w <= 0).
std::optional<Vec3> project_to_pixel(const Camera& camera, int width, int height, const Vec3& p);

}  // namespace rotorcert::render
