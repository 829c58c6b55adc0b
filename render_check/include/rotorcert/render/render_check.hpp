// The render check as one call (spec VIS-1, VIS-2, VIS-3): for each scene, clip and
// frame, every method poses and skins the character (pose_job.hpp, skin_job.hpp), the MPFR
// reference does the same for each technique (reference_pose.hpp), and both are drawn by one
// OsmesaRenderer with one camera. The result is a JSON object (layout below) with a verdict per
// method, and, when an output directory is given, PNG files: every file is written atomically
// (write_png; certify::write_atomically for text).
//
// render.json (format "rotorcert-render", format_version 1):
//   {"format", "format_version", "rotorcert_version", "spec_version", "renderer": GL_RENDERER; GL_VERSION,
//    "options": {"width", "height", "frames", "clips": [] (empty: all), "metres_per_unit"},
//    "bars": {"vis1_mm": [strict, loose], "vis1_rad": [strict, loose], "vis2_levels": 1, "vis2_fail_share": 0.01,
//             "vis2_displacement_px": 1, "vis2_edge_levels": 16},
//    "scenes": [{"scene", "vertices", "triangles", "joints", "closed",
//                "clips": [{"name", "times": [s, ...], "reference_volume_pct": {"LBS", "DQS"} | null}],
//                "figures": {"figure1": [png, ...], "candy_wrapper": [png, ...]}   (paths relative to the out dir)
//                "methods": [MethodResult]}],
//    "summary": {"counts": {"PASS": n, "QUALITY_WARNING": n, "FAIL": n} (VIS-1 and VIS-2 verdicts),
//                "as_expected": bool, "exit_code": 0 | 1}}
//   MethodResult: {"method": "rotor_m2 float LBS", "table", "scalar": "float"|"double", "technique": "LBS"|"DQS",
//     "expected": "PASS" | "FAIL" | null, "expected_why", "as_expected",
//     "failure": "" | why a job stopped,
//     "vis1": {"verdict", "max_mm", "mean_mm", "worst_frame", "worst_vertex", "virtual_max_mm", "virtual_joint",
//              "virtual_axis", "virtual_frame", "normal_max_rad"},
//     "vis2": {"verdict", "max_channel_diff", "share_differing", "share_over", "psnr_db" (null: identical),
//              "pixels_outside_band", "displacement_px", "worst_frame"},
//     "shader": {"max_channel_diff", "share_over", "psnr_db"}   (informative: the vertex-shader frame),
//     "volume_pct": {clip: per cent} (VIS-3, closed meshes only),
//     "frames": {clip: {"image": png, "diff": png}} (last frame of each clip; paths relative to the out dir)}
//   Numbers that are NaN or infinite are written as null.
#pragma once

#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <rotorcert/render/image.hpp>
#include <rotorcert/render/method.hpp>
#include <rotorcert/render/osmesa_renderer.hpp>
#include <rotorcert/render/scene.hpp>

namespace rotorcert::render {

/// The bars of VIS-1 and VIS-2 (spec/SPEC.md Section 10b; classes vis-mm, vis-rad and vis-image of
/// spec/clauses.json, which the tests compare with these numbers).
struct VisualBars {
  double mm_strict = 0.1;     // ACL's 0.1 mm at 3 cm
  double mm_loose = 1.0;      // half a pixel of a 1,080-pixel view of a 2 m character
  double rad_strict = 1e-3;   // 0.19 of an 8-bit level of the lighting
  double rad_loose = 4e-3;    // 0.77 of a level
  int levels = 1;             // one 8-bit level: rounding of the same colour
  double fail_share = 0.01;   // of the character's pixels beyond `levels`
  double displacement_px = 1.0;
  int edge_levels = 16;       // neighbours differing by more are an edge (silhouette band)
};

enum class Verdict { pass, quality_warning, fail };
/// "PASS", "QUALITY_WARNING", "FAIL" (RESULT-1's codes).
const char* to_string(Verdict v);

/// VIS-1: the verdict of the worst vertex, virtual-vertex and normal errors (NaN: FAIL).
Verdict vis1_verdict(double max_mm, double virtual_mm, double normal_rad, const VisualBars& bars = {});

/// VIS-2's image measures of one frame against the reference frame of the same renderer and camera.
struct ImageCheck {
  ImageDiff diff;                     // compare(method, reference, bars.levels)
  std::size_t character_pixels = 0;   // not background in either frame
  std::size_t over_pixels = 0;        // character pixels with d > levels
  std::size_t outside_band = 0;       // pixels outside the silhouette band with d > levels
  double share_over = 0.0;            // over_pixels / character_pixels
  double displacement_px = 0.0;       // largest projected vertex displacement (set by the caller)
  Verdict verdict = Verdict::pass;
};
/// The silhouette band of VIS-2: true for pixels within Chebyshev distance 1 of an edge pixel of
/// `reference` (a 4-neighbour differs in coverage or by more than bars.edge_levels in a channel).
std::vector<bool> silhouette_band(const Image& reference, Rgba8 background, const VisualBars& bars = {});
/// The measures and the verdict; `displacement_px` is the projected displacement of the frame.
ImageCheck check_image(const Image& method, const Image& reference, Rgba8 background, double displacement_px,
                       const VisualBars& bars = {});

/// Inputs of run_render_check.
struct RenderCheckOptions {
  std::vector<std::string> clips;  // clip names to use; empty: every clip of each scene
  int frames = 4;                  // per clip (VIS-1's frame times)
  int width = 512;
  int height = 512;
  double metres_per_unit = 1.0;    // glTF scenes are in metres
  std::filesystem::path out;       // where PNGs go; empty: none written
  VisualBars bars;
};

/// A scene to check, with the label used in file names and the JSON ("medium", "walk.glb").
struct SceneInput {
  std::string label;
  const Scene* scene = nullptr;
};

/// VIS-1's frame times of a clip: start + duration (k - 1/2) / n for k = 1..n-1, then the end.
std::vector<double> frame_times(const Clip& clip, int n);

/// What the render check expects of a method, from data only: PASS when its table claims every
/// clause of the ops the method uses and impls/*/expected_failures.json lists none of them (then
/// VIS-1 and VIS-2 must both PASS); FAIL (VIS-1 or VIS-2, or both)
/// when a listed known defect is a Core clause among them (a rotation that is wrong, not merely
/// inaccurate: the pose is wrong by the size of the rotation); otherwise no expectation (a known
/// accuracy defect whose visible size the check measures and reports).
struct Expectation {
  std::optional<Verdict> verdict;
  std::string why;
};
Expectation expectation(const SkinningMethod& method);

/// Runs the check (requires rotorcert::ref::use_reference_precision()). Throws RenderError when
/// OpenGL fails, ImageError when a PNG cannot be written; a method whose job stops is a FAIL with
/// `failure` set, never an exception.
nlohmann::json run_render_check(std::span<const SceneInput> scenes, std::span<const SkinningMethod> methods,
                                const RenderCheckOptions& options, OsmesaRenderer& renderer);

/// render.html for a render.json (self-contained: the figure strips are embedded as base64 data:
/// URIs read from `out`; per-method frames are linked by relative path).
std::string render_html(const nlohmann::json& result, const std::filesystem::path& out);

/// sections.render of report.json, from a render check's result (run_render_check's value, in
/// memory when `rotorcert report` ran it; read_render_result's when it reads an earlier run) and
/// the directory its PNGs were written to:
///   {"source": "DIR/render.json", "renderer", "spec_version", "as_expected", "counts",
///    "figures": [{"scene", "kind": "figure1" | "candy_wrapper", "clip", "panels": [names, left to right],
///                 "file": PNG path, "data_uri": "data:image/png;base64,...",
///                 "volume_pct": {"reference LBS", "reference DQS", <method>: per cent} (candy_wrapper only)}],
///    "rows": [{"scene", "method", "technique", "scalar", "expected", "as_expected", "failure",
///              "vis1", "max_mm", "mean_mm", "virtual_max_mm", "normal_max_rad",
///              "vis2", "max_channel_diff", "share_over", "psnr_db"}]}
/// Figures: per scene those of its "twist" clip (the candy-wrapper pose), else of its first clip;
/// embedded so that report.html stays self-contained. std::runtime_error when a PNG cannot be read.
nlohmann::json report_section(const nlohmann::json& result, const std::filesystem::path& dir);

/// The render.json that `rotorcert render --out DIR` wrote (`rotorcert report --render DIR`).
/// std::runtime_error when it cannot be read or is not a "rotorcert-render" document.
nlohmann::json read_render_result(const std::filesystem::path& dir);


}  // namespace rotorcert::render
