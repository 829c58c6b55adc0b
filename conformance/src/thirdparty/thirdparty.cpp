#include <rotorcert/thirdparty/thirdparty.hpp>

#include <algorithm>
#include <fstream>
#include <iostream>
#include <set>
#include <stdexcept>

#include <rotorcert/certify/report_document.hpp>
#include <rotorcert/certify/verdict.hpp>
#include <rotorcert/certify/wire.hpp>
#include <rotorcert/vectors/check.hpp>
#include <rotorcert/vectors/error.hpp>
#include <rotorcert/vectors/vector_file.hpp>
#include <rotorcert/vectors/vector_set.hpp>

namespace rotorcert::thirdparty {
namespace fs = std::filesystem;
using certify::json;

namespace {

/// The last lines of a log, for a reason that fits in a report cell.
std::string log_tail(const fs::path& log, std::size_t lines = 6) {
  std::ifstream in(log);
  std::vector<std::string> all;
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) all.push_back(line);
  std::string tail;
  for (std::size_t i = all.size() > lines ? all.size() - lines : 0; i < all.size(); ++i) tail += (tail.empty() ? "" : "\n") + all[i];
  return tail;
}

/// The versions the library's certificates report, each once, in order.
std::vector<json> version_list(const Library& lib) {
  std::vector<json> versions;
  for (const certify::Certificate& c : lib.certificates)
    if (std::find(versions.begin(), versions.end(), json(c.table.version)) == versions.end()) versions.emplace_back(c.table.version);
  return versions;
}

/// The entries of a library's expected_failures.json that are its own (a built-in table's file is
/// in impls/ and may list other tables); empty when there is no file.
std::vector<json> listed_failures(const Manifest& m) {
  const fs::path ef = m.builtin.empty() ? m.dir / "expected_failures.json" : certify::builtin_expected_failures_file(m.builtin);
  std::vector<json> r;
  if (!fs::exists(ef)) return r;
  const json listed = spec::read_json(ef);  // a local: a range-for over read_json(ef).at(...) would dangle
  for (const json& f : listed.at("failures"))
    if (f.value("table", "") == (m.builtin.empty() ? m.name : m.builtin)) r.push_back(f);
  return r;
}

/// Listed defects whose entry says "intermittent": true (the library reads uninitialised memory, so
/// whether the defect shows depends on the stack it finds): not reproducing one is no surprise.
std::set<std::string> intermittent_defects(const std::vector<json>& listed) {
  std::set<std::string> r;
  for (const json& f : listed)
    if (f.value("intermittent", false)) r.insert(f.at("scalar").get<std::string>() + "/" + f.at("clause").get<std::string>());
  return r;
}

/// Every claimed clause that did not pass, with its worst input and error: the library's defects
/// (known: listed in its expected_failures.json) and surprises (not listed).
void add_defects(Library& lib, const certify::Certificate& cert) {
  for (const engine::ClauseResult& r : cert.clauses) {
    if (!certify::claimed(cert, r.clause) || !certify::is_defect(r.outcome)) continue;
    Defect d{cert.table.scalar, r, std::nullopt, "", std::nullopt, std::nullopt};
    if (const std::string* why = certify::expected_failure(cert, r.clause)) d.why = *why;
    if (const auto rp = cert.reproduce.find(r.clause); rp != cert.reproduce.end()) d.reproduce = rp->second;
    lib.defects.push_back(std::move(d));
  }
}

/// Whether a library is as expected: no claimed clause fails unless listed (a new defect, or the
/// adapter changed), and every listed defect FAILs (a pass is news too: the library was fixed).
/// The listed defects were found with kListedAtCases cases per family; a run with fewer cases may
/// not reach a listed defect's input, so there such a clause is "not reproduced", not a surprise;
/// so is an intermittent one.
void finish(Library& lib, int cases_per_family, const std::set<std::string>& intermittent) {
  bool expected = true;
  lib.defects.clear();
  lib.not_reproduced.clear();
  for (const certify::Certificate& c : lib.certificates) {
    expected = expected && c.error.empty();
    for (const engine::ClauseResult& r : c.clauses) {
      if (!certify::claimed(c, r.clause)) continue;
      if (certify::expected_failure(c, r.clause) == nullptr) {
        expected = expected && certify::claimed_clause_good(r);  // NOT_SUPPORTED too, as certify::as_expected
      } else if (r.outcome != engine::Outcome::fail) {
        const bool flaky = intermittent.count(c.table.scalar + "/" + r.clause) > 0;
        if (cases_per_family >= kListedAtCases && !flaky) expected = false;
        lib.not_reproduced.push_back({c.table.scalar, r.clause, r.outcome});
      }
    }
    add_defects(lib, c);
  }
  lib.status = LibraryStatus::certified;
  lib.as_expected = expected;
}

/// The entry of expected_failures.json that lists defect `d` (its scalar and clause), or nullptr.
const json* listed_entry(const std::vector<json>& listed, const Defect& d) {
  for (const json& f : listed)
    if (f.value("scalar", "") == d.scalar && f.value("clause", "") == d.result.clause) return &f;
  return nullptr;
}

/// REPORT-3: every defect of a third-party library comes with a reproducer in the library's own
/// language that calls it directly (conformance/adapters/NAME/reproducers/, named by the
/// "reproducer" field of expected_failures.json, else by the clause), with the command that runs it
/// and the ctest that checks it still shows the defect.
void attach_reproducers(Library& lib, const std::vector<json>& listed) {
  const Manifest& m = lib.manifest;
  for (Defect& d : lib.defects) {
    const std::string& clause = d.result.clause;
    std::string file;
    if (const json* f = listed_entry(listed, d); f != nullptr && f->contains("reproducer")) file = f->at("reproducer");
    else
      for (const char* ext : {".cpp", ".py", ".js", ".rs"})
        if (fs::exists(m.dir / "reproducers" / (clause + ext))) file = clause + ext;
    d.reproducer.reset();
    if (file.empty() || !fs::exists(m.dir / "reproducers" / file)) continue;
    // Relative to the checkout (conformance/adapters/NAME/reproducers/FILE): the same report.json
    // wherever the tree lies, and a path a maintainer can paste.
    const fs::path root = m.dir.parent_path().parent_path().parent_path();
    const fs::path path = (m.dir / "reproducers" / file).lexically_relative(root);
    const std::string stem = fs::path(file).stem().string(), ext = fs::path(file).extension().string();
    // Rust: an example target of the adapter's crate (its Cargo.toml lists reproducers/*.rs), built
    // against the pinned crate in the target directory scripts/setup-adapters made.
    const std::string crate = (m.dir / "Cargo.toml").lexically_relative(root).string();
    // Python and JavaScript run in the environment of the certified version (NAME@VER for another).
    std::string run = ext == ".py" ? "build/adapters/" + m.run_name() + "/venv/bin/python " + path.string()
                      : ext == ".js" ? "NODE_PATH=build/adapters/" + m.run_name() + "/node_modules node " + path.string()
                      : ext == ".rs" ? "cargo run --quiet --release --locked --manifest-path " + crate + " --target-dir build/adapters/" +
                                           m.name + "/target --example " + stem
                                     : "ctest --preset default -R '^reproducer_" + m.name + "_" + stem + "$' -V";
    const char* language = ext == ".cpp" ? "C++" : ext == ".py" ? "Python" : ext == ".rs" ? "Rust" : "JavaScript";
    d.reproducer = Reproducer{path.string(), language, run, "reproducer_" + m.name + "_" + stem};
  }
}

/// REPORT-3: what the library's tracker knows of each listed defect (the entry's "upstream").
void attach_upstream(Library& lib, const std::vector<json>& listed) {
  for (Defect& d : lib.defects) {
    d.upstream.reset();
    if (const json* f = listed_entry(listed, d); f != nullptr && f->contains("upstream"))
      d.upstream = parse_upstream(f->at("upstream"));
  }
}

/// A library whose certificates are all in: its verdict and its defects' reproducers and
/// upstream status, from one reading of its expected_failures.json.
void conclude(Library& lib, int cases_per_family) {
  const std::vector<json> listed = listed_failures(lib.manifest);
  finish(lib, cases_per_family, intermittent_defects(listed));
  attach_reproducers(lib, listed);
  attach_upstream(lib, listed);
}

json upstream_json(const std::optional<Upstream>& u) {
  if (!u) return nullptr;
  return {{"status", to_string(u->status)}, {"refs", u->refs}, {"note", u->note}, {"searched", u->searched}};
}

json defect_json(const Defect& d) {
  json reproducer = nullptr;
  if (d.reproducer)
    reproducer = {{"file", d.reproducer->file}, {"language", d.reproducer->language}, {"run", d.reproducer->run},
                  {"ctest", d.reproducer->ctest}};
  return {{"scalar", d.scalar},
          {"clause", d.result.clause},
          {"outcome", engine::to_string(d.result.outcome)},
          {"known", d.why.has_value()},
          {"why", d.why ? json(*d.why) : json(nullptr)},
          {"cases", d.result.cases},
          {"failures", d.result.failures},
          {"worst", certify::worst_json(d.result)},
          {"conventions", d.result.conventions},
          {"note", d.result.note},
          {"reproduce", d.reproduce},
          {"reproducer", reproducer},
          {"upstream", upstream_json(d.upstream)}};
}

/// One library of the section: its manifest, flattened, and what the run made of it.
json library_json(const Library& lib) {
  const Manifest& m = lib.manifest;
  const json& r = m.raw;
  json j = {{"name", m.run_name()},
            {"library", m.library},
            {"homepage", r.value("homepage", "")},
            {"license", r.value("license", "")},
            {"package", r.value("package", json::object())},
            {"route", m.route},
            {"language", m.language},
            {"scalars", m.scalars},
            {"description", r.value("description", "")},
            {"conventions", r.value("conventions", json::array())},
            {"ops", r.value("ops", json::object())},
            {"unsupported", r.value("unsupported", json::object())},
            {"adapter", (fs::path("conformance/adapters") / m.name).generic_string()},
            {"status", to_string(lib.status)},
            {"reason", lib.reason},
            {"reproduce", lib.reproduce},
            {"certificates", json::array()},
            {"defects", json::array()},
            {"as_expected", nullptr}};
  for (const certify::Certificate& c : lib.certificates) j["certificates"].push_back(certify::certificate_json(c));
  for (const Defect& d : lib.defects) j["defects"].push_back(defect_json(d));
  if (lib.status == LibraryStatus::certified) {
    j["as_expected"] = lib.as_expected;
    json not_reproduced = json::array();
    for (const NotReproduced& n : lib.not_reproduced)
      not_reproduced.push_back({{"scalar", n.scalar}, {"clause", n.clause}, {"outcome", engine::to_string(n.outcome)}});
    j["not_reproduced"] = not_reproduced;
    const std::vector<json> versions = version_list(lib);
    j["version"] = versions.size() == 1 ? versions.front() : json(versions);
  }
  if (!m.version.empty()) {
    // Another version than the pin: what changed against the pin's known defects, not a verdict.
    j["package"]["version"] = m.version;
    j["requested_version"] = m.version;
    j["pinned_version"] = r.value("package", json::object()).value("version", "");
    if (lib.status == LibraryStatus::certified) {
      json fixed = json::array(), appeared = json::array();
      for (const NotReproduced& n : lib.not_reproduced)
        if (n.outcome == engine::Outcome::pass || n.outcome == engine::Outcome::quality_warning)
          fixed.push_back({{"scalar", n.scalar}, {"clause", n.clause}, {"outcome", engine::to_string(n.outcome)}});
      for (const Defect& d : lib.defects)
        if (!d.why) appeared.push_back({{"scalar", d.scalar}, {"clause", d.result.clause}});
      j["against_pin"] = {{"fixed", fixed}, {"appeared", appeared}};
    }
  }
  if (lib.adapter_seconds) {
    j["adapter_seconds"] = *lib.adapter_seconds;
    j["adapter_log"] = lib.adapter_log;
  }
  return j;
}

}  // namespace

std::string reproduce_command(const std::string& adapter, const std::vector<std::string>& clauses) {
  std::string s = "rotorcert thirdparty --adapter " + adapter;
  for (const std::string& c : clauses) s += " --clause " + c;
  return s + " --out third-party-" + adapter;
}

Outcome certify_third_party(const spec::Spec& spec, const Options& o, const KnownCertificates& known) {
  std::vector<Manifest> manifests = load_manifests(o.adapters_dir);
  for (const std::string& n : o.names)
    if (std::none_of(manifests.begin(), manifests.end(), [&](const Manifest& m) { return m.name == n; })) {
      std::string have;
      for (const Manifest& m : manifests) have += (have.empty() ? "" : ", ") + m.name;
      throw std::runtime_error("no adapter named '" + n + "' in " + o.adapters_dir.string() + " (have: " + have + ")");
    }
  const std::vector<Manifest> all = manifests;
  std::erase_if(manifests, [&](const Manifest& m) {
    return !o.names.empty() && std::find(o.names.begin(), o.names.end(), m.name) == o.names.end();
  });
  // Other versions: the same adapter on another release of its library, a library of its own.
  for (const auto& [name, version] : o.versions) {
    // A plain reference: clang 14 cannot capture a structured binding (C++20 allows it; clang 16 does).
    const std::string& adapter = name;
    const auto it = std::find_if(all.begin(), all.end(), [&adapter](const Manifest& m) { return m.name == adapter; });
    if (it == all.end()) throw std::runtime_error("--version " + name + "=" + version + ": no adapter named '" + name + "'");
    if (!it->uses_environment())
      throw std::runtime_error("--version " + name + "=" + version + ": " + it->library + " comes from " +
                               it->raw.value("package", json::object()).value("registry", "the build") +
                               ", one version per installation; certify another by building the plugin against it");
    Manifest v = *it;
    v.version = version;
    manifests.push_back(std::move(v));
  }
  // Seed and cases other than the defaults travel with the reproduce commands.
  std::string run_options;
  if (o.certify.cases.seed != 1) run_options += " --seed " + std::to_string(o.certify.cases.seed);
  if (o.certify.cases.cases_per_family != certify::kDefaultCasesPerFamily)
    run_options += " --cases " + std::to_string(o.certify.cases.cases_per_family);
  if (o.certify.cases.search_budget != certify::kDefaultSearchBudget)
    run_options += " --search " + std::to_string(o.certify.cases.search_budget);
  auto reproduce = [&](const Manifest& m, const std::vector<std::string>& clauses) {
    std::string s = reproduce_command(m.name, clauses);
    const std::string version = m.version.empty() ? "" : " --version " + m.name + "=" + m.version;
    s.insert(s.find(" --out"), run_options + version);
    if (!m.version.empty()) s += "@" + m.version;
    return s;
  };

  std::vector<Library> libs;
  for (const Manifest& m : manifests) {
    Library lib;
    lib.manifest = m;
    lib.reproduce = reproduce(m, o.certify.clauses);
    libs.push_back(std::move(lib));
  }

  // Route abi: one certification run over every table, children in parallel.
  struct Slot {
    std::size_t lib;
    std::string scalar;
  };
  std::vector<certify::Target> targets;
  std::vector<Slot> slots;
  std::vector<std::vector<certify::Certificate>> made(libs.size());
  const std::vector<certify::Target> builtins = certify::builtin_targets();
  for (std::size_t i = 0; i < manifests.size(); ++i) {
    const Manifest& m = manifests[i];
    if (m.route != "abi") continue;
    for (const std::string& scalar : m.scalars) {
      if (!m.builtin.empty()) {
        if (const auto k = known.find(m.builtin + "/" + scalar); k != known.end()) {
          made[i].push_back(k->second);
          continue;
        }
        const auto t = std::find_if(builtins.begin(), builtins.end(), [&](const certify::Target& b) {
          return b.info.name == m.builtin && b.info.scalar == scalar;
        });
        if (t == builtins.end()) {
          libs[i].status = LibraryStatus::error;
          libs[i].reason = "no built-in " + scalar + " table named " + m.builtin;
          continue;
        }
        targets.push_back(*t);
        slots.push_back({i, scalar});
        continue;
      }
      // A C or C++ plugin comes from the build (--plugins); a Rust one from the environment
      // scripts/setup-adapters built it in (cargo), named by its status.json.
      fs::path path;
      if (m.uses_environment()) {
        const Environment env = read_environment(o.env_dir, m.run_name());
        if (!env.installed) {
          libs[i].reason = env.reason;
          break;
        }
        path = env.plugin;
        if (path.empty()) {
          libs[i].status = LibraryStatus::error;
          libs[i].reason = "the environment of " + m.run_name() + " (" + (o.env_dir / m.run_name() / "status.json").string() +
                           ") names no plugin (run scripts/setup-adapters " + m.name + ")";
          break;
        }
      } else {
        path = o.plugin_dir / (m.plugin + ".so");
        if (!fs::exists(path)) {
          libs[i].reason = "the plugin " + path.string() + " was not built: its library was not found when the build was " +
                           "configured (scripts/bootstrap installs it; then cmake --preset default again)";
          break;
        }
      }
      try {
        bool found = false;
        for (const certify::Target& t : certify::probe_plugin(path.string(), o.certify.limits))
          if (t.info.scalar == scalar) {
            targets.push_back(t);
            slots.push_back({i, scalar});
            found = true;
          }
        if (!found) throw std::runtime_error("it has no " + scalar + " table");
      } catch (const std::exception& e) {
        libs[i].status = LibraryStatus::error;
        libs[i].reason = "the plugin " + path.string() + " cannot be certified: " + e.what();
      }
    }
  }
  if (!targets.empty()) {
    if (!o.quiet) std::cout << "third-party: certifying " << targets.size() << " C-ABI table(s) ...\n" << std::flush;
    std::vector<certify::Certificate> certs = certify::certify_targets(spec, targets, o.certify);
    for (std::size_t t = 0; t < certs.size(); ++t) {
      const Manifest& m = manifests[slots[t].lib];
      // Plugins' known defects live beside their adapter; built-ins' in impls/ (certify did those).
      if (!m.plugin.empty()) certs[t].expected_failures = adapter_expected_failures(m, slots[t].scalar);
      made[slots[t].lib].push_back(std::move(certs[t]));
    }
  }
  for (std::size_t i = 0; i < manifests.size(); ++i) {
    if (manifests[i].route != "abi" || made[i].empty() || libs[i].status == LibraryStatus::error) continue;
    // In the manifest's scalar order, whichever route made them; every clause reproduced by the
    // one command that certifies this library.
    for (const std::string& scalar : manifests[i].scalars)
      for (certify::Certificate& cert : made[i]) {
        if (cert.table.scalar != scalar) continue;
        for (auto& [clause, command] : cert.reproduce)
          if (!command.empty()) command = reproduce(manifests[i], {clause});
        libs[i].certificates.push_back(cert);
      }
    conclude(libs[i], o.certify.cases.cases_per_family);
  }

  // Route vectors: one export for the run, each adapter in its own environment.
  const fs::path vectors_dir = o.out / "vectors";
  bool exported = false;
  for (std::size_t i = 0; i < manifests.size(); ++i) {
    const Manifest& m = manifests[i];
    Library& lib = libs[i];
    if (m.route != "vectors") continue;
    const Environment env = read_environment(o.env_dir, m.run_name());
    if (!env.installed) {
      lib.reason = env.reason;
      continue;
    }
    if (!exported) {
      vectors::BuildOptions b;
      b.seed = o.certify.cases.seed;
      b.cases_per_family = o.certify.cases.cases_per_family;
      b.clauses = o.certify.clauses;
      vectors::write_export(vectors_dir, vectors::render_export(spec, b));
      exported = true;
    }
    const fs::path dir = o.out / m.run_name();
    fs::create_directories(dir);
    const fs::path results_file = dir / "results.json", log = dir / "adapter.log";
    fs::remove(results_file);  // a stale file must not stand in for this run's
    std::vector<std::string> argv = env.command;
    argv.insert(argv.end(), {"--vectors", fs::absolute(vectors_dir).string(), "--out", fs::absolute(results_file).string()});
    if (!o.quiet) std::cout << "third-party: running the " << m.run_name() << " adapter ...\n" << std::flush;
    const ProgramRun run = run_program(argv, env.env, log, o.adapter_timeout_s);
    lib.adapter_seconds = run.seconds;
    lib.adapter_log = log.string();
    if (!run.started || run.timed_out || run.exit_code != 0 || !fs::exists(results_file)) {
      lib.status = LibraryStatus::error;
      lib.reason = !run.started ? run.error
                   : run.timed_out ? "the adapter ran past " + std::to_string(static_cast<int>(o.adapter_timeout_s)) + " s"
                   : run.exit_code != 0 ? "the adapter exited with " + std::to_string(run.exit_code) + ": " + log_tail(log)
                                        : "the adapter wrote no results file";
      continue;
    }
    try {
      vectors::ResultsFile results = vectors::parse_results(vectors::read_json_file(results_file), results_file);
      // DECL-1: the manifest declares the library's documented preconditions and chosen
      // conventions (with their citations); the results file may add its own.
      for (const char* key : {"declared_preconditions", "declared_conventions"})
        if (const auto d = m.raw.find(key); d != m.raw.end() && d->is_array())
          for (const json& x : *d) {
            const std::string decl = x.is_object() ? x.at("id").get<std::string>() : x.get<std::string>();
            auto& into = std::string(key) == "declared_preconditions" ? results.preconditions : results.conventions;
            if (std::find(into.begin(), into.end(), decl) == into.end()) into.push_back(decl);
          }
      if (results.name != m.name) throw std::runtime_error("its results name the implementation '" + results.name + "', its manifest '" + m.name + "'");
      if (results.scalar != m.scalars.front()) throw std::runtime_error("its results are " + results.scalar + ", its manifest says " + m.scalars.front());
      const ref::Format format = results.format();
      const vectors::VectorSet set = vectors::load_vectors(spec, vectors_dir, &format);
      vectors::Grading g = vectors::grade(spec, set, results);
      g.certificate.expected_failures = adapter_expected_failures(m, results.scalar);
      for (auto& [clause, command] : g.certificate.reproduce) command = reproduce(m, {clause});
      lib.certificates.push_back(std::move(g.certificate));
      conclude(lib, o.certify.cases.cases_per_family);
    } catch (const std::exception& e) {
      lib.status = LibraryStatus::error;
      lib.reason = std::string("its results file cannot be graded: ") + e.what();
    }
  }
  return {std::move(libs)};
}

const char* to_string(Upstream::Status s) {
  switch (s) {
    case Upstream::Status::reported: return "reported";
    case Upstream::Status::not_found: return "not found";
    case Upstream::Status::declined: return "declined";
  }
  return "not found";
}

Upstream parse_upstream(const json& j) {
  const auto fail = [](const std::string& what) { throw std::invalid_argument("upstream: " + what); };
  if (!j.is_object()) fail("not an object");
  for (const auto& [key, value] : j.items())
    if (key != "status" && key != "refs" && key != "note" && key != "searched") fail("unknown field \"" + key + "\"");
  Upstream u;
  const std::string status = j.value("status", "");
  if (status == "reported") u.status = Upstream::Status::reported;
  else if (status == "not found") u.status = Upstream::Status::not_found;
  else if (status == "declined") u.status = Upstream::Status::declined;
  else fail("status \"" + status + "\" is none of reported, not found, declined");
  if (!j.contains("refs") || !j.at("refs").is_array()) fail("refs is not an array");
  for (const json& r : j.at("refs")) {
    if (!r.is_string() || r.get<std::string>().rfind("https://", 0) != 0) fail("a ref is not an https URL: " + r.dump());
    u.refs.push_back(r.get<std::string>());
  }
  if (u.status != Upstream::Status::not_found && u.refs.empty()) fail("status \"" + status + "\" names no thread");
  u.note = j.value("note", "");
  if (u.note.empty()) fail("no note (what the threads say, or what was searched)");
  u.searched = j.value("searched", "");
  const std::string& d = u.searched;
  const bool date = d.size() == 10 && d[4] == '-' && d[7] == '-' &&
                    std::all_of(d.begin(), d.end(), [](char c) { return c == '-' || (c >= '0' && c <= '9'); });
  if (!date) fail("searched \"" + d + "\" is not a date YYYY-MM-DD");
  return u;
}

const char* to_string(LibraryStatus s) {
  switch (s) {
    case LibraryStatus::not_run: return "not run";
    case LibraryStatus::certified: return "certified";
    case LibraryStatus::error: return "error";
  }
  return "error";
}

bool Outcome::as_expected() const {
  // A library at another version than its pin is compared with the pin's known defects, to show
  // what changed; that it differs is the finding, not a failure of the run.
  return std::all_of(libraries.begin(), libraries.end(), [](const Library& lib) {
    return lib.status != LibraryStatus::error &&
           (lib.status != LibraryStatus::certified || lib.as_expected || !lib.manifest.version.empty());
  });
}

std::vector<certify::Certificate> Outcome::certificates() const {
  std::vector<certify::Certificate> all;
  for (const Library& lib : libraries) all.insert(all.end(), lib.certificates.begin(), lib.certificates.end());
  return all;
}

json section_json(const Outcome& outcome, const Options& o) {
  json list = json::array();
  int certified = 0, not_run = 0, errors = 0;
  for (const Library& lib : outcome.libraries) {
    certified += lib.status == LibraryStatus::certified;
    not_run += lib.status == LibraryStatus::not_run;
    errors += lib.status == LibraryStatus::error;
    list.push_back(library_json(lib));
  }
  // Another version beside its pin in the same run: per clause that FAILs in both, how the worst
  // error moved (more than 2x either way, the threshold of rotorcert diff).
  for (json& v : list) {
    if (!v.contains("against_pin")) continue;
    const std::string pin_name = v.value("name", "").substr(0, v.value("name", "").find('@'));
    const auto pin = std::find_if(list.begin(), list.end(), [&](const json& l) { return l.value("name", "") == pin_name; });
    if (pin == list.end()) continue;
    json moved = json::array();
    for (const json& d : v.value("defects", json::array()))
      for (const json& p : pin->value("defects", json::array())) {
        if (p.value("clause", "") != d.value("clause", "") || p.value("scalar", "") != d.value("scalar", "")) continue;
        const json& a = p.value("worst", json::object());
        const json& b = d.value("worst", json::object());
        if (!a.contains("error_eps") || !b.contains("error_eps") || !a["error_eps"].is_number() || !b["error_eps"].is_number())
          continue;
        const double pinned = a["error_eps"].get<double>(), here = b["error_eps"].get<double>();
        if (pinned > 2 * here || here > 2 * pinned)
          moved.push_back({{"scalar", d.value("scalar", "")}, {"clause", d.value("clause", "")},
                           {"pin_error_eps", pinned}, {"error_eps", here}});
      }
    v["against_pin"]["worst_error_moved"] = moved;
  }
  return {{"adapters_dir", o.adapters_dir.string()},
          {"environments", o.env_dir.string()},
          {"seed", o.certify.cases.seed},
          {"cases_per_family", o.certify.cases.cases_per_family},
          {"certified", certified},
          {"not_run", not_run},
          {"errors", errors},
          {"as_expected", outcome.as_expected()},
          {"libraries", list}};
}

}  // namespace rotorcert::thirdparty
