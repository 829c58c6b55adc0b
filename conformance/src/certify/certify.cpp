#include <rotorcert/certify/certify.hpp>

#include <unistd.h>

#include <algorithm>
#include <cfenv>
#include <filesystem>
#include <cstdio>
#include <iostream>
#include <stdexcept>
#include <tuple>
#include <utility>

#include <rotorcert/certify/platform.hpp>
#include <rotorcert/certify/wire.hpp>
#include <rotorcert/engine/declarations.hpp>
#include <rotorcert/registry.hpp>

namespace rotorcert::certify {
namespace {

using engine::ClauseResult;
using engine::Outcome;

/// The table a target names, inside the child (a plugin is loaded there, and stays loaded until
/// the child exits).
const rc_impl& open_table(const Target& t) {
  if (t.plugin_path.empty()) {
    const rc_impl* table = impl::find_builtin(t.info.name, t.info.scalar == "float" ? RC_SCALAR_FLOAT32 : RC_SCALAR_FLOAT64);
    if (table == nullptr) throw std::runtime_error("no built-in table " + t.info.name + " " + t.info.scalar);
    return *table;
  }
  static std::unique_ptr<impl::Plugin> plugin;  // per child: one target per child
  plugin = impl::Plugin::load(t.plugin_path);
  if (t.plugin_index >= plugin->tables().size()) throw std::runtime_error("the plugin lost a table between two loads");
  return *plugin->tables()[t.plugin_index];
}

std::string reproduce_command(const CertifyOptions& o, const Target& t, const std::string& clause) {
  std::string s = o.reproduce_prefix + " certify ";
  s += t.plugin_path.empty() ? "--impl " + t.info.name : "--plugin " + t.plugin_path;
  s += " --scalar " + t.info.scalar + " --clause " + clause + " --seed " + std::to_string(o.cases.seed) + " --cases " +
       std::to_string(o.cases.cases_per_family) + " --search " + std::to_string(o.cases.search_budget) +
       " --verbose --out rotorcert-" + clause;
  return s;
}

/// What a child does for one clause: run, and on FAIL try the conventions.
std::string run_clause_in_child(const spec::Spec& spec, const Target& target, const std::string& clause,
                                const CertifyOptions& options, bool one_at_a_time, ChildChannel& channel) {
  const rc_impl& table = open_table(target);
  // The implementation runs in the environment its loading left (FTZ/DAZ of -ffast-math
  // included); the reference and the judging run in the default one.
  std::fenv_t loaded;
  std::fegetenv(&loaded);
  const json environment = fp_environment_json();
  engine::set_call_environment(loaded);
  std::fesetenv(FE_DFL_ENV);
  const ref::Format f = engine::format_of(table);
  engine::RunHooks hooks;
  hooks.one_at_a_time = one_at_a_time;
  hooks.before_call = [&](const engine::AbiOp& op, const std::vector<const engine::Case*>& cases) {
    WorkingOn w{op.name, "", "", op.name + " on a batch of " + std::to_string(cases.size()) + " cases"};
    if (cases.size() == 1) {
      w.label = cases[0]->label;
      w.input = engine::describe_inputs(op, *cases[0], f);
      w.text = op.name + " [" + w.label + "] " + w.input;
    }
    channel.progress(to_json(w).dump());
  };
  ClauseResult r = engine::run_clause(table, spec, clause, options.cases, hooks);
  if (r.outcome == Outcome::fail && options.detect_conventions) {
    channel.progress(to_json(WorkingOn{"", "", "", "convention detection for " + clause}).dump());
    engine::detect_conventions(table, spec, clause, options.cases, r);
  }
  return json{{"result", to_json(r, true)}, {"fp_environment", environment}}.dump();
}

/// The result a child handed over (run_clause_in_child), checked field by field: it must be the
/// result of `clause`, with a valid outcome and consistent counts, and an environment object.
std::pair<ClauseResult, json> result_from_child(const std::string& text, const std::string& clause) {
  const json child = json::parse(text);
  if (!child.is_object()) throw std::runtime_error("not a JSON object");
  ClauseResult r = clause_result_from_json(child.at("result"));
  if (r.clause != clause) throw std::runtime_error("the result of clause \"" + r.clause.substr(0, 40) + "\"");
  if (r.outcome == Outcome::crash || r.outcome == Outcome::timeout)
    throw std::runtime_error(std::string("an outcome only the certify tool gives: ") + engine::to_string(r.outcome));
  if (r.failures > r.cases) throw std::runtime_error("more failing inputs than inputs");
  json environment = child.at("fp_environment");
  if (!environment.is_object()) throw std::runtime_error("fp_environment is not an object");
  for (const auto& [key, value] : environment.items())
    if (!value.is_null() && !value.is_boolean() && !value.is_number() && !value.is_string())
      throw std::runtime_error("fp_environment." + key.substr(0, 40) + " is not a plain value");
  return {std::move(r), std::move(environment)};
}

void show_progress(const CertifyOptions& o, std::size_t done, std::size_t total, const std::string& what) {
  if (!o.progress) return;
  std::fprintf(stderr, "\r\033[K[%zu/%zu] %s", done, total, what.c_str());
  if (done == total) std::fputs("\r\033[K", stderr);
  std::fflush(stderr);
}

}  // namespace

std::vector<Target> builtin_targets() {
  std::vector<Target> all;
  for (const rc_impl* t : impl::builtin_tables()) all.push_back({table_info(*t), {}, 0, {}});
  return all;
}

std::vector<Target> probe_plugin(const std::string& given_path, const ChildLimits& limits) {
  if (!std::filesystem::exists(given_path)) throw std::runtime_error("no such file");
  // Absolute, so that reproduce commands work from any directory.
  const std::string path = std::filesystem::absolute(given_path).lexically_normal().string();
  ChildPool pool(1, limits);
  pool.submit(0, [&](ChildChannel& channel) {
    channel.progress("loading " + path);
    const auto plugin = impl::Plugin::load(path);
    json tables = json::array();
    for (const rc_impl* t : plugin->tables()) {
      if (const std::string problem = impl::validate_table(*t); !problem.empty())
        throw std::runtime_error("invalid table: " + problem);
      if (const std::string problem = engine::declaration_problem(
              engine::declarations_of(*t), [&](const std::string& op) { return engine::supports(*t, op); });
          !problem.empty())
        throw std::runtime_error("invalid table: " + std::string(t->name) + ": DECL-1: " + problem);
      tables.push_back(to_json(table_info(*t, "plugin", path)));
    }
    return tables.dump();
  });
  const auto [id, out] = pool.wait_any();
  (void)id;
  if (out.kind == ChildOutcome::Kind::timed_out) throw std::runtime_error("loading the plugin hung: " + out.message);
  if (out.kind == ChildOutcome::Kind::crashed) throw std::runtime_error("cannot be certified: " + out.message);
  std::vector<Target> targets;
  std::uint32_t index = 0;
  for (const json& t : json::parse(out.result)) targets.push_back({table_info_from_json(t), path, index++, {}});
  if (targets.empty()) throw std::runtime_error("the plugin offers no table for ABI version " + std::to_string(RC_ABI_VERSION));
  return targets;
}

std::vector<std::string> clauses_to_certify(const spec::Spec& spec, const std::vector<std::string>& levels,
                                            const std::vector<std::string>& only) {
  std::vector<std::string> ids;
  for (const spec::Clause& c : spec.clauses) {
    if (c.level == "Meta" || std::find(levels.begin(), levels.end(), c.level) == levels.end()) continue;
    if (!only.empty() && std::find(only.begin(), only.end(), c.id) == only.end()) continue;
    ids.push_back(c.id);
  }
  return ids;
}

std::vector<Certificate> certify_targets(const spec::Spec& spec, const std::vector<Target>& targets,
                                         const CertifyOptions& options) {
  const std::vector<std::string> all_clauses = clauses_to_certify(spec, options.levels, options.clauses);
  std::vector<Certificate> certs(targets.size());
  struct Job {
    std::size_t target, slot;
    std::string clause;
    bool pinpoint = false;        // second run, one case at a time, to find the crashing input
    ChildOutcome first;           // the first run's outcome, for a pinpoint run
  };
  std::vector<Job> jobs;
  ChildPool pool(options.jobs, options.limits);
  std::size_t total = 0, done = 0;

  auto submit = [&](Job job) {
    const std::size_t id = jobs.size();
    jobs.push_back(job);
    const Target& target = targets[job.target];
    pool.submit(id, [&spec, &options, target, job](ChildChannel& channel) {
      return run_clause_in_child(spec, target, job.clause, options, job.pinpoint, channel);
    });
  };

  for (std::size_t t = 0; t < targets.size(); ++t) {
    Certificate& c = certs[t];
    c.table = targets[t].info;
    c.levels = options.levels;
    if (targets[t].plugin_path.empty()) c.expected_failures = expected_failures(c.table.name, c.table.scalar);
    const std::vector<std::string>& clauses = targets[t].clauses.empty() ? all_clauses : targets[t].clauses;
    const std::string key = table_key(targets[t]);
    for (const std::string& id : clauses) {
      const spec::Clause* cl = spec.find_clause(id);
      ClauseResult r;
      r.clause = id;
      r.level = cl->level;
      r.tolerance = cl->tolerance;
      const bool claimed =
          std::find(c.table.claimed_clauses.begin(), c.table.claimed_clauses.end(), id) != c.table.claimed_clauses.end();
      const bool run = claimed || options.run_unclaimed || !targets[t].clauses.empty();
      if (!run) {
        r.outcome = Outcome::not_supported;
        r.note = "not claimed by the implementation";
      }
      c.reproduce[id] = reproduce_command(options, targets[t], id);
      if (const Journal::Entry* finished = run && options.journal ? options.journal->take(key, id) : nullptr) {
        // Finished before an interruption (--resume): not run again.
        c.clauses.push_back(finished->result);
        if (c.fp_environment.is_null() && !finished->fp_environment.empty()) c.fp_environment = finished->fp_environment;
        continue;
      }
      c.clauses.push_back(r);
      if (run) {
        submit({t, c.clauses.size() - 1, id, false, {}});
        ++total;
      }
    }
  }

  while (pool.pending() > 0) {
    auto [id, out] = pool.wait_any();
    const Job job = jobs[id];
    Certificate& c = certs[job.target];
    ClauseResult& slot = c.clauses[job.slot];
    ClauseResult r;
    json environment;
    if (out.kind == ChildOutcome::Kind::finished) {
      // The result comes from the process the implementation ran in: untrusted input. One that
      // does not parse, or is not the result of the clause asked for, is a fault of the child.
      try {
        std::tie(r, environment) = result_from_child(out.result, job.clause);
      } catch (const std::exception& e) {
        out.kind = ChildOutcome::Kind::crashed;
        std::string why = std::string(e.what()).substr(0, 300);
        for (char& ch : why)  // the parser quotes what it read: keep the note plain ASCII
          if (static_cast<unsigned char>(ch) < 0x20 || static_cast<unsigned char>(ch) >= 0x7F) ch = '?';
        out.message = "handed over a malformed result (" + why + ")";
      }
    }
    if (out.kind == ChildOutcome::Kind::finished) {
      if (c.fp_environment.is_null()) c.fp_environment = std::move(environment);
      if (job.pinpoint) {
        // The crash or hang did not come back one case at a time: report the first run's.
        r = slot;
        r.note += "; run again one case at a time, it did not recur (the fault depends on the batch)";
      }
      slot = std::move(r);
      if (options.journal) options.journal->record(table_key(targets[job.target]), slot, environment);
    } else {
      const bool timeout = out.kind == ChildOutcome::Kind::timed_out;
      const ChildOutcome& first = job.pinpoint ? job.first : out;
      r = slot;
      r.outcome = timeout || first.kind == ChildOutcome::Kind::timed_out ? Outcome::timeout : Outcome::crash;
      // Sanitizer builds run children without the limit (ChildPool::start): say so only where it applied.
      r.note = first.message + (r.outcome == Outcome::crash && pool.limits().memory_mb && !built_with_sanitizer()
                                    ? " (the process ran with an address-space limit of " +
                                          std::to_string(pool.limits().memory_mb) + " MiB)"
                                    : "");
      r.worst_error = NAN;
      // The crash site from the child's last progress frame, as fields (never parsed out of its text).
      const WorkingOn w = working_on_from_progress(out.last_progress);
      r.worst_op = w.op;
      r.worst_label = w.label;
      r.worst_input = w.input.empty() ? w.text : w.input;
      r.worst_detail = (timeout ? "hung while working on: " : "crashed while working on: ") + w.text;
      slot = r;
      if (!job.pinpoint) {
        // Run the clause again one case at a time, so the report names the input.
        Job again = job;
        again.pinpoint = true;
        again.first = out;
        submit(again);
        ++total;
      } else if (options.journal) {
        options.journal->record(table_key(targets[job.target]), slot, json::object());
      }
    }
    ++done;
    show_progress(options, done, total, c.table.name + " " + c.table.scalar + " " + job.clause);
  }
  return certs;
}

std::string table_key(const Target& t) {
  std::string key = t.info.name + "/" + t.info.scalar;
  if (!t.plugin_path.empty()) key += "@" + t.plugin_path + "#" + std::to_string(t.plugin_index);
  return key;
}

json run_identity(const spec::Spec& spec, const std::vector<Target>& targets, const CertifyOptions& o) {
  json tables = json::array();
  for (const Target& t : targets)
    tables.push_back({{"key", table_key(t)}, {"version", t.info.version}, {"clauses", t.clauses}});
  return {{"rotorcert_version", ROTORCERT_VERSION},
          {"spec_version", spec.version},
          {"seed", o.cases.seed},
          {"cases_per_family", o.cases.cases_per_family},
          {"search_budget", o.cases.search_budget},
          {"levels", o.levels},
          {"clauses", o.clauses},
          {"run_unclaimed", o.run_unclaimed},
          {"detect_conventions", o.detect_conventions},
          {"tables", tables}};
}

json options_json(const CertifyOptions& o) {
  return {{"seed", o.cases.seed},
          {"cases_per_family", o.cases.cases_per_family},
          {"search_budget", o.cases.search_budget},
          {"levels", o.levels},
          {"clauses", o.clauses},
          {"timeout_s", o.limits.timeout_s},
          {"memory_mb", o.limits.memory_mb},
          {"isolation", "one child process per clause"}};
}

}  // namespace rotorcert::certify
