#include <rotorcert/certify/platform.hpp>

#include <sys/utsname.h>

#include <cfenv>
#include <cstdio>
#include <fstream>
#include <string>
#include <thread>


#if defined(__x86_64__) || defined(__i386__)
#include <xmmintrin.h>
#endif

#include <rotorcert/reference/scalar.hpp>

namespace rotorcert::certify {

nlohmann::json fp_environment_json() {
  const char* rounding = "unknown";
  switch (std::fegetround()) {
    case FE_TONEAREST: rounding = "to nearest"; break;
    case FE_TOWARDZERO: rounding = "toward zero"; break;
    case FE_UPWARD: rounding = "upward"; break;
    case FE_DOWNWARD: rounding = "downward"; break;
    default: break;
  }
#if defined(__x86_64__) || defined(__i386__)
  // Control bits only: the sticky exception flags (bits 0-5) depend on what ran before.
  const unsigned csr = _mm_getcsr() & ~0x3fu;
  char hex[16];
  std::snprintf(hex, sizeof hex, "0x%04x", csr);
  return {{"mxcsr", hex},
          {"flush_to_zero", (csr & 0x8000u) != 0},
          {"denormals_are_zero", (csr & 0x0040u) != 0},
          {"rounding", rounding}};
#else
  return {{"mxcsr", nullptr}, {"flush_to_zero", false}, {"denormals_are_zero", false}, {"rounding", rounding}};
#endif
}

nlohmann::json platform_json() {
  utsname u{};
  ::uname(&u);
  std::string cpu = "unknown";
  std::ifstream info("/proc/cpuinfo");
  for (std::string line; std::getline(info, line);)
    if (line.rfind("model name", 0) == 0) {
      cpu = line.substr(line.find(':') + 2);
      break;
    }
#if defined(__clang__)
  const std::string compiler = std::string("clang ") + __clang_version__;
#elif defined(__GNUC__)
  const std::string compiler = std::string("GCC ") + __VERSION__;
#else
  const std::string compiler = "unknown";
#endif
  return {{"os", std::string(u.sysname) + " " + u.release},
          {"machine", u.machine},
          {"cpu", cpu},
          {"cores", std::thread::hardware_concurrency()},
          {"compiler", compiler},
          {"mpfr", mpfr_get_version()},
          {"reference_precision_bits", ref::kReferenceBits},
          {"fp_environment", fp_environment_json()}};
}

}  // namespace rotorcert::certify
