// Markup helpers of the report renderings (markup.hpp).
#include "markup.hpp"

#include <algorithm>
#include <cstdio>

namespace rotorcert::report::detail {

std::string esc(const std::string& text) {
  std::string s;
  s.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&': s += "&amp;"; break;
      case '<': s += "&lt;"; break;
      case '>': s += "&gt;"; break;
      case '"': s += "&quot;"; break;
      case '\'': s += "&#39;"; break;
      default: s += c;
    }
  }
  return s;
}

std::string px(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f", v);
  return buf;
}

std::string cell(const std::string& text) {
  std::string s;
  for (char c : text) {
    if (c == '|') s += "\\|";
    else if (c == '<') s += "\\<";
    else if (c == '\n') s += "<br>";
    else if (c != '\r') s += c;
  }
  return s;
}

std::string code(const std::string& text) {
  if (text.empty()) return "";
  std::size_t run = 0, longest = 0;
  for (char c : text) {
    run = c == '`' ? run + 1 : 0;
    longest = std::max(longest, run);
  }
  const std::string fence(longest + 1, '`');
  const bool pad = text.front() == '`' || text.back() == '`';
  std::string body;
  for (char c : text) {
    if (c == '|') body += "\\|";
    else if (c == '\n') body += ' ';
    else if (c != '\r') body += c;
  }
  return fence + (pad ? " " : "") + body + (pad ? " " : "") + fence;
}

void row(std::ostream& out, const std::vector<std::string>& cells) {
  out << "|";
  for (const std::string& c : cells) out << " " << c << " |";
  out << "\n";
}

void header(std::ostream& out, const std::vector<std::string>& cells) {
  row(out, cells);
  out << "|";
  for (std::size_t i = 0; i < cells.size(); ++i) out << "---|";
  out << "\n";
}

}  // namespace rotorcert::report::detail
