// frame/<scene>/<impl>/<float|double>/<LBS|DQS>: one benchmark per skinning method (every
// method skinning_methods(builtin_tables()) offers) and scene: the built-in characters simple,
// medium and full, and each glTF file of the mocap directory. Each times FrameJob::run() (one
// frame: two clips sampled and blended, hierarchy, skinning transforms, every vertex), time
// advancing one 60 Hz frame per iteration, after a guard (not timed) that the job's vertices
// are the render check's (PoseJob + SkinJob) within VIS-1's strict bars.
// frame_pose/<same>: the same frames without the vertices (FrameJob::skin_vertices = false):
// the part that is the rotation library's alone (the LBS vertex loop is the suite's).
#include "frame_bench.hpp"
#include "options.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <benchmark/benchmark.h>
#include <rotorcert/reference/scalar.hpp>
#include <rotorcert/registry.hpp>
#include <rotorcert/render/character.hpp>
#include <rotorcert/render/gltf_load.hpp>
#include <rotorcert/render/render_check.hpp>

#include "frame_job.hpp"

#ifndef ROTORCERT_SHARED_DIR
#define ROTORCERT_SHARED_DIR ""
#endif

namespace rotorcert::bench {
namespace {

namespace r = rotorcert::render;
namespace fs = std::filesystem;

constexpr double kAlpha = 0.25;             // weight of clip B in the pose blend
constexpr double kFrameStep = 1.0 / 60.0;   // one iteration = one frame of a 60 Hz display
constexpr double kPhase = 1.0 / 240.0;      // frames at (1 + 4i)/240 s never fall on a 30 or 24 Hz keyframe
constexpr std::size_t kInfluences = 4;      // per vertex (glTF's JOINTS_0 / WEIGHTS_0)
/// Frames the guard compares (indices into the benchmark's frame sequence).
constexpr std::size_t kGuardFrames[] = {0, 13, 42, 77};

/// A scene with its rig (which points into it: held by unique_ptr, never moved) and its clips.
struct FrameScene {
  std::string label;
  r::Scene scene;
  r::Rig rig;
  double metres_per_unit = 1.0;  // vertex_error.hpp: glTF metres; the mocap clips are in cm
  const r::Clip* a = nullptr;
  const r::Clip* b = nullptr;
  double b_offset = 0.0;  // B is A half a clip later when the scene has one clip
};

std::vector<std::unique_ptr<FrameScene>>& scenes() {
  static std::vector<std::unique_ptr<FrameScene>> s;
  return s;
}

/// Frame i: (time on A, time on B), wrapping around each clip.
std::pair<double, double> frame_times(const FrameScene& s, std::size_t i) {
  auto at = [](const r::Clip& c, double t) {
    const double d = c.duration();
    return d > 0 ? c.start + std::fmod(t, d) : c.start;
  };
  const double t = kPhase + static_cast<double>(i) * kFrameStep;
  return {at(*s.a, t), at(*s.b, t + s.b_offset)};
}

/// The FrameJob of the (scene, method) last run, prepared and checked once (Google Benchmark
/// calls a benchmark's function several times while it grows the iteration count, and
/// frame/ and frame_pose/ of one method run one after the other).
struct Prepared {
  std::string key;
  FrameJob job;
  std::string error;
};
Prepared& prepared() {
  static Prepared p;
  return p;
}

void prepare(Prepared& p, const FrameScene& sc, const r::SkinningMethod& m, const std::string& key) {
  p.key = key;
  p.error.clear();
  p.job = FrameJob{};
  FrameJob& job = p.job;
  job.method = m;
  job.scene = &sc.scene;
  job.rig = &sc.rig;
  job.clip_a = sc.a;
  job.clip_b = sc.b;
  job.alpha = kAlpha;
  if (!job.prepare()) {
    p.error = job.message;
    return;
  }
  // The guard: what is timed must be the render check's frame (VIS-1's strict bars, the
  // spec's classes vis-mm and vis-rad).
  std::vector<std::pair<double, double>> times;
  for (const std::size_t i : kGuardFrames) times.push_back(frame_times(sc, i));
  const FrameAgreement a = compare_with_render_check(job, times, sc.metres_per_unit);
  const r::VisualBars bars;
  if (!a.failure.empty()) {
    p.error = a.failure;
  } else if (!(a.max_mm <= bars.mm_strict) || !(a.max_normal_rad <= bars.rad_strict)) {
    char buf[160];
    std::snprintf(buf, sizeof buf,
                  "FrameJob is not the render check's frame: %.3g mm, %.3g rad (bars %g mm, %g rad) at ",
                  a.max_mm, a.max_normal_rad, bars.mm_strict, bars.rad_strict);
    p.error = buf + a.worst;
  }
}

void run_frame(benchmark::State& state, const FrameScene& sc, const r::SkinningMethod& m, bool pose_only,
               const std::string& key) {
  Prepared& p = prepared();
  if (p.key != key) prepare(p, sc, m, key);
  if (!p.error.empty()) {
    state.SkipWithError(p.error.c_str());
    return;
  }
  FrameJob& job = p.job;
  job.skin_vertices = !pose_only;
  std::size_t i = 0;
  for (auto _ : state) {
    const auto [ta, tb] = frame_times(sc, i++);
    job.time_a = ta;
    job.time_b = tb;
    if (!job.run()) {
      state.SkipWithError(job.message.c_str());
      break;
    }
    benchmark::ClobberMemory();  // the outputs count as read
  }

  using benchmark::Counter;
  state.counters["us_per_frame"] = Counter(1e-6, Counter::kIsIterationInvariantRate | Counter::kInvert);
  state.counters["frames_per_second"] = Counter(1.0, Counter::kIsIterationInvariantRate);
  state.counters["joints"] = static_cast<double>(job.joint_count());
  state.counters["vertices"] = pose_only ? 0.0 : static_cast<double>(job.vertex_count());  // skinned per frame
  state.counters["influences"] = static_cast<double>(kInfluences);
  state.counters["levels"] = static_cast<double>(job.level_count());
  state.counters["rotation_channels"] = static_cast<double>(job.rotation_channels());
  const rc_impl& t = *m.table;
  state.SetLabel(std::string("impl=") + t.name + " scalar=" + (m.is_float() ? "float" : "double") +
                 " technique=" + r::to_string(m.technique) + " scene=" + sc.label +
                 " part=" + (pose_only ? "pose" : "frame") +
                 " target=" + (t.current_target != nullptr ? t.current_target() : "none"));
}

/// Adds a loaded scene, or says why it is skipped.
void add_scene(const std::string& label, double metres_per_unit, r::Scene scene) {
  if (scene.clips.empty()) {
    std::fprintf(stderr, "frame: %s has no clip: skipped\n", label.c_str());
    return;
  }
  auto s = std::make_unique<FrameScene>();
  s->label = label;
  s->scene = std::move(scene);
  s->rig = r::prepare_rig(s->scene.skeleton);
  s->metres_per_unit = metres_per_unit;
  s->a = &s->scene.clips[0];
  s->b = s->scene.clips.size() > 1 ? &s->scene.clips[1] : s->a;
  if (s->b == s->a) s->b_offset = 0.5 * s->a->duration();
  scenes().push_back(std::move(s));
}

}  // namespace

void register_frame_benchmarks(const RunConfig& /*config*/, bool quick) {
  ref::use_reference_precision();  // prepare_rig decomposes matrices with the MPFR reference
  benchmark::AddCustomContext("rotorcert_frame_alpha", std::to_string(kAlpha));
  benchmark::AddCustomContext("rotorcert_frame_step_s", std::to_string(kFrameStep));
  const std::vector<r::Complexity> builtin =
      quick ? std::vector{r::Complexity::medium, r::Complexity::full}
            : std::vector{r::Complexity::simple, r::Complexity::medium, r::Complexity::full};
  for (const r::Complexity c : builtin) {
    try {
      add_scene(r::to_string(c), 1.0, r::make_character(c));
    } catch (const std::exception& e) {
      std::fprintf(stderr, "frame: %s: %s: skipped\n", r::to_string(c), e.what());
    }
  }

  const fs::path mocap = fs::path(ROTORCERT_SHARED_DIR) / "data" / "mocap";
  std::error_code ec;
  if (!fs::is_directory(mocap, ec)) {
    std::fprintf(stderr, "frame: %s is absent: the mocap scenes are skipped\n", mocap.string().c_str());
  } else {
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(mocap, ec))
      if (e.path().extension() == ".gltf" || e.path().extension() == ".glb") files.push_back(e.path());
    std::sort(files.begin(), files.end());
    if (quick && files.size() > 1) files.resize(1);
    for (const fs::path& f : files) {
      try {
        add_scene(f.filename().string(), 0.01, r::load_gltf_file(f));  // centimetres (vertex_error.hpp)
      } catch (const std::exception& e) {
        std::fprintf(stderr, "frame: %s: %s: skipped\n", f.string().c_str(), e.what());
      }
    }
  }

  const std::vector<const rc_impl*> tables = impl::builtin_tables();
  const std::vector<r::SkinningMethod> methods = r::skinning_methods(tables);
  struct Registration {
    std::string name, key;
    const FrameScene* scene;
    r::SkinningMethod method;
    bool pose_only;
  };
  std::vector<Registration> once;
  for (const auto& sp : scenes()) {
    const FrameScene& sc = *sp;
    for (const r::SkinningMethod& m : methods) {
      FrameJob probe;
      probe.method = m;
      probe.scene = &sc.scene;
      probe.rig = &sc.rig;
      probe.clip_a = sc.a;
      probe.clip_b = sc.b;
      const std::string why = probe.validate();
      if (!why.empty()) {
        std::fprintf(stderr, "frame: %s, %s: %s: skipped\n", sc.label.c_str(), m.name().c_str(), why.c_str());
        continue;
      }
      for (const bool pose_only : {false, true})
        once.push_back({std::string(pose_only ? "frame_pose/" : "frame/") + sc.label + "/" + m.table->name + "/" +
                            (m.is_float() ? "float" : "double") + "/" + r::to_string(m.technique),
                        sc.label + "/" + m.name(),  // frame/ and frame_pose/ share one preparation
                        &sc, m, pose_only});
    }
  }
  // Every frame benchmark runs kFrameRepetitions times under its own name (the report takes the
  // median and the range, REPORT-2), in rounds: round k runs every benchmark once, so that a
  // drift of the machine's speed during the run spreads over every method alike instead of
  // landing on the methods that happened to run last. Registered by hand rather than with
  // Repetitions(), which renames the runs and adds aggregate rows whose coefficient of
  // variation is NaN (invalid JSON) for a counter that is 0 in every run.
  const int rounds = quick ? kQuickFrameRepetitions : kFrameRepetitions;
  benchmark::AddCustomContext("rotorcert_frame_repetitions", std::to_string(rounds));
  for (int round = 0; round < rounds; ++round)
    for (const Registration& g : once) {
      const FrameScene* sc = g.scene;
      const r::SkinningMethod m = g.method;
      const bool pose_only = g.pose_only;
      const std::string key = g.key;
      benchmark::RegisterBenchmark(g.name.c_str(), [sc, m, pose_only, key](benchmark::State& st) {
        run_frame(st, *sc, m, pose_only, key);
      });
    }
}

}  // namespace rotorcert::bench
