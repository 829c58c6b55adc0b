// Visual equivalence (spec VIS-1, VIS-2, VIS-3; render_check.hpp) and `rotorcert render`: the
// bars are the spec's, the image verdict follows its definition on constructed frames, conforming
// methods pass and the paper as printed fails on the built-in medium character, and the command
// writes its files, or exits 2 naming a malformed file.
//
// Tests that draw skip, saying why, when OSMesa cannot make an OpenGL context.
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <set>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <rotorcert/registry.hpp>
#include <rotorcert/render/camera.hpp>
#include <rotorcert/render/character.hpp>
#include <rotorcert/render/render_check.hpp>
#include <rotorcert/testing/clause.hpp>
#include <rotorcert/testing/shell.hpp>

namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;
using namespace rotorcert::render;

const Rgba8 kWhite{255, 255, 255, 255};

json spec_classes() {
  std::ifstream in(std::string(ROTORCERT_SPEC_DIR) + "/clauses.json");
  return json::parse(in).at("tolerance_classes");
}

/// A fresh directory under the system's temporary directory, removed with everything in it when
/// the test ends (also when it fails: the files of interest are printed by the assertions).
struct Scratch {
  fs::path path;
  explicit Scratch(const std::string& name)
      : path(fs::temp_directory_path() / ("rotorcert_vis_" + std::to_string(::getpid()) + "_" + name)) {
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~Scratch() {
    std::error_code ignored;
    fs::remove_all(path, ignored);
  }
  Scratch(const Scratch&) = delete;
  Scratch& operator=(const Scratch&) = delete;
};

// The library's bars are the spec's classes vis-mm and vis-rad (VIS-1), not numbers of its own.
TEST(VisBars, AreTheSpecClasses) {
  RC_CLAUSE("VIS-1");
  const json c = spec_classes();
  const VisualBars b;
  EXPECT_EQ(std::stod(c.at("vis-mm").at("strict").get<std::string>()), b.mm_strict);
  EXPECT_EQ(std::stod(c.at("vis-mm").at("loose").get<std::string>()), b.mm_loose);
  EXPECT_EQ(std::stod(c.at("vis-rad").at("strict").get<std::string>()), b.rad_strict);
  EXPECT_EQ(std::stod(c.at("vis-rad").at("loose").get<std::string>()), b.rad_loose);
  EXPECT_EQ(c.at("vis-image").at("kind"), "formula");
  // VIS-1's rule at and around the bars (inclusive), and NaN.
  EXPECT_EQ(vis1_verdict(b.mm_strict, 0.0, 0.0), Verdict::pass);
  EXPECT_EQ(vis1_verdict(0.0, std::nextafter(b.mm_strict, 1.0), 0.0), Verdict::quality_warning);
  EXPECT_EQ(vis1_verdict(0.0, 0.0, std::nextafter(b.rad_strict, 1.0)), Verdict::quality_warning);
  EXPECT_EQ(vis1_verdict(b.mm_loose, 0.0, b.rad_loose), Verdict::quality_warning);
  EXPECT_EQ(vis1_verdict(std::nextafter(b.mm_loose, 2.0), 0.0, 0.0), Verdict::fail);
  EXPECT_EQ(vis1_verdict(0.0, 0.0, std::nextafter(b.rad_loose, 1.0)), Verdict::fail);
  EXPECT_EQ(vis1_verdict(std::nan(""), 0.0, 0.0), Verdict::fail);
  EXPECT_EQ(vis1_verdict(INFINITY, 0.0, 0.0), Verdict::fail);
}

/// A 40 x 40 frame with a grey 20 x 20 square at (10, 10): edges at its border only.
Image square(int x0 = 10) {
  Image im = Image::filled(40, 40, kWhite);
  for (int y = 10; y < 30; ++y)
    for (int x = x0; x < x0 + 20; ++x) im.set_pixel(x, y, {150, 140, 130, 255});
  return im;
}

// VIS-2's rule on constructed frames, each case built from the definition.
TEST(VisImage, VerdictFollowsTheDefinition) {
  RC_CLAUSE("VIS-2");
  const Image ref = square();
  EXPECT_EQ(check_image(ref, ref, kWhite, 0.0).verdict, Verdict::pass);
  EXPECT_EQ(check_image(ref, ref, kWhite, 0.0).character_pixels, 400u);

  // One level everywhere inside: rounding, PASS.
  Image one = ref;
  for (int y = 10; y < 30; ++y)
    for (int x = 10; x < 30; ++x) one.set_pixel(x, y, {151, 141, 131, 255});
  EXPECT_EQ(check_image(one, ref, kWhite, 0.0).verdict, Verdict::pass);

  // Two levels in one interior pixel (outside the band): not rounding. Within 1 px of
  // displacement a QUALITY_WARNING, beyond it a FAIL.
  Image two = ref;
  two.set_pixel(20, 20, {152, 140, 130, 255});
  const ImageCheck c = check_image(two, ref, kWhite, 0.5);
  EXPECT_EQ(c.outside_band, 1u);
  EXPECT_EQ(c.verdict, Verdict::quality_warning);
  EXPECT_EQ(check_image(two, ref, kWhite, 2.0).verdict, Verdict::fail);

  // A coverage flip on the silhouette (a pixel just outside the square): inside the band, PASS.
  Image edge = ref;
  edge.set_pixel(9, 20, {150, 140, 130, 255});
  const ImageCheck e = check_image(edge, ref, kWhite, 0.0);
  EXPECT_EQ(e.over_pixels, 1u);
  EXPECT_EQ(e.outside_band, 0u);
  EXPECT_EQ(e.verdict, Verdict::pass);

  // The square moved by one pixel: about 2 x 20 of 420 character pixels change, over 1 %: FAIL
  // even though every changed pixel is in the band.
  const ImageCheck moved = check_image(square(11), ref, kWhite, 1.0);
  EXPECT_GT(moved.share_over, 0.01);
  EXPECT_EQ(moved.verdict, Verdict::fail);
}

struct Renderer {
  std::unique_ptr<OsmesaRenderer> r;
  std::string why;
};
Renderer& renderer() {
  static Renderer r = [] {
    Renderer x;
    try {
      x.r = std::make_unique<OsmesaRenderer>();
    } catch (const std::exception& e) {
      x.why = e.what();
    }
    return x;
  }();
  return r;
}

const Scene& medium() {
  static const Scene s = make_character(Complexity::medium);
  return s;
}

// Every method the render check expects to pass (it claims every clause it uses, no known defect
// among them: decided from data) passes VIS-1 and VIS-2 on the medium character, both clips.
TEST(VisRender, ConformingMethodsPassOnTheMediumCharacter) {
  RC_CLAUSE("VIS-1");
  RC_CLAUSE("VIS-2");
  RC_CLAUSE("VIS-3");
  if (!renderer().r) GTEST_SKIP() << "no OpenGL context: " << renderer().why;
  std::vector<SkinningMethod> methods;
  for (const auto& m : skinning_methods(rotorcert::impl::builtin_tables()))
    if (expectation(m).verdict == Verdict::pass) methods.push_back(m);
  std::set<std::string> names;
  for (const auto& m : methods) names.insert(m.name());
  // The brief's conforming implementations are among them, both techniques.
  for (const char* n : {"rotor_m1 float LBS", "rotor_m2 float LBS", "rotor_m2 double LBS", "rotor_simd float LBS",
                        "rotor_gen float LBS",
                        "dq float DQS", "dq double DQS", "motor_pga float DQS"})
    EXPECT_EQ(names.count(n), 1u) << n;
  RenderCheckOptions opt;
  opt.frames = 2;
  const SceneInput in[] = {{"medium", &medium()}};
  const json r = run_render_check(in, methods, opt, *renderer().r);
  const json& scene = r.at("scenes").at(0);
  ASSERT_EQ(scene.at("methods").size(), methods.size());
  for (const json& m : scene.at("methods")) {
    SCOPED_TRACE(m.dump());
    EXPECT_EQ(m.at("failure"), "");
    EXPECT_EQ(m.at("vis1").at("verdict"), "PASS");
    EXPECT_EQ(m.at("vis2").at("verdict"), "PASS");
    EXPECT_TRUE(m.at("as_expected").get<bool>());
    std::printf("%-24s max %.3e mm, virtual %.3e mm, normal %.2e rad; image max %d, share>1 %.2e, PSNR %s\n",
                m.at("method").get<std::string>().c_str(), m["vis1"]["max_mm"].get<double>(),
                m["vis1"]["virtual_max_mm"].get<double>(), m["vis1"]["normal_max_rad"].get<double>(),
                m["vis2"]["max_channel_diff"].get<int>(), m["vis2"]["share_over"].get<double>(),
                m["vis2"]["psnr_db"].dump().c_str());
  }
  EXPECT_TRUE(r.at("summary").at("as_expected").get<bool>());
  EXPECT_EQ(r.at("summary").at("exit_code"), 0);
  // VIS-3: the medium character is closed; at the full wrist twist LBS loses volume, DQS far less.
  ASSERT_TRUE(scene.at("closed").get<bool>());
  for (const json& c : scene.at("clips"))
    if (c.at("name") == "twist") {
      const double lbs = c.at("reference_volume_pct").at("LBS"), dqs = c.at("reference_volume_pct").at("DQS");
      std::printf("twist volume change: reference LBS %.3f %%, DQS %.3f %%\n", lbs, dqs);
      EXPECT_LT(lbs, 0.0);
      EXPECT_LT(std::abs(dqs), std::abs(lbs));
    }
}

// The 1 % bar of VIS-2 against what it stands for: the medium character drawn at 512 x 512 and
// the same frame moved by one pixel. A whole-character shift of one pixel is visible side by side
// and must FAIL; the share it changes is printed (SPEC.md quotes it).
TEST(VisRender, OnePixelShiftOfTheCharacterFails) {
  RC_CLAUSE("VIS-2");
  if (!renderer().r) GTEST_SKIP() << "no OpenGL context: " << renderer().why;
  const SkinnedMesh& mesh = medium().meshes.at(0);
  MeshDraw d;
  d.mesh = &mesh;
  d.mode = SkinningMode::pass_through;
  d.positions = mesh.positions;
  d.normals = mesh.normals;
  d.colour = {200, 190, 180, 255};
  RenderJob job;
  job.meshes = {d};
  job.camera = frame_box(bounding_box(mesh.positions), 1.0);
  const Image frame = renderer().r->run(job);
  for (const auto& [dx, dy] : {std::pair{1, 0}, std::pair{0, 1}}) {
    Image moved = Image::filled(frame.width, frame.height, kWhite);
    for (int y = 0; y + dy < frame.height; ++y)
      for (int x = 0; x + dx < frame.width; ++x) moved.set_pixel(x + dx, y + dy, frame.pixel(x, y));
    const ImageCheck c = check_image(moved, frame, kWhite, 1.0);
    std::printf("one-pixel shift (%d, %d): %zu of %zu character pixels (%.2f %%) beyond one level, %zu outside the band\n",
                dx, dy, c.over_pixels, c.character_pixels, 100.0 * c.share_over, c.outside_band);
    EXPECT_GT(c.share_over, VisualBars{}.fail_share);
    EXPECT_EQ(c.verdict, Verdict::fail);
  }
}

// The paper as printed (ERRATUM-2, ERRATUM-3: reversed compose, inverse sandwich) fails both,
// which is what the render check expects of a table with known Core defects.
TEST(VisRender, PaperLiteralFails) {
  RC_CLAUSE("VIS-1");
  RC_CLAUSE("VIS-2");
  if (!renderer().r) GTEST_SKIP() << "no OpenGL context: " << renderer().why;
  const auto paper = make_method(*rotorcert::impl::find_builtin("paper_literal", RC_SCALAR_FLOAT32), Technique::lbs);
  EXPECT_EQ(expectation(paper).verdict, Verdict::fail);
  RenderCheckOptions opt;
  opt.frames = 1;
  opt.clips = {"bend"};
  const SceneInput in[] = {{"medium", &medium()}};
  const SkinningMethod ms[] = {paper};
  const json r = run_render_check(in, ms, opt, *renderer().r);
  const json& m = r.at("scenes").at(0).at("methods").at(0);
  SCOPED_TRACE(m.dump());
  EXPECT_EQ(m.at("vis1").at("verdict"), "FAIL");
  EXPECT_EQ(m.at("vis2").at("verdict"), "FAIL");
  EXPECT_TRUE(m.at("as_expected").get<bool>());
}

TEST(VisCli, MalformedFileExitsTwoNamingIt) {
  RC_CLAUSE("GLTF-3");
  const Scratch dir_scratch("bad");
  const fs::path& dir = dir_scratch.path;
  const fs::path bad = dir / "broken_character.gltf";
  std::ofstream(bad) << "{\"asset\": {\"version\": \"2.0\"}, \"nodes\": [{\"children\": [0]}]";  // truncated JSON
  const auto run = rotorcert::testing::run_rotorcert("render '" + bad.string() + "' --out '" + (dir / "out").string() + "'");
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find("broken_character.gltf"), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find("internal error"), std::string::npos) << run.output;
  EXPECT_FALSE(fs::exists(dir / "out" / "render.json"));
}

// The built-in characters, one frame of the twist clip, four implementations: the files exist
// and say what happened, and the exit code is 0 (the conforming pass, paper_literal fails).
TEST(VisCli, BuiltinCharactersWriteTheFiles) {
  RC_CLAUSE("VIS-1");
  RC_CLAUSE("VIS-3");
  if (!renderer().r) GTEST_SKIP() << "no OpenGL context: " << renderer().why;
  const Scratch out_scratch("builtin");
  const fs::path& out = out_scratch.path;
  const auto run = rotorcert::testing::run_rotorcert("render --out '" + out.string() +
                                                     "' --clip twist --frames 1 --width 160 --height 160 "
                                                     "--impl rotor_m2 --impl dq --impl glm_quat --impl paper_literal");
  EXPECT_EQ(run.exit_code, 0) << run.output;
  ASSERT_TRUE(fs::exists(out / "render.json")) << run.output;
  std::ifstream in(out / "render.json");
  const json r = json::parse(in);
  EXPECT_EQ(r.at("format"), "rotorcert-render");
  ASSERT_EQ(r.at("scenes").size(), 3u);
  for (const json& s : r.at("scenes")) {
    SCOPED_TRACE(s.at("scene").dump());
    EXPECT_EQ(s.at("figures").at("figure1").size(), 1u);
    for (const char* kind : {"figure1", "candy_wrapper"})
      for (const json& f : s.at("figures").at(kind)) EXPECT_TRUE(fs::exists(out / f.at("png").get<std::string>()));
    for (const json& m : s.at("methods")) {
      if (m.at("table") == "paper_literal") {
        EXPECT_EQ(m.at("vis1").at("verdict"), "FAIL");
      }
      for (const auto& [clip, f] : m.at("frames").items()) {
        EXPECT_TRUE(fs::exists(out / f.at("image").get<std::string>()));
        EXPECT_TRUE(fs::exists(out / f.at("diff").get<std::string>()));
      }
    }
  }
  // The closed characters have a candy-wrapper strip (the simple strip is an open mesh, but the
  // strip is still drawn).
  EXPECT_EQ(r.at("scenes").at(1).at("figures").at("candy_wrapper").size(), 1u);
  std::ifstream html(out / "render.html");
  std::stringstream text;
  text << html.rdbuf();
  EXPECT_NE(text.str().find("data:image/png;base64,"), std::string::npos);
  EXPECT_NE(text.str().find("rotor_m2 float LBS"), std::string::npos);
  // No temporary left behind by the atomic writes.
  for (const auto& e : fs::recursive_directory_iterator(out))
    EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << e.path();

  // `rotorcert report --render DIR` adds the section: one row per scene and method, the twist
  // figures embedded.
  const Scratch rep_scratch("report");
  const fs::path& rep = rep_scratch.path;
  const auto report = rotorcert::testing::run_rotorcert("report --out '" + rep.string() +
                                                        "' --impl rotor_m2 --cases 4 --no-mutants --no-third-party -q --render '" +
                                                        out.string() + "'");
  EXPECT_EQ(report.exit_code, 0) << report.output;
  std::ifstream rin(rep / "report.json");
  const json section = json::parse(rin).at("sections").at("render");
  std::size_t methods = 0;
  for (const json& s : r.at("scenes")) methods += s.at("methods").size();
  EXPECT_EQ(section.at("rows").size(), methods);
  EXPECT_EQ(section.at("figures").size(), 6u);  // Figure 1 and candy wrapper of each character
  for (const json& f : section.at("figures"))
    EXPECT_EQ(f.at("data_uri").get<std::string>().rfind("data:image/png;base64,iVBOR", 0), 0u);  // a PNG signature
  // A directory without render.json is a usage error, named.
  const auto bad = rotorcert::testing::run_rotorcert("report --out '" + rep.string() + "' --impl rotor_m2 --no-mutants -q --render '" +
                                                     rep.string() + "'");
  EXPECT_EQ(bad.exit_code, 2) << bad.output;
  EXPECT_NE(bad.output.find("render.json"), std::string::npos) << bad.output;
}

}  // namespace
