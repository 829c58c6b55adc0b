// Finding implementations: the built-in ones linked into the tool, and plugins loaded with
// dlopen through the same ABI.
#pragma once

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "impl_abi.h"

namespace rotorcert::impl {

/// Every table of every built-in implementation (one per scalar type), in a fixed order.
std::vector<const rc_impl*> builtin_tables();

/// The built-in table with this name and scalar type (RC_SCALAR_*), or nullptr.
const rc_impl* find_builtin(const std::string& name, std::uint32_t scalar);

/// A plugin library held open; its tables stay valid while the Plugin lives.
class Plugin {
 public:
  /// Loads the library and reads every table of its entry point. Throws PluginError with a
  /// message saying what is wrong (no such file, no entry symbol, ABI mismatch, bad table).
  static std::unique_ptr<Plugin> load(const std::string& path);
  ~Plugin();
  Plugin(const Plugin&) = delete;
  Plugin& operator=(const Plugin&) = delete;

  const std::vector<const rc_impl*>& tables() const { return tables_; }
  const std::string& path() const { return path_; }

 private:
  Plugin() = default;
  void* handle_ = nullptr;
  std::string path_;
  std::vector<const rc_impl*> tables_;
};

struct PluginError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Checks a table for internal consistency (names set, scalar type matches the ops pointer,
/// clause list terminated, levels known). Returns an empty string when it is fine.
std::string validate_table(const rc_impl& table);

}  // namespace rotorcert::impl
