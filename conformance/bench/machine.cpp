#include "machine.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>

namespace rotorcert::bench {

std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  for (std::string line; std::getline(in, line);)
    if (line.starts_with("model name")) {
      const std::size_t colon = line.find(':');
      if (colon != std::string::npos && colon + 2 <= line.size()) return line.substr(colon + 2);
    }
  return "unknown";
}

std::size_t last_level_cache_bytes() {
  std::size_t best = 0;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator("/sys/devices/system/cpu/cpu0/cache", ec)) {
    if (!entry.path().filename().string().starts_with("index")) continue;
    std::ifstream in(entry.path() / "size");
    std::size_t value = 0;
    std::string unit;
    if (!(in >> value)) continue;
    in >> unit;  // "107520K": sysfs writes K (KiB), sometimes M
    if (unit.starts_with('K')) value <<= 10;
    else if (unit.starts_with('M')) value <<= 20;
    best = std::max(best, value);
  }
  return best;
}

std::size_t default_stream_bytes() { return std::max<std::size_t>(2 * last_level_cache_bytes(), std::size_t{64} << 20); }

}  // namespace rotorcert::bench
