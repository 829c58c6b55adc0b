#include "certify_cli.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <thread>

#include <rotorcert/certify/interrupt.hpp>
#include <rotorcert/spec/data_layout.hpp>

#include "commands.hpp"

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
  app.add_flag("--resume", o.resume,
               "Continue the interrupted run whose journal (certify-journal.jsonl) is in --out, without redoing "
               "finished clauses; the options must be the same");
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

std::optional<std::vector<certify::Certificate>> certify_resumably(const char* command, const CertifyCli& o,
                                                                   const spec::Spec& spec,
                                                                   const std::vector<certify::Target>& targets,
                                                                   certify::CertifyOptions& options,
                                                                   std::unique_ptr<certify::Journal>& journal, int& code) {
  try {
    std::filesystem::create_directories(o.out);
    journal = std::make_unique<certify::Journal>(certify::Journal::file_in(o.out),
                                                 certify::run_identity(spec, targets, options), o.resume);
  } catch (const std::exception& e) {
    std::cerr << "rotorcert " << command << ": " << e.what() << '\n';
    code = kExitUsage;
    return std::nullopt;
  }
  if (o.resume && !o.quiet)
    std::cout << "resuming: " << journal->resumable() << " clauses finished before the interruption are not run again\n";
  options.journal = journal.get();
  certify::InterruptGuard guard;
  try {
    std::vector<certify::Certificate> certs = certify::certify_targets(spec, targets, options);
    if (const int sig = certify::interruption(); sig != 0) throw certify::Interrupted(sig);
    return certs;
  } catch (const certify::Interrupted& e) {
    if (options.progress) std::fputs("\r\033[K", stderr);
    std::cerr << "rotorcert " << command << ": interrupted by " << certify::signal_name(e.signal)
              << "; the report in " << o.out << " is unchanged. The clauses finished so far are in "
              << journal->file().string() << "; continue with the same command and --resume\n";
    code = 128 + e.signal;
    return std::nullopt;
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
