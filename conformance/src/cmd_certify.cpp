// `rotorcert certify --impl NAME | --plugin PATH.so [--scalar S] [--level L] [--clause C]
//  [--seed S] [--cases N] --out DIR`: certifies one implementation (every table of it, or the
// one of the chosen scalar type), each clause in its own child process, and writes the report.
// Exit 0 when every claimed clause passes (PASS or QUALITY_WARNING), 1 otherwise, 2 on usage.
// With --require-level L (repeatable) or --require-claimed-levels, the exit code asks only that
// those levels are met (LEVEL-1: met or met with warnings) by every table certified: the gate a
// library's own CI runs (rotorcert_add_certification() in cmake/RotorcertCertification.cmake).
#include <algorithm>
#include <chrono>
#include <iostream>
#include <memory>

#include <rotorcert/report/write.hpp>
#include <rotorcert/certify/certify.hpp>
#include <rotorcert/certify/print.hpp>
#include <rotorcert/certify/report_document.hpp>
#include <rotorcert/certify/verdict.hpp>
#include <rotorcert/registry.hpp>

#include "certify_cli.hpp"
#include "commands.hpp"

namespace rotorcert::cli {
namespace {

struct Args {
  CertifyCli common;
  std::string impl, plugin, scalar = "both";
  std::vector<std::string> required_levels;
  bool require_claimed_levels = false;
};

/// The levels a table must meet: those asked for, and its claimed ones with
/// --require-claimed-levels.
std::vector<std::string> required_levels(const Args& a, const certify::Certificate& c) {
  std::vector<std::string> r = a.required_levels;
  if (a.require_claimed_levels)
    for (const std::string& l : c.table.claimed_levels)
      if (std::find(r.begin(), r.end(), l) == r.end()) r.push_back(l);
  return r;
}

/// Whether every table meets its required levels; says which does not, and why.
bool required_levels_met(const Args& a, const std::vector<certify::Certificate>& certs) {
  bool ok = true;
  for (const certify::Certificate& c : certs) {
    const std::vector<certify::LevelResult> levels = certify::level_results(c);
    for (const std::string& level : required_levels(a, c)) {
      const auto l = std::find_if(levels.begin(), levels.end(), [&](const certify::LevelResult& x) { return x.level == level; });
      if (l != levels.end() && l->status != certify::LevelStatus::not_met) continue;
      ok = false;
      std::cerr << "rotorcert certify: " << c.table.name << " (" << c.table.scalar << "): required level " << level
                << " not met";
      if (l != levels.end()) {
        std::cerr << "; not passing:";
        for (const std::string& clause : l->not_pass) std::cerr << ' ' << clause;
      } else {
        std::cerr << " (not certified: see --level)";
      }
      std::cerr << '\n';
    }
  }
  return ok;
}

int run(const Args& a) {
  const auto started = std::chrono::steady_clock::now();
  spec::Spec spec;
  certify::CertifyOptions options;
  if (!load_spec_and_options("certify", a.common, spec, options)) return kExitUsage;

  std::vector<certify::Target> targets;
  if (!a.plugin.empty()) {
    try {
      targets = certify::probe_plugin(a.plugin, options.limits);
    } catch (const std::exception& e) {
      std::cerr << "rotorcert certify: " << a.plugin << ": " << e.what() << '\n';
      return kExitUsage;
    }
  } else {
    for (const certify::Target& t : certify::builtin_targets())
      if (t.info.name == a.impl) targets.push_back(t);
    if (targets.empty()) {
      std::cerr << "rotorcert certify: no built-in implementation named '" << a.impl
                << "' (see `rotorcert list`; a third-party library comes as --plugin PATH.so)\n";
      return kExitUsage;
    }
  }
  std::erase_if(targets, [&](const certify::Target& t) { return a.scalar != "both" && t.info.scalar != a.scalar; });
  if (targets.empty()) {
    std::cerr << "rotorcert certify: the implementation has no " << a.scalar << " table\n";
    return kExitUsage;
  }

  std::unique_ptr<certify::Journal> journal;
  int interrupted_code = 0;
  const auto certified = certify_resumably("certify", a.common, spec, targets, options, journal, interrupted_code);
  if (!certified) return interrupted_code;
  const std::vector<certify::Certificate>& certs = *certified;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  certify::json report =
      certify::report_json(spec, "certify", certify::options_json(options), run_json(seconds, command_line(), options.jobs), certs);
  if (a.common.resume) report["run"]["resumed_clauses"] = journal->taken();
  if (!a.required_levels.empty() || a.require_claimed_levels) {
    certify::json required = a.required_levels;
    if (a.require_claimed_levels) required.push_back("claimed");
    report["options"]["required_levels"] = required;
    report["summary"]["exit_code"] = required_levels_met(a, certs) ? 0 : 1;
  }
  if (!a.common.quiet)
    for (const certify::Certificate& c : certs) certify::print_certificate(std::cout, c, a.common.verbose);
  try {
    report::write_report(a.common.out, report);
    journal->remove();  // the run is complete: nothing left to resume
  } catch (const std::exception& e) {
    std::cerr << "rotorcert certify: cannot write the report: " << e.what() << '\n';
    return kExitUsage;
  }
  if (!a.common.quiet) std::cout << "report: " << a.common.out << "/report.html (and report.json, report.md)\n";
  return report.at("summary").at("exit_code").get<int>();
}

}  // namespace

Command add_certify(CLI::App& parent) {
  auto args = std::make_shared<Args>();
  CLI::App* app = parent.add_subcommand(
      "certify", "Certify one implementation: every clause it claims, each in an isolated child process");
  auto* impl = app->add_option("--impl", args->impl, "A built-in implementation (see `rotorcert list`)");
  auto* plugin = app->add_option("--plugin", args->plugin, "A third-party implementation: a plugin .so through the C ABI");
  impl->excludes(plugin);
  app->add_option("--scalar", args->scalar, "Which table: float, double or both")
      ->check(CLI::IsMember({"float", "double", "both"}))
      ->capture_default_str();
  app->add_option("--require-level", args->required_levels,
                  "Exit 0 only if every table meets this level (met or met with warnings); repeatable")
      ->check(CLI::IsMember({"Core", "Interp", "Blend", "Rigid", "Skinning", "Extended", "Robust", "Hygiene"}));
  app->add_flag("--require-claimed-levels", args->require_claimed_levels,
                "Exit 0 only if every table meets every level it claims");
  add_certify_options(*app, args->common);
  app->callback([impl, plugin] {
    if (impl->count() + plugin->count() != 1) throw CLI::RequiredError("exactly one of --impl or --plugin");
  });
  return {app, [args] { return run(*args); }};
}

}  // namespace rotorcert::cli
