// Shared by the render_check_test_skin_* tests: the built-in characters, the frames measured,
// the spec bound for a posed and skinned character, which tables conform for a method, and the
// error table the tests print.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include <rotorcert/reference/tolerance.hpp>
#include <rotorcert/registry.hpp>
#include <rotorcert/render/character.hpp>
#include <rotorcert/render/method.hpp>
#include <rotorcert/render/pose_job.hpp>
#include <rotorcert/render/reference_pose.hpp>
#include <rotorcert/render/vertex_error.hpp>
#include <rotorcert/testing/tolerance.hpp>

namespace rotorcert::render::skin_test {

inline std::filesystem::path shared_data() { return std::filesystem::path(ROTORCERT_SHARED_DIR) / "data"; }

/// A scene and its rig (the rig points into the scene, so both live at one address).
struct Character {
  Scene scene;
  Rig rig;
};

inline std::unique_ptr<Character> make_rigged(Scene s) {
  auto c = std::make_unique<Character>();
  c->scene = std::move(s);
  c->rig = prepare_rig(c->scene.skeleton);
  return c;
}

/// The built-in character, made once per test process.
inline const Character& character(Complexity c) {
  static std::map<Complexity, std::unique_ptr<Character>> cache;
  auto& slot = cache[c];
  if (!slot) slot = make_rigged(make_character(c));
  return *slot;
}

inline const Clip& clip_named(const Scene& s, const std::string& name) {
  for (const auto& c : s.clips)
    if (c.name == name) return c;
  throw std::runtime_error(s.name + " has no clip " + name);
}

/// Frames measured: fractions 0.27, 0.51 and 0.77 of the clip, which fall between keyframes of
/// the 30 and 24 frames-per-second clips (so the method's slerp is used), and the clip's end (a
/// keyframe: the full bend or twist).
inline std::vector<double> frame_times(const Clip& c) {
  return {c.start + 0.27 * c.duration(), c.start + 0.51 * c.duration(), c.start + 0.77 * c.duration(), c.end};
}

/// The tolerance class of a clause (spec/clauses.json).
inline std::string tolerance_class(const std::string& clause) {
  static const std::map<std::string, std::string> classes = [] {
    std::ifstream in(std::string(ROTORCERT_SPEC_DIR) + "/clauses.json");
    std::map<std::string, std::string> m;
    const nlohmann::json spec = nlohmann::json::parse(in);  // named: a range-for over a temporary's member dangles
    for (const auto& c : spec.at("clauses")) m[c.at("id").get<std::string>()] = c.at("tolerance").get<std::string>();
    return m;
  }();
  return classes.at(clause);
}

inline ref::Bars clause_bars(const std::string& clause) { return testing::eps_class_bars(tolerance_class(clause)); }

/// The bound of a posed and skinned vertex in eps units of the method's format, relative to the
/// character's size s (METRIC-3 with SKIN-1's scale taken over the whole character), from the
/// spec classes of the ops the method chains. A rotation error of e radians at any joint moves a
/// vertex by at most e times its lever arm (<= s), and a translation error relative to |t| <= s
/// moves it as much, so the errors of the chain add in units of eps * s:
///   per joint of the longest chain (root to deepest skin joint, `chain` joints):
///     LBS  keyframe slerp (SLERP-1) + compose (COMPOSE-1) + apply_vector (APPLY-1)
///     DQS  keyframe slerp (SLERP-1) or dq_sclerp (DQ-5) + dq_from_rotation_translation (DQ-1)
///          + dq_compose (DQ-2)
///     a pose blend adds its clause per joint: QLB-1, NLERP-1, DQ-6 or DQ-5;
///   once, the skinning transform (global * inverse bind): LBS COMPOSE-1 + APPLY-1 + MAT-1,
///     DQS DQ-1 + DQ-2;
///   once, the vertex: SKIN-1 (LBS) or SKIN-2 (DQS).
/// The strict bar sums the strict bars, the loose bar the loose ones. Rounding the binary64 rest
/// transforms to binary32 for a float table costs eps/2 per joint, well inside the per-joint sum.
inline ref::Bars chain_bars(Technique technique, KeyInterpolation keys, int chain, PoseBlend blend = PoseBlend::none) {
  std::vector<std::string> level{keys == KeyInterpolation::slerp ? "SLERP-1" : "DQ-5"};
  std::vector<std::string> once;
  if (technique == Technique::lbs) {
    level.insert(level.end(), {"COMPOSE-1", "APPLY-1"});
    once = {"COMPOSE-1", "APPLY-1", "MAT-1", "SKIN-1"};
  } else {
    level.insert(level.end(), {"DQ-1", "DQ-2"});
    once = {"DQ-1", "DQ-2", "SKIN-2"};
  }
  switch (blend) {
    case PoseBlend::qlb: level.push_back("QLB-1"); break;
    case PoseBlend::nlerp: level.push_back("NLERP-1"); break;
    case PoseBlend::dlb: level.push_back("DQ-6"); break;
    case PoseBlend::sclerp: level.push_back("DQ-5"); break;
    case PoseBlend::none: break;
  }
  ref::Bars b;
  for (const auto& c : level) {
    b.strict += chain * clause_bars(c).strict;
    b.loose += chain * clause_bars(c).loose;
  }
  for (const auto& c : once) {
    b.strict += clause_bars(c).strict;
    b.loose += clause_bars(c).loose;
  }
  return b;
}
inline ref::Bars chain_bars(const SkinningMethod& m, int chain, PoseBlend blend = PoseBlend::none) {
  return chain_bars(m.technique, m.key_interpolation(), chain, blend);
}

/// Joints on the longest root-to-skin-joint chain.
inline int chain_length(const Rig& rig) {
  int n = 0;
  for (std::size_t j : rig.skeleton->skin_joints) n = std::max(n, rig.depth[j] + 1);
  return n;
}

/// The character's size: max(1, largest |position| of the bind and of the posed reference), in
/// scene units (SKIN-1's scale max(1, |v|, max |t_i|), taken over the whole character).
inline double size_scale(const SkinnedMesh& mesh, const SkinOutput& reference) {
  double s = 1.0;
  for (const auto* ps : {&mesh.positions, &reference.positions})
    for (const auto& p : *ps) s = std::max(s, std::hypot(p[0], p[1], p[2]));
  return s;
}

/// impls/*/expected_failures.json: (table, "float"/"double") -> clauses it is known to fail.
inline const std::map<std::pair<std::string, std::string>, std::set<std::string>>& expected_failures() {
  static const auto table = [] {
    std::map<std::pair<std::string, std::string>, std::set<std::string>> r;
    for (const auto& dir : std::filesystem::directory_iterator(std::string(ROTORCERT_SOURCE_DIR) + "/impls")) {
      const auto file = dir.path() / "expected_failures.json";
      if (!std::filesystem::exists(file)) continue;
      std::ifstream in(file);
      const nlohmann::json j = nlohmann::json::parse(in);
      for (const auto& e : j.at("failures"))
        r[{e.at("table").get<std::string>(), e.at("scalar").get<std::string>()}].insert(e.at("clause").get<std::string>());
    }
    return r;
  }();
  return table;
}

/// A method conforms for the render check when its table claims every clause of the ops it
/// uses (method.hpp) and its expected_failures.json lists none of them: decided from data, not
/// from names.
inline bool conforming(const SkinningMethod& m) {
  if (!m.unclaimed().empty()) return false;
  const auto it = expected_failures().find({m.table->name, m.is_float() ? "float" : "double"});
  if (it == expected_failures().end()) return true;
  for (const auto& c : m.clauses())
    if (it->second.count(c) != 0) return false;
  return true;
}

/// Every built-in (table, technique) pair.
inline std::vector<SkinningMethod> builtin_methods() {
  const auto tables = impl::builtin_tables();
  return skinning_methods(tables);
}

/// One method over the frames of one clip.
struct Row {
  SkinningMethod method;
  ErrorSummary summary;
  double eps_units = 0.0;          // worst vertex error / (eps * size), over the frames
  double virtual_eps_units = 0.0;  // the same for the virtual vertices
  double volume_change_pct = std::numeric_limits<double>::quiet_NaN();  // at the last frame, closed meshes
  std::string failure;             // a job that failed (DOMAIN_ERROR, ...)
};

struct ClipResult {
  std::vector<Row> rows;
  bool closed = false;
  double reference_lbs_volume_pct = std::numeric_limits<double>::quiet_NaN();
  double reference_dqs_volume_pct = std::numeric_limits<double>::quiet_NaN();
};

inline std::string frame_label(double t) {
  char b[32];
  std::snprintf(b, sizeof b, "t=%.4f", t);
  return b;
}

/// Poses and skins `mesh` for every frame with the reference (both techniques) and every method,
/// and measures each method against the reference of its technique.
/// `volumes`: report volume changes when the mesh is closed (false where the rest pose is not a
/// pose of the animated skeleton, so that the change says nothing about skinning).
inline ClipResult measure_clip(const std::vector<SkinningMethod>& methods, const Rig& rig, const SkinnedMesh& mesh,
                               const Clip& clip, const std::vector<double>& times, double metres_per_unit = 1.0,
                               bool volumes = true) {
  ClipResult out;
  for (const auto& m : methods) out.rows.push_back({m, {}, 0.0, 0.0, std::numeric_limits<double>::quiet_NaN(), {}});
  const MeshVolume rest = mesh_volume(mesh.positions, mesh.indices);
  out.closed = volumes && rest.closed;
  auto change = [&](const SkinOutput& s) { return 100.0 * (mesh_volume(s.positions, mesh.indices).total - rest.total) / rest.total; };
  const auto& joints = rig.skeleton->skin_joints;
  for (std::size_t f = 0; f < times.size(); ++f) {
    PoseRequest req;
    req.a = {&clip, times[f]};
    const ReferencePose rp = reference_pose(rig, req);
    const SkinOutput ref[2] = {reference_skin(rp, mesh, Technique::lbs), reference_skin(rp, mesh, Technique::dqs)};
    const auto vv = reference_virtual_vertices(rp, joints, kVirtualVertexMetres / metres_per_unit);
    const bool last = f + 1 == times.size();
    if (last && out.closed) {
      out.reference_lbs_volume_pct = change(ref[0]);
      out.reference_dqs_volume_pct = change(ref[1]);
    }
    for (auto& row : out.rows) {
      if (!row.failure.empty()) continue;
      const SkinOutput& r = ref[row.method.technique == Technique::lbs ? 0 : 1];
      try {
        const FrameResult fr = measure_frame(row.method, rig, mesh, req, r, vv, joints, metres_per_unit);
        row.summary.add(frame_label(times[f]), fr.vertex, fr.virtual_vertex);
        const double unit = 1000.0 * metres_per_unit * row.method.epsilon() * size_scale(mesh, r);
        row.eps_units = std::max(row.eps_units, fr.vertex.max_mm / unit);
        row.virtual_eps_units = std::max(row.virtual_eps_units, fr.virtual_vertex.max_mm / unit);
        if (last && out.closed) row.volume_change_pct = change(fr.skin);
      } catch (const std::exception& e) {
        row.failure = e.what();
      }
    }
  }
  return out;
}

/// One table line per method: | character | clip | method | max mm | mean mm | virtual mm (joint,
/// axis, frame) | eps units | volume % |.
inline void print_table(const std::string& character, const std::string& clip, const ClipResult& r, const Rig& rig) {
  std::printf("| %s | %s | reference LBS / DQS | 0 | 0 | 0 | - | %s |\n", character.c_str(), clip.c_str(),
              r.closed ? (std::to_string(r.reference_lbs_volume_pct) + " / " + std::to_string(r.reference_dqs_volume_pct)).c_str()
                       : "-");
  for (const auto& row : r.rows) {
    if (!row.failure.empty()) {
      std::printf("| %s | %s | %s | job failed: %s |\n", character.c_str(), clip.c_str(), row.method.name().c_str(),
                  row.failure.c_str());
      continue;
    }
    const auto& s = row.summary;
    std::printf("| %s | %s | %s%s | %.3e | %.3e | %.3e (%s %c, %s) | %.1f | %s |\n", character.c_str(), clip.c_str(),
                row.method.name().c_str(), conforming(row.method) ? "" : " (nc)", s.max_mm, s.mean_mm(), s.virtual_max_mm,
                rig.skeleton->joints[s.virtual_joint].name.c_str(), "xyz"[s.virtual_axis], s.virtual_frame.c_str(),
                row.eps_units, std::isnan(row.volume_change_pct) ? "-" : std::to_string(row.volume_change_pct).c_str());
  }
}

}  // namespace rotorcert::render::skin_test
