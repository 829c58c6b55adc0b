#include <rotorcert/certify/print.hpp>

#include <cmath>
#include <iomanip>
#include <sstream>

#include <rotorcert/certify/verdict.hpp>

namespace rotorcert::certify {

void print_certificate(std::ostream& out, const Certificate& c, bool verbose) {
  using engine::Outcome;
  out << c.table.name << " (" << c.table.scalar << ", " << c.table.source << "): " << claim(c) << '\n';
  if (!c.error.empty()) out << "  error: " << c.error << '\n';
  if (const json& env = c.fp_environment; env.is_object() &&
      (env.at("flush_to_zero").get<bool>() || env.at("denormals_are_zero").get<bool>()))
    out << "  floating-point environment after loading the implementation: flush-to-zero "
        << (env.at("flush_to_zero").get<bool>() ? "ON" : "off") << ", denormals-are-zero "
        << (env.at("denormals_are_zero").get<bool>() ? "ON" : "off") << " (MXCSR " << env.at("mxcsr").get<std::string>()
        << "); it was tested so (NUM-1)\n";
  for (const engine::ClauseResult& r : c.clauses) {
    const bool expected = expected_failure(c, r.clause) != nullptr;
    if (!verbose && r.outcome == Outcome::pass) continue;
    if (!verbose && r.outcome == Outcome::not_supported && !claimed(c, r.clause)) continue;
    const bool has_worst = r.has_worst();
    out << "  " << std::left << std::setw(11) << r.clause << std::setw(16) << engine::to_string(r.outcome);
    if (has_worst) {
      std::ostringstream err;
      if (!std::isfinite(r.worst_error)) err << "NaN/status";
      else err << std::setprecision(3) << r.worst_error << " eps";
      out << std::setw(14) << err.str() << r.worst_op << " [" << r.worst_label << "]";
    }
    if (expected) out << "  (known defect)";
    out << '\n';
    if (!r.note.empty()) out << "      " << r.note << '\n';
    const bool shown = r.outcome != Outcome::pass && r.outcome != Outcome::not_supported;
    if (shown && has_worst) {
      out << "      input:  " << r.worst_input << '\n';
      if (verbose || !expected) out << "      detail: " << r.worst_detail << '\n';
    }
    if (!r.conventions.empty()) {
      out << "      consistent with convention:";
      for (const std::string& cv : r.conventions) out << ' ' << cv;
      out << '\n';
    }
    if (const auto rp = c.reproduce.find(r.clause); shown && !expected && rp != c.reproduce.end() && !rp->second.empty())
      out << "      reproduce: " << rp->second << '\n';
  }
  out << "  levels:";
  for (const LevelResult& l : level_results(c)) out << "  " << l.level << ": " << to_string(l.status);
  out << '\n';
}

}  // namespace rotorcert::certify
