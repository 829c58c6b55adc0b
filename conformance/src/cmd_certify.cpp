// `rotorcert certify --impl NAME | --plugin PATH.so [--scalar S] [--level L] [--clause C]
//  [--seed S] [--cases N] --out DIR`: certifies one implementation (every table of it, or the
// one of the chosen scalar type), each clause in its own child process, and writes the report.
// Exit 0 when every claimed clause passes (PASS or QUALITY_WARNING), 1 otherwise, 2 on usage.
#include <chrono>
#include <iostream>
#include <memory>

#include <rotorcert/certify/certify.hpp>
#include <rotorcert/certify/print.hpp>
#include <rotorcert/certify/report_document.hpp>
#include <rotorcert/registry.hpp>

#include "certify_cli.hpp"
#include "commands.hpp"

namespace rotorcert::cli {
namespace {

struct Args {
  CertifyCli common;
  std::string impl, plugin, scalar = "both";
};

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

  const auto certs = certify::certify_targets(spec, targets, options);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  const certify::json report =
      certify::report_json(spec, "certify", certify::options_json(options), run_json(seconds, command_line(), options.jobs), certs);
  if (!a.common.quiet)
    for (const certify::Certificate& c : certs) certify::print_certificate(std::cout, c, a.common.verbose);
  try {
    certify::write_report(a.common.out, report);
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
  add_certify_options(*app, args->common);
  app->callback([app, impl, plugin] {
    if (impl->count() + plugin->count() != 1) throw CLI::RequiredError("exactly one of --impl or --plugin");
  });
  return {app, [args] { return run(*args); }};
}

}  // namespace rotorcert::cli
