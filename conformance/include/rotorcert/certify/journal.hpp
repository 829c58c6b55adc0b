// The certification journal (RESULT-4): OUT/certify-journal.jsonl, kept while `certify` or
// `report` runs, so an interrupted run loses nothing it finished and `--resume` goes on from there.
//
// Layout, one JSON object per line (JSON Lines), each line written whole and flushed to disk
// before the next clause is counted as done:
//   line 1   {"rotorcert_journal": 1, "run": {...}}  the identity of the run: tool and spec version,
//            the options that decide results (seed, cases, search budget, levels, clauses) and the
//            tables (name, scalar, version, plugin path). --resume continues only the same run.
//   then     {"table": KEY, "clause": ID, "result": {...}, "fp_environment": {...}} per finished
//            clause (KEY: TableKey()), in the order they finished; "result" is the child's wire form
//            (wire.hpp) or, for CRASH and TIMEOUT, the tool's own.
// A line cut short by a kill -9 is ignored. The journal is removed once the complete report is
// written.
#pragma once

#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <string>
#include <utility>

#include <nlohmann/json.hpp>

#include <rotorcert/engine/runner.hpp>

namespace rotorcert::certify {

using json = nlohmann::json;

class Journal {
 public:
  struct Entry {
    engine::ClauseResult result;
    json fp_environment;
  };

  /// The journal of OUT (its file: OUT/certify-journal.jsonl).
  static std::filesystem::path file_in(const std::filesystem::path& out_dir);

  /// Opens `file` for the run `identity`. resume = false: starts a new journal (an old one is
  /// replaced). resume = true: keeps the entries of the journal there, which must exist and be of
  /// the same run; throws std::runtime_error saying why not.
  Journal(std::filesystem::path file, json identity, bool resume);

  /// The recorded result of `clause` of table `table_key`, if the journal has one; counted as taken.
  const Entry* take(const std::string& table_key, const std::string& clause);

  /// Appends a finished clause and flushes it to disk.
  void record(const std::string& table_key, const engine::ClauseResult& result, const json& fp_environment);

  /// Entries read from the interrupted run, and how many of them take() has handed out.
  std::size_t resumable() const { return entries_.size(); }
  std::size_t taken() const { return taken_; }
  const std::filesystem::path& file() const { return file_; }

  /// Deletes the journal (the run is complete and its report written).
  void remove();

 private:
  std::filesystem::path file_;
  int fd_ = -1;
  std::size_t taken_ = 0;
  std::map<std::pair<std::string, std::string>, Entry> entries_;  // resumed: (table, clause) -> entry

 public:
  ~Journal();
  Journal(const Journal&) = delete;
  Journal& operator=(const Journal&) = delete;
};

}  // namespace rotorcert::certify
