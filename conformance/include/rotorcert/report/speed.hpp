// The speed section of report.json (REPORT-2), computed from the Google Benchmark JSON that
// `rotorcert_bench` writes (conformance/bench/README.md) and, for the accuracy-versus-speed chart,
// from the certificates of the same report. Everything the section says is derived from those two
// inputs alone, so that a bench.json kept from another machine gives the same section.
//
// sections.speed (all times are CPU time; ratios are taken within the one run):
//   {"source": bench.json path, "quick": bool, "date",
//    "machine": {"cpu_model", "num_cpus", "mhz_per_cpu", "caches": [...], "load_avg": [...], "hwy_target",
//                "compiler", "library_build_type"},
//    "roofs": {"peak_flops": {"float", "double"} (FMA = 2 flops, one core), "bandwidth": {"read", "triad"} (B/s)},
//    "baselines": [{"name": "glm_slerp"|"glm_mix", "scalar", "n", "ns_per_element"}],
//    "targets": [{"id", "what", "kernel", "baseline", "n", "ratio", "target", "met", "missed_by"}]
//               (missed_by: target / ratio when not met, else null),
//    "ops": [{"impl", "scalar", "op", "n", "k", "simd_target", "ns_per_element", "items_per_second",
//             "flops_per_element", "bytes_per_element", "bound": "compute"|"memory",
//             "attainable_per_second", "roofline_fraction", "vs_glm_slerp", "vs_glm_mix"}],
//    "frames": [{"scene", "impl", "scalar", "technique", "method", "us_per_frame", "pose_us" (the frame without
//                skinning the vertices, or null), "joints", "vertices"}],
//    "paper_claim": [{"scene", "scalar", "qlb_us", "dqb_us", "rotor", "rotor_us", "vs_qlb", "vs_dqb", "holds"}],
//    "accuracy_vs_speed": [{"impl", "scalar", "op", "n", "ns_per_element", "max_eps", "p99_eps"}],
//    "parity": {"families": [{"id", "what", "unit", "bar", "met", "rows", "worst": row or null}],
//               "rows": [{"family", "impl", "scalar", "what" (op or scene), "time", "baseline", "kernel_key",
//                         "baseline_key", "slowdown" = time / baseline (or "excess_ns" = time - baseline for
//                         SIMD-SINGLE), "bar", "met"}]}
//               (issue 18's bars; a row only where both times were measured in this run),
//    "notes": [text]}
// Roofline: a kernel's bound is min(peak_flops / flops_per_element, bandwidth.triad / bytes_per_element)
// at the streaming size (n >= 65536), and peak_flops / flops_per_element for batches that run
// from cache (the memory roof does not bound them); roofline_fraction = items_per_second / bound.
#pragma once

#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace rotorcert::report {

/// The label rotorcert_bench gives an op benchmark ("impl=glm_quat scalar=float op=slerp n=4096
/// k=1 target=none") as key/value pairs: how a benchmark is read, never from its name.
std::map<std::string, std::string> bench_label_fields(const nlohmann::json& benchmark);

/// The speed targets of REPORT-2: ratios at 4096 float elements against a GLM baseline of the same run.
struct SpeedTarget {
  const char* id;
  const char* what;
  const char* kernel;    // benchmark name
  const char* baseline;  // benchmark name
  double target;         // required ratio baseline_ns / kernel_ns
};
inline constexpr SpeedTarget kSpeedTargets[] = {
    {"SIMD-SLERP", "SIMD rotor slerp (slerp clauses) vs glm::slerp", "op/slerp/rotor_simd/float/4096",
     "baseline/glm_slerp/float/4096", 10.0},
    {"SIMD-QLB", "SIMD QLB (blend_qlb, k = 4) vs glm::mix", "op/blend_qlb/rotor_simd/float/4096",
     "baseline/glm_mix/float/4096", 15.0},
    {"SIMD-NLERP", "SIMD nlerp (QLB of two) vs glm::mix", "op/nlerp/rotor_simd/float/4096",
     "baseline/glm_mix/float/4096", 15.0},
};

/// sections.speed.parity from the section's "ops" and "frames" rows (speed_parity.cpp).
nlohmann::json parity_section(const nlohmann::json& ops, const nlohmann::json& frames);

/// sections.speed from a rotorcert_bench JSON document. `certificates` are the report's
/// (accuracy per op); may be empty. Throws std::runtime_error when `bench` is not a Google
/// Benchmark JSON document with a "benchmarks" array.
nlohmann::json speed_section(const nlohmann::json& bench, const std::vector<nlohmann::json>& certificates,
                             const std::string& source);

}  // namespace rotorcert::report
