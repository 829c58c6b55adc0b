// `rotorcert render [FILE.gltf|.glb] --out DIR [--clip NAME]... [--frames N] [--width W --height H]
// [--impl NAME]...`: the render check (spec VIS-1..3, render_check/). Without FILE the built-in
// characters (CHAR-1) are used. Writes DIR/render.json, DIR/render.html (figure strips embedded as
// data: URIs, per-method frames linked relative to it) and the PNGs, every file atomically.
// Exit: 0 when every method gives what is expected of it (render_check.hpp's expectation()),
// 1 otherwise, 2 for a usage error or an unreadable or malformed glTF file (GLTF-3).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include <rotorcert/certify/atomic_file.hpp>
#include <rotorcert/registry.hpp>
#include <rotorcert/render/character.hpp>
#include <rotorcert/render/gltf_load.hpp>
#include <rotorcert/render/render_check.hpp>

#include "commands.hpp"

namespace rotorcert::cli {

int run_render(const RenderRequest& o, const char* who, nlohmann::json* result_out) {
  namespace r = rotorcert::render;
  std::vector<r::Scene> scenes;
  std::vector<r::SceneInput> inputs;
  if (!o.file.empty()) {
    try {
      scenes.push_back(r::load_gltf_file(o.file));
    } catch (const r::GltfError& e) {
      // The loader's message names the file and the glTF object.
      std::cerr << who << ": " << e.what() << '\n';
      return kExitUsage;
    } catch (const std::exception& e) {
      std::cerr << who << ": " << o.file << ": " << e.what() << '\n';
      return kExitUsage;
    }
    if (scenes[0].meshes.empty() || scenes[0].clips.empty()) {
      std::cerr << who << ": " << o.file << ": no skinned mesh or no animation to check\n";
      return kExitUsage;
    }
    inputs.push_back({std::filesystem::path(o.file).filename().string(), &scenes[0]});
    // glTF is in metres (GLTF spec 3.4); a bind pose taller than a building is most likely in
    // centimetres (the CMU clips are), which scales every error in mm by 100.
    double lo = INFINITY, hi = -INFINITY;
    for (const auto& mesh : scenes[0].meshes)
      for (const auto& p : mesh.positions) lo = std::min(lo, p[1]), hi = std::max(hi, p[1]);
    const double height_m = (hi - lo) * o.metres_per_unit;
    if (height_m > 20.0)
      std::cerr << who << ": note: " << o.file << " is " << height_m
                << " m tall in its bind pose; if its unit is the centimetre, pass --metres-per-unit 0.01\n";
  } else {
    for (auto c : {r::Complexity::simple, r::Complexity::medium, r::Complexity::full}) scenes.push_back(r::make_character(c));
    for (std::size_t i = 0; i < scenes.size(); ++i)
      inputs.push_back({r::to_string(static_cast<r::Complexity>(i)), &scenes[i]});
  }
  for (const auto& c : o.clips) {
    bool found = false;
    for (const auto& s : scenes)
      for (const auto& clip : s.clips) found = found || clip.name == c;
    if (!found) {
      std::cerr << who << ": no clip named \"" << c << "\"\n";
      return kExitUsage;
    }
  }

  std::vector<const rc_impl*> tables;
  for (const rc_impl* t : impl::builtin_tables())
    if (o.impls.empty() || std::find(o.impls.begin(), o.impls.end(), t->name) != o.impls.end()) tables.push_back(t);
  for (const auto& name : o.impls)
    if (std::none_of(tables.begin(), tables.end(), [&](const rc_impl* t) { return t->name == name; })) {
      std::cerr << who << ": unknown implementation \"" << name << "\" (see rotorcert list)\n";
      return kExitUsage;
    }
  const std::vector<r::SkinningMethod> methods = r::skinning_methods(tables);
  if (methods.empty() && !o.require_methods) return kExitOk;  // nothing to draw, nothing written
  if (methods.empty()) {
    std::cerr << who << ": the implementations chosen offer neither LBS nor DQS\n";
    return kExitUsage;
  }

  r::RenderCheckOptions options;
  options.clips = o.clips;
  options.frames = o.frames;
  options.width = o.width;
  options.height = o.height;
  options.metres_per_unit = o.metres_per_unit;
  options.out = o.out;
  std::filesystem::create_directories(options.out);
  std::unique_ptr<r::OsmesaRenderer> renderer;
  try {
    renderer = std::make_unique<r::OsmesaRenderer>();
  } catch (const r::RenderError& e) {
    std::cerr << who << ": no OpenGL context: " << e.what() << '\n';
    return kExitFailed;
  }
  const auto result = r::run_render_check(inputs, methods, options, *renderer);
  certify::write_atomically(options.out / "render.json", result.dump(1) + "\n");
  certify::write_atomically(options.out / "render.html", r::render_html(result, options.out));
  if (result_out != nullptr) *result_out = result;

  if (!o.print) return result.at("summary").at("exit_code").get<int>();
  std::printf("%-16s %-28s %-15s %11s %11s %11s %-15s %8s %9s %s\n", "scene", "method", "VIS-1", "max mm", "virtual mm",
              "normal rad", "VIS-2", "share>1", "PSNR dB", "expected");
  const auto f = [](const nlohmann::json& x) { return x.is_number() ? x.get<double>() : std::nan(""); };
  for (const auto& s : result.at("scenes"))
    for (const auto& m : s.at("methods"))
      std::printf("%-16s %-28s %-15s %11.3e %11.3e %11.3e %-15s %8.2e %9.1f %s%s\n", s.at("scene").get<std::string>().c_str(),
                  m.at("method").get<std::string>().c_str(), m.at("vis1").at("verdict").get<std::string>().c_str(),
                  f(m["vis1"]["max_mm"]), f(m["vis1"]["virtual_max_mm"]), f(m["vis1"]["normal_max_rad"]),
                  m.at("vis2").at("verdict").get<std::string>().c_str(), f(m["vis2"]["share_over"]),
                  m["vis2"]["psnr_db"].is_null() ? INFINITY : f(m["vis2"]["psnr_db"]),  // null: identical frames
                  m.at("expected").is_null() ? "-" : m.at("expected").get<std::string>().c_str(),
                  m.at("as_expected").get<bool>() ? "" : "  (NOT AS EXPECTED)");
  std::printf("wrote %s/render.json, render.html and PNGs; %s\n", o.out.c_str(),
              result.at("summary").at("as_expected").get<bool>() ? "every result as expected" : "some results NOT as expected");
  return result.at("summary").at("exit_code").get<int>();
}

Command add_render(CLI::App& parent) {
  CLI::App* app = parent.add_subcommand(
      "render", "Render check: pose, skin and draw characters with each implementation against the reference (VIS-1..3)");
  auto o = std::make_shared<RenderRequest>();
  app->add_option("file", o->file, "A skinned, animated .gltf or .glb (default: the built-in characters)");
  app->add_option("--out", o->out, "Output directory (render.json, render.html, PNGs)")->required();
  app->add_option("--clip", o->clips, "Only this clip; repeatable");
  app->add_option("--frames", o->frames, "Frames per clip (VIS-1's times)")->check(CLI::Range(1, 1000));
  app->add_option("--width", o->width, "Frame width in pixels")->check(CLI::Range(16, 4096));
  app->add_option("--height", o->height, "Frame height in pixels")->check(CLI::Range(16, 4096));
  app->add_option("--impl", o->impls, "Only this implementation (both scalar types); repeatable");
  app->add_option("--metres-per-unit", o->metres_per_unit, "Scene unit in metres (glTF: 1; the mocap clips: 0.01)")
      ->check(CLI::PositiveNumber);
  return {app, [o]() { return run_render(*o, "rotorcert render"); }};
}

}  // namespace rotorcert::cli
