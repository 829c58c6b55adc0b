#include <rotorcert/certify/journal.hpp>

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <sstream>
#include <stdexcept>

#include <rotorcert/certify/wire.hpp>

namespace rotorcert::certify {
namespace {

constexpr int kJournalFormat = 1;

/// The first key of the identity where `a` and `b` differ ("options.seed"), for the message.
std::string first_difference(const json& a, const json& b, const std::string& at = "") {
  if (a.is_object() && b.is_object()) {
    for (const auto& [k, v] : a.items()) {
      const std::string here = at.empty() ? k : at + "." + k;
      if (!b.contains(k)) return here;
      if (v != b.at(k)) return first_difference(v, b.at(k), here);
    }
    for (const auto& [k, v] : b.items())
      if (!a.contains(k)) return at.empty() ? k : at + "." + k;
  }
  return at.empty() ? "the run" : at;
}

void write_all(int fd, const std::string& text, const std::filesystem::path& file) {
  const char* p = text.data();
  std::size_t left = text.size();
  while (left > 0) {
    const ssize_t w = ::write(fd, p, left);
    if (w < 0 && errno == EINTR) continue;
    if (w < 0) throw std::runtime_error("cannot write " + file.string() + ": " + std::strerror(errno));
    p += w;
    left -= static_cast<std::size_t>(w);
  }
  if (::fsync(fd) != 0) throw std::runtime_error("cannot flush " + file.string() + ": " + std::strerror(errno));
}

}  // namespace

std::filesystem::path Journal::file_in(const std::filesystem::path& out_dir) { return out_dir / "certify-journal.jsonl"; }

Journal::Journal(std::filesystem::path file, json identity, bool resume) : file_(std::move(file)) {
  const json header = {{"rotorcert_journal", kJournalFormat}, {"run", identity}};
  std::size_t valid_bytes = 0;  // the journal up to its last complete line
  if (resume) {
    std::ifstream in(file_, std::ios::binary);
    if (!in)
      throw std::runtime_error("nothing to resume: no journal " + file_.string() +
                               " (an interrupted certify or report leaves one in its --out directory)");
    std::string line;
    bool first = true;
    std::size_t at = 0;
    while (std::getline(in, line)) {
      const bool complete = !in.eof();  // a last line without its newline was cut short
      if (!complete) break;
      json j;
      try {
        j = json::parse(line);
      } catch (const std::exception& e) {
        throw std::runtime_error(file_.string() + " line " + std::to_string(at + 1) + " is not JSON: " + e.what());
      }
      if (first) {
        if (!j.is_object() || j.value("rotorcert_journal", 0) != kJournalFormat)
          throw std::runtime_error(file_.string() + " is not a rotorcert journal of format " + std::to_string(kJournalFormat));
        if (j.at("run") != identity)
          throw std::runtime_error("the journal " + file_.string() + " belongs to another run (" +
                                   first_difference(j.at("run"), identity) +
                                   " differs); run again with the same options, or without --resume to start over");
        first = false;
      } else {
        try {
          Entry e{clause_result_from_json(j.at("result")), j.at("fp_environment")};
          const std::string table = j.at("table").get<std::string>(), clause = j.at("clause").get<std::string>();
          if (e.result.clause != clause) throw std::runtime_error("the result of another clause");
          entries_[{table, clause}] = std::move(e);
        } catch (const std::exception& e) {
          throw std::runtime_error(file_.string() + " line " + std::to_string(at + 1) + ": " + e.what());
        }
      }
      valid_bytes += line.size() + 1;
      ++at;
    }
    if (first) resume = false;  // empty, or its header was cut short: begin again
  }
  if (resume) {
    fd_ = ::open(file_.c_str(), O_WRONLY | O_CLOEXEC);
    if (fd_ < 0 || ::ftruncate(fd_, static_cast<off_t>(valid_bytes)) != 0 ||
        ::lseek(fd_, 0, SEEK_END) < 0)
      throw std::runtime_error("cannot reopen " + file_.string() + ": " + std::strerror(errno));
    return;
  }
  fd_ = ::open(file_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd_ < 0) throw std::runtime_error("cannot create " + file_.string() + ": " + std::strerror(errno));
  write_all(fd_, header.dump() + "\n", file_);
}

Journal::~Journal() {
  if (fd_ >= 0) ::close(fd_);
}

const Journal::Entry* Journal::take(const std::string& table_key, const std::string& clause) {
  const auto it = entries_.find({table_key, clause});
  if (it == entries_.end()) return nullptr;
  ++taken_;
  return &it->second;
}

void Journal::record(const std::string& table_key, const engine::ClauseResult& result, const json& fp_environment) {
  const json line = {{"table", table_key},
                     {"clause", result.clause},
                     {"result", to_json(result, true)},
                     {"fp_environment", fp_environment.is_null() ? json::object() : fp_environment}};
  write_all(fd_, line.dump() + "\n", file_);
}

void Journal::remove() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  std::error_code ec;
  std::filesystem::remove(file_, ec);
}

}  // namespace rotorcert::certify
