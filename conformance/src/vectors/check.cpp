#include <rotorcert/vectors/check.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include <rotorcert/engine/runner.hpp>
#include <rotorcert/vectors/error.hpp>

namespace rotorcert::vectors {
namespace {

using engine::Real;

bool contains(const std::vector<std::string>& v, const std::string& s) { return std::find(v.begin(), v.end(), s) != v.end(); }

/// The ABI ops a file op needs.
std::vector<std::string> abi_ops_of(const std::string& file_op) {
  if (file_op == kRoundTripOp) return {"log", "exp"};
  return {file_op};
}

/// One result decoded against its vector's output arrays.
engine::Observed decode(const ResultsFile& results, const ResultEntry& e, const VectorFile& f) {
  engine::Observed o;
  o.call_rc = e.call_rc;
  o.status = e.status;
  for (const engine::Array& a : file_outputs(f.clause, f.op)) {
    const std::string p = e.json_path + "/out/" + a.name;
    if (!e.out.contains(a.name)) throw VectorsError(results.file, e.json_path + "/out", "missing output \"" + a.name + "\"");
    const nlohmann::json& values = e.out[a.name];
    if (!values.is_array() || values.size() != static_cast<std::size_t>(a.stride))
      throw VectorsError(results.file, p, "expected an array of " + std::to_string(a.stride) + " values");
    std::vector<Real> got;
    for (std::size_t i = 0; i < values.size(); ++i) {
      Real x;
      std::string why;
      if (!parse_value(values[i], f.format, x, why)) throw VectorsError(results.file, p + "/" + std::to_string(i), why);
      got.push_back(x);
    }
    o.outputs.push_back(std::move(got));
  }
  const auto outs = file_outputs(f.clause, f.op);
  for (const auto& item : e.out.items())
    if (std::none_of(outs.begin(), outs.end(), [&](const engine::Array& a) { return a.name == item.key(); }))
      throw VectorsError(results.file, e.json_path + "/out/" + item.key(), "no output \"" + item.key() + "\" for op " + f.op);
  return o;
}

/// The observations of one file's vectors.
struct Observations {
  const VectorFile* file;
  std::vector<std::pair<const Vector*, engine::Observed>> cases;
};

/// Whether any observation of the file fails, judged as specified or under a convention.
bool fails(const spec::Spec& spec, const Observations& o, ref::Format format, const engine::Convention* convention) {
  const spec::ToleranceClass& tc = spec.lookup(o.file->tolerance);
  for (const auto& [v, got] : o.cases) {
    const engine::CaseVerdict verdict =
        o.file->round_trip() ? engine::judge_round_trip(tc, v->input, engine::Observed{got.call_rc, got.status, {}, {}}, got, format)
                             : engine::judge_case(o.file->abi_op(), tc, v->input, got, format, convention);
    if (verdict.verdict == ref::Verdict::fail) return true;
  }
  return false;
}

/// The conventions that explain a failed clause, by the rule of engine::detect_conventions():
/// every file that fails as specified is one the convention applies to and passes under it, and
/// every other file it applies to still passes. The observations are re-judged, not re-run:
/// an implementation is a function of its inputs.
std::vector<std::string> explaining_conventions(const spec::Spec& spec, const std::vector<Observations>& observed,
                                                ref::Format format) {
  std::vector<bool> failed;
  for (const Observations& o : observed) failed.push_back(fails(spec, o, format, nullptr));
  std::vector<std::string> found;
  for (const engine::Convention& convention : engine::conventions()) {
    bool explains = true, covers = false;
    for (std::size_t i = 0; i < observed.size() && explains; ++i) {
      const Observations& o = observed[i];
      if (o.file->round_trip() || !convention.applies(o.file->abi_op())) {
        explains = !failed[i];  // the round trip of EXP-2 is convention-free
        continue;
      }
      if (fails(spec, o, format, &convention)) explains = false;
      else covers = covers || failed[i];
    }
    if (explains && covers) found.push_back(convention.id);
  }
  return found;
}

}  // namespace

Grading grade(const spec::Spec& spec, const VectorSet& set, const ResultsFile& results) {
  const ref::Format format = results.format();
  Grading g;

  // Every vector of the set by id; every result by id.
  std::map<std::string, std::pair<const VectorFile*, const Vector*>> vectors;
  for (const VectorFile& f : set.files)
    if (f.format == format)
      for (const Vector& v : f.tests) vectors[v.id] = {&f, &v};
  std::map<std::string, const ResultEntry*> by_id;
  std::set<std::string> ops_with_results;
  for (const ResultEntry& e : results.results) {
    const auto it = vectors.find(e.id);
    if (it == vectors.end()) {
      const char* other = format == ref::Format::binary32 ? "/binary64/" : "/binary32/";
      throw VectorsError(results.file, e.json_path + "/id",
                         e.id.find(other) != std::string::npos
                             ? "\"" + e.id + "\" is a vector of the other format; the implementation's scalar is " + results.scalar
                             : "no vector \"" + e.id + "\" in " + set.index.string());
    }
    if (!by_id.emplace(e.id, &e).second) throw VectorsError(results.file, e.json_path + "/id", "a second result for \"" + e.id + "\"");
    const std::string& op = it->second.first->op;
    for (const std::string& abi : abi_ops_of(op))
      if (contains(results.unsupported_ops, abi))
        throw VectorsError(results.file, e.json_path + "/id", "a result for op " + abi + ", which unsupported_ops declares NOT_SUPPORTED");
    ops_with_results.insert(op);
  }
  for (std::size_t i = 0; i < results.unsupported_ops.size(); ++i)
    if (engine::find_abi_op(results.unsupported_ops[i]) == nullptr)
      throw VectorsError(results.file, "/unsupported_ops/" + std::to_string(i), "no ABI op \"" + results.unsupported_ops[i] + "\"");
  auto supported = [&](const std::string& file_op) {
    if (!ops_with_results.count(file_op)) return false;
    for (const std::string& abi : abi_ops_of(file_op))
      if (contains(results.unsupported_ops, abi)) return false;
    return true;
  };

  const engine::Declarations declared{{results.preconditions.begin(), results.preconditions.end()},
                                      {results.conventions.begin(), results.conventions.end()}};
  if (const std::string problem = engine::declaration_problem(declared, supported); !problem.empty())
    throw VectorsError(results.file, "/implementation", "DECL-1: " + problem);
  std::vector<std::string> graded;  // clauses with at least one result judged
  std::vector<engine::ClauseResult> all;
  for (const spec::Clause& cl : spec.clauses) {
    if (cl.level == "Meta") continue;
    engine::ClauseResult r;
    r.clause = cl.id;
    r.level = cl.level;
    r.tolerance = cl.tolerance;
    if (cl.id == "HYG-1" && contains(results.hygiene, cl.id)) {
      // HYG-1 from the results themselves: the writer compared every call's inputs before and
      // after it (the rotorcert-vectors packages' watch) and says what a call modified.
      engine::ClauseJudge judge{r};
      for (const VectorFile& f : set.files) {
        if (f.format != format || !supported(f.op)) continue;
        for (const Vector& v : f.tests) {
          const auto it = by_id.find(v.id);
          if (it == by_id.end()) continue;
          const std::string& modified = it->second->modified_inputs;
          judge.record(modified.empty() ? engine::CaseVerdict{ref::Verdict::pass, 0, "inputs unchanged"}
                                        : engine::CaseVerdict{ref::Verdict::fail, NAN, f.op + ": " + modified},
                       f.abi_op(), v.input, format);
        }
      }
      judge.finish();
      if (r.cases > 0) graded.push_back(cl.id);
      all.push_back(std::move(r));
      continue;
    }
    std::vector<const VectorFile*> files;
    for (const VectorFile& f : set.files)
      if (f.clause == cl.id && f.format == format) files.push_back(&f);
    std::vector<const VectorFile*> run;
    for (const VectorFile* f : files)
      if (supported(f->op)) run.push_back(f);
    if (files.empty()) {
      r.note = "the vectors (" + set.index.string() + ") hold no test of this clause";
    } else if (run.empty()) {
      r.note = "no result for any operation of this clause";
    } else {
      engine::ClauseJudge judge{r};
      std::size_t missing = 0;
      std::string first_missing;
      std::vector<Observations> observed;  // per file, for convention detection
      for (const VectorFile* f : run) {
        observed.push_back({f, {}});
        const spec::ToleranceClass& tc = spec.lookup(f->tolerance);
        const engine::AbiOp& op = f->abi_op();
        // The order certify records cases in: one batch per k, ascending (run_check), so ties
        // of the worst case resolve the same way on both routes.
        std::map<std::size_t, std::vector<const Vector*>> groups;
        for (const Vector& v : f->tests) groups[v.input.k].push_back(&v);
        for (const auto& [k, tests] : groups)
          for (const Vector* v : tests) {
            const auto it = by_id.find(v->id);
            if (it == by_id.end()) {
              if (missing++ == 0) first_missing = v->id;
              judge.record({ref::Verdict::fail, NAN, "no result for vector " + v->id}, op, v->input, format);
              continue;
            }
            const engine::Observed got = decode(results, *it->second, *f);
            observed.back().cases.emplace_back(v, got);
            ++g.results;
            if (f->round_trip()) {
              // The results file reports the round trip as one status: OK iff log and exp both were.
              const engine::Observed log_got{got.call_rc, got.status, {}, {}};
              judge.record(engine::judge_round_trip(tc, v->input, log_got, got, format), op, v->input, format);
            } else {
              judge.record(engine::judge_case(op, tc, v->input, got, format, nullptr, &declared), op, v->input, format);
            }
          }
      }
      judge.finish();
      if (r.outcome == engine::Outcome::fail && missing == 0) r.conventions = explaining_conventions(spec, observed, format);
      if (missing > 0)
        r.note = std::to_string(missing) + " vector" + (missing == 1 ? "" : "s") + " without a result (first: " + first_missing + ")";
      if (missing < r.cases) graded.push_back(cl.id);
    }
    all.push_back(std::move(r));
  }

  certify::TableInfo& t = g.certificate.table;
  t.name = results.name;
  t.scalar = results.scalar;
  t.version = results.version;
  t.description = results.description;
  t.source = "results file";
  t.plugin_path = results.file.string();
  t.declared_preconditions = results.preconditions;
  t.declared_conventions = results.conventions;
  t.claimed_clauses = results.claimed_clauses ? *results.claimed_clauses : graded;
  for (const std::string& op : ops_with_results)
    for (const std::string& abi : abi_ops_of(op))
      if (!contains(t.supported_ops, abi)) t.supported_ops.push_back(abi);
  std::sort(t.supported_ops.begin(), t.supported_ops.end(), [](const std::string& a, const std::string& b) {
    return engine::find_abi_op(a) < engine::find_abi_op(b);  // ABI order: abi_ops() is one vector
  });
  if (results.claimed_levels) {
    t.claimed_levels = *results.claimed_levels;
  } else {
    for (const std::string& level : spec.levels)
      for (const std::string& id : t.claimed_clauses)
        if (const spec::Clause* cl = spec.find_clause(id); cl && cl->level == level && !contains(t.claimed_levels, level))
          t.claimed_levels.push_back(level);
  }
  for (std::size_t i = 0; i < t.claimed_clauses.size(); ++i)
    if (spec.find_clause(t.claimed_clauses[i]) == nullptr)
      throw VectorsError(results.file, "/implementation/claimed_clauses/" + std::to_string(i),
                         "\"" + t.claimed_clauses[i] + "\" is not a clause of spec " + spec.version);
  // Meta clauses bind the suite, not implementations: a claim of one is not scored. Hygiene
  // clauses (section 9a) need the library's own calls, which a results file cannot show, except
  // HYG-1 where the writer checked it on every call (implementation.hygiene).
  std::erase_if(t.claimed_clauses, [&](const std::string& id) {
    const std::string& level = spec.find_clause(id)->level;
    return level == "Meta" || (level == "Hygiene" && !contains(results.hygiene, id));
  });
  std::erase(t.claimed_levels, std::string("Hygiene"));
  for (std::size_t i = 0; i < t.claimed_levels.size(); ++i)
    if (!contains(spec.levels, t.claimed_levels[i]) || t.claimed_levels[i] == "Meta")
      throw VectorsError(results.file, "/implementation/claimed_levels/" + std::to_string(i),
                         "\"" + t.claimed_levels[i] + "\" is not a conformance level");
  g.certificate.levels = t.claimed_levels;
  // The certificate covers every clause of the certified levels, and any claimed clause besides.
  for (engine::ClauseResult& r : all)
    if (contains(g.certificate.levels, r.level) || contains(t.claimed_clauses, r.clause)) {
      g.certificate.reproduce[r.clause] = "rotorcert vectors check " + results.file.string();
      g.certificate.clauses.push_back(std::move(r));
    }
  return g;
}

const engine::ClauseResult* find_clause(const Grading& g, const std::string& clause) {
  for (const engine::ClauseResult& r : g.certificate.clauses)
    if (r.clause == clause) return &r;
  return nullptr;
}

}  // namespace rotorcert::vectors
