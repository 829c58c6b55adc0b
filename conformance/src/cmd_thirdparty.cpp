// `rotorcert thirdparty --out DIR [--adapter NAME]...`: certifies the third-party libraries of
// conformance/adapters/ (spec REPORT-3; guide: conformance/CERTIFY.md), each by the route its
// adapter.json declares, and writes report.json (kind "third-party"), report.md and report.html
// with the third-party section and every certificate. Exit 0 when every library that ran gives
// exactly its known defects (expected_failures.json beside its adapter, impls/ for the built-in
// GLM and Eigen), 1 otherwise (a library not as expected, an adapter that failed to run), 2 on
// usage. A library whose adapter cannot run here (package not installable, plugin not built) is
// "not run" with the reason and does not change the exit code.
#include <chrono>
#include <cstdlib>
#include <iostream>
#include <memory>

#include <rotorcert/certify/print.hpp>
#include <rotorcert/certify/report_document.hpp>
#include <rotorcert/certify/verdict.hpp>
#include <rotorcert/spec/data_layout.hpp>
#include <rotorcert/thirdparty/thirdparty.hpp>

#include "certify_cli.hpp"
#include "commands.hpp"


namespace rotorcert::cli {

std::string default_adapters_env() {
  const char* env = std::getenv("ROTORCERT_ADAPTERS_ENV");
  return env != nullptr && *env != '\0' ? env : spec::data_layout().adapters_env.string();
}

ThirdPartyRequest::ThirdPartyRequest()
    : adapters_dir(spec::data_layout().adapters_dir.string()),
      env_dir(default_adapters_env()),
      plugin_dir(spec::data_layout().adapter_plugin_dir.string()) {}

int run_third_party(const ThirdPartyRequest& r, const spec::Spec& spec, const certify::CertifyOptions& options,
                    const thirdparty::KnownCertificates& known, const char* who, thirdparty::Outcome& outcome,
                    nlohmann::json& section) {
  thirdparty::Options o;
  o.adapters_dir = r.adapters_dir;
  o.env_dir = r.env_dir;
  o.plugin_dir = r.plugin_dir;
  o.out = r.out;
  o.names = r.names;
  o.certify = options;
  o.adapter_timeout_s = r.adapter_timeout_s;
  o.quiet = r.quiet;
  try {
    outcome = thirdparty::certify_third_party(spec, o, known);
  } catch (const std::exception& e) {
    std::cerr << who << ": " << e.what() << '\n';
    return kExitUsage;
  }
  section = thirdparty::section_json(outcome, o);
  return outcome.as_expected() ? kExitOk : kExitFailed;
}

void print_third_party_summary(std::ostream& out, const thirdparty::Outcome& outcome) {
  for (const thirdparty::Library& lib : outcome.libraries) {
    out << "third-party " << lib.manifest.name << ": " << thirdparty::to_string(lib.status);
    if (lib.status == thirdparty::LibraryStatus::certified) {
      std::string claims;
      for (const certify::Certificate& c : lib.certificates) claims += (claims.empty() ? "" : "; ") + certify::claim(c);
      out << ", " << lib.defects.size() << " defect(s), " << (lib.as_expected ? "as expected" : "NOT as expected") << " ("
          << claims << ")";
    } else {
      out << ": " << lib.reason;
    }
    out << '\n';
  }
}

namespace {

struct Args {
  CertifyCli common;
  ThirdPartyRequest request;
};

int run(Args a) {
  const auto started = std::chrono::steady_clock::now();
  spec::Spec spec;
  certify::CertifyOptions options;
  if (!load_spec_and_options("thirdparty", a.common, spec, options)) return kExitUsage;
  a.request.out = a.common.out;
  a.request.quiet = a.common.quiet;
  thirdparty::Outcome outcome;
  certify::json section;
  const int rc = run_third_party(a.request, spec, options, {}, "rotorcert thirdparty", outcome, section);
  if (rc == kExitUsage) return rc;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  const std::vector<certify::Certificate> certificates = outcome.certificates();
  certify::json report = certify::report_json(spec, "third-party", certify::options_json(options),
                                              run_json(seconds, command_line(), options.jobs), certificates);
  report["summary"]["as_expected"] = outcome.as_expected();
  report["summary"]["exit_code"] = rc;
  report["sections"]["third_party"] = std::move(section);
  if (!a.common.quiet) {
    for (const certify::Certificate& c : certificates) certify::print_certificate(std::cout, c, a.common.verbose);
    print_third_party_summary(std::cout, outcome);
  }
  try {
    certify::write_report(a.common.out, report);
  } catch (const std::exception& e) {
    std::cerr << "rotorcert thirdparty: cannot write the report: " << e.what() << '\n';
    return kExitUsage;
  }
  if (!a.common.quiet) std::cout << "report: " << a.common.out << "/report.html (and report.json, report.md)\n";
  return rc;
}

}  // namespace

void add_third_party_options(CLI::App& app, ThirdPartyRequest& r) {
  app.add_option("--adapters", r.adapters_dir, "Directory of the adapters (each NAME/adapter.json)")->capture_default_str();
  app.add_option("--adapters-env", r.env_dir,
                 "Where scripts/setup-adapters installed their environments (default $ROTORCERT_ADAPTERS_ENV, else build/adapters)")
      ->capture_default_str();
  app.add_option("--plugins", r.plugin_dir, "Directory of the adapters' plugins the build made")->capture_default_str();
  app.add_option("--adapter-timeout", r.adapter_timeout_s, "Wall-clock limit of one run of a vectors adapter, seconds")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
}

Command add_thirdparty(CLI::App& parent) {
  auto args = std::make_shared<Args>();
  CLI::App* app = parent.add_subcommand(
      "thirdparty", "Certify the third-party libraries of conformance/adapters (C ABI and JSON-vector adapters)");
  app->add_option("--adapter", args->request.names, "Only this adapter (e.g. clifford); repeatable");
  add_third_party_options(*app, args->request);
  add_certify_options(*app, args->common);
  return {app, [args] { return run(*args); }};
}

}  // namespace rotorcert::cli
