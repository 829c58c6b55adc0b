// Verdicts (TOL-1). The tolerance classes themselves are data: spec/clauses.json,
// "tolerance_classes", loaded by the suite (conformance/); here only the rule that turns a
// measured error and a class's two bars into a verdict.
#pragma once

#include <cmath>
#include <string>

namespace rotorcert::ref {

enum class Verdict { pass, quality_warning, fail };

inline const char* to_string(Verdict v) {
  switch (v) {
    case Verdict::pass: return "PASS";
    case Verdict::quality_warning: return "QUALITY_WARNING";
    case Verdict::fail: return "FAIL";
  }
  return "FAIL";
}

/// Two bars in the same unit as the error (eps units for eps classes, absolute otherwise).
struct Bars {
  double strict = 0;
  double loose = 0;
};

namespace clause {

/// TOL-1: err <= strict -> PASS; err <= loose -> QUALITY_WARNING; otherwise, and for a NaN
/// error, FAIL. Written with <= on purpose: an error of exactly 0 passes the exact classes.
inline Verdict TOL_1_verdict(double err, const Bars& bars) {
  if (std::isnan(err)) return Verdict::fail;
  if (err <= bars.strict) return Verdict::pass;
  if (err <= bars.loose) return Verdict::quality_warning;
  return Verdict::fail;
}

/// TOL-1: the worst case over the inputs decides (FAIL > QUALITY_WARNING > PASS).
inline Verdict TOL_1_worst(Verdict a, Verdict b) { return static_cast<int>(a) >= static_cast<int>(b) ? a : b; }

}  // namespace clause
}  // namespace rotorcert::ref
