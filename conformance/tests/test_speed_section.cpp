// The speed section (REPORT-2) computed from a Google Benchmark document built here by hand: the
// expected numbers follow from REPORT-2's definitions applied to these inputs, not from the code.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>

#include <rotorcert/report/render.hpp>
#include <rotorcert/report/speed.hpp>
#include <rotorcert/testing/clause.hpp>

namespace {

using json = nlohmann::json;
using rotorcert::report::speed_section;

json op_run(const std::string& impl, const std::string& scalar, const std::string& op, int n, double ns, double flops,
            double bytes) {
  const std::string name = "op/" + op + "/" + impl + "/" + scalar + "/" + std::to_string(n);
  return {{"name", name}, {"run_type", "iteration"}, {"ns_per_element", ns}, {"items_per_second", 1e9 / ns},
          {"flops_per_element", flops}, {"bytes_per_element", bytes},
          {"label", "impl=" + impl + " scalar=" + scalar + " op=" + op + " n=" + std::to_string(n) + " k=1 target=none"}};
}
json baseline_run(const std::string& base, const std::string& scalar, int n, double ns) {
  return {{"name", "baseline/" + base + "/" + scalar + "/" + std::to_string(n)}, {"run_type", "iteration"},
          {"ns_per_element", ns}, {"items_per_second", 1e9 / ns},
          {"label", "impl=glm scalar=" + scalar + " op=x n=" + std::to_string(n) + " k=1 target=none"}};
}
json frame_run(const std::string& scene, const std::string& impl, const std::string& technique, double us) {
  return {{"name", "frame/" + scene + "/" + impl + "/float/" + technique}, {"run_type", "iteration"}, {"us_per_frame", us},
          {"joints", 42}, {"vertices", 1000},
          {"label", "impl=" + impl + " scalar=float technique=" + technique + " scene=" + scene}};
}

json bench_document() {
  json b = {{"context", {{"num_cpus", 2}, {"load_avg", json::array({0.1, 0.1, 0.1})}, {"rotorcert_quick", "false"}}},
            {"benchmarks", json::array()}};
  auto& runs = b["benchmarks"];
  runs.push_back({{"name", "roofline/peak_fma/float"}, {"run_type", "iteration"}, {"flops_per_second", 100e9}});
  runs.push_back({{"name", "roofline/peak_fma/double"}, {"run_type", "iteration"}, {"flops_per_second", 50e9}});
  runs.push_back({{"name", "roofline/bandwidth/read"}, {"run_type", "iteration"}, {"bytes_per_second", 12e9}});
  runs.push_back({{"name", "roofline/bandwidth/triad"}, {"run_type", "iteration"}, {"bytes_per_second", 10e9}});
  runs.push_back(baseline_run("glm_slerp", "float", 4096, 50.0));
  runs.push_back(baseline_run("glm_mix", "float", 4096, 45.0));
  runs.push_back(op_run("rotor_simd", "float", "slerp", 4096, 4.0, 100.0, 52.0));     // 12.5x: met
  runs.push_back(op_run("rotor_simd", "float", "blend_qlb", 4096, 5.0, 60.0, 96.0));  // 9x: missed by 15/9
  runs.push_back(op_run("rotor_simd", "float", "slerp", 65536, 8.0, 100.0, 52.0));    // memory bound
  runs.push_back(frame_run("medium", "glm_quat", "LBS", 300.0));
  runs.push_back(frame_run("medium", "dq", "DQS", 400.0));
  runs.push_back(frame_run("medium", "rotor_m2", "LBS", 350.0));
  runs.push_back(frame_run("medium", "rotor_simd", "LBS", 250.0));
  runs.push_back(frame_run("simple", "glm_quat", "LBS", 10.0));
  runs.push_back(frame_run("simple", "dq", "DQS", 9.0));
  runs.push_back(frame_run("simple", "rotor_m1", "LBS", 9.5));
  // An error and an aggregate are not measurements.
  runs.push_back({{"name", "op/nlerp/rotor_simd/float/4096"}, {"run_type", "iteration"}, {"error_occurred", true}});
  runs.push_back({{"name", "op/compose/glm_quat/float/4096_mean"}, {"run_type", "aggregate"}, {"ns_per_element", 1.0}});
  return b;
}

const json* find_op(const json& s, const std::string& op, long long n) {
  for (const json& r : s.at("ops"))
    if (r.at("op") == op && r.at("n") == n) return &r;
  return nullptr;
}

TEST(SpeedSection, TargetsAreRatiosWithinTheRun) {
  RC_CLAUSE("REPORT-2");
  const json s = speed_section(bench_document(), {}, "bench.json");
  ASSERT_EQ(s.at("targets").size(), 3u);
  const json& slerp = s["targets"][0];
  EXPECT_EQ(slerp.at("id"), "SIMD-SLERP");
  EXPECT_DOUBLE_EQ(slerp.at("ratio").get<double>(), 50.0 / 4.0);
  EXPECT_TRUE(slerp.at("met").get<bool>());
  EXPECT_TRUE(slerp.at("missed_by").is_null());
  const json& qlb = s["targets"][1];
  EXPECT_DOUBLE_EQ(qlb.at("ratio").get<double>(), 45.0 / 5.0);
  EXPECT_FALSE(qlb.at("met").get<bool>());
  EXPECT_DOUBLE_EQ(qlb.at("missed_by").get<double>(), 15.0 / (45.0 / 5.0));
  // nlerp errored: not measured, said so, never "met".
  const json& nlerp = s["targets"][2];
  EXPECT_TRUE(nlerp.at("ratio").is_null());
  EXPECT_TRUE(nlerp.at("met").is_null());
  EXPECT_FALSE(s.at("notes").empty());
}

TEST(SpeedSection, RooflineBoundIsComputeInCacheAndTheLowerRoofWhenStreaming) {
  RC_CLAUSE("REPORT-2");
  const json s = speed_section(bench_document(), {}, "bench.json");
  const json* cached = find_op(s, "slerp", 4096);
  ASSERT_NE(cached, nullptr);
  EXPECT_EQ(cached->at("bound"), "compute");
  EXPECT_DOUBLE_EQ(cached->at("attainable_per_second").get<double>(), 100e9 / 100.0);
  EXPECT_DOUBLE_EQ(cached->at("roofline_fraction").get<double>(), (1e9 / 4.0) / (100e9 / 100.0));
  EXPECT_DOUBLE_EQ(cached->at("vs_glm_slerp").get<double>(), 50.0 / 4.0);
  // 65536: compute 1e9/s, memory (triad) 10e9 / 52 = 1.92e8/s: memory bound.
  const json* streaming = find_op(s, "slerp", 65536);
  ASSERT_NE(streaming, nullptr);
  EXPECT_EQ(streaming->at("bound"), "memory");
  EXPECT_DOUBLE_EQ(streaming->at("attainable_per_second").get<double>(), 10e9 / 52.0);
  EXPECT_TRUE(streaming->at("vs_glm_slerp").is_null());  // no baseline at 65536 in this run
  EXPECT_EQ(find_op(s, "compose", 4096), nullptr);        // the aggregate row is not an op
}

TEST(SpeedSection, PaperClaimComparesTheFastestRotorWithQlbAndDqb) {
  RC_CLAUSE("REPORT-2");
  const json s = speed_section(bench_document(), {}, "bench.json");
  ASSERT_EQ(s.at("paper_claim").size(), 2u);
  for (const json& c : s["paper_claim"]) {
    if (c.at("scene") == "medium") {
      EXPECT_EQ(c.at("rotor"), "rotor_simd LBS");  // the faster of rotor_m2 (350) and rotor_simd (250)
      EXPECT_DOUBLE_EQ(c.at("vs_qlb").get<double>(), 300.0 / 250.0);
      EXPECT_DOUBLE_EQ(c.at("vs_dqb").get<double>(), 400.0 / 250.0);
      EXPECT_TRUE(c.at("holds").get<bool>());
    } else {
      EXPECT_EQ(c.at("scene"), "simple");
      EXPECT_FALSE(c.at("holds").get<bool>());  // 9.5 us: faster than QLB (10), slower than DQB (9)
    }
  }
  bool named = false;
  for (const json& f : s.at("frames")) named = named || (f.at("impl") == "dq" && f.at("method") == "DQB");
  EXPECT_TRUE(named);
}

// The generated rotor (rotor_gen) is one of the GA rotors of the paper's claim.
TEST(SpeedSection, PaperClaimCountsTheGeneratedRotorAsAGaRotor) {
  RC_CLAUSE("REPORT-2");
  json b = bench_document();
  json& runs = b["benchmarks"];
  runs.push_back(frame_run("generated", "glm_quat", "LBS", 300.0));
  runs.push_back(frame_run("generated", "dq", "DQS", 400.0));
  runs.push_back(frame_run("generated", "rotor_m2", "LBS", 350.0));
  runs.push_back(frame_run("generated", "rotor_gen", "LBS", 200.0));
  const json s = speed_section(b, {}, "bench.json");
  bool seen = false;
  for (const json& c : s.at("paper_claim"))
    if (c.at("scene") == "generated") {
      seen = true;
      EXPECT_EQ(c.at("rotor"), "rotor_gen LBS");  // the fastest of rotor_m2 (350) and rotor_gen (200)
      EXPECT_TRUE(c.at("holds").get<bool>());
    }
  EXPECT_TRUE(seen);
}

// Repeated frames (REPORT-2): the frame time is the median of the repetitions, and a verdict is
// "faster" or "slower" only where the two ranges do not overlap.
TEST(SpeedSection, PaperClaimVerdictsComeFromTheRangesOfTheRepetitions) {
  RC_CLAUSE("REPORT-2");
  json b = bench_document();
  json& runs = b["benchmarks"];
  json kept = json::array();
  for (const json& r : runs)
    if (r.at("name").get<std::string>().rfind("frame/", 0) != 0) kept.push_back(r);
  runs = kept;
  const auto reps = [&](const std::string& scene, const std::string& impl, const std::string& technique,
                        std::initializer_list<double> us) {
    for (double t : us) runs.push_back(frame_run(scene, impl, technique, t));
  };
  // "clear": the rotor's slowest run (95) beats QLB's fastest (100); DQB's ranges overlap it.
  reps("clear", "glm_quat", "LBS", {100, 104, 101, 110, 102});
  reps("clear", "dq", "DQS", {90, 97, 95, 93, 99});
  reps("clear", "rotor_m2", "LBS", {90, 95, 91, 92, 93});
  // "slow": every rotor run is slower than every QLB and DQB run.
  reps("slow", "glm_quat", "LBS", {10, 11, 12});
  reps("slow", "dq", "DQS", {20, 21, 19});
  reps("slow", "rotor_simd", "LBS", {30, 31, 29});
  const json s = speed_section(b, {}, "bench.json");
  ASSERT_EQ(s.at("paper_claim").size(), 2u);
  for (const json& c : s["paper_claim"]) {
    if (c.at("scene") == "clear") {
      EXPECT_DOUBLE_EQ(c.at("qlb_us").get<double>(), 102.0);   // median of 100 101 102 104 110
      EXPECT_DOUBLE_EQ(c.at("rotor_us").get<double>(), 92.0);  // median of 90 91 92 93 95
      EXPECT_DOUBLE_EQ(c.at("vs_qlb").get<double>(), 102.0 / 92.0);
      EXPECT_DOUBLE_EQ(c.at("vs_qlb_interval")[0].get<double>(), 100.0 / 95.0);
      EXPECT_DOUBLE_EQ(c.at("vs_qlb_interval")[1].get<double>(), 110.0 / 90.0);
      EXPECT_EQ(c.at("verdict_qlb"), "faster");
      EXPECT_EQ(c.at("verdict_dqb"), "parity");  // DQB 90-99 against 90-95
      EXPECT_FALSE(c.at("holds").get<bool>());
      EXPECT_EQ(c.at("qlb").at("repetitions"), 5);
    } else {
      EXPECT_EQ(c.at("scene"), "slow");
      EXPECT_EQ(c.at("verdict_qlb"), "slower");
      EXPECT_EQ(c.at("verdict_dqb"), "slower");
      EXPECT_DOUBLE_EQ(c.at("vs_dqb_interval")[1].get<double>(), 21.0 / 29.0);
    }
  }
  for (const json& f : s.at("frames"))
    if (f.at("scene") == "clear" && f.at("impl") == "glm_quat") {
      EXPECT_DOUBLE_EQ(f.at("us_range")[0].get<double>(), 100.0);
      EXPECT_DOUBLE_EQ(f.at("us_range")[1].get<double>(), 110.0);
    }
  const std::string md = rotorcert::report::render_markdown({{"sections", {{"speed", s}}}});
  EXPECT_NE(md.find("102 (100\u2013110, 5 runs)"), std::string::npos) << md;
  EXPECT_NE(md.find("faster"), std::string::npos);
}

TEST(SpeedSection, AccuracyJoinsTheCertificateOfTheSameTableAndOp) {
  RC_CLAUSE("REPORT-2");
  const json cert = {{"name", "rotor_simd"},
                     {"scalar", "float"},
                     {"accuracy", json::array({{{"op", "slerp"}, {"max_eps", 3.5}, {"p99_eps", 1.0}},
                                               {{"op", "exp"}, {"max_eps", 1.0}, {"p99_eps", 0.5}}})}};
  const json s = speed_section(bench_document(), {cert}, "bench.json");
  ASSERT_EQ(s.at("accuracy_vs_speed").size(), 1u);  // exp was not benchmarked
  const json& p = s["accuracy_vs_speed"][0];
  EXPECT_EQ(p.at("op"), "slerp");
  EXPECT_DOUBLE_EQ(p.at("ns_per_element").get<double>(), 4.0);
  EXPECT_DOUBLE_EQ(p.at("max_eps").get<double>(), 3.5);
}

// REPORT-2's operation counts: the generated rotor's counters (as rotorcert_bench
// writes them for rotor_gen) beside glm_quat's time for the same op, scalar and n = 4096.
TEST(SpeedSection, OperationCountsOfTheGeneratedRotorStandBesideBothTimes) {
  RC_CLAUSE("REPORT-2");
  json b = bench_document();
  json gen = op_run("rotor_gen", "float", "compose", 4096, 3.0, 28.0, 49.0);
  gen["generated_mul"] = 24;
  gen["generated_add"] = 18;
  gen["generated_div"] = 0;
  gen["generated_sqrt"] = 0;
  b["benchmarks"].push_back(gen);
  b["benchmarks"].push_back(op_run("glm_quat", "float", "compose", 4096, 2.0, 28.0, 49.0));
  json alone = op_run("rotor_gen", "double", "slerp", 4096, 10.0, 105.0, 105.0);  // no glm_quat row
  alone["generated_mul"] = 64;
  alone["generated_add"] = 36;
  alone["generated_div"] = 4;
  alone["generated_sqrt"] = 3;
  b["benchmarks"].push_back(alone);
  b["benchmarks"].push_back(op_run("rotor_gen", "float", "compose", 64, 5.0, 28.0, 49.0));  // not at 4096
  const json s = speed_section(b, {}, "bench.json");
  ASSERT_EQ(s.at("operation_counts").size(), 2u);
  const json& c = s["operation_counts"][0]["scalar"] == "float" ? s["operation_counts"][0] : s["operation_counts"][1];
  const json& d = s["operation_counts"][0]["scalar"] == "float" ? s["operation_counts"][1] : s["operation_counts"][0];
  EXPECT_EQ(c.at("op"), "compose");
  EXPECT_DOUBLE_EQ(c.at("generated_total").get<double>(), 42.0);  // 24 mul + 18 add
  EXPECT_DOUBLE_EQ(c.at("formula_flops").get<double>(), 28.0);
  EXPECT_DOUBLE_EQ(c.at("vs_glm_quat").get<double>(), 1.5);  // 3 ns against 2 ns
  EXPECT_DOUBLE_EQ(d.at("generated_total").get<double>(), 107.0);
  EXPECT_TRUE(d.at("vs_glm_quat").is_null());
  // Tables without the counters (every one but rotor_gen) have none.
  EXPECT_TRUE(find_op(s, "slerp", 65536)->at("generated_ops").is_null());
  json report = {{"sections", {{"speed", s}}}};
  EXPECT_NE(rotorcert::report::render_html(report).find("24 mul + 18 add (42)"), std::string::npos);
  EXPECT_NE(rotorcert::report::render_markdown(report).find("| compose | float | 24 mul + 18 add (42) | 28 |"), std::string::npos);
}

/// The row, or null (whose .at() throws, a test failure rather than a crash).
const json& parity_row(const json& s, const std::string& family, const std::string& impl, const std::string& what) {
  static const json none;
  for (const json& r : s.at("parity").at("rows"))
    if (r.at("family") == family && r.at("impl") == impl && r.at("what") == what) return r;
  return none;
}

// Issue 18's bars: each implementation's time over its quaternion baseline's from the same run.
TEST(SpeedSection, ParityComparesEachImplementationWithItsQuaternionBaseline) {
  RC_CLAUSE("REPORT-2");
  json doc = bench_document();
  auto& runs = doc["benchmarks"];
  runs.push_back(op_run("glm_quat", "float", "compose", 4096, 10.0, 28.0, 48.0));
  runs.push_back(op_run("rotor_gen", "float", "compose", 4096, 10.5, 28.0, 48.0));  // 1.05 <= 1.1: met
  runs.push_back(op_run("glm_quat", "float", "slerp", 4096, 20.0, 100.0, 52.0));
  runs.push_back(op_run("rotor_gen", "float", "slerp", 4096, 30.0, 100.0, 52.0));    // 1.5 > 1.1: missed
  runs.push_back(op_run("dq", "float", "compose", 4096, 16.0, 28.0, 48.0));          // 1.6 > 1.5: missed
  runs.push_back(op_run("glm_quat", "float", "normalize", 4096, 4.0, 8.0, 32.0));
  runs.push_back(op_run("dq", "float", "normalize", 4096, 5.0, 8.0, 32.0));          // 1.25: met
  runs.push_back(op_run("glm_quat", "float", "blend_qlb", 4096, 50.0, 62.0, 97.0));
  runs.push_back(op_run("dq", "float", "dq_blend", 4096, 90.0, 112.0, 177.0));        // 1.8 <= 2: met
  runs.push_back(op_run("motor_pga", "float", "dq_blend", 4096, 110.0, 112.0, 177.0)); // 2.2: missed
  runs.push_back(op_run("rotor_m2", "float", "compose", 1, 25.0, 28.0, 48.0));
  json simd_compose = op_run("rotor_simd", "float", "compose", 1, 40.0, 28.0, 48.0);  // +15 ns: met
  // rotor_simd's label names the SIMD target it dispatched to, not "none".
  simd_compose["label"] = "impl=rotor_simd scalar=float op=compose n=1 k=1 target=AVX2";
  runs.push_back(simd_compose);
  runs.push_back(op_run("rotor_m2", "float", "exp", 1, 15.0, 40.0, 28.0));
  runs.push_back(op_run("rotor_simd", "float", "exp", 1, 90.0, 40.0, 28.0));      // +75 ns: missed
  const json s = speed_section(doc, {}, "bench.json");

  const json& gen_compose = parity_row(s, "GEN-PARITY", "rotor_gen", "compose");
  EXPECT_DOUBLE_EQ(gen_compose.at("slowdown").get<double>(), 1.05);
  EXPECT_TRUE(gen_compose.at("met").get<bool>());
  EXPECT_FALSE(parity_row(s, "GEN-PARITY", "rotor_gen", "slerp").at("met").get<bool>());
  // A rotor_gen op without a glm_quat time of the same run has no row.
  EXPECT_TRUE(parity_row(s, "GEN-PARITY", "rotor_gen", "nlerp").is_null());
  EXPECT_DOUBLE_EQ(parity_row(s, "SCALAR-1.5", "dq", "compose").at("slowdown").get<double>(), 1.6);
  EXPECT_FALSE(parity_row(s, "SCALAR-1.5", "dq", "compose").at("met").get<bool>());
  EXPECT_TRUE(parity_row(s, "SCALAR-1.5", "dq", "normalize").at("met").get<bool>());
  EXPECT_DOUBLE_EQ(parity_row(s, "DLB-2", "dq", "dq_blend").at("slowdown").get<double>(), 1.8);
  EXPECT_TRUE(parity_row(s, "DLB-2", "dq", "dq_blend").at("met").get<bool>());
  EXPECT_FALSE(parity_row(s, "DLB-2", "motor_pga", "dq_blend").at("met").get<bool>());
  // Frames of bench_document(): medium DQS 400 vs LBS 300, simple 9 vs 10; rotor_simd 250 vs 300 is
  // 0.83 of the QLB frame, not the quarter that the bar asks.
  EXPECT_DOUBLE_EQ(parity_row(s, "DQS-FRAME", "dq", "medium").at("slowdown").get<double>(), 400.0 / 300.0);
  EXPECT_TRUE(parity_row(s, "DQS-FRAME", "dq", "medium").at("met").get<bool>());
  EXPECT_TRUE(parity_row(s, "DQS-FRAME", "dq", "simple").at("met").get<bool>());
  EXPECT_FALSE(parity_row(s, "SIMD-FRAME", "rotor_simd", "medium").at("met").get<bool>());
  EXPECT_DOUBLE_EQ(parity_row(s, "SIMD-SINGLE", "rotor_simd", "compose").at("excess_ns").get<double>(), 15.0);
  EXPECT_TRUE(parity_row(s, "SIMD-SINGLE", "rotor_simd", "compose").at("met").get<bool>());
  EXPECT_FALSE(parity_row(s, "SIMD-SINGLE", "rotor_simd", "exp").at("met").get<bool>());

  // Family summaries: counts and the worst row.
  std::map<std::string, json> families;
  for (const json& f : s.at("parity").at("families")) families[f.at("id").get<std::string>()] = f;
  EXPECT_EQ(families.at("SCALAR-1.5").at("met"), 1);
  EXPECT_EQ(families.at("SCALAR-1.5").at("rows"), 2);
  EXPECT_EQ(families.at("SCALAR-1.5").at("worst").at("what"), "compose");
  EXPECT_EQ(families.at("SIMD-SINGLE").at("worst").at("what"), "exp");
  EXPECT_EQ(families.at("DLB-2").at("worst").at("impl"), "motor_pga");

  json report = {{"sections", {{"speed", s}}}};
  const std::string md = rotorcert::report::render_markdown(report);
  EXPECT_NE(md.find("| SCALAR-1.5 | `dq` | float | compose |"), std::string::npos) << md;
  EXPECT_NE(md.find("+75 ns"), std::string::npos);
  const std::string html = rotorcert::report::render_html(report);
  EXPECT_NE(html.find("Parity with the quaternion code"), std::string::npos);
}

TEST(SpeedSection, NotABenchmarkDocumentIsAnError) {
  RC_CLAUSE("REPORT-2");
  EXPECT_THROW(speed_section(json::object(), {}, "x.json"), std::runtime_error);
  EXPECT_THROW(speed_section(json{{"benchmarks", 3}}, {}, "x.json"), std::runtime_error);
}

// The renderers show the section and never throw on one with fields missing.
TEST(SpeedSection, RenderedInHtmlAndMarkdown) {
  RC_CLAUSE("REPORT-2");
  json report = {{"sections", {{"speed", speed_section(bench_document(), {}, "bench.json")}}}};
  const std::string html = rotorcert::report::render_html(report);
  EXPECT_NE(html.find("id=\"section-speed\""), std::string::npos);
  EXPECT_NE(html.find("missed by"), std::string::npos);
  EXPECT_NE(html.find("does not hold"), std::string::npos);
  const std::string md = rotorcert::report::render_markdown(report);
  EXPECT_NE(md.find("| SIMD rotor slerp"), std::string::npos);
  report["sections"]["speed"] = {{"targets", json::array({json::object()})}, {"ops", json::array({{{"op", 3}}})}};
  EXPECT_NO_THROW(rotorcert::report::render_html(report));
  EXPECT_NO_THROW(rotorcert::report::render_markdown(report));
}

}  // namespace
