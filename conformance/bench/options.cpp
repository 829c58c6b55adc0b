#include "options.hpp"

#include <charconv>
#include <cstdio>
#include <string_view>

namespace rotorcert::bench {
namespace {

bool parse_size(std::string_view s, std::size_t& out) {
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
  return ec == std::errc() && end == s.data() + s.size() && out > 0;
}

bool parse_sizes(std::string_view s, std::vector<std::size_t>& out) {
  out.clear();
  while (!s.empty()) {
    const std::size_t comma = s.find(',');
    std::size_t v = 0;
    if (!parse_size(s.substr(0, comma), v)) return false;
    out.push_back(v);
    s = comma == std::string_view::npos ? std::string_view{} : s.substr(comma + 1);
  }
  return !out.empty();
}

}  // namespace

CommandLine parse_command_line(int argc, char** argv) {
  CommandLine cl;
  Options& o = cl.options;
  cl.args.emplace_back(argc > 0 ? argv[0] : "rotorcert_bench");
  for (int i = 1; i < argc; ++i) {
    const std::string_view a = argv[i];
    if (a == "--quick") {
      o.quick = true;
    } else if (a.starts_with("--sizes=")) {
      if (!parse_sizes(a.substr(8), o.sizes)) cl.error = "bad --sizes (want N[,N...], N > 0): " + std::string(a);
    } else if (a.starts_with("--plugin=")) {
      if (a.size() == 9) cl.error = "bad --plugin (want --plugin=PATH)";
      o.plugins.emplace_back(a.substr(9));
    } else if (a.starts_with("--stream-mib=")) {
      std::size_t mib = 0;
      if (!parse_size(a.substr(13), mib)) cl.error = "bad --stream-mib (want N > 0): " + std::string(a);
      o.stream_bytes = mib << 20;
    } else {
      if (a.starts_with("--benchmark_min_time")) o.min_time_given = true;
      if (a == "--help" || a == "-h") cl.help = true;
      cl.args.emplace_back(a);
    }
  }
  // --quick picks the quick sizes unless --sizes chose others.
  bool sizes_given = false;
  for (int i = 1; i < argc; ++i) sizes_given = sizes_given || std::string_view(argv[i]).starts_with("--sizes=");
  if (o.quick && !sizes_given) o.sizes = kQuickSizes;
  if (!o.min_time_given) {
    o.min_time = o.quick ? kQuickMinTime : kDefaultMinTime;
    char buf[64];
    std::snprintf(buf, sizeof buf, "--benchmark_min_time=%g", o.min_time);
    cl.args.insert(cl.args.begin() + 1, buf);  // first, so that nothing can shadow it
  }
  return cl;
}

std::string usage() {
  char min_times[128];
  std::snprintf(min_times, sizeof min_times, "Default --benchmark_min_time: %g (full run), %g (--quick).\n\n",
                kDefaultMinTime, kQuickMinTime);
  return std::string(
             "rotorcert_bench: every op of every built-in implementation, glm baselines, roofline.\n"
             "Own flags (every other flag goes to Google Benchmark):\n"
             "  --quick           sizes 64 and 4096 and the quick min time\n"
             "  --sizes=N[,N...]  batch sizes (default 1,64,4096,65536; >= 65536 streams from memory)\n"
             "  --stream-mib=N    bytes a streaming benchmark cycles through (default: 2 x last-level\n"
             "                    cache, at least 64 MiB)\n"
             "  --plugin=PATH     also time every table of this C-ABI plugin (op/<op>/<table>/...); repeatable\n") +
         min_times;
}

}  // namespace rotorcert::bench
