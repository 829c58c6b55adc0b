// sections.speed from rotorcert_bench's JSON (speed.hpp).
#include <rotorcert/report/speed.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>

namespace rotorcert::report {

std::map<std::string, std::string> bench_label_fields(const nlohmann::json& b) {
  std::map<std::string, std::string> out;
  std::istringstream in(b.value("label", std::string()));
  std::string word;
  while (in >> word) {
    const auto eq = word.find('=');
    if (eq != std::string::npos) out[word.substr(0, eq)] = word.substr(eq + 1);
  }
  return out;
}

namespace {

using json = nlohmann::json;


std::optional<double> number(const json& b, const char* key) {
  if (!b.contains(key) || !b[key].is_number()) return std::nullopt;
  const double v = b[key].get<double>();
  return std::isfinite(v) ? std::optional<double>(v) : std::nullopt;
}

json or_null(std::optional<double> v) { return v ? json(*v) : json(nullptr); }

/// Benchmarks that ran (not aggregates, not errors), by name.
std::map<std::string, json> runs_by_name(const json& bench) {
  std::map<std::string, json> out;
  for (const json& b : bench.at("benchmarks")) {
    if (!b.is_object() || b.value("run_type", "iteration") != "iteration") continue;
    if (b.value("error_occurred", false)) continue;
    out[b.value("name", "")] = b;
  }
  return out;
}

/// The method a frame row stands for in the paper's terms (Figure 1's QLB, DQB, GA rotor).
std::string method_name(const std::string& impl, const std::string& technique) {
  if ((impl == "glm_quat" || impl == "eigen_quat") && technique == "LBS") return "QLB";
  if (impl == "dq" && technique == "DQS") return "DQB";
  if (impl == "rotor_m1") return "rotor Method 1";
  if (impl == "rotor_m2") return "rotor Method 2";
  if (impl == "rotor_simd") return "SIMD rotor";
  if (impl == "rotor_gen") return "generated rotor";
  if (impl == "motor_pga") return "PGA motor";
  if (impl == "paper_literal") return "paper as printed";
  return impl;
}

/// The repetitions of one frame benchmark (Google Benchmark writes each as an "iteration" run
/// with the same name): their median, least and greatest time in microseconds.
struct Spread {
  double median = 0, low = 0, high = 0;
  std::size_t count = 0;
};
Spread spread_of(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  Spread s;
  s.count = v.size();
  s.low = v.front();
  s.high = v.back();
  s.median = v.size() % 2 ? v[v.size() / 2] : (v[v.size() / 2 - 1] + v[v.size() / 2]) / 2;
  return s;
}

/// How a GA rotor compares with a baseline frame (REPORT-2): the ratio of the medians
/// baseline / rotor, and the interval [low_b / high_r, high_b / low_r] from the two ranges. Faster
/// where even the slowest rotor repetition beats the fastest baseline one (interval above 1),
/// slower where the reverse holds, parity where the ranges overlap. With R repetitions each
/// median lies within its range with probability 1 - 2^(1-R) (94 % for R = 5, 98 % for 7).
json compare(const Spread& baseline, const Spread& rotor) {
  const double lo = baseline.low / rotor.high, hi = baseline.high / rotor.low;
  const char* verdict = lo > 1 ? "faster" : hi < 1 ? "slower" : "parity";
  return {{"ratio", baseline.median / rotor.median}, {"low", lo}, {"high", hi}, {"verdict", verdict}};
}

json spread_json(const Spread& s) {
  return {{"median", s.median}, {"low", s.low}, {"high", s.high}, {"repetitions", s.count}};
}

json machine_json(const json& context) {
  json m = json::object();
  for (const char* k : {"cpu_model", "num_cpus", "mhz_per_cpu", "caches", "load_avg", "hwy_target", "compiler",
                        "library_build_type", "date"})
    if (context.contains(k)) m[k] = context[k];
  return m;
}

}  // namespace

json speed_section(const json& bench, const std::vector<json>& certificates, const std::string& source) {
  if (!bench.is_object() || !bench.contains("benchmarks") || !bench["benchmarks"].is_array())
    throw std::runtime_error(source + ": not a Google Benchmark JSON document (no \"benchmarks\" array)");
  const json context = bench.value("context", json::object());
  const auto runs = runs_by_name(bench);
  const auto find = [&](const std::string& name) -> const json* {
    const auto it = runs.find(name);
    return it == runs.end() ? nullptr : &it->second;
  };

  json section = {{"source", source},
                  {"quick", context.value("rotorcert_quick", "false") == "true"},
                  {"date", context.value("date", "")},
                  {"machine", machine_json(context)}};
  json notes = json::array();

  // Roofs.
  const auto roof = [&](const char* name, const char* counter) -> std::optional<double> {
    const json* b = find(name);
    return b ? number(*b, counter) : std::nullopt;
  };
  const auto flops_f = roof("roofline/peak_fma/float", "flops_per_second");
  const auto flops_d = roof("roofline/peak_fma/double", "flops_per_second");
  const auto bw_read = roof("roofline/bandwidth/read", "bytes_per_second");
  const auto bw_triad = roof("roofline/bandwidth/triad", "bytes_per_second");
  section["roofs"] = {{"peak_flops", {{"float", or_null(flops_f)}, {"double", or_null(flops_d)}}},
                      {"bandwidth", {{"read", or_null(bw_read)}, {"triad", or_null(bw_triad)}}}};
  if (!flops_f || !flops_d || !bw_triad) notes.push_back("roofline benchmarks missing: no roofline fractions");

  // Baselines, and their ns/element by (name, scalar, n) for the ratios of every op.
  json baselines = json::array();
  std::map<std::string, double> baseline_ns;  // "glm_slerp/float/4096" -> ns
  for (const auto& [name, b] : runs) {
    if (name.rfind("baseline/", 0) != 0) continue;
    auto f = bench_label_fields(b);
    const auto ns = number(b, "ns_per_element");
    const std::string base = name.substr(9, name.find('/', 9) - 9);
    if (!ns) continue;
    baselines.push_back({{"name", base}, {"scalar", f["scalar"]}, {"n", std::stoll(f["n"])}, {"ns_per_element", *ns}});
    baseline_ns[base + "/" + f["scalar"] + "/" + f["n"]] = *ns;
  }
  section["baselines"] = baselines;

  // Ops, with the roofline.
  json ops = json::array();
  for (const auto& [name, b] : runs) {
    if (name.rfind("op/", 0) != 0) continue;
    auto f = bench_label_fields(b);
    const auto ns = number(b, "ns_per_element");
    const auto ips = number(b, "items_per_second");
    if (!ns || !ips) continue;
    const auto flops = number(b, "flops_per_element");
    const auto bytes = number(b, "bytes_per_element");
    const long long n = std::stoll(f["n"]);
    const auto peak = f["scalar"] == "float" ? flops_f : flops_d;
    std::optional<double> compute, memory;
    if (peak && flops && *flops > 0) compute = *peak / *flops;
    if (n >= 65536 && bw_triad && bytes && *bytes > 0) memory = *bw_triad / *bytes;
    std::optional<double> bound;
    std::string bound_kind;
    if (compute && (!memory || *compute <= *memory)) bound = compute, bound_kind = "compute";
    else if (memory) bound = memory, bound_kind = "memory";
    json row = {{"impl", f["impl"]}, {"scalar", f["scalar"]}, {"op", f["op"]}, {"n", n},
                {"k", f.count("k") ? std::stoll(f["k"]) : 1}, {"simd_target", f["target"]},
                {"ns_per_element", *ns}, {"items_per_second", *ips}, {"flops_per_element", or_null(flops)},
                {"bytes_per_element", or_null(bytes)}, {"bound", bound ? json(bound_kind) : json(nullptr)},
                {"attainable_per_second", or_null(bound)},
                {"roofline_fraction", bound ? json(*ips / *bound) : json(nullptr)}};
    for (const char* base : {"glm_slerp", "glm_mix"}) {
      const auto it = baseline_ns.find(std::string(base) + "/" + f["scalar"] + "/" + f["n"]);
      row[std::string("vs_") + base] = it == baseline_ns.end() ? json(nullptr) : json(it->second / *ns);
    }
    const auto g_mul = number(b, "generated_mul"), g_add = number(b, "generated_add"),
               g_div = number(b, "generated_div"), g_sqrt = number(b, "generated_sqrt");
    row["generated_ops"] = g_mul && g_add && g_div && g_sqrt
                               ? json{{"mul", *g_mul}, {"add", *g_add}, {"div", *g_div}, {"sqrt", *g_sqrt}}
                               : json(nullptr);
    ops.push_back(row);
  }
  section["ops"] = ops;

  // Algebra or implementation: the generated rotor's arithmetic per op (its generator's count of
  // the fast path) beside the quaternion formula's nominal flops and both tables' times at 4096.
  // Equal arithmetic with unequal times puts a gap in the implementation, not the algebra.
  // The op rows at 4096, by "impl/scalar/op" (also the accuracy-versus-speed join below).
  std::map<std::string, const json*> op4096;
  for (const json& r : ops)
    if (r.at("n") == 4096)
      op4096[r.at("impl").get<std::string>() + "/" + r.at("scalar").get<std::string>() + "/" + r.at("op").get<std::string>()] = &r;
  json counts = json::array();
  for (const auto& [key, r] : op4096) {
    if (r->at("impl") != "rotor_gen" || r->at("generated_ops").is_null()) continue;
    const json& g = r->at("generated_ops");
    const auto glm = op4096.find("glm_quat/" + r->at("scalar").get<std::string>() + "/" + r->at("op").get<std::string>());
    const double ns = r->at("ns_per_element").get<double>();
    json c = {{"op", r->at("op")}, {"scalar", r->at("scalar")}, {"n", 4096}, {"generated", g},
              {"generated_total", g.at("mul").get<double>() + g.at("add").get<double>() + g.at("div").get<double>() +
                                      g.at("sqrt").get<double>()},
              {"formula_flops", r->at("flops_per_element")}, {"ns_per_element", ns}};
    if (glm != op4096.end()) {
      const double glm_ns = glm->second->at("ns_per_element").get<double>();
      c["glm_quat_ns_per_element"] = glm_ns;
      c["vs_glm_quat"] = ns / glm_ns;
    } else {
      c["glm_quat_ns_per_element"] = nullptr;
      c["vs_glm_quat"] = nullptr;
    }
    counts.push_back(c);
  }
  section["operation_counts"] = counts;

  // Targets.
  json targets = json::array();
  for (const SpeedTarget& t : kSpeedTargets) {
    const json* k = find(t.kernel);
    const json* base = find(t.baseline);
    json row = {{"id", t.id}, {"what", t.what}, {"kernel", t.kernel}, {"baseline", t.baseline}, {"n", 4096},
                {"target", t.target}};
    const auto kn = k ? number(*k, "ns_per_element") : std::nullopt;
    const auto bn = base ? number(*base, "ns_per_element") : std::nullopt;
    if (kn && bn) {
      const double ratio = *bn / *kn;
      row["ratio"] = ratio;
      row["met"] = ratio >= t.target;
      row["missed_by"] = ratio >= t.target ? json(nullptr) : json(t.target / ratio);
    } else {
      row["ratio"] = nullptr;
      row["met"] = nullptr;
      row["missed_by"] = nullptr;
      notes.push_back(std::string("target ") + t.id + ": " + (kn ? t.baseline : t.kernel) + " was not run");
    }
    targets.push_back(row);
  }
  section["targets"] = targets;

  // Frame pipeline; the pose part alone (frame_pose/: no vertices) beside each whole frame.
  std::map<std::string, double> pose_us;
  for (const auto& [name, b] : runs)
    if (name.rfind("frame_pose/", 0) == 0) {
      auto f = bench_label_fields(b);
      if (const auto us = number(b, "us_per_frame"))
        pose_us[f["scene"] + "|" + f["impl"] + "|" + f["scalar"] + "|" + f["technique"]] = *us;
    }
  // Every repetition of a frame benchmark: the frame time is the median, with the range beside it.
  std::map<std::string, std::vector<double>> frame_times;
  for (const json& b : bench.at("benchmarks")) {
    if (!b.is_object() || b.value("run_type", "iteration") != "iteration" || b.value("error_occurred", false)) continue;
    const std::string name = b.value("name", "");
    if (name.rfind("frame/", 0) != 0) continue;
    if (const auto us = number(b, "us_per_frame")) frame_times[name].push_back(*us);
  }
  json frames = json::array();
  std::map<std::pair<std::string, std::string>, std::map<std::string, Spread>> by_scene;
  for (const auto& [name, b] : runs) {
    if (name.rfind("frame/", 0) != 0 || !frame_times.count(name)) continue;
    auto f = bench_label_fields(b);
    const Spread t = spread_of(frame_times[name]);
    const std::string method = method_name(f["impl"], f["technique"]);
    frames.push_back({{"scene", f["scene"]}, {"impl", f["impl"]}, {"scalar", f["scalar"]}, {"technique", f["technique"]},
                      {"method", method}, {"us_per_frame", t.median}, {"us_range", {t.low, t.high}},
                      {"repetitions", t.count}, {"joints", or_null(number(b, "joints"))},
                      {"vertices", or_null(number(b, "vertices"))}});
    const auto pose = pose_us.find(f["scene"] + "|" + f["impl"] + "|" + f["scalar"] + "|" + f["technique"]);
    frames.back()["pose_us"] = pose == pose_us.end() ? json(nullptr) : json(pose->second);
    by_scene[{f["scene"], f["scalar"]}][f["impl"] + " " + f["technique"]] = t;
  }
  section["frames"] = frames;
  section["parity"] = parity_section(ops, frames);

  // The paper's claim: GA rotors (Method 1, Method 2, the SIMD rotor, the generated rotor; the
  // fastest of them) take less time per frame than QLB (glm_quat LBS) and DQB (dq DQS).
  // "Faster" only where the repetitions' ranges do not overlap (compare()); "holds" where the
  // fastest rotor (by median) is faster than both.
  json claim = json::array();
  for (const auto& [key, m] : by_scene) {
    const auto qlb = m.find("glm_quat LBS");
    const auto dqb = m.find("dq DQS");
    std::string rotor;
    const Spread* r = nullptr;
    for (const auto& [impl_tech, v] : m)
      if ((impl_tech.rfind("rotor_m1 ", 0) == 0 || impl_tech.rfind("rotor_m2 ", 0) == 0 ||
           impl_tech.rfind("rotor_simd ", 0) == 0 || impl_tech.rfind("rotor_gen ", 0) == 0) &&
          (r == nullptr || v.median < r->median))
        rotor = impl_tech, r = &v;
    if (qlb == m.end() || dqb == m.end() || r == nullptr) continue;
    const json vs_qlb = compare(qlb->second, *r), vs_dqb = compare(dqb->second, *r);
    claim.push_back({{"scene", key.first}, {"scalar", key.second}, {"qlb_us", qlb->second.median},
                     {"dqb_us", dqb->second.median}, {"rotor", rotor}, {"rotor_us", r->median},
                     {"qlb", spread_json(qlb->second)}, {"dqb", spread_json(dqb->second)}, {"rotor_spread", spread_json(*r)},
                     {"vs_qlb", vs_qlb["ratio"]}, {"vs_dqb", vs_dqb["ratio"]}, {"vs_qlb_interval", {vs_qlb["low"], vs_qlb["high"]}},
                     {"vs_dqb_interval", {vs_dqb["low"], vs_dqb["high"]}}, {"verdict_qlb", vs_qlb["verdict"]},
                     {"verdict_dqb", vs_dqb["verdict"]},
                     {"holds", vs_qlb["verdict"] == "faster" && vs_dqb["verdict"] == "faster"}});
    if (r->count < 2 || qlb->second.count < 2 || dqb->second.count < 2)
      notes.push_back("paper claim, " + key.first + " " + key.second +
                      ": a single repetition, so no spread: the verdicts compare single times");
  }
  section["paper_claim"] = claim;

  // Accuracy versus speed: the certificate's accuracy of each op beside its ns/element at 4096.
  json avs = json::array();
  for (const json& c : certificates) {
    if (!c.is_object() || !c.contains("accuracy") || !c["accuracy"].is_array()) continue;
    for (const json& a : c["accuracy"]) {
      const std::string key = c.value("name", "") + "/" + c.value("scalar", "") + "/" + a.value("op", "");
      const auto it = op4096.find(key);
      if (it == op4096.end()) continue;
      avs.push_back({{"impl", c.value("name", "")}, {"scalar", c.value("scalar", "")}, {"op", a.value("op", "")},
                     {"n", 4096}, {"ns_per_element", it->second->at("ns_per_element")},
                     {"max_eps", a.contains("max_eps") ? a["max_eps"] : json(nullptr)},
                     {"p99_eps", a.contains("p99_eps") ? a["p99_eps"] : json(nullptr)}});
    }
  }
  section["accuracy_vs_speed"] = avs;
  if (certificates.empty()) notes.push_back("no certificates given: no accuracy-versus-speed chart");
  const double load = context.contains("load_avg") && context["load_avg"].is_array() && !context["load_avg"].empty() &&
                              context["load_avg"][0].is_number()
                          ? context["load_avg"][0].get<double>()
                          : 0.0;
  if (load > context.value("num_cpus", 1) * 0.75)
    notes.push_back("load average " + std::to_string(load).substr(0, 4) +
                    " when the run began: other work shared the CPUs, absolute times are pessimistic (ratios within "
                    "the run less so)");
  section["notes"] = notes;
  return section;
}

}  // namespace rotorcert::report
