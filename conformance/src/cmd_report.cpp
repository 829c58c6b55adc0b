// `rotorcert report --out DIR`: the main job. Certifies every built-in implementation (each
// clause in an isolated child process), runs every mutant of conformance/mutants/ against the
// clauses it must break, runs the render check (VIS-1..3, render_check/) on the built-in
// characters, certifies the third-party libraries of conformance/adapters (REPORT-3, into
// OUT/third_party), runs the quick benchmarks (the speed section, shown and not scored) and writes
// report.json, report.md and report.html.
// Exit 0 when every table behaves as expected (its known defects, impls/*/expected_failures.json,
// FAIL and everything else it claims passes), every mutant is killed, every render-check
// method gives what is expected of it and every third-party library that ran gives exactly its
// known defects; 1 otherwise; 2 on usage.
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>

#include <rotorcert/report/write.hpp>
#include <rotorcert/certify/certify.hpp>
#include <rotorcert/certify/print.hpp>
#include <rotorcert/certify/report_document.hpp>
#include <rotorcert/render/render_check.hpp>
#include <rotorcert/spec/data_layout.hpp>
#include <rotorcert/report/speed.hpp>

#include "certify_cli.hpp"
#include "commands.hpp"


namespace rotorcert::cli {
namespace {

struct Args {
  CertifyCli common;
  std::vector<std::string> impls;
  std::string mutant_dir = spec::data_layout().mutant_plugin_dir.string();
  bool no_mutants = false;
  std::string render_dir;   // --render: the output directory of an earlier `rotorcert render`
  std::string render_file;  // --render-file: a glTF file instead of the built-in characters
  int render_frames = 4;
  bool no_render = false;
  std::string bench_dir;  // --bench: a directory with the bench.json of an earlier `rotorcert bench`
  bool bench_full = false;
  bool no_bench = false;
  ThirdPartyRequest third_party;
  bool no_third_party = false;
};

struct MutantRun {
  certify::json entry;           // the mutants.json entry
  std::size_t target = SIZE_MAX;  // index into the targets, or SIZE_MAX when it could not be loaded
  std::string error;
};

/// The mutants section: each mutant judged on the clauses it must break; killed when every one
/// of them FAILs.
certify::json mutants_section(const std::vector<MutantRun>& runs, const std::vector<certify::Certificate>& certs,
                              std::size_t first, const std::string& dir) {
  certify::json list = certify::json::array();
  int killed = 0;
  for (const MutantRun& m : runs) {
    certify::json j = {{"mutant", m.entry.at("mutant")}, {"scalar", m.entry.at("scalar")}, {"bug", m.entry.at("bug")},
                       {"breaks", m.entry.at("breaks")}};
    bool all_fail = m.error.empty();
    certify::json clauses = certify::json::array();
    if (m.target != SIZE_MAX) {
      for (const engine::ClauseResult& r : certs[first + m.target].clauses) {
        all_fail = all_fail && r.outcome == engine::Outcome::fail;
        clauses.push_back({{"id", r.clause},
                           {"outcome", engine::to_string(r.outcome)},
                           {"label", r.worst_label},
                           {"input", r.worst_input},
                           {"detail", r.worst_detail},
                           {"conventions", r.conventions}});
      }
    }
    j["clauses"] = clauses;
    j["error"] = m.error.empty() ? certify::json(nullptr) : certify::json(m.error);
    j["killed"] = all_fail;
    killed += all_fail ? 1 : 0;
    list.push_back(j);
  }
  return {{"directory", dir}, {"killed", killed}, {"total", runs.size()}, {"mutants", list}};
}

int run(const Args& a) {
  const auto started = std::chrono::steady_clock::now();
  spec::Spec spec;
  certify::CertifyOptions options;
  if (!load_spec_and_options("report", a.common, spec, options)) return kExitUsage;

  std::vector<certify::Target> targets;
  for (const certify::Target& t : certify::builtin_targets())
    if (a.impls.empty() || std::find(a.impls.begin(), a.impls.end(), t.info.name) != a.impls.end()) targets.push_back(t);
  for (const std::string& name : a.impls)
    if (std::none_of(targets.begin(), targets.end(), [&](const certify::Target& t) { return t.info.name == name; })) {
      std::cerr << "rotorcert report: no built-in implementation named '" << name << "'\n";
      return kExitUsage;
    }
  const std::size_t builtin_count = targets.size();

  // The render check (VIS-1..3) runs first, so that a malformed --render-file is a usage error at
  // once: on the built-in characters into OUT/render, or read from an earlier `rotorcert render`.
  // Its outcome joins the exit code: a method not as expected (render_check.hpp) makes it 1.
  certify::json render_section;
  std::string render_note;
  if (!a.no_render) {
    std::string dir = a.render_dir;
    certify::json result;  // this run's render check, handed over in memory
    if (dir.empty()) {
      RenderRequest request;
      request.file = a.render_file;
      request.out = (std::filesystem::path(a.common.out) / "render").string();
      request.frames = a.render_frames;
      request.impls = a.impls;
      request.print = false;
      request.require_methods = false;
      if (!a.common.quiet) std::cout << "render check (VIS-1..3) into " << request.out << " ...\n" << std::flush;
      const int rc = run_render(request, "rotorcert report: render", &result);
      if (rc == kExitUsage) return kExitUsage;
      if (result.is_null())
        render_note = rc == kExitOk ? "the implementations chosen offer neither linear blend nor dual quaternion skinning"
                                    : "the render check could not run (its message is on stderr)";
      dir = request.out;
    }
    if (render_note.empty()) {
      try {
        if (!a.render_dir.empty()) result = render::read_render_result(dir);
        render_section = render::report_section(result, dir);
        // report.md links the strips relative to itself.
        const auto out_abs = std::filesystem::absolute(a.common.out);
        for (certify::json& f : render_section.at("figures"))
          f["file"] = std::filesystem::absolute(f.at("file").get<std::string>()).lexically_relative(out_abs).generic_string();
      } catch (const std::exception& e) {
        std::cerr << "rotorcert report: render: " << e.what() << '\n';
        return kExitUsage;
      }
    }
  } else {
    render_note = "left out (--no-render)";
  }

  // Mutants: plugins of the build tree, each judged on the clauses it must break.
  std::vector<MutantRun> mutants;
  std::string mutants_note;
  if (!a.no_mutants) {
    if (!std::filesystem::is_directory(a.mutant_dir)) {
      mutants_note = "mutant plugins not found in " + a.mutant_dir + " (build the whole tree to include them)";
    } else {
      for (const certify::json& entry : spec::read_json(spec::data_layout().mutants_json)) {
        // A mutant that breaks nothing is an acceptable convention (ACC-1; test_mutants checks
        // that it is graded ACCEPTABLE): there is nothing to kill.
        if (entry.at("breaks").empty()) continue;
        MutantRun m{entry, SIZE_MAX, {}};
        const std::string path = a.mutant_dir + "/rotorcert_mutant_" + entry.at("mutant").get<std::string>() + ".so";
        try {
          for (certify::Target t : certify::probe_plugin(path, options.limits))
            if (t.info.scalar == entry.at("scalar")) {
              t.clauses = entry.at("breaks").get<std::vector<std::string>>();
              m.target = targets.size() - builtin_count;
              targets.push_back(t);
              break;
            }
          if (m.target == SIZE_MAX) m.error = "the plugin has no " + entry.at("scalar").get<std::string>() + " table";
        } catch (const std::exception& e) {
          m.error = e.what();
        }
        mutants.push_back(std::move(m));
      }
    }
  }

  std::unique_ptr<certify::Journal> journal;
  int interrupted_code = 0;
  const auto certified = certify_resumably("report", a.common, spec, targets, options, journal, interrupted_code);
  if (!certified) return interrupted_code;
  const std::vector<certify::Certificate>& certs = *certified;
  const std::vector<certify::Certificate> builtin(certs.begin(), certs.begin() + static_cast<std::ptrdiff_t>(builtin_count));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  certify::json report =
      certify::report_json(spec, "report", certify::options_json(options), run_json(seconds, command_line(), options.jobs), builtin);
  if (a.common.resume) report["run"]["resumed_clauses"] = journal->taken();
  if (mutants_note.empty()) {
    certify::json section = mutants_section(mutants, certs, builtin_count, a.mutant_dir);
    if (section.at("killed") != section.at("total")) report["summary"]["exit_code"] = 1;
    report["summary"]["mutants_killed"] = section.at("killed");
    report["summary"]["mutants_total"] = section.at("total");
    report["sections"]["mutants"] = std::move(section);
  } else {
    report["sections"]["mutants"] = {{"note", mutants_note}};
  }
  if (!render_section.is_null()) {
    if (!render_section.at("as_expected").get<bool>()) {
      report["summary"]["as_expected"] = false;
      report["summary"]["exit_code"] = 1;
    }
    report["sections"]["render"] = std::move(render_section);
  } else {
    report["sections"]["render"] = {{"note", render_note}};
  }

  // Third-party libraries (REPORT-3): GLM and Eigen reuse the certificates just made.
  thirdparty::Outcome third_party;
  if (a.no_third_party) {
    report["sections"]["third_party"] = {{"note", "left out (--no-third-party)"}};
  } else {
    thirdparty::KnownCertificates known;
    for (const certify::Certificate& c : builtin) known[c.table.name + "/" + c.table.scalar] = c;
    ThirdPartyRequest request = a.third_party;
    request.out = (std::filesystem::path(a.common.out) / "third_party").string();
    request.quiet = a.common.quiet;
    request.speed = !a.no_bench;  // the native libraries timed beside GLM, as the speed section is
    // The before/after pairs the adapters name (adapter.json "compare_versions": a release on the
    // other side of a fix), unless the command line chose versions itself.
    if (request.versions.empty()) {
      try {
        for (const thirdparty::Manifest& m : thirdparty::load_manifests(request.adapters_dir))
          for (const nlohmann::json& v : m.raw.value("compare_versions", nlohmann::json::array()))
            if (v.is_object() && v.contains("version")) request.versions.push_back(m.name + "=" + v["version"].get<std::string>());
      } catch (const std::exception&) {
        // A malformed manifest is reported by run_third_party itself.
      }
    }
    certify::json section;
    const int rc = run_third_party(request, spec, options, known, "rotorcert report: third-party", third_party, section);
    if (rc == kExitUsage) return kExitUsage;
    if (rc != kExitOk) {
      report["summary"]["as_expected"] = false;
      report["summary"]["exit_code"] = 1;
    }
    report["sections"]["third_party"] = std::move(section);
  }

  // Speed (REPORT-2): the quick benchmark run into OUT/bench, after certifying so that no child
  // process of the certification competes with it for the CPUs. Shown, not scored.
  if (a.no_bench) {
    report["sections"]["speed"] = {{"note", "left out (--no-bench)"}};
  } else {
    certify::json bench;
    std::string bench_file;
    int rc = kExitOk;
    if (!a.bench_dir.empty()) {
      bench_file = (std::filesystem::path(a.bench_dir) / "bench.json").string();
      try {
        std::ifstream in(bench_file);
        if (!in) throw std::runtime_error("cannot be read (run rotorcert bench --out " + a.bench_dir + ")");
        bench = certify::json::parse(in);
      } catch (const std::exception& e) {
        std::cerr << "rotorcert report: --bench: " << bench_file << ": " << e.what() << '\n';
        return kExitUsage;
      }
    } else {
      BenchRequest request;
      request.out = (std::filesystem::path(a.common.out) / "bench").string();
      request.quick = !a.bench_full;
      bench_file = (std::filesystem::path(request.out) / "bench.json").string();
      if (!a.common.quiet) std::cout << "benchmarks (" << (request.quick ? "quick" : "full") << ") into " << request.out << " ...\n" << std::flush;
      rc = run_bench(request, "rotorcert report: bench", bench);
    }
    try {
      // The accuracy of each op comes from the certificates as report.json shows them, the same
      // input `rotorcert bench --accuracy report.json` reads.
      const std::vector<certify::json> shown(report.at("implementations").begin(), report.at("implementations").end());
      report["sections"]["speed"] = rc == kExitOk ? report::speed_section(bench, shown, bench_file)
                                                  : certify::json{{"note", "the benchmark run failed; see " + bench_file + " and bench.log"}};
    } catch (const std::exception& e) {
      report["sections"]["speed"] = {{"note", std::string("no speed section: ") + e.what()}};
    }
  }

  if (!a.common.quiet) {
    for (const certify::Certificate& c : builtin) certify::print_certificate(std::cout, c, a.common.verbose);
    if (mutants_note.empty())
      std::cout << "mutants killed: " << report["summary"]["mutants_killed"] << " of " << report["summary"]["mutants_total"]
                << '\n';
    else
      std::cout << "mutants: " << mutants_note << '\n';
    const certify::json& rs = report["sections"]["render"];
    if (rs.contains("counts"))
      std::cout << "render check: " << rs.at("counts").dump() << ", "
                << (rs.at("as_expected").get<bool>() ? "every method as expected" : "some methods NOT as expected") << '\n';
    else
      std::cout << "render check: " << rs.at("note").get<std::string>() << '\n';
    if (!a.no_third_party) print_third_party_summary(std::cout, third_party);
    const certify::json& sp = report["sections"]["speed"];
    if (sp.contains("targets"))
      print_speed_summary(std::cout, sp);
    else
      std::cout << "speed: " << sp.at("note").get<std::string>() << '\n';
  }
  try {
    report::write_report(a.common.out, report);
    journal->remove();  // the run is complete: nothing left to resume
  } catch (const std::exception& e) {
    std::cerr << "rotorcert report: cannot write the report: " << e.what() << '\n';
    return kExitUsage;
  }
  if (!a.common.quiet)
    std::cout << "report: " << a.common.out << "/report.html (and report.json, report.md); results "
              << (report["summary"]["as_expected"].get<bool>() ? "match" : "DO NOT match") << " expectations\n";
  return report.at("summary").at("exit_code").get<int>();
}

}  // namespace

Command add_report(CLI::App& parent) {
  auto args = std::make_shared<Args>();
  CLI::App* app = parent.add_subcommand(
      "report", "The main job: certify every built-in implementation and the mutants, write the HTML/Markdown/JSON report");
  app->add_option("--impl", args->impls, "Only this built-in implementation; repeatable");
  app->add_option("--mutants", args->mutant_dir, "Directory of the mutant plugins")->capture_default_str();
  app->add_flag("--no-mutants", args->no_mutants, "Leave the mutants out");
  app->add_option("--render", args->render_dir,
                  "Use the render check that `rotorcert render --out DIR` wrote instead of running it");
  app->add_option("--render-file", args->render_file,
                  "Render check on this skinned, animated .gltf/.glb instead of the built-in characters");
  app->add_option("--render-frames", args->render_frames, "Frames per clip in the render check")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  app->add_flag("--no-render", args->no_render, "Leave the render check out");
  app->add_option("--bench", args->bench_dir, "Use the bench.json that `rotorcert bench --out DIR` wrote instead of running it");
  app->add_flag("--bench-full", args->bench_full, "Run every benchmark size (not only the quick set)");
  app->add_flag("--no-bench", args->no_bench, "Leave the speed section out");
  app->add_flag("--no-third-party", args->no_third_party, "Leave the third-party libraries out");
  add_third_party_options(*app, args->third_party);
  add_certify_options(*app, args->common);
  return {app, [args] { return run(*args); }};
}

}  // namespace rotorcert::cli
