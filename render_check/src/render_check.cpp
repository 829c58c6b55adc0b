// The render check as one call: poses, skins, draws and judges every method (render_check.hpp;
// spec VIS-1, VIS-2, VIS-3).
#include <rotorcert/render/render_check.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

#include <rotorcert/certify/certificate.hpp>
#include <rotorcert/render/base64.hpp>
#include <rotorcert/render/camera.hpp>
#include <rotorcert/render/pose_job.hpp>
#include <rotorcert/render/reference_pose.hpp>
#include <rotorcert/render/skin_job.hpp>
#include <rotorcert/render/vertex_error.hpp>
#include <rotorcert/spec/spec.hpp>

#ifndef ROTORCERT_VERSION
#error "ROTORCERT_VERSION must be defined by the build"
#endif

namespace rotorcert::render {

using json = nlohmann::json;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// No mesh colour reaches 255 (the lighting scales colours of at most 200), so the white
// background is exactly "not covered" (VIS-2's character pixels).
const Rgba8 kBackground{255, 255, 255, 255};
const Rgba8 kMeshColour{200, 190, 180, 255};
// Strips are made of smaller panels, so that a strip of twenty methods stays viewable.
constexpr int kPanel = 256;

/// NaN and infinities have no JSON number: null.
json num(double x) { return std::isfinite(x) ? json(x) : json(nullptr); }

int rank(Verdict v) { return static_cast<int>(v); }
Verdict worst(Verdict a, Verdict b) { return rank(a) >= rank(b) ? a : b; }

std::string slug(std::string s) {
  for (char& c : s)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '.')) c = '_';
  return s;
}

/// The method's skinning transforms as the renderer's LBS palette: [R(q) K | t], column-major.
std::vector<Mat4> lbs_palette(const std::vector<JointTransform>& skinning) {
  std::vector<Mat4> out;
  out.reserve(skinning.size());
  for (const auto& x : skinning) {
    const Mat3 a = x.stretched ? pose_math::mul3(pose_math::rotation3(x.rotation), x.stretch)
                               : pose_math::rotation3(x.rotation);
    Mat4 m{};
    for (int c = 0; c < 3; ++c)
      for (int r = 0; r < 3; ++r) m[4 * c + r] = a[3 * c + r];
    m[12] = x.translation[0];
    m[13] = x.translation[1];
    m[14] = x.translation[2];
    m[15] = 1.0;
    out.push_back(m);
  }
  return out;
}

/// The method's own dual quaternions as the renderer's DQS palette (the stretch of a few 1e-8 in
/// binary32 inverse binds cannot be expressed and is dropped: the shader frame is informative).
std::vector<DualQuaternion> dqs_palette(const std::vector<JointTransform>& skinning) {
  std::vector<DualQuaternion> out;
  out.reserve(skinning.size());
  for (const auto& x : skinning) {
    DualQuaternion d;
    if (x.has_motion) {
      d.real = {x.motion[0], x.motion[1], x.motion[2], x.motion[3]};
      d.dual = {x.motion[4], x.motion[5], x.motion[6], x.motion[7]};
    } else {
      const Quat& r = x.rotation;
      const Vec3& t = x.translation;  // dual = 0.5 [t, 0] r (DQ-1)
      d.real = r;
      d.dual = {0.5 * (t[0] * r[3] + t[1] * r[2] - t[2] * r[1]), 0.5 * (-t[0] * r[2] + t[1] * r[3] + t[2] * r[0]),
                0.5 * (t[0] * r[1] - t[1] * r[0] + t[2] * r[3]), 0.5 * (-t[0] * r[0] - t[1] * r[1] - t[2] * r[2])};
    }
    out.push_back(d);
  }
  return out;
}

MeshDraw pass_draw(const SkinnedMesh& mesh, const SkinOutput& s) {
  MeshDraw d;
  d.mesh = &mesh;
  d.mode = SkinningMode::pass_through;
  d.positions = s.positions;
  d.normals = s.normals;
  d.colour = kMeshColour;
  return d;
}

Image draw(OsmesaRenderer& renderer, const std::vector<MeshDraw>& meshes, const Camera& camera, int w, int h) {
  RenderJob job;
  job.meshes = meshes;
  job.camera = camera;
  job.width = w;
  job.height = h;
  job.background = kBackground;
  return renderer.run(job);
}

Image draw_skins(OsmesaRenderer& renderer, const std::vector<SkinnedMesh>& meshes, const std::vector<SkinOutput>& skins,
                 const Camera& camera, int w, int h) {
  std::vector<MeshDraw> d;
  for (std::size_t i = 0; i < meshes.size(); ++i) d.push_back(pass_draw(meshes[i], skins[i]));
  return draw(renderer, d, camera, w, h);
}

double displacement_px(const Camera& camera, int w, int h, const std::vector<SkinOutput>& a,
                       const std::vector<SkinOutput>& b) {
  double d = 0.0;
  for (std::size_t m = 0; m < a.size(); ++m)
    for (std::size_t v = 0; v < a[m].positions.size(); ++v) {
      const auto p = project_to_pixel(camera, w, h, a[m].positions[v]);
      const auto q = project_to_pixel(camera, w, h, b[m].positions[v]);
      if (!p || !q) continue;
      d = std::max(d, std::hypot((*p)[0] - (*q)[0], (*p)[1] - (*q)[1]));
    }
  return d;
}

bool finite_skin(const std::vector<SkinOutput>& skins) {
  for (const auto& s : skins)
    for (const auto* a : {&s.positions, &s.normals})
      for (const auto& p : *a)
        if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) return false;
  return true;
}

/// Total enclosed volume, or NaN unless every mesh is closed (VIS-3).
double volume(const std::vector<SkinnedMesh>& meshes, const std::vector<SkinOutput>* skins) {
  double total = 0.0;
  for (std::size_t i = 0; i < meshes.size(); ++i) {
    const MeshVolume v = mesh_volume(skins ? (*skins)[i].positions : meshes[i].positions, meshes[i].indices);
    if (!v.closed) return kNaN;
    total += v.total;
  }
  return meshes.empty() ? kNaN : total;
}

/// Vertices weighted (w > 0) to the first joint a clip rotates or to its parent: the twisting arm.
std::vector<std::pair<std::size_t, std::size_t>> twisting_vertices(const Scene& scene, const Clip& clip) {
  std::size_t joint = std::numeric_limits<std::size_t>::max();
  for (const auto& c : clip.channels)
    if (c.path == ChannelPath::rotation) joint = std::min(joint, c.joint);
  std::vector<std::pair<std::size_t, std::size_t>> out;
  if (joint == std::numeric_limits<std::size_t>::max()) return out;
  const int parent = scene.skeleton.joints[joint].parent;
  for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
    const auto& mesh = scene.meshes[m];
    for (std::size_t v = 0; v < mesh.positions.size(); ++v)
      for (int k = 0; k < 4; ++k)
        if (mesh.weights[v][k] > 0.0 &&
            (mesh.joints[v][k] == joint || (parent >= 0 && mesh.joints[v][k] == static_cast<std::size_t>(parent)))) {
          out.push_back({m, v});
          break;
        }
  }
  return out;
}

/// Where the reference normal has a direction (VIS-1): LBS normals are M n / |M n| with M the
/// blended linear part, and where the blend shrinks n below kNormalDefined (the candy-wrapper
/// neck: a tube collapsing onto its twist axis) the direction is set by rounding, not by the pose;
/// at the exact half turn of the simple strip M n is exactly 0. DQS rotates n by a unit
/// quaternion: always defined.
constexpr double kNormalDefined = 1.0 / 64.0;
std::vector<bool> normal_defined(const std::vector<JointTransform>& skinning, const SkinnedMesh& mesh, Technique t) {
  std::vector<bool> out(mesh.positions.size(), true);
  if (t != Technique::lbs) return out;
  std::vector<Mat3> a(skinning.size());
  for (std::size_t j = 0; j < skinning.size(); ++j)
    a[j] = skinning[j].stretched ? pose_math::mul3(pose_math::rotation3(skinning[j].rotation), skinning[j].stretch)
                                 : pose_math::rotation3(skinning[j].rotation);
  for (std::size_t v = 0; v < out.size(); ++v) {
    double total = 0.0;
    for (int k = 0; k < 4; ++k) total += mesh.weights[v][k];
    Vec3 m{0.0, 0.0, 0.0};
    for (int k = 0; k < 4; ++k) {
      if (mesh.weights[v][k] == 0.0) continue;
      const Vec3 x = pose_math::mul3v(a[mesh.joints[v][k]], mesh.normals[v]);
      for (int i = 0; i < 3; ++i) m[i] += mesh.weights[v][k] / total * x[i];
    }
    out[v] = std::hypot(m[0], m[1], m[2]) >= kNormalDefined;
  }
  return out;
}

/// Largest angle between the method's and the reference's normals where defined; NaN when a
/// method normal there is not finite.
double normal_error(const SkinOutput& method, const SkinOutput& reference, const std::vector<bool>& defined) {
  double worst = 0.0;
  for (std::size_t v = 0; v < defined.size(); ++v) {
    if (!defined[v]) continue;
    const Vec3& a = method.normals[v];
    const Vec3& b = reference.normals[v];
    const Vec3 c{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    const double angle = std::atan2(std::hypot(c[0], c[1], c[2]), a[0] * b[0] + a[1] * b[1] + a[2] * b[2]);
    if (std::isnan(angle)) return kNaN;
    worst = std::max(worst, angle);
  }
  return worst;
}

/// One method's accumulated results over a scene.
struct MethodRun {
  SkinningMethod method;
  Expectation expected;
  ErrorSummary error;
  std::string failure;
  Verdict vis2 = Verdict::pass;
  ImageCheck worst_image;
  std::string worst_image_frame;
  double min_psnr = std::numeric_limits<double>::infinity();
  bool have_image = false;
  int shader_max = 0;
  double shader_share_over = 0.0;
  double shader_min_psnr = std::numeric_limits<double>::infinity();
  json volume_pct = json::object();
  json frames = json::object();
  Image last_frame;       // the last frame of the current clip, for the figures
  Image candy;            // the candy-wrapper panel of the current clip
};

const spec::Spec& the_spec() {
  static const spec::Spec s = spec::load_spec(spec::resolve_spec_dir());
  return s;
}

}  // namespace

const char* to_string(Verdict v) {
  switch (v) {
    case Verdict::pass: return "PASS";
    case Verdict::quality_warning: return "QUALITY_WARNING";
    case Verdict::fail: return "FAIL";
  }
  return "FAIL";
}

Verdict vis1_verdict(double max_mm, double virtual_mm, double normal_rad, const VisualBars& bars) {
  if (std::isnan(max_mm) || std::isnan(virtual_mm) || std::isnan(normal_rad)) return Verdict::fail;
  const double mm = std::max(max_mm, virtual_mm);
  if (mm <= bars.mm_strict && normal_rad <= bars.rad_strict) return Verdict::pass;
  if (mm <= bars.mm_loose && normal_rad <= bars.rad_loose) return Verdict::quality_warning;
  return Verdict::fail;
}

std::vector<bool> silhouette_band(const Image& reference, Rgba8 background, const VisualBars& bars) {
  const int w = reference.width, h = reference.height;
  const auto at = [&](int x, int y) { return reference.rgba.data() + 4 * (static_cast<std::size_t>(y) * w + x); };
  const auto covered = [&](int x, int y) { return !std::equal(at(x, y), at(x, y) + 4, background.begin()); };
  std::vector<bool> edge(static_cast<std::size_t>(w) * h, false), band(edge.size(), false);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      static constexpr int dx[4] = {1, -1, 0, 0}, dy[4] = {0, 0, 1, -1};
      for (int k = 0; k < 4 && !edge[static_cast<std::size_t>(y) * w + x]; ++k) {
        const int nx = x + dx[k], ny = y + dy[k];
        if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
        bool differ = covered(x, y) != covered(nx, ny);
        for (int c = 0; c < 4 && !differ; ++c) differ = std::abs(int(at(x, y)[c]) - int(at(nx, ny)[c])) > bars.edge_levels;
        if (differ) edge[static_cast<std::size_t>(y) * w + x] = true;
      }
    }
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (!edge[static_cast<std::size_t>(y) * w + x]) continue;
      for (int yy = std::max(0, y - 1); yy <= std::min(h - 1, y + 1); ++yy)
        for (int xx = std::max(0, x - 1); xx <= std::min(w - 1, x + 1); ++xx) band[static_cast<std::size_t>(yy) * w + xx] = true;
    }
  return band;
}

ImageCheck check_image(const Image& method, const Image& reference, Rgba8 background, double displacement,
                       const VisualBars& bars) {
  ImageCheck r;
  r.diff = compare(method, reference, bars.levels);
  r.displacement_px = displacement;
  const std::vector<bool> band = silhouette_band(reference, background, bars);
  for (std::size_t p = 0; p < band.size(); ++p) {
    const std::uint8_t* a = method.rgba.data() + 4 * p;
    const std::uint8_t* b = reference.rgba.data() + 4 * p;
    const bool covered = !std::equal(a, a + 4, background.begin()) || !std::equal(b, b + 4, background.begin());
    int d = 0;
    for (int c = 0; c < 4; ++c) d = std::max(d, std::abs(int(a[c]) - int(b[c])));
    if (covered) ++r.character_pixels;
    if (d > bars.levels) {
      if (covered) ++r.over_pixels;
      if (!band[p]) ++r.outside_band;
    }
  }
  r.share_over = r.character_pixels == 0 ? 0.0 : static_cast<double>(r.over_pixels) / static_cast<double>(r.character_pixels);
  if (r.share_over > bars.fail_share || std::isnan(displacement)) r.verdict = Verdict::fail;
  else if (r.outside_band == 0) r.verdict = Verdict::pass;
  else if (displacement <= bars.displacement_px) r.verdict = Verdict::quality_warning;
  else r.verdict = Verdict::fail;
  return r;
}

std::vector<double> frame_times(const Clip& clip, int n) {
  std::vector<double> t;
  for (int k = 1; k < n; ++k) t.push_back(clip.start + clip.duration() * (k - 0.5) / n);
  t.push_back(clip.end);
  return t;
}

Expectation expectation(const SkinningMethod& m) {
  Expectation e;
  if (!m.unclaimed().empty()) {
    std::string list;
    for (const auto& c : m.unclaimed()) list += (list.empty() ? "" : ", ") + c;
    e.why = "does not claim " + list;
  }
  const auto known = certify::expected_failures(m.table->name, m.is_float() ? "float" : "double");
  std::string core, other;
  for (const auto& c : m.clauses()) {
    const auto it = known.find(c);
    if (it == known.end()) continue;
    const spec::Clause* clause = the_spec().find_clause(c);
    std::string& list = clause && clause->level == "Core" ? core : other;
    list += (list.empty() ? "" : "; ") + c + ": " + it->second;
  }
  if (!core.empty()) {
    e.verdict = Verdict::fail;
    e.why = "known Core defect: " + core;
  } else if (!other.empty()) {
    e.why = "known accuracy defect (measured, not expected either way): " + other;
  } else if (e.why.empty()) {
    e.verdict = Verdict::pass;
    e.why = "claims every clause it uses, no known defect among them";
  }
  return e;
}

json run_render_check(std::span<const SceneInput> scenes, std::span<const SkinningMethod> methods,
                      const RenderCheckOptions& opt, OsmesaRenderer& renderer) {
  if (opt.frames < 1) throw std::invalid_argument("render check: frames must be at least 1");
  const VisualBars& bars = opt.bars;
  const bool write = !opt.out.empty();
  std::map<std::string, int> counts{{"PASS", 0}, {"QUALITY_WARNING", 0}, {"FAIL", 0}};
  bool all_expected = true;
  json scenes_json = json::array();
  const double aspect = static_cast<double>(opt.width) / opt.height;

  for (const SceneInput& input : scenes) {
    const Scene& scene = *input.scene;
    const Rig rig = prepare_rig(scene.skeleton);
    const auto& joints = scene.skeleton.skin_joints;
    const double vv_offset = kVirtualVertexMetres / opt.metres_per_unit;
    const double rest_volume = volume(scene.meshes, nullptr);
    std::vector<MethodRun> runs;
    for (const auto& m : methods) {
      MethodRun run;
      run.method = m;
      run.expected = expectation(m);
      runs.push_back(std::move(run));
    }
    json clips_json = json::array();
    json figure1 = json::array(), candy = json::array();

    for (const Clip& clip : scene.clips) {
      if (!opt.clips.empty() && std::find(opt.clips.begin(), opt.clips.end(), clip.name) == opt.clips.end()) continue;
      const std::vector<double> times = frame_times(clip, opt.frames);
      const std::filesystem::path dir = std::filesystem::path(slug(input.label)) / slug(clip.name);
      if (write) std::filesystem::create_directories(opt.out / dir);
      json clip_json = {{"name", clip.name}, {"times", times}, {"reference_volume_pct", nullptr}};
      const bool candy_clip = clip.name == "twist";
      const auto arm = candy_clip ? twisting_vertices(scene, clip) : std::vector<std::pair<std::size_t, std::size_t>>{};

      for (std::size_t f = 0; f < times.size(); ++f) {
        const bool last = f + 1 == times.size();
        char label[64];
        std::snprintf(label, sizeof label, "%s t=%.4f", clip.name.c_str(), times[f]);
        PoseRequest req;
        req.a = {&clip, times[f]};
        const ReferencePose rp = reference_pose(rig, req);
        std::vector<SkinOutput> ref[2];  // LBS, DQS
        for (const auto& mesh : scene.meshes) {
          ref[0].push_back(reference_skin(rp, mesh, Technique::lbs));
          ref[1].push_back(reference_skin(rp, mesh, Technique::dqs));
        }
        const auto ref_vv = reference_virtual_vertices(rp, joints, vv_offset);
        const std::vector<JointTransform> ref_skinning = to_binary64(rp.skinning);
        std::vector<std::vector<bool>> defined[2];
        for (const auto& mesh : scene.meshes)
          for (int k = 0; k < 2; ++k)
            defined[k].push_back(normal_defined(ref_skinning, mesh, k == 0 ? Technique::lbs : Technique::dqs));
        // One camera per frame, framing both references, so every method of either technique is
        // drawn with the same view as its reference.
        std::vector<Vec3> pts;
        for (const auto& r : ref)
          for (const auto& s : r) pts.insert(pts.end(), s.positions.begin(), s.positions.end());
        const Camera camera = frame_box(bounding_box(pts), aspect);
        const Image ref_img[2] = {draw_skins(renderer, scene.meshes, ref[0], camera, opt.width, opt.height),
                                  draw_skins(renderer, scene.meshes, ref[1], camera, opt.width, opt.height)};
        std::optional<Camera> arm_camera;
        Image ref_candy[2];
        if (last && candy_clip && !arm.empty()) {
          std::vector<Vec3> arm_pts;
          for (const auto& r : ref)
            for (const auto& [m, v] : arm) arm_pts.push_back(r[m].positions[v]);
          arm_camera = frame_box(bounding_box(arm_pts), 1.0);
          for (int k = 0; k < 2; ++k) ref_candy[k] = draw_skins(renderer, scene.meshes, ref[k], *arm_camera, kPanel, kPanel);
        }
        if (last) {
          const double lv = volume(scene.meshes, &ref[0]), dv = volume(scene.meshes, &ref[1]);
          if (!std::isnan(rest_volume) && !std::isnan(lv))
            clip_json["reference_volume_pct"] = {{"LBS", num(100.0 * (lv - rest_volume) / rest_volume)},
                                                 {"DQS", num(100.0 * (dv - rest_volume) / rest_volume)}};
          if (write) {
            write_png(opt.out / dir / "reference_LBS.png", ref_img[0]);
            write_png(opt.out / dir / "reference_DQS.png", ref_img[1]);
          }
        }

        for (MethodRun& run : runs) {
          if (!run.failure.empty()) continue;
          const int t = run.method.technique == Technique::lbs ? 0 : 1;
          std::vector<JointTransform> globals, skinning;
          std::vector<SkinOutput> skins(scene.meshes.size());
          PoseJob pose{run.method, &rig, req, &globals, &skinning, {}};
          if (!pose.run()) {
            run.failure = std::string(label) + ": pose: " + pose.message;
            continue;
          }
          bool ok = true;
          VertexError frame_error;
          frame_error.count = 0;
          for (std::size_t m = 0; m < scene.meshes.size() && ok; ++m) {
            SkinJob skin{run.method, &scene.meshes[m], &skinning, &skins[m], {}};
            if (!skin.run()) {
              run.failure = std::string(label) + ": skin: " + skin.message;
              ok = false;
              break;
            }
            const VertexError e = vertex_error(skins[m], ref[t][m], opt.metres_per_unit);
            if (!std::isnan(frame_error.max_mm) && !(e.max_mm <= frame_error.max_mm)) {  // NaN is the worst and stays
              frame_error.max_mm = e.max_mm;
              frame_error.worst_vertex = e.worst_vertex;
            }
            frame_error.sum_mm += e.sum_mm;
            frame_error.count += e.count;
            const double n = normal_error(skins[m], ref[t][m], defined[t][m]);
            if (!std::isnan(frame_error.max_normal_rad) && !(n <= frame_error.max_normal_rad)) frame_error.max_normal_rad = n;
          }
          if (!ok) continue;
          const auto vv = virtual_vertex_error(virtual_vertices(globals, joints, vv_offset), ref_vv, joints, opt.metres_per_unit);
          run.error.add(label, frame_error, vv);
          if (std::isnan(frame_error.max_normal_rad)) run.error.max_normal_rad = kNaN;

          // VIS-2: the method's skin drawn like the reference's, with the reference's normal where
          // the normal has no defined direction (VIS-1).
          for (std::size_t m = 0; m < skins.size(); ++m)
            for (std::size_t v = 0; v < skins[m].normals.size(); ++v)
              if (!defined[t][m][v]) skins[m].normals[v] = ref[t][m].normals[v];
          if (!finite_skin(skins)) {
            run.vis2 = Verdict::fail;
            run.worst_image.verdict = Verdict::fail;
            run.worst_image_frame = std::string(label) + " (not finite: cannot be drawn)";
            run.worst_image.displacement_px = kNaN;
            run.have_image = true;
            continue;
          }
          const Image img = draw_skins(renderer, scene.meshes, skins, camera, opt.width, opt.height);
          const ImageCheck ic = check_image(img, ref_img[t], kBackground,
                                            displacement_px(camera, opt.width, opt.height, skins, ref[t]), bars);
          run.min_psnr = std::min(run.min_psnr, ic.diff.psnr_db);
          if (!run.have_image || rank(ic.verdict) > rank(run.worst_image.verdict) ||
              (ic.verdict == run.worst_image.verdict && ic.share_over > run.worst_image.share_over)) {
            run.worst_image = ic;
            run.worst_image_frame = label;
          }
          run.have_image = true;
          run.vis2 = worst(run.vis2, ic.verdict);

          // Informative: the same transforms skinned by the renderer's vertex shader.
          std::vector<Mat4> mats;
          std::vector<DualQuaternion> dqs;
          std::vector<MeshDraw> shader;
          if (t == 0) mats = lbs_palette(skinning);
          else dqs = dqs_palette(skinning);
          for (const auto& mesh : scene.meshes) {
            MeshDraw d;
            d.mesh = &mesh;
            d.mode = t == 0 ? SkinningMode::linear_blend : SkinningMode::dual_quaternion;
            d.matrices = mats;
            d.dual_quaternions = dqs;
            d.colour = kMeshColour;
            shader.push_back(d);
          }
          try {
            const ImageCheck sc = check_image(draw(renderer, shader, camera, opt.width, opt.height), ref_img[t], kBackground, kNaN, bars);
            run.shader_max = std::max(run.shader_max, sc.diff.max_channel_diff);
            run.shader_share_over = std::max(run.shader_share_over, sc.share_over);
            run.shader_min_psnr = std::min(run.shader_min_psnr, sc.diff.psnr_db);
          } catch (const std::invalid_argument&) {
            run.shader_share_over = kNaN;  // a palette the shader refuses (not finite)
          }

          if (last) {
            run.last_frame = img;
            const double v = volume(scene.meshes, &skins);
            if (!std::isnan(rest_volume) && !std::isnan(v)) run.volume_pct[clip.name] = num(100.0 * (v - rest_volume) / rest_volume);
            if (arm_camera) run.candy = draw_skins(renderer, scene.meshes, skins, *arm_camera, kPanel, kPanel);
            if (write) {
              const std::string s = slug(run.method.name());
              write_png(opt.out / dir / (s + ".png"), img);
              write_png(opt.out / dir / (s + "_diff.png"), diff_heat(img, ref_img[t]));
              run.frames[clip.name] = {{"image", (dir / (s + ".png")).generic_string()},
                                       {"diff", (dir / (s + "_diff.png")).generic_string()}};
            }
          }
        }

        // Figure 1 of the paper for this pose: QLB (glm_quat LBS), DQB (dq DQS), GA rotor
        // (rotor_m2 LBS), float tables preferred; the figure names tables, the verdicts never do.
        if (last && write) {
          std::vector<Image> panels;
          json names = json::array();
          for (const auto& [table, tech] : {std::pair{"glm_quat", Technique::lbs}, std::pair{"dq", Technique::dqs},
                                            std::pair{"rotor_m2", Technique::lbs}}) {
            const MethodRun* pick = nullptr;
            for (const auto& r : runs)
              if (r.method.table->name == std::string(table) && r.method.technique == tech && r.failure.empty() &&
                  !r.last_frame.rgba.empty() && (!pick || (r.method.is_float() && !pick->method.is_float())))
                pick = &r;
            if (pick) {
              panels.push_back(pick->last_frame);
              names.push_back(pick->method.name());
            }
          }
          if (!panels.empty()) {
            write_png(opt.out / dir / "figure1.png", side_by_side(panels, 4, {0, 0, 0, 255}));
            figure1.push_back({{"clip", clip.name}, {"png", (dir / "figure1.png").generic_string()}, {"panels", names}});
          }
          if (arm_camera) {
            std::vector<Image> strip{ref_candy[0], ref_candy[1]};
            json cnames = json::array({"reference LBS", "reference DQS"});
            for (auto& r : runs)
              if (r.failure.empty() && !r.candy.rgba.empty()) {
                strip.push_back(r.candy);
                cnames.push_back(r.method.name());
              }
            write_png(opt.out / dir / "candy_wrapper.png", side_by_side(strip, 4, {0, 0, 0, 255}));
            candy.push_back({{"clip", clip.name}, {"png", (dir / "candy_wrapper.png").generic_string()}, {"panels", cnames}});
          }
        }
        for (auto& r : runs) {
          if (last) r.last_frame = {};
          r.candy = {};
        }
      }
      clips_json.push_back(clip_json);
    }

    json methods_json = json::array();
    for (MethodRun& run : runs) {
      const auto& s = run.error;
      const Verdict v1 = run.failure.empty() ? vis1_verdict(s.max_mm, s.virtual_max_mm, s.max_normal_rad, bars) : Verdict::fail;
      const Verdict v2 = run.failure.empty() ? run.vis2 : Verdict::fail;
      ++counts[to_string(v1)];
      ++counts[to_string(v2)];
      bool as_expected = true;
      if (run.expected.verdict == Verdict::pass)
        as_expected = v1 == Verdict::pass && v2 == Verdict::pass;
      else if (run.expected.verdict == Verdict::fail)  // visibly wrong by either measure
        as_expected = worst(v1, v2) == Verdict::fail;
      all_expected = all_expected && as_expected;
      const auto& img = run.worst_image;
      methods_json.push_back({
          {"method", run.method.name()},
          {"table", run.method.table->name},
          {"scalar", run.method.is_float() ? "float" : "double"},
          {"technique", to_string(run.method.technique)},
          {"expected", run.expected.verdict ? json(to_string(*run.expected.verdict)) : json(nullptr)},
          {"expected_why", run.expected.why},
          {"as_expected", as_expected},
          {"failure", run.failure},
          {"vis1",
           {{"verdict", to_string(v1)}, {"max_mm", num(s.max_mm)}, {"mean_mm", num(s.mean_mm())},
            {"worst_frame", s.worst_frame}, {"worst_vertex", s.worst_vertex}, {"virtual_max_mm", num(s.virtual_max_mm)},
            {"virtual_joint", s.virtual_frame.empty() ? json(nullptr) : json(scene.skeleton.joints[s.virtual_joint].name)},
            {"virtual_axis", std::string(1, "xyz"[s.virtual_axis])}, {"virtual_frame", s.virtual_frame},
            {"normal_max_rad", num(s.max_normal_rad)}}},
          {"vis2",
           {{"verdict", to_string(v2)}, {"max_channel_diff", img.diff.max_channel_diff},
            {"share_differing", img.character_pixels == 0 ? 0.0
                                                          : static_cast<double>(img.diff.differing_pixels) / img.character_pixels},
            {"share_over", num(img.share_over)}, {"psnr_db", num(run.min_psnr)},
            {"pixels_outside_band", img.outside_band}, {"displacement_px", num(img.displacement_px)},
            {"worst_frame", run.worst_image_frame}}},
          {"shader",
           {{"max_channel_diff", run.shader_max}, {"share_over", num(run.shader_share_over)},
            {"psnr_db", num(run.shader_min_psnr)}}},
          {"volume_pct", run.volume_pct},
          {"frames", run.frames},
      });
    }
    std::size_t vertices = 0, triangles = 0;
    for (const auto& m : scene.meshes) {
      vertices += m.positions.size();
      triangles += m.triangle_count();
    }
    scenes_json.push_back({{"scene", input.label},
                           {"vertices", vertices},
                           {"triangles", triangles},
                           {"joints", joints.size()},
                           {"closed", !std::isnan(rest_volume)},
                           {"clips", clips_json},
                           {"figures", {{"figure1", figure1}, {"candy_wrapper", candy}}},
                           {"methods", methods_json}});
  }

  json clip_names = opt.clips;
  return {{"format", "rotorcert-render"},
          {"format_version", 1},
          {"rotorcert_version", ROTORCERT_VERSION},
          {"spec_version", the_spec().version},
          {"renderer", renderer.description()},
          {"options",
           {{"width", opt.width}, {"height", opt.height}, {"frames", opt.frames}, {"clips", clip_names},
            {"metres_per_unit", opt.metres_per_unit}}},
          {"bars",
           {{"vis1_mm", {bars.mm_strict, bars.mm_loose}}, {"vis1_rad", {bars.rad_strict, bars.rad_loose}},
            {"vis2_levels", bars.levels}, {"vis2_fail_share", bars.fail_share},
            {"vis2_displacement_px", bars.displacement_px}, {"vis2_edge_levels", bars.edge_levels}}},
          {"scenes", scenes_json},
          {"summary", {{"counts", counts}, {"as_expected", all_expected}, {"exit_code", all_expected ? 0 : 1}}}};
}


namespace {

std::string escape(const std::string& s) {
  std::string o;
  for (char c : s) {
    switch (c) {
      case '<': o += "&lt;"; break;
      case '>': o += "&gt;"; break;
      case '&': o += "&amp;"; break;
      case '"': o += "&quot;"; break;
      default: o += c;
    }
  }
  return o;
}

std::string fmt(const json& x, const char* f = "%.3g") {
  if (!x.is_number()) return "-";
  char b[64];
  std::snprintf(b, sizeof b, f, x.get<double>());
  return b;
}

std::string embedded_png(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::runtime_error(file.string() + ": cannot be read");
  std::ostringstream s;
  s << in.rdbuf();
  return "data:image/png;base64," + base64(s.str());
}

}  // namespace

json read_render_result(const std::filesystem::path& dir) {
  const auto file = dir / "render.json";
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::runtime_error(file.string() + ": cannot be read (run rotorcert render --out " + dir.string() + ")");
  json r;
  try {
    r = json::parse(in);
  } catch (const json::parse_error& e) {
    throw std::runtime_error(file.string() + ": not valid JSON: " + e.what());
  }
  if (!r.is_object() || r.value("format", "") != "rotorcert-render")
    throw std::runtime_error(file.string() + ": not a render.json of rotorcert render");
  return r;
}

json report_section(const json& r, const std::filesystem::path& dir) {
  const auto file = dir / "render.json";
  json figures = json::array(), rows = json::array();
  for (const auto& sc : r.at("scenes")) {
    const std::string scene = sc.at("scene");
    std::string clip;
    for (const auto& c : sc.at("clips")) {
      const std::string name = c.at("name");
      if (clip.empty() || name == "twist") clip = name;  // the twist clip, else the first
    }
    for (const char* kind : {"figure1", "candy_wrapper"})
      for (const auto& f : sc.at("figures").at(kind)) {
        if (f.at("clip") != clip) continue;
        const auto png = dir / f.at("png").get<std::string>();
        json entry = {{"scene", scene}, {"kind", kind}, {"clip", clip}, {"panels", f.at("panels")},
                      {"file", png.generic_string()}, {"data_uri", embedded_png(png)}};
        if (std::string(kind) == "candy_wrapper") {
          json v = json::object();
          for (const auto& c : sc.at("clips"))
            if (c.at("name") == clip && c.at("reference_volume_pct").is_object()) {
              v["reference LBS"] = c["reference_volume_pct"]["LBS"];
              v["reference DQS"] = c["reference_volume_pct"]["DQS"];
            }
          for (const auto& m : sc.at("methods"))
            if (m.at("volume_pct").contains(clip)) v[m.at("method").get<std::string>()] = m["volume_pct"][clip];
          entry["volume_pct"] = v;
        }
        figures.push_back(entry);
      }
    for (const auto& m : sc.at("methods")) {
      const auto& v1 = m.at("vis1");
      const auto& v2 = m.at("vis2");
      rows.push_back({{"scene", scene}, {"method", m.at("method")}, {"technique", m.at("technique")},
                      {"scalar", m.at("scalar")}, {"expected", m.at("expected")}, {"as_expected", m.at("as_expected")},
                      {"failure", m.at("failure")}, {"vis1", v1.at("verdict")}, {"max_mm", v1.at("max_mm")},
                      {"mean_mm", v1.at("mean_mm")}, {"virtual_max_mm", v1.at("virtual_max_mm")},
                      {"normal_max_rad", v1.at("normal_max_rad")}, {"vis2", v2.at("verdict")},
                      {"max_channel_diff", v2.at("max_channel_diff")}, {"share_over", v2.at("share_over")},
                      {"psnr_db", v2.at("psnr_db")}});
    }
  }
  return {{"source", file.generic_string()},
          {"renderer", r.value("renderer", "")},
          {"spec_version", r.value("spec_version", "")},
          {"as_expected", r.at("summary").at("as_expected")},
          {"counts", r.at("summary").at("counts")},
          {"figures", figures},
          {"rows", rows}};
}

std::string render_html(const json& r, const std::filesystem::path& out) {
  std::ostringstream h;
  h << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>rotorcert render check</title>\n"
       "<style>body{font-family:sans-serif;margin:1.5em}table{border-collapse:collapse}td,th{border:1px solid #bbb;"
       "padding:2px 6px;text-align:right}td:first-child{text-align:left}.PASS{background:#cfc}.QUALITY_WARNING{background:#ffc}"
       ".FAIL{background:#fcc}img{max-width:100%}</style></head><body>\n";
  h << "<h1>rotorcert render check</h1>\n<p>rotorcert " << escape(r.value("rotorcert_version", "")) << ", spec "
    << escape(r.value("spec_version", "")) << "; renderer " << escape(r.value("renderer", ""))
    << ". Verdicts: VIS-1 (vertex error, mm) and VIS-2 (image against the reference frame) of spec Section 10b; "
       "the figure strips are embedded, per-method frames are linked relative to this file.</p>\n";
  const auto& s = r.at("summary");
  h << "<p>Summary: " << escape(s.at("counts").dump()) << "; as expected: " << (s.at("as_expected").get<bool>() ? "yes" : "no")
    << "</p>\n";
  for (const auto& sc : r.at("scenes")) {
    h << "<h2>" << escape(sc.at("scene").get<std::string>()) << "</h2>\n<p>" << sc.at("vertices") << " vertices, "
      << sc.at("triangles") << " triangles, " << sc.at("joints") << " skin joints.</p>\n";
    for (const char* kind : {"figure1", "candy_wrapper"})
      for (const auto& f : sc.at("figures").at(kind)) {
        h << "<figure><img alt=\"" << kind << "\" src=\"" << embedded_png(out / f.at("png").get<std::string>())
          << "\"><figcaption>" << (std::string(kind) == "figure1" ? "Figure 1 strip" : "Candy-wrapper strip") << ", clip "
          << escape(f.at("clip").get<std::string>()) << ", last frame; left to right: ";
        std::string names;
        for (const auto& n : f.at("panels")) names += (names.empty() ? "" : ", ") + n.get<std::string>();
        h << escape(names);
        if (std::string(kind) == "candy_wrapper")
          for (const auto& c : sc.at("clips"))
            if (c.at("name") == f.at("clip") && !c.at("reference_volume_pct").is_null())
              h << ". Volume change: reference LBS " << fmt(c["reference_volume_pct"]["LBS"], "%.2f") << " %, reference DQS "
                << fmt(c["reference_volume_pct"]["DQS"], "%.2f") << " %";
        h << ".</figcaption></figure>\n";
      }
    h << "<table><tr><th>method</th><th>expected</th><th>VIS-1</th><th>max mm</th><th>mean mm</th><th>virtual mm</th>"
         "<th>normal rad</th><th>VIS-2</th><th>max diff</th><th>share &gt;1</th><th>PSNR dB</th><th>displ. px</th>"
         "<th>shader share &gt;1</th><th>volume %</th><th>frame</th></tr>\n";
    for (const auto& m : sc.at("methods")) {
      const auto& v1 = m.at("vis1");
      const auto& v2 = m.at("vis2");
      std::string vol;
      for (const auto& [clip, v] : m.at("volume_pct").items()) vol += clip + " " + fmt(v, "%.2f") + " ";
      std::string link;
      for (const auto& [clip, f] : m.at("frames").items())
        link += "<a href=\"" + escape(f.at("image").get<std::string>()) + "\">" + escape(clip) + "</a> <a href=\"" +
                escape(f.at("diff").get<std::string>()) + "\">diff</a> ";
      h << "<tr><td>" << escape(m.at("method").get<std::string>()) << (m.at("failure").get<std::string>().empty() ? "" : " (job stopped)")
        << "</td><td>" << (m.at("expected").is_null() ? "-" : escape(m.at("expected").get<std::string>())) << "</td><td class=\""
        << v1.at("verdict").get<std::string>() << "\">" << v1.at("verdict").get<std::string>() << "</td><td>" << fmt(v1.at("max_mm"))
        << "</td><td>" << fmt(v1.at("mean_mm")) << "</td><td>" << fmt(v1.at("virtual_max_mm")) << "</td><td>"
        << fmt(v1.at("normal_max_rad")) << "</td><td class=\"" << v2.at("verdict").get<std::string>() << "\">"
        << v2.at("verdict").get<std::string>() << "</td><td>" << v2.at("max_channel_diff") << "</td><td>"
        << fmt(v2.at("share_over")) << "</td><td>"
        << (v2.at("psnr_db").is_null() ? std::string("&infin;") : fmt(v2.at("psnr_db"), "%.1f")) << "</td><td>"
        << fmt(v2.at("displacement_px"))
        << "</td><td>" << fmt(m.at("shader").at("share_over")) << "</td><td>" << escape(vol) << "</td><td>" << link << "</td></tr>\n";
    }
    h << "</table>\n";
  }
  h << "</body></html>\n";
  return h.str();
}

}  // namespace rotorcert::render
