// `rotorcert selfcheck`: checks the reference against every worked example of the spec
// (selfcheck.hpp). Exit 0 if nothing failed, 1 if a clause failed, 2 on usage or spec errors.
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include <rotorcert/conformance/selfcheck.hpp>
#include <rotorcert/spec/spec.hpp>

#include "commands.hpp"

namespace rotorcert::cli {

namespace {

struct SelfcheckOptions {
  std::string spec_dir;
  std::string json_file;
  bool verbose = false;
};

int run_selfcheck(const SelfcheckOptions& o) {
  try {
    const auto dir = spec::resolve_spec_dir(o.spec_dir.empty() ? std::nullopt
                                                               : std::optional<std::filesystem::path>(o.spec_dir));
    const spec::Spec s = spec::load_spec(dir);
    const conformance::SelfcheckReport report = conformance::run_selfcheck(s);
    if (o.verbose) std::cout << "spec: " << dir.string() << " (version " << s.version << ")\n";
    conformance::print_report(std::cout, report, o.verbose);
    if (!o.json_file.empty()) {
      conformance::write_file_atomically(o.json_file, conformance::to_json(report).dump(2) + "\n");
      if (o.verbose) std::cout << "wrote " << o.json_file << '\n';
    }
    return report.ok() ? kExitOk : kExitFailed;
  } catch (const spec::SpecError& e) {
    std::cerr << "rotorcert selfcheck: error: " << e.what() << '\n';
    return kExitUsage;
  } catch (const std::exception& e) {
    std::cerr << "rotorcert selfcheck: error: " << e.what() << '\n';
    return kExitUsage;
  }
}

}  // namespace

Command add_selfcheck(CLI::App& parent) {
  auto options = std::make_shared<SelfcheckOptions>();
  CLI::App* app = parent.add_subcommand(
      "selfcheck", "Check the reference implementation against every worked example of the spec");
  app->add_option("--spec", options->spec_dir,
                  "Spec directory (default: $ROTORCERT_SPEC_DIR, else " + spec::default_spec_dir().string() + ")")
      ->check(CLI::ExistingDirectory)
      ->option_text("DIR");
  app->add_option("--json", options->json_file, "Also write the results as JSON to FILE (atomically)")
      ->option_text("FILE");
  app->add_flag("-v,--verbose", options->verbose, "Full clause titles and the spec directory");
  return {app, [options] { return run_selfcheck(*options); }};
}

}  // namespace rotorcert::cli
