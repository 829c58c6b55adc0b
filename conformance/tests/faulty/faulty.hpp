// A correct binary64 implementation of NORM-1 and SLERP-1/3/4 built on the mutants' toolkit;
// each faulty plugin derives from it and breaks in one way the certify tool must survive
// (a fault of the process, not a wrong number): segfault, hang, runaway allocation.
#pragma once

#include "mutant.hpp"

namespace faulty {
using namespace mutant;

inline constexpr const char* const kClaims[] = {"NORM-1", "SLERP-1", "SLERP-3", "SLERP-4", "EDGE-6", "EDGE-8", nullptr};

struct Correct {
  using Scalar = double;
  static constexpr const char* version = "0";
  static constexpr std::uint32_t levels = 0;
  static constexpr const char* const* clauses = kClaims;

  static Status normalize(const Q<double>& q, Q<double>& out) {
    if (!valid(q)) return Status::domain_error;
    out = normalized(q);
    return Status::ok;
  }
  static Status slerp(const Q<double>& a, const Q<double>& b, const double& t, Q<double>& out) {
    if (!valid(a) || !valid(b) || !std::isfinite(t)) return Status::domain_error;
    out = slerp_unit(normalized(a), normalized(b), t, dot(a, b) < 0);
    return Status::ok;
  }
};

}  // namespace faulty
