#include "certify_cli.hpp"

#include <unistd.h>

#include <algorithm>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <thread>

#include <rotorcert/spec/data_layout.hpp>

namespace rotorcert::cli {

void add_certify_options(CLI::App& app, CertifyCli& o) {
  app.add_option("--out", o.out, "Directory for report.json, report.md, report.html")->required();
  app.add_option("--seed", o.seed, "Seed of the reference vectors (same seed, same report.json)")->capture_default_str();
  app.add_option("--cases", o.cases, "Cases per family of reference vectors")->check(CLI::Range(1, 100000))->capture_default_str();
  app.add_option("--search", o.search,
                 "Worst-case search: implementation calls per check spent walking ulps around the worst input (0 = none)")
      ->check(CLI::Range(0, 100000))->capture_default_str();
  app.add_option("--level", o.levels, "Certify only this level (Core, Interp, Blend, Rigid, Skinning, Extended, Robust, Hygiene); repeatable");
  app.add_option("--clause", o.clauses, "Certify only this clause (e.g. SLERP-1); repeatable");
  app.add_option("--timeout", o.timeout_s, "Wall-clock limit per clause, seconds (TIMEOUT beyond)")
      ->check(CLI::PositiveNumber)->capture_default_str();
  app.add_option("--memory-mb", o.memory_mb, "Address-space limit per clause process, MiB (0 = none)")->capture_default_str();
  app.add_option("--jobs,-j", o.jobs, "Clause processes run at once (0 = one per core)")->check(CLI::NonNegativeNumber);
  app.add_option("--spec", o.spec_dir, "Spec directory (default: $ROTORCERT_SPEC_DIR or the built-in one)");
  app.add_flag("--verbose,-v", o.verbose, "Print every clause, PASS included");
  app.add_flag("--quiet,-q", o.quiet, "No progress line and no certificate on stdout (the report is still written)");
}

certify::CertifyOptions make_options(const spec::Spec& spec, const CertifyCli& o) {
  certify::CertifyOptions opt;
  opt.cases.seed = o.seed;
  opt.cases.cases_per_family = o.cases;
  opt.cases.search_budget = o.search;
  for (const std::string& l : spec.levels)
    if (l != "Meta" && (o.levels.empty() || std::find(o.levels.begin(), o.levels.end(), l) != o.levels.end()))
      opt.levels.push_back(l);
  for (const std::string& l : o.levels)
    if (l == "Meta" || std::find(spec.levels.begin(), spec.levels.end(), l) == spec.levels.end())
      throw std::invalid_argument("--level " + l + ": not an implementation level (Core, Interp, Blend, Rigid, Skinning, Extended, Robust, Hygiene)");
  for (const std::string& c : o.clauses) {
    const spec::Clause* cl = spec.find_clause(c);
    if (cl == nullptr) throw std::invalid_argument("--clause " + c + ": no such clause in the spec");
    if (cl->level == "Meta") throw std::invalid_argument("--clause " + c + ": a Meta clause binds the suite, not an implementation");
    if (std::find(opt.levels.begin(), opt.levels.end(), cl->level) == opt.levels.end())
      throw std::invalid_argument("--clause " + c + " is of level " + cl->level + ", which --level excludes");
  }
  opt.clauses = o.clauses;
  opt.limits.timeout_s = o.timeout_s;
  opt.limits.memory_mb = o.memory_mb;
  opt.jobs = o.jobs > 0 ? o.jobs : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  opt.progress = !o.quiet && ::isatty(STDERR_FILENO);
  return opt;
}

bool load_spec_and_options(const char* command, const CertifyCli& o, spec::Spec& spec,
                           certify::CertifyOptions& options) {
  try {
    spec = spec::load_spec(spec::resolve_spec_dir(o.spec_dir));
    options = make_options(spec, o);
    return true;
  } catch (const std::exception& e) {  // SpecError, or a bad --level / --clause
    std::cerr << "rotorcert " << command << ": " << e.what() << '\n';
    return false;
  }
}

std::string command_line() {
  std::ifstream in("/proc/self/cmdline", std::ios::binary);
  std::string all((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::string s;
  for (std::size_t i = 0, j; i < all.size(); i = j + 1) {
    j = all.find('\0', i);
    if (j == std::string::npos) j = all.size();
    std::string arg = all.substr(i, j - i);
    if (i == 0) arg = "rotorcert";
    s += (s.empty() ? "" : " ") + arg;
  }
  return s;
}

certify::json run_json(double seconds, const std::string& command, int jobs) {
  char host[256] = {};
  ::gethostname(host, sizeof host - 1);
  char date[32] = {};
  const std::time_t now = std::time(nullptr) - static_cast<std::time_t>(seconds);
  std::strftime(date, sizeof date, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
  const spec::DataLayout& layout = spec::data_layout();
  const std::filesystem::path data = layout.installed ? layout.prefix / "share/rotorcert" : layout.prefix;
  return {{"started_utc", date}, {"duration_s", seconds}, {"host", host},
          {"command", command}, {"jobs", jobs},   {"data_dir", data.string()}};
}

}  // namespace rotorcert::cli
