// The camera (camera.hpp) and the OSMesa renderer (osmesa_renderer.hpp): frames of the built-in
// characters drawn with linear blend and dual quaternion skinning in the vertex shader, compared
// with the same meshes skinned here on the CPU in binary64 and drawn through the pass-through
// mode. The CPU skinning below is written from the formulas (scene.hpp's LBS; DQS by the rotation
// matrix of the blended real part plus t = 2 d conj(r), not by the shader's cross products), so a
// wrong shader formula shows as a frame that differs.
//
// Tests that need an OpenGL context skip, saying why, when OSMesa cannot make one.
// ROTORCERT_RENDER_TEST_OUT=<dir> writes the frames the tests compare as PNG files, to look at.
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <limits>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include <rotorcert/render/camera.hpp>
#include <rotorcert/render/character.hpp>
#include <rotorcert/render/image.hpp>
#include <rotorcert/render/osmesa_renderer.hpp>
#include <rotorcert/render/sample.hpp>
#include <rotorcert/render/transform.hpp>

namespace {

using namespace rotorcert::render;

constexpr double kPi = 3.14159265358979323846;
// Mesh colours are at most 200 and shading only darkens them, so no mesh pixel can equal the
// white background: "not background" is exactly "covered by a triangle".
const Rgba8 kBackground{255, 255, 255, 255};
const Rgba8 kMeshColour{200, 190, 180, 255};

// Agreement of two frames of the same pose drawn by different float paths (shader binary32 vs
// CPU binary64 rounded to binary32, or LBS vs DQS at the rest pose). Vertices then differ by a
// few binary32 ulps (about 1e-7 m on a 2 m character) while a pixel is millimetres wide, so
// coverage almost never changes, and the lit colour differs only where its rounding to 8 bits
// flips: one level in a few pixels. Allowed:
//   - at most kOverPixels pixels differing by more than kLevels levels (a coverage change at an
//     edge through a pixel centre, or a visibly different normal), and
//   - at most kShareDiffering of the pixels differing at all: a formula difference moves whole
//     regions by a level or two (a wrong third influence in the full character's LBS shifted
//     1172 pixels of 262144 = 0.45% while only 5 changed by more than 2 levels).
// Observed on llvmpipe (Mesa 22.3.6, LLVM 15): at most 4 pixels differ, by 1 level, none by more
// (printed by expect_agree for every comparison).
constexpr int kLevels = 2;
constexpr std::size_t kOverPixels = 8;
constexpr double kShareDiffering = 1e-3;

// --- CPU skinning in binary64, from the definitions --------------------------------------------

Vec3 add(const Vec3& a, const Vec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
Vec3 scaled(const Vec3& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
Vec3 normalized(const Vec3& a) { return scaled(a, 1.0 / std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2])); }

Quat qmul(const Quat& a, const Quat& b) {
  return {a[3] * b[0] + a[0] * b[3] + a[1] * b[2] - a[2] * b[1], a[3] * b[1] - a[0] * b[2] + a[1] * b[3] + a[2] * b[0],
          a[3] * b[2] + a[0] * b[1] - a[1] * b[0] + a[2] * b[3], a[3] * b[3] - a[0] * b[0] - a[1] * b[1] - a[2] * b[2]};
}
Quat conj(const Quat& q) { return {-q[0], -q[1], -q[2], q[3]}; }

struct Skinned {
  std::vector<Vec3> positions, normals;
};

/// scene.hpp: v' = sum_k w_k M_k [p, 1]; normals by the blended matrix's linear part, renormalised.
Skinned cpu_lbs(const SkinnedMesh& mesh, const std::vector<Mat4>& palette) {
  Skinned out;
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    Mat4 m{};
    for (std::size_t k = 0; k < 4; ++k)
      for (std::size_t i = 0; i < 16; ++i) m[i] += mesh.weights[v][k] * palette[mesh.joints[v][k]][i];
    out.positions.push_back(transform_point(m, mesh.positions[v]));
    out.normals.push_back(normalized(transform_vector(m, mesh.normals[v])));
  }
  return out;
}

/// Shepperd's method: the unit quaternion of the rotation part of a rigid m.
Quat quaternion_of(const Mat4& m) {
  const auto r = [&](int row, int col) { return m[static_cast<std::size_t>(4 * col + row)]; };
  const double trace = r(0, 0) + r(1, 1) + r(2, 2);
  Quat q;
  if (trace > 0) {
    const double s = 2 * std::sqrt(trace + 1);
    q = {(r(2, 1) - r(1, 2)) / s, (r(0, 2) - r(2, 0)) / s, (r(1, 0) - r(0, 1)) / s, s / 4};
  } else if (r(0, 0) >= r(1, 1) && r(0, 0) >= r(2, 2)) {
    const double s = 2 * std::sqrt(1 + r(0, 0) - r(1, 1) - r(2, 2));
    q = {s / 4, (r(0, 1) + r(1, 0)) / s, (r(0, 2) + r(2, 0)) / s, (r(2, 1) - r(1, 2)) / s};
  } else if (r(1, 1) >= r(2, 2)) {
    const double s = 2 * std::sqrt(1 + r(1, 1) - r(0, 0) - r(2, 2));
    q = {(r(0, 1) + r(1, 0)) / s, s / 4, (r(1, 2) + r(2, 1)) / s, (r(0, 2) - r(2, 0)) / s};
  } else {
    const double s = 2 * std::sqrt(1 + r(2, 2) - r(0, 0) - r(1, 1));
    q = {(r(0, 2) + r(2, 0)) / s, (r(1, 2) + r(2, 1)) / s, s / 4, (r(1, 0) - r(0, 1)) / s};
  }
  const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  return {q[0] / n, q[1] / n, q[2] / n, q[3] / n};
}

/// The dual quaternions of rigid skinning matrices: real = rotation, dual = 0.5 t real (DQ-1).
std::vector<DualQuaternion> dual_quaternions(const std::vector<Mat4>& palette) {
  std::vector<DualQuaternion> out;
  for (const Mat4& m : palette) {
    DualQuaternion q;
    q.real = quaternion_of(m);
    // Guards this helper: the quaternion's matrix is the palette's rotation (to binary32 level,
    // as the inverse binds are binary32 values).
    const Mat4 back = rotation_matrix(q.real);
    for (int c = 0; c < 3; ++c)
      for (int r = 0; r < 3; ++r) EXPECT_NEAR(back[static_cast<std::size_t>(4 * c + r)], m[static_cast<std::size_t>(4 * c + r)], 1e-5);
    const Quat t{m[12], m[13], m[14], 0.0};
    const Quat d = qmul(t, q.real);
    q.dual = {0.5 * d[0], 0.5 * d[1], 0.5 * d[2], 0.5 * d[3]};
    out.push_back(q);
  }
  return out;
}

/// DQS (Kavan et al.): pivot-aligned blend, divided by |real|, then p' = R(r) p + t with
/// t = vector part of 2 d conj(r) and R(r) the rotation matrix of r; n' = R(r) n.
Skinned cpu_dqs(const SkinnedMesh& mesh, const std::vector<DualQuaternion>& palette) {
  Skinned out;
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    std::size_t pivot = 0;
    while (pivot < 3 && !(mesh.weights[v][pivot] > 0)) ++pivot;
    const Quat& rp = palette[mesh.joints[v][pivot]].real;
    Quat br{}, bd{};
    for (std::size_t k = 0; k < 4; ++k) {
      double w = mesh.weights[v][k];
      if (!(w > 0)) continue;
      const DualQuaternion& q = palette[mesh.joints[v][k]];
      if (q.real[0] * rp[0] + q.real[1] * rp[1] + q.real[2] * rp[2] + q.real[3] * rp[3] < 0) w = -w;
      for (std::size_t i = 0; i < 4; ++i) {
        br[i] += w * q.real[i];
        bd[i] += w * q.dual[i];
      }
    }
    const double n = std::sqrt(br[0] * br[0] + br[1] * br[1] + br[2] * br[2] + br[3] * br[3]);
    for (std::size_t i = 0; i < 4; ++i) {
      br[i] /= n;
      bd[i] /= n;
    }
    const Quat t = qmul(bd, conj(br));
    const Mat4 rot = rotation_matrix(br);
    out.positions.push_back(add(transform_vector(rot, mesh.positions[v]), {2 * t[0], 2 * t[1], 2 * t[2]}));
    out.normals.push_back(normalized(transform_vector(rot, mesh.normals[v])));
  }
  return out;
}

// --- Poses and frames --------------------------------------------------------------------------

const Clip& clip_named(const Scene& s, const std::string& name) {
  for (const auto& c : s.clips)
    if (c.name == name) return c;
  throw std::runtime_error("no clip " + name);
}

std::vector<Mat4> rest_palette(const Scene& s) {
  return skinning_matrices(s.skeleton, global_matrices(s.skeleton, rest_pose(s.skeleton)));
}
std::vector<Mat4> clip_palette(const Scene& s, const std::string& clip, double t) {
  return skinning_matrices(s.skeleton, global_matrices(s.skeleton, sample_pose(s.skeleton, clip_named(s, clip), t)));
}

const SkinnedMesh& only_mesh(const Scene& s) {
  EXPECT_EQ(s.meshes.size(), 1u);
  return s.meshes.at(0);
}

RenderJob job_for(const Camera& camera, int width, int height) {
  RenderJob job;
  job.camera = camera;
  job.width = width;
  job.height = height;
  job.background = kBackground;
  return job;
}

MeshDraw lbs_draw(const SkinnedMesh& mesh, const std::vector<Mat4>& palette) {
  MeshDraw d;
  d.mesh = &mesh;
  d.mode = SkinningMode::linear_blend;
  d.matrices = palette;
  d.colour = kMeshColour;
  return d;
}
MeshDraw dqs_draw(const SkinnedMesh& mesh, const std::vector<DualQuaternion>& palette) {
  MeshDraw d;
  d.mesh = &mesh;
  d.mode = SkinningMode::dual_quaternion;
  d.dual_quaternions = palette;
  d.colour = kMeshColour;
  return d;
}
MeshDraw pass_draw(const SkinnedMesh& mesh, const Skinned& skinned) {
  MeshDraw d;
  d.mesh = &mesh;
  d.mode = SkinningMode::pass_through;
  d.positions = skinned.positions;
  d.normals = skinned.normals;
  d.colour = kMeshColour;
  return d;
}

void save(const Image& image, const std::string& name) {
  if (const char* dir = std::getenv("ROTORCERT_RENDER_TEST_OUT")) write_png(std::filesystem::path(dir) / (name + ".png"), image);
}

std::size_t covered_pixels(const Image& image, PixelBox* box) {
  std::size_t n = 0;
  PixelBox b{image.width, image.height, -1, -1};
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      if (image.pixel(x, y) != kBackground) {
        ++n;
        b = {std::min(b.x_min, x), std::min(b.y_min, y), std::max(b.x_max, x), std::max(b.y_max, y)};
      }
  if (box) *box = b;
  return n;
}

/// The image rectangle (x_min, y_min, x_max, y_max) holding the projections of the box's corners.
std::array<double, 4> projected_box(const Camera& camera, int w, int h, const Aabb& box) {
  std::array<double, 4> r{1e300, 1e300, -1e300, -1e300};
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 p{(corner & 1) ? box.max[0] : box.min[0], (corner & 2) ? box.max[1] : box.min[1], (corner & 4) ? box.max[2] : box.min[2]};
    const auto q = project_to_pixel(camera, w, h, p);
    EXPECT_TRUE(q.has_value());
    if (!q) continue;
    r = {std::min(r[0], (*q)[0]), std::min(r[1], (*q)[1]), std::max(r[2], (*q)[0]), std::max(r[3], (*q)[1])};
  }
  return r;
}

void expect_agree(const Image& a, const Image& b, const std::string& what) {
  const ImageDiff d = compare(a, b, kLevels);
  std::cout << "[ agree    ] " << what << ": max " << d.max_channel_diff << " levels, " << d.differing_pixels
            << " pixels differ, " << d.over_threshold_pixels << " by more than " << kLevels << ", PSNR " << d.psnr_db << " dB\n";
  EXPECT_LE(d.over_threshold_pixels, kOverPixels) << what << ": PSNR " << d.psnr_db << " dB, max " << d.max_channel_diff;
  EXPECT_LE(d.share_differing, kShareDiffering) << what << ": " << d.differing_pixels << " pixels differ";
}

// --- Camera ------------------------------------------------------------------------------------

TEST(RenderCamera, FramesTheBoxFromTheFrontAndAbove) {
  const Aabb box{{-0.8, 0.0, -0.2}, {0.8, 1.8, 0.3}};
  for (const auto& [w, h] : std::vector<std::pair<int, int>>{{512, 512}, {800, 300}, {300, 800}}) {
    const Camera c = frame_box(box, static_cast<double>(w) / h);
    // The eye is in front (+Z) of the box and above its centre, looking at the centre.
    EXPECT_GT(c.eye[2], box.max[2]);
    EXPECT_GT(c.eye[1], 0.9);
    EXPECT_DOUBLE_EQ(c.target[1], 0.9);
    const auto centre = project_to_pixel(c, w, h, c.target);
    ASSERT_TRUE(centre);
    EXPECT_NEAR((*centre)[0], w / 2.0, 1e-9 * w);
    EXPECT_NEAR((*centre)[1], h / 2.0, 1e-9 * h);
    // Every corner lands inside the image, strictly between the near and far planes.
    for (int corner = 0; corner < 8; ++corner) {
      const Vec3 p{(corner & 1) ? box.max[0] : box.min[0], (corner & 2) ? box.max[1] : box.min[1], (corner & 4) ? box.max[2] : box.min[2]};
      const auto q = project_to_pixel(c, w, h, p);
      ASSERT_TRUE(q);
      EXPECT_GE((*q)[0], 0.0);
      EXPECT_LE((*q)[0], w);
      EXPECT_GE((*q)[1], 0.0);
      EXPECT_LE((*q)[1], h);
      EXPECT_GT((*q)[2], 0.0);
      EXPECT_LT((*q)[2], 1.0);
    }
    // World +X is to the right of the image, +Y up (smaller row).
    const auto right = project_to_pixel(c, w, h, add(c.target, {0.1, 0, 0}));
    const auto up = project_to_pixel(c, w, h, add(c.target, {0, 0.1, 0}));
    EXPECT_GT((*right)[0], (*centre)[0]);
    EXPECT_LT((*up)[1], (*centre)[1]);
  }
}

TEST(RenderCamera, ViewAndProjectionMatrices) {
  Camera c;
  c.eye = {0, 0, 5};
  c.target = {0, 0, 0};
  c.fov_y = kPi / 2;  // tan(45 deg) = 1: the image's top edge is at y = distance from the eye
  c.near_plane = 1;
  c.far_plane = 9;
  // The view moves the eye to the origin: a point at the target is at eye depth -5.
  const Vec3 e = transform_point(view_matrix(c), {0, 0, 0});
  EXPECT_NEAR(e[2], -5.0, 1e-15);
  // Near plane -> depth 0, far plane -> 1; the top edge of the view at distance 5 is row 0.
  EXPECT_NEAR((*project_to_pixel(c, 100, 100, {0, 0, 4}))[2], 0.0, 1e-12);
  EXPECT_NEAR((*project_to_pixel(c, 100, 100, {0, 0, -4}))[2], 1.0, 1e-12);
  EXPECT_NEAR((*project_to_pixel(c, 100, 100, {0, 5, 0}))[1], 0.0, 1e-12);
  EXPECT_NEAR((*project_to_pixel(c, 200, 100, {10, 0, 0}))[0], 200.0, 1e-12);  // aspect 2: x reaches 2 * 5
  EXPECT_FALSE(project_to_pixel(c, 100, 100, {0, 0, 6}).has_value());            // behind the eye
  Camera bad = c;
  bad.up = {0, 0, 1};  // parallel to the view direction
  EXPECT_THROW(view_matrix(bad), std::invalid_argument);
  bad = c;
  bad.near_plane = 0;
  EXPECT_THROW(projection_matrix(bad, 1.0), std::invalid_argument);
  EXPECT_THROW(frame_box({{0, 0, 0}, {1, 1, 1}}, 0.0), std::invalid_argument);
  EXPECT_THROW(bounding_box(std::vector<Vec3>{}), std::invalid_argument);
}

// --- Job validation (no context needed) --------------------------------------------------------

TEST(RenderJob, ValidateNamesTheProblem) {
  const Scene s = make_character(Complexity::simple);
  const SkinnedMesh& mesh = only_mesh(s);
  const std::vector<Mat4> palette = rest_palette(s);
  const Camera camera = frame_box(bounding_box(mesh.positions), 1.0);

  RenderJob job = job_for(camera, 64, 64);
  job.meshes.push_back(lbs_draw(mesh, palette));
  EXPECT_FALSE(job.validate().has_value()) << *job.validate();

  const auto problem = [](const RenderJob& j) { return j.validate().value_or(""); };
  RenderJob bad = job;
  bad.width = 0;
  EXPECT_NE(problem(bad).find("image size"), std::string::npos);
  bad = job;
  bad.meshes.clear();
  EXPECT_NE(problem(bad).find("no meshes"), std::string::npos);
  bad = job;
  bad.meshes[0].mesh = nullptr;
  EXPECT_NE(problem(bad).find("no mesh"), std::string::npos);
  // A palette one joint short of the joints the mesh uses.
  std::size_t used = 0;
  for (const auto& js : mesh.joints)
    for (auto j : js) used = std::max<std::size_t>(used, j + 1);
  bad = job;
  bad.meshes[0].matrices = std::span<const Mat4>(palette).first(used - 1);
  EXPECT_NE(problem(bad).find("palette has"), std::string::npos) << problem(bad);
  bad = job;
  bad.meshes[0].mode = SkinningMode::dual_quaternion;  // no dual quaternions given
  EXPECT_NE(problem(bad).find("empty palette"), std::string::npos);
  std::vector<DualQuaternion> zero(palette.size());
  zero[mesh.joints[0][0]].real = {0, 0, 0, 0};
  bad.meshes[0].dual_quaternions = zero;
  EXPECT_NE(problem(bad).find("zero real part"), std::string::npos);
  bad = job;
  bad.meshes[0].mode = SkinningMode::pass_through;
  bad.meshes[0].positions = mesh.positions;  // normals missing
  EXPECT_NE(problem(bad).find("pass_through"), std::string::npos);
  SkinnedMesh broken = mesh;
  broken.indices.back() = static_cast<std::uint32_t>(mesh.positions.size());
  bad = job;
  bad.meshes[0].mesh = &broken;
  EXPECT_NE(problem(bad).find("index"), std::string::npos);
  SkinnedMesh weightless = mesh;
  weightless.weights[1] = {0, 0, 0, 0};
  bad = job;
  bad.meshes[0].mesh = &weightless;
  EXPECT_NE(problem(bad).find("no positive weight"), std::string::npos);
  std::vector<Mat4> inf_palette = palette;
  inf_palette[0][0] = std::numeric_limits<double>::infinity();
  bad = job;
  bad.meshes[0].matrices = inf_palette;
  EXPECT_NE(problem(bad).find("not finite"), std::string::npos);
}

// --- Rendering ---------------------------------------------------------------------------------

class Render : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    try {
      const auto t0 = std::chrono::steady_clock::now();
      renderer_ = std::make_unique<OsmesaRenderer>();
      const std::chrono::duration<double, std::milli> took = std::chrono::steady_clock::now() - t0;
      std::cout << "[ renderer ] " << renderer_->description() << " (context and shaders: " << took.count() << " ms)\n";
    } catch (const RenderError& e) {
      why_ = e.what();
    }
  }
  static void TearDownTestSuite() { renderer_.reset(); }
  void SetUp() override {
    if (!renderer_) GTEST_SKIP() << "no OpenGL context: " << why_;
  }
  static OsmesaRenderer& renderer() { return *renderer_; }

  static std::unique_ptr<OsmesaRenderer> renderer_;
  static std::string why_;
};
std::unique_ptr<OsmesaRenderer> Render::renderer_;
std::string Render::why_;

TEST_F(Render, InvalidJobThrowsInvalidArgument) {
  RenderJob job;
  EXPECT_THROW(renderer().run(job), std::invalid_argument);
}

TEST_F(Render, RestPoseModesAgreeAndFillTheFrame) {
  for (const Complexity c : {Complexity::simple, Complexity::medium}) {
    SCOPED_TRACE(to_string(c));
    const Scene s = make_character(c);
    const SkinnedMesh& mesh = only_mesh(s);
    const std::vector<Mat4> palette = rest_palette(s);
    const std::vector<DualQuaternion> dq = dual_quaternions(palette);
    const Skinned cpu = cpu_lbs(mesh, palette);
    const int w = 320, h = 240;
    const Aabb box = bounding_box(cpu.positions);
    const Camera camera = frame_box(box, static_cast<double>(w) / h);

    RenderJob job = job_for(camera, w, h);
    job.meshes = {lbs_draw(mesh, palette)};
    const Image lbs = renderer().run(job);
    job.meshes = {dqs_draw(mesh, dq)};
    const Image dqs = renderer().run(job);
    job.meshes = {pass_draw(mesh, cpu)};
    const Image pass = renderer().run(job);
    save(lbs, std::string("rest_lbs_") + to_string(c));
    save(dqs, std::string("rest_dqs_") + to_string(c));
    save(pass, std::string("rest_cpu_") + to_string(c));

    ASSERT_EQ(lbs.width, w);
    ASSERT_EQ(lbs.height, h);
    // The character is drawn, and only where the camera says its box lands.
    PixelBox drawn;
    const std::size_t n = covered_pixels(lbs, &drawn);
    EXPECT_GT(n, static_cast<std::size_t>(w * h / 50)) << "the character covers under 2% of the frame";
    const auto expected = projected_box(camera, w, h, box);
    EXPECT_GE(drawn.x_min, std::floor(expected[0]));
    EXPECT_GE(drawn.y_min, std::floor(expected[1]));
    EXPECT_LE(drawn.x_max, std::ceil(expected[2]));
    EXPECT_LE(drawn.y_max, std::ceil(expected[3]));
    EXPECT_GT(drawn.x_min, 0);
    EXPECT_GT(drawn.y_min, 0);
    EXPECT_LT(drawn.x_max, w - 1);
    EXPECT_LT(drawn.y_max, h - 1);
    // The palette is the identity to binary32 level here, so all three paths draw the bind pose.
    expect_agree(lbs, pass, std::string("rest LBS shader vs CPU, ") + to_string(c));
    expect_agree(dqs, pass, std::string("rest DQS shader vs CPU LBS, ") + to_string(c));
    expect_agree(lbs, dqs, std::string("rest LBS vs DQS shader, ") + to_string(c));
  }
}

/// Shader skinning against CPU skinning of the same posed palette: this is where a wrong formula in
/// either shader shows (at the rest pose every palette entry is close to the identity).
void check_posed(OsmesaRenderer& renderer, Complexity c, const std::string& clip, double t, int w, int h) {
  SCOPED_TRACE(std::string(to_string(c)) + " " + clip);
  const Scene s = make_character(c);
  const SkinnedMesh& mesh = only_mesh(s);
  const std::vector<Mat4> palette = clip_palette(s, clip, t);
  const std::vector<DualQuaternion> dq = dual_quaternions(palette);
  const Skinned lbs_cpu = cpu_lbs(mesh, palette), dqs_cpu = cpu_dqs(mesh, dq);
  const Camera camera = frame_box(bounding_box(lbs_cpu.positions), static_cast<double>(w) / h);
  RenderJob job = job_for(camera, w, h);
  job.meshes = {lbs_draw(mesh, palette)};
  const Image lbs = renderer.run(job);
  job.meshes = {pass_draw(mesh, lbs_cpu)};
  const Image lbs_ref = renderer.run(job);
  job.meshes = {dqs_draw(mesh, dq)};
  const Image dqs = renderer.run(job);
  job.meshes = {pass_draw(mesh, dqs_cpu)};
  const Image dqs_ref = renderer.run(job);
  const std::string tag = std::string(to_string(c)) + "_" + clip;
  save(side_by_side({lbs, lbs_ref, dqs, dqs_ref}, 4, {0, 0, 0, 255}), "posed_" + tag);
  save(diff_heat(lbs, dqs), "posed_lbs_vs_dqs_heat_" + tag);
  expect_agree(lbs, lbs_ref, tag + " LBS shader vs CPU");
  expect_agree(dqs, dqs_ref, tag + " DQS shader vs CPU");
}

TEST_F(Render, PosedShaderSkinningMatchesCpu) {
  check_posed(renderer(), Complexity::simple, "bend", 2.0, 256, 256);
  // Not at the twist's end: a half turn puts the tip's and mid's real parts at dot 0, where the
  // hemisphere choice, and so the DQS result, hangs on the last bit of binary32 vs binary64.
  check_posed(renderer(), Complexity::simple, "twist", 1.5, 256, 256);
  check_posed(renderer(), Complexity::medium, "bend", 2.0, 320, 320);
  check_posed(renderer(), Complexity::medium, "twist", 1.2, 320, 320);
}

TEST_F(Render, RotatedJointMovesPixels) {
  const Scene s = make_character(Complexity::medium);
  const SkinnedMesh& mesh = only_mesh(s);
  const std::vector<Mat4> rest = rest_palette(s), bent = clip_palette(s, "bend", 2.0);
  const int w = 320, h = 320;
  const Camera camera = frame_box(bounding_box(cpu_lbs(mesh, rest).positions), 1.0);
  RenderJob job = job_for(camera, w, h);
  job.meshes = {lbs_draw(mesh, rest)};
  const Image before = renderer().run(job);
  job.meshes = {lbs_draw(mesh, bent)};
  const Image after = renderer().run(job);
  save(diff_heat(before, after), "bend_vs_rest_heat");
  const ImageDiff d = compare(before, after, kLevels);
  // The forearms (0.25 m of arm and the hands, each side) turn by 135 degrees: thousands of pixels.
  EXPECT_GT(d.over_threshold_pixels, static_cast<std::size_t>(w * h / 100));
  // Only the arms move: nothing changes below the chest (rows under the projection of the
  // spine at y = 1.2 m, below the arms at 1.45 m and below where the bent forearms reach).
  ASSERT_TRUE(d.differing_box);
  const auto chest = project_to_pixel(camera, w, h, {0.0, 1.2, 0.0});
  ASSERT_TRUE(chest);
  EXPECT_LT(d.differing_box->y_max, (*chest)[1]);

  // Dual quaternion skinning of the half-turned wrists keeps the wrist's volume; linear blending
  // collapses it (the candy wrapper): the two modes give visibly different frames there.
  const std::vector<Mat4> twisted = clip_palette(s, "twist", 2.0);
  const std::vector<DualQuaternion> twisted_dq = dual_quaternions(twisted);
  job.meshes = {lbs_draw(mesh, twisted)};
  const Image lbs = renderer().run(job);
  job.meshes = {dqs_draw(mesh, twisted_dq)};
  const Image dqs = renderer().run(job);
  save(diff_heat(lbs, dqs), "twist_lbs_vs_dqs_heat");
  EXPECT_GT(compare(lbs, dqs, kLevels).over_threshold_pixels, 10 * kOverPixels);
}

TEST_F(Render, DualQuaternionSignsDoNotMatter) {
  // sigma and -sigma are the same motion: with the hemisphere alignment of the blend, negating any
  // palette entries changes nothing (negation is exact in binary32, so not a single bit).
  const Scene s = make_character(Complexity::medium);
  const SkinnedMesh& mesh = only_mesh(s);
  const std::vector<DualQuaternion> dq = dual_quaternions(clip_palette(s, "bend", 1.5));
  std::vector<DualQuaternion> flipped = dq;
  for (std::size_t j = 0; j < flipped.size(); j += 2)
    for (std::size_t i = 0; i < 4; ++i) {
      flipped[j].real[i] = -flipped[j].real[i];
      flipped[j].dual[i] = -flipped[j].dual[i];
    }
  const Camera camera = frame_box(bounding_box(mesh.positions), 1.0);
  RenderJob job = job_for(camera, 256, 256);
  job.meshes = {dqs_draw(mesh, dq)};
  const Image plain = renderer().run(job);
  job.meshes = {dqs_draw(mesh, flipped)};
  const Image other = renderer().run(job);
  save(diff_heat(plain, other), "dq_signs_heat");
  EXPECT_EQ(compare(plain, other).differing_pixels, 0u);
}

TEST_F(Render, DepthTestKeepsTheNearerMesh) {
  // The same character twice, one copy blue, 0.3 m nearer the camera and 0.1 m to its left:
  // whatever the draw order, the nearer copy hides the other where they overlap, and each shows
  // where they do not.
  const Scene s = make_character(Complexity::medium);
  const SkinnedMesh& mesh = only_mesh(s);
  const std::vector<Mat4> palette = rest_palette(s);
  std::vector<Mat4> nearer;
  Mat4 shift = identity_matrix();
  shift[12] = 0.1;
  shift[14] = 0.3;
  for (const Mat4& m : palette) nearer.push_back(multiply(shift, m));
  const Camera camera = frame_box(bounding_box(mesh.positions), 1.0, Framing{.elevation = 0.0});
  RenderJob job = job_for(camera, 256, 256);
  MeshDraw far_draw = lbs_draw(mesh, palette), near_draw = lbs_draw(mesh, nearer);
  near_draw.colour = {40, 60, 200, 255};
  job.meshes = {far_draw, near_draw};
  const Image far_first = renderer().run(job);
  job.meshes = {near_draw, far_draw};
  const Image near_first = renderer().run(job);
  save(side_by_side({far_first, near_first}, 4, {0, 0, 0, 255}), "depth_order");
  EXPECT_EQ(compare(far_first, near_first).differing_pixels, 0u);
  std::size_t blue = 0, grey = 0;
  for (int y = 0; y < 256; ++y)
    for (int x = 0; x < 256; ++x) {
      const Rgba8 p = far_first.pixel(x, y);
      if (p != kBackground) ++(p[2] > p[0] ? blue : grey);
    }
  EXPECT_GT(blue, 1000u);
  EXPECT_GT(grey, 100u);
  // Where both torsos are (x = 0.05 m, chest height), the nearer copy is what is seen.
  const auto chest = project_to_pixel(camera, 256, 256, {0.05, 1.25, 0.3});
  ASSERT_TRUE(chest);
  const Rgba8 seen = far_first.pixel(static_cast<int>((*chest)[0]), static_cast<int>((*chest)[1]));
  EXPECT_GT(seen[2], seen[0]) << "pixel " << int(seen[0]) << " " << int(seen[1]) << " " << int(seen[2]);
}

TEST_F(Render, Deterministic) {
  const Scene s = make_character(Complexity::medium);
  const SkinnedMesh& mesh = only_mesh(s);
  const std::vector<Mat4> palette = clip_palette(s, "bend", 1.0);
  const std::vector<DualQuaternion> dq = dual_quaternions(palette);
  const Camera camera = frame_box(bounding_box(mesh.positions), 1.0);
  RenderJob job = job_for(camera, 200, 200);
  job.meshes = {dqs_draw(mesh, dq), lbs_draw(mesh, palette)};
  job.meshes[1].colour = {90, 120, 200, 255};
  const Image first = renderer().run(job);
  // Another size in between (the framebuffer is reallocated), then the same job again.
  RenderJob other = job;
  other.width = 77;
  other.height = 131;
  EXPECT_EQ(renderer().run(other).width, 77);
  EXPECT_EQ(renderer().run(job).rgba, first.rgba);
  // A second context renders the same bytes.
  OsmesaRenderer second;
  EXPECT_EQ(second.run(job).rgba, first.rgba);
  EXPECT_EQ(renderer().run(job).rgba, first.rgba);
}

TEST_F(Render, FullCharacterAt512IsFastAndAgrees) {
  const Scene s = make_character(Complexity::full);
  const SkinnedMesh& mesh = only_mesh(s);
  std::cout << "[ full     ] " << mesh.positions.size() << " vertices, " << mesh.triangle_count() << " triangles\n";
  const std::vector<Mat4> palette = clip_palette(s, "walk", 0.5);
  const std::vector<DualQuaternion> dq = dual_quaternions(palette);
  const Skinned cpu = cpu_lbs(mesh, palette);
  const Camera camera = frame_box(bounding_box(cpu.positions), 1.0);
  RenderJob job = job_for(camera, 512, 512);
  job.meshes = {lbs_draw(mesh, palette)};
  using clock = std::chrono::steady_clock;
  const auto time = [&](const RenderJob& j, Image& out) {
    const auto t0 = clock::now();
    out = renderer().run(j);
    return std::chrono::duration<double, std::milli>(clock::now() - t0).count();
  };
  // Warm-up: the first draw of a size allocates the framebuffer (and llvmpipe may compile
  // shader variants); printed, not timed below.
  Image warm;
  const double t_first = time(job, warm);
  Image lbs, dqs, pass, dqs_ref;
  const double t_lbs = time(job, lbs);
  job.meshes = {dqs_draw(mesh, dq)};
  const double t_dqs = time(job, dqs);
  job.meshes = {pass_draw(mesh, cpu)};
  const double t_pass = time(job, pass);
  const Skinned cpu_dq = cpu_dqs(mesh, dq);
  job.meshes = {pass_draw(mesh, cpu_dq)};
  dqs_ref = renderer().run(job);
  std::cout << "[ timing   ] full character 512x512: first frame " << t_first << " ms; then LBS " << t_lbs << " ms, DQS " << t_dqs << " ms, pass-through "
            << t_pass << " ms (upload + draw + read-back)\n";
  RecordProperty("full_512_lbs_ms", std::to_string(t_lbs));
  RecordProperty("full_512_dqs_ms", std::to_string(t_dqs));
  save(side_by_side({lbs, dqs, pass}, 4, {0, 0, 0, 255}), "full_walk");
  expect_agree(lbs, pass, "full walk LBS shader vs CPU");
  expect_agree(dqs, dqs_ref, "full walk DQS shader vs CPU");
  // Generous: the brief asks for well under a second; a loaded two-core machine may be slower
  // than an idle one, so only an order of magnitude beyond that fails.
  EXPECT_LT(t_lbs, 5000.0);
  EXPECT_LT(t_dqs, 5000.0);
}

}  // namespace
