// sections.speed.parity (speed.hpp): issue 18's bars for the implementations against the quaternion
// code they are isomorphic to, each row a time and its baseline's from the same run.
#include <rotorcert/report/speed.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <tuple>

namespace rotorcert::report {

namespace {

using json = nlohmann::json;

/// The time of an op row ("impl/scalar/op/n" -> ns per element, at the SIMD target the table
/// dispatched to) or of a frame row ("scene/impl/scalar/technique" -> median us per frame).
using Times = std::map<std::string, double>;

Times op_times(const json& ops) {
  Times t;
  for (const json& r : ops) {
    if (!r.contains("ns_per_element") || !r["ns_per_element"].is_number()) continue;
    t[r.value("impl", "") + "/" + r.value("scalar", "") + "/" + r.value("op", "") + "/" +
      std::to_string(r.value("n", 0LL))] = r["ns_per_element"].get<double>();
  }
  return t;
}

std::string frame_key(const std::string& scene, const std::string& impl, const std::string& scalar,
                      const std::string& technique) {
  return scene + "/" + impl + "/" + scalar + "/" + technique;
}

Times frame_times(const json& frames) {
  Times t;
  for (const json& r : frames)
    if (r.contains("us_per_frame") && r["us_per_frame"].is_number())
      t[frame_key(r.value("scene", ""), r.value("impl", ""), r.value("scalar", ""), r.value("technique", ""))] =
          r["us_per_frame"].get<double>();
  return t;
}

/// The ops of op rows at n, by (impl, scalar).
std::map<std::pair<std::string, std::string>, std::vector<std::string>> ops_at(const json& ops, long long n) {
  std::map<std::pair<std::string, std::string>, std::vector<std::string>> out;
  for (const json& r : ops)
    if (r.value("n", 0LL) == n) {
      auto& v = out[{r.value("impl", ""), r.value("scalar", "")}];
      if (std::find(v.begin(), v.end(), r.value("op", "")) == v.end()) v.push_back(r.value("op", ""));
    }
  return out;
}

struct Family {
  const char* id;
  const char* what;
  const char* unit;  // of the two times
  const char* bar_text;
};

/// Issue 18's families. A ratio bar holds where time / baseline <= bar; SIMD-SINGLE's where
/// time - baseline <= bar (ns).
constexpr Family kFamilies[] = {
    {"GEN-PARITY", "rotor_gen vs glm_quat, same op (compose, apply_vector, normalize, nlerp, slerp)", "ns/element",
     "\u2264 1.1\u00d7"},
    {"SCALAR-1.5", "rotor_m1, rotor_m2, dq, motor_pga vs glm_quat, every op both have", "ns/element", "\u2264 1.5\u00d7"},
    {"DLB-2", "dq_blend (DLB) vs glm_quat blend_qlb (QLB), same influences", "ns/element", "\u2264 2\u00d7"},
    {"DQS-FRAME", "DQS frame (dq, motor_pga) vs the glm_quat LBS (QLB) frame, same scene", "\u00b5s/frame",
     "\u2264 1.5\u00d7"},
    {"SIMD-SINGLE", "rotor_simd single-element call vs rotor_m2's", "ns/call", "\u2264 +20 ns"},
    {"SIMD-FRAME", "rotor_simd LBS frame vs the glm_quat LBS frame, same scene", "\u00b5s/frame", "\u2264 0.25\u00d7"},
};

}  // namespace

json parity_section(const json& ops, const json& frames) {
  const Times op = op_times(ops), fr = frame_times(frames);
  json rows = json::array();
  // One row when both times are there: `slowdown` = time / baseline, or the difference for SIMD-SINGLE.
  const auto add = [&](const char* family, const std::string& impl, const std::string& scalar, const std::string& what,
                       const Times& times, const std::string& key, const std::string& base_key, double bar,
                       bool difference) {
    const auto k = times.find(key), b = times.find(base_key);
    if (k == times.end() || b == times.end() || !(b->second > 0)) return;
    const double measure = difference ? k->second - b->second : k->second / b->second;
    rows.push_back({{"family", family}, {"impl", impl}, {"scalar", scalar}, {"what", what}, {"time", k->second},
                    {"baseline", b->second}, {"kernel_key", key}, {"baseline_key", base_key},
                    {difference ? "excess_ns" : "slowdown", measure}, {"bar", bar}, {"met", measure <= bar}});
  };
  const auto by_impl = ops_at(ops, 4096);
  for (const char* s : {"float", "double"}) {
    const std::string scalar = s;
    for (const char* o : {"compose", "apply_vector", "normalize", "nlerp", "slerp"})
      add("GEN-PARITY", "rotor_gen", scalar, o, op, "rotor_gen/" + scalar + "/" + o + "/4096",
          "glm_quat/" + scalar + "/" + o + "/4096", 1.1, false);
    for (const char* impl : {"rotor_m1", "rotor_m2", "dq", "motor_pga"}) {
      const auto it = by_impl.find({impl, scalar});
      if (it == by_impl.end()) continue;
      for (const std::string& o : it->second)
        add("SCALAR-1.5", impl, scalar, o, op, std::string(impl) + "/" + scalar + "/" + o + "/4096",
            "glm_quat/" + scalar + "/" + o + "/4096", 1.5, false);
    }
    for (const char* impl : {"dq", "motor_pga"})
      add("DLB-2", impl, scalar, "dq_blend", op, std::string(impl) + "/" + scalar + "/dq_blend/4096",
          "glm_quat/" + scalar + "/blend_qlb/4096", 2.0, false);
  }
  for (const json& f : frames) {
    const std::string scene = f.value("scene", ""), impl = f.value("impl", ""), scalar = f.value("scalar", ""),
                      technique = f.value("technique", "");
    const std::string key = frame_key(scene, impl, scalar, technique);
    const std::string qlb = frame_key(scene, "glm_quat", scalar, "LBS");
    if ((impl == "dq" || impl == "motor_pga") && technique == "DQS")
      add("DQS-FRAME", impl, scalar, scene, fr, key, qlb, 1.5, false);
    if (impl == "rotor_simd" && technique == "LBS") add("SIMD-FRAME", impl, scalar, scene, fr, key, qlb, 0.25, false);
  }
  for (const auto& [impl_scalar, list] : ops_at(ops, 1))
    if (impl_scalar.first == "rotor_simd")
      for (const std::string& o : list)
        add("SIMD-SINGLE", "rotor_simd", impl_scalar.second, o, op, "rotor_simd/" + impl_scalar.second + "/" + o + "/1",
            "rotor_m2/" + impl_scalar.second + "/" + o + "/1", 20.0, true);

  json families = json::array();
  for (const Family& f : kFamilies) {
    std::size_t met = 0, total = 0;
    const json* worst = nullptr;
    const char* measure = std::string(f.id) == "SIMD-SINGLE" ? "excess_ns" : "slowdown";
    for (const json& r : rows) {
      if (r["family"] != f.id) continue;
      ++total;
      met += r["met"].get<bool>() ? 1 : 0;
      if (!worst || r[measure].get<double>() > (*worst)[measure].get<double>()) worst = &r;
    }
    families.push_back({{"id", f.id}, {"what", f.what}, {"unit", f.unit}, {"bar", f.bar_text}, {"met", met},
                        {"rows", total}, {"worst", worst ? *worst : json(nullptr)}});
  }
  return {{"families", families}, {"rows", rows}};
}

}  // namespace rotorcert::report
