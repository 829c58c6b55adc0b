// `rotorcert vectors`: test vectors for implementations in any language (conformance/VECTORS.md).
//   export --out DIR [--seed S] [--cases N] [--scalar float|double|both] [--clause ID]...
//       writes one file per (clause, op, format) and DIR/index.json; deterministic.
//   check RESULTS.json [--vectors DIR] [--out DIR] [--verbose]
//       grades a results file written by an adapter and prints the certificate; with --out also
//       writes report.json/.md/.html. Exit 0 if every claimed clause is PASS or QUALITY_WARNING.
//   run (--impl NAME | --plugin PATH [--table NAME]) --scalar float|double --vectors DIR --out RESULTS.json
//       runs a built-in or plugin table on the vectors and writes its results file.
// Exit 2 on usage errors and on files that cannot be read or are malformed (the message names
// the file and the JSON path).
#include <chrono>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <rotorcert/report/write.hpp>
#include <rotorcert/certify/atomic_file.hpp>
#include <rotorcert/certify/certificate.hpp>
#include <rotorcert/certify/print.hpp>
#include <rotorcert/certify/report_document.hpp>
#include <rotorcert/registry.hpp>
#include <rotorcert/vectors/check.hpp>
#include <rotorcert/vectors/error.hpp>
#include <rotorcert/vectors/run.hpp>
#include <rotorcert/vectors/vector_set.hpp>

#include "certify_cli.hpp"
#include "commands.hpp"

namespace rotorcert::cli {
namespace {

struct ExportArgs {
  std::string out;
  std::uint64_t seed = 1;
  int cases = 16;
  std::string scalar = "both";
  std::vector<std::string> clauses;
};

struct CheckArgs {
  std::string results;
  std::string vectors;
  std::string out;
  bool verbose = false;
};

struct RunArgs {
  std::string impl, plugin, table, scalar, vectors, out;
};

struct Args {
  std::optional<std::string> spec_dir;
  ExportArgs exp;
  CheckArgs check;
  RunArgs run;
  CLI::App *export_app = nullptr, *check_app = nullptr, *run_app = nullptr;
};

spec::Spec load(const Args& a) { return spec::load_spec(spec::resolve_spec_dir(a.spec_dir)); }

int usage(const std::string& message) {
  std::cerr << "rotorcert vectors: " << message << '\n';
  return kExitUsage;
}

/// A JSON object with `key` (an array) written one element per line: diffable and compact.
std::string one_per_line(const nlohmann::ordered_json& j, const std::string& key) {
  nlohmann::ordered_json head = j;
  head[key] = nullptr;
  std::string list = "[";
  const auto& items = j.at(key);
  for (std::size_t i = 0; i < items.size(); ++i) list += (i ? ",\n    " : "\n    ") + items[i].dump();
  list += items.empty() ? "]" : "\n  ]";
  std::string text = head.dump(2);
  const std::string placeholder = "\"" + key + "\": null";
  text.replace(text.rfind(placeholder), placeholder.size(), "\"" + key + "\": " + list);
  return text + "\n";
}

int run_export(const Args& a) {
  const spec::Spec spec = load(a);
  vectors::BuildOptions o;
  o.seed = a.exp.seed;
  o.cases_per_family = a.exp.cases;
  if (a.exp.scalar == "float") o.formats = {ref::Format::binary32};
  else if (a.exp.scalar == "double") o.formats = {ref::Format::binary64};
  for (const std::string& id : a.exp.clauses) {
    const spec::Clause* cl = spec.find_clause(id);
    if (cl == nullptr) return usage("no clause " + id + " in spec " + spec.version);
    if (cl->level == "Meta") return usage(id + " is a Meta clause: it binds the suite and has no test vectors");
    o.clauses.push_back(id);
  }
  const auto files = vectors::render_export(spec, o);
  try {
    vectors::write_export(a.exp.out, files);
  } catch (const std::exception& e) {
    std::cerr << "rotorcert vectors export: cannot write " << a.exp.out << ": " << e.what() << '\n';
    return kExitUsage;
  }
  const auto index = nlohmann::json::parse(files.at("index.json"));
  std::cout << "wrote " << index.at("numberOfFiles") << " vector files (" << index.at("numberOfTests")
            << " tests, seed " << o.seed << ", spec " << spec.version << ") and index.json to " << a.exp.out << '\n';
  return kExitOk;
}

int run_check(const Args& a) {
  const auto started = std::chrono::steady_clock::now();
  const spec::Spec spec = load(a);
  const vectors::ResultsFile results =
      vectors::parse_results(vectors::read_json_file(a.check.results), a.check.results);
  const std::filesystem::path where = a.check.vectors.empty() ? results.vectors_path() : std::filesystem::path(a.check.vectors);
  const ref::Format format = results.format();
  const vectors::VectorSet set = vectors::load_vectors(spec, where, &format);
  if (set.files.empty())
    throw vectors::VectorsError(set.index, "/files", std::string("no vectors of format ") + vectors::format_name(format) +
                                                         " for a " + results.scalar + " implementation");
  const vectors::Grading g = vectors::grade(spec, set, results);
  certify::print_certificate(std::cout, g.certificate, a.check.verbose);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  // No child processes here: no time or memory limit applies (null).
  const certify::json options = {{"seed", set.seed},       {"cases_per_family", set.cases_per_family},
                                 {"levels", g.certificate.levels},     {"clauses", certify::json::array()},
                                 {"timeout_s", nullptr},   {"memory_mb", nullptr},
                                 {"isolation", "in process (vectors check)"}};
  const certify::json report =
      certify::report_json(spec, "vectors-check", options, run_json(seconds, command_line(), 1), {g.certificate});
  if (!a.check.out.empty()) {
    try {
      report::write_report(a.check.out, report);
    } catch (const std::exception& e) {
      std::cerr << "rotorcert vectors check: cannot write the report: " << e.what() << '\n';
      return kExitUsage;
    }
    std::cout << "report: " << a.check.out << "/report.html (and report.json, report.md)\n";
  }
  if (a.check.verbose) std::cout << g.results << " results judged against " << set.index.string() << '\n';
  return report.at("summary").at("exit_code").get<int>();
}

int run_run(const Args& a) {
  const spec::Spec spec = load(a);
  if (a.run.impl.empty() == a.run.plugin.empty()) return usage("run needs exactly one of --impl NAME and --plugin PATH");
  const std::uint32_t scalar = a.run.scalar == "float" ? RC_SCALAR_FLOAT32 : RC_SCALAR_FLOAT64;
  std::unique_ptr<impl::Plugin> plugin;
  const rc_impl* table = nullptr;
  if (!a.run.impl.empty()) {
    table = impl::find_builtin(a.run.impl, scalar);
    if (table == nullptr) return usage("no built-in " + a.run.scalar + " table named '" + a.run.impl + "' (see `rotorcert list`)");
  } else {
    try {
      plugin = impl::Plugin::load(a.run.plugin);
    } catch (const impl::PluginError& e) {
      return usage(e.what());
    }
    // A plugin may hold several tables of one scalar (glm_quat and glm_mix, say): --table picks
    // one by name, and without it only an unambiguous plugin is accepted.
    std::vector<const rc_impl*> candidates;
    std::string names;
    for (const rc_impl* t : plugin->tables())
      if (t->scalar == scalar && (a.run.table.empty() || a.run.table == (t->name ? t->name : ""))) {
        candidates.push_back(t);
        names += std::string(names.empty() ? "" : ", ") + (t->name ? t->name : "?");
      }
    if (candidates.empty())
      return usage(a.run.plugin + " has no " + a.run.scalar + " table" + (a.run.table.empty() ? "" : " named '" + a.run.table + "'"));
    if (candidates.size() > 1)
      return usage(a.run.plugin + " has " + std::to_string(candidates.size()) + " " + a.run.scalar + " tables (" + names +
                   "): choose one with --table NAME");
    table = candidates.front();
  }
  const ref::Format format = engine::format_of(*table);
  const vectors::VectorSet set = vectors::load_vectors(spec, a.run.vectors, &format);
  const auto results = vectors::run_table(*table, set, a.run.out);
  try {
    certify::write_atomically(a.run.out, one_per_line(results, "results"));
  } catch (const std::exception& e) {
    std::cerr << "rotorcert vectors run: cannot write " << a.run.out << ": " << e.what() << '\n';
    return kExitUsage;
  }
  std::cout << "wrote " << results.at("results").size() << " results of " << table->name << " (" << a.run.scalar << ") to "
            << a.run.out << '\n';
  return kExitOk;
}

int dispatch(const Args& a) {
  try {
    if (a.export_app->parsed()) return run_export(a);
    if (a.check_app->parsed()) return run_check(a);
    if (a.run_app->parsed()) return run_run(a);
    return usage("give a subcommand: export, check or run");
  } catch (const vectors::VectorsError& e) {
    return usage(e.what());
  } catch (const spec::SpecError& e) {
    return usage(e.what());
  }
}

}  // namespace

Command add_vectors(CLI::App& parent) {
  auto a = std::make_shared<Args>();
  CLI::App* app = parent.add_subcommand("vectors", "Test vectors for any language: export them, check a results file");
  app->require_subcommand(1);
  app->add_option("--spec", a->spec_dir, "Spec directory (default: $ROTORCERT_SPEC_DIR, else the tool's own spec/)")
      ->check(CLI::ExistingDirectory)
      ->option_text("DIR");

  CLI::App* e = a->export_app = app->add_subcommand("export", "Write test vectors: one JSON file per (clause, op, format) and index.json");
  e->add_option("--out", a->exp.out, "Directory to write (created if needed)")->required()->option_text("DIR");
  e->add_option("--seed", a->exp.seed, "Seed of the generated case families (default 1)");
  e->add_option("--cases", a->exp.cases, "Cases per family (default 16)")->check(CLI::Range(1, 100000));
  e->add_option("--scalar", a->exp.scalar, "float, double or both (default)")->check(CLI::IsMember({"float", "double", "both"}));
  e->add_option("--clause", a->exp.clauses, "Only this clause; repeatable")->option_text("ID");

  CLI::App* c = a->check_app = app->add_subcommand("check", "Grade a results file against the vectors it answers");
  c->add_option("results", a->check.results, "Results file (format rotorcert-results)")->required()->option_text("RESULTS.json");
  c->add_option("--vectors", a->check.vectors, "The vectors (directory or index.json); default: the results file's \"vectors\"")
      ->option_text("DIR");
  c->add_option("--out", a->check.out, "Also write report.json, report.md and report.html here")->option_text("DIR");
  c->add_flag("-v,--verbose", a->check.verbose, "Every clause, also those not claimed");

  CLI::App* r = a->run_app = app->add_subcommand("run", "Run a built-in or plugin table on the vectors and write its results file");
  r->add_option("--impl", a->run.impl, "Built-in implementation (see `rotorcert list`)")->option_text("NAME");
  r->add_option("--plugin", a->run.plugin, "Plugin library (.so through the C ABI)")->option_text("PATH");
  r->add_option("--table", a->run.table, "With --plugin: the table of that name (needed when it has several of the scalar)")
      ->option_text("NAME");
  r->add_option("--scalar", a->run.scalar, "float or double")->required()->check(CLI::IsMember({"float", "double"}));
  r->add_option("--vectors", a->run.vectors, "The vectors (directory or index.json)")->required()->option_text("DIR");
  r->add_option("--out", a->run.out, "Results file to write")->required()->option_text("RESULTS.json");

  return {app, [a] { return dispatch(*a); }};
}

}  // namespace rotorcert::cli
