#include <rotorcert/thirdparty/adapter.hpp>

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <thread>

#include <rotorcert/certify/certificate.hpp>

extern char** environ;

namespace rotorcert::thirdparty {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

json read_json(const fs::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error(file.string() + ": cannot be read");
  try {
    return json::parse(in);
  } catch (const json::exception& e) {
    throw std::runtime_error(file.string() + ": not JSON: " + e.what());
  }
}

std::string text_field(const json& j, const fs::path& file, const char* key) {
  if (!j.contains(key) || !j.at(key).is_string() || j.at(key).get<std::string>().empty())
    throw std::runtime_error(file.string() + ": /" + key + " must be a non-empty string");
  return j.at(key);
}

}  // namespace

std::vector<Manifest> load_manifests(const fs::path& adapters_dir) {
  std::vector<Manifest> all;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(adapters_dir, ec)) {
    const fs::path file = entry.path() / "adapter.json";
    if (!entry.is_directory() || !fs::exists(file)) continue;
    const json j = read_json(file);
    if (j.value("format", "") != "rotorcert-adapter" || j.value("format_version", 0) != 1)
      throw std::runtime_error(file.string() + ": not a rotorcert-adapter manifest of format version 1");
    Manifest m;
    m.dir = entry.path();
    m.raw = j;
    m.name = text_field(j, file, "name");
    if (m.name != entry.path().filename().string())
      throw std::runtime_error(file.string() + ": /name '" + m.name + "' is not the directory's name");
    m.library = text_field(j, file, "library");
    m.route = text_field(j, file, "route");
    m.language = text_field(j, file, "language");
    if (!j.contains("scalars") || !j.at("scalars").is_array() || j.at("scalars").empty())
      throw std::runtime_error(file.string() + ": /scalars must list float and/or double");
    for (const json& s : j.at("scalars")) {
      if (s != "float" && s != "double") throw std::runtime_error(file.string() + ": /scalars: " + s.dump() + " is not float or double");
      m.scalars.push_back(s);
    }
    if (m.route == "abi") {
      const json& e = j.value("entry", json::object());
      if (e.is_object() && e.contains("builtin")) m.builtin = e.at("builtin");
      if (e.is_object() && e.contains("plugin")) m.plugin = e.at("plugin");
      if (m.builtin.empty() == m.plugin.empty())
        throw std::runtime_error(file.string() + ": /entry of route abi needs exactly one of builtin and plugin");
      if (m.language == "rust" && m.plugin.empty())
        throw std::runtime_error(file.string() + ": /entry of a Rust adapter is {\"plugin\": STEM} (its Cargo crate builds STEM.so)");
    } else if (m.route == "vectors") {
      text_field(j, file, "entry");
      if (m.scalars.size() != 1) throw std::runtime_error(file.string() + ": a vectors adapter answers one number format");
    } else {
      throw std::runtime_error(file.string() + ": /route must be abi or vectors, not '" + m.route + "'");
    }
    all.push_back(std::move(m));
  }
  if (ec) throw std::runtime_error(adapters_dir.string() + ": " + ec.message());
  std::sort(all.begin(), all.end(), [](const Manifest& a, const Manifest& b) { return a.name < b.name; });
  return all;
}

Environment read_environment(const fs::path& env_dir, const std::string& name) {
  Environment env;
  const fs::path file = env_dir / name / "status.json";
  if (!fs::exists(file)) {
    env.reason = "not installed: scripts/setup-adapters has not run for it (" + file.string() + " is missing)";
    return env;
  }
  try {
    const json j = read_json(file);
    env.installed = j.value("installed", false);
    env.reason = j.value("reason", json()).is_string() ? j.at("reason").get<std::string>() : "";
    if (env.installed && j.contains("plugin") && j.at("plugin").is_string()) {
      // A plugin the environment built (a Rust adapter): the file must still be there.
      env.plugin = j.at("plugin").get<std::string>();
      if (env.plugin.empty() || !fs::exists(env.plugin)) {
        env.installed = false;
        env.reason = "the plugin recorded in " + file.string() + " (" + env.plugin.string() +
                     ") is gone (run scripts/setup-adapters)";
      }
    } else if (env.installed) {
      env.command = j.at("command").get<std::vector<std::string>>();
      const json vars = j.value("env", json::object());  // named: items() must not outlive it
      for (const auto& [k, v] : vars.items()) env.env.emplace_back(k, v.get<std::string>());
      // A path must still exist (a deleted venv); a bare name is looked up on PATH when run.
      if (env.command.empty() ||
          (env.command.front().find('/') != std::string::npos && !fs::exists(env.command.front()))) {
        env.installed = false;
        env.reason = "the environment recorded in " + file.string() + " is gone (run scripts/setup-adapters)";
      }
    }
  } catch (const std::exception& e) {
    env = Environment{};
    env.reason = std::string("unreadable ") + file.string() + ": " + e.what() + " (run scripts/setup-adapters)";
  }
  return env;
}

std::map<std::string, std::string> adapter_expected_failures(const Manifest& m, const std::string& scalar) {
  return certify::read_expected_failures(m.dir / "expected_failures.json", m.name, scalar);
}

ProgramRun run_program(const std::vector<std::string>& argv, const std::vector<std::pair<std::string, std::string>>& extra_env,
                       const fs::path& log, double timeout_s) {
  ProgramRun r;
  std::vector<std::string> env_text;
  for (char** e = environ; *e != nullptr; ++e) {
    const std::string kv = *e;
    const bool replaced = std::any_of(extra_env.begin(), extra_env.end(),
                                      [&](const auto& p) { return kv.rfind(p.first + "=", 0) == 0; });
    if (!replaced) env_text.push_back(kv);
  }
  for (const auto& [k, v] : extra_env) env_text.push_back(k + "=" + v);
  std::vector<char*> envp, args;
  for (std::string& s : env_text) envp.push_back(s.data());
  envp.push_back(nullptr);
  std::vector<std::string> argv_copy = argv;
  for (std::string& s : argv_copy) args.push_back(s.data());
  args.push_back(nullptr);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  posix_spawnattr_t attr;
  posix_spawnattr_init(&attr);
  posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETPGROUP);  // its own group: a timeout kills its children too
  posix_spawnattr_setpgroup(&attr, 0);
  pid_t pid = 0;
  const auto started = std::chrono::steady_clock::now();
  const int spawned = posix_spawnp(&pid, args[0], &actions, &attr, args.data(), envp.data());
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attr);
  if (spawned != 0) {
    r.error = "cannot start " + argv.front() + ": " + std::strerror(spawned);
    return r;
  }
  r.started = true;
  int status = 0;
  for (;;) {
    const pid_t w = waitpid(pid, &status, WNOHANG);
    if (w == pid) break;
    if (w < 0 && errno != EINTR) break;
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    if (elapsed > timeout_s) {
      r.timed_out = true;
      kill(-pid, SIGKILL);
      while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
      }
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

}  // namespace rotorcert::thirdparty
