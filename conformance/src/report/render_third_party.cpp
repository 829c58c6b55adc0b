// sections.third_party in HTML and Markdown (sections.hpp). Like every renderer here it never throws
// on a section with missing fields: reads go through str / arr / obj_at or check the type.
#include "sections.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "common.hpp"
#include "markup.hpp"

namespace rotorcert::report::detail {

namespace {
/// The library's tracker on a listed defect: "reported" with its threads, "not found" (searched,
/// none), "declined" (maintainers call it intended); "not searched" when the entry has no
/// "upstream". Threads as text, not links: the report links nothing outside itself.
std::string upstream_text(const json& defect) {
  if (!defect.contains("upstream") || !defect["upstream"].is_object()) return "not searched";
  const json& u = defect["upstream"];
  std::string t = str(u, "status");
  std::vector<std::string> refs;
  for (const json& r : arr(u, "refs"))
    if (r.is_string()) refs.push_back(r.get<std::string>());
  if (!refs.empty()) t += ": " + join(refs, ", ");
  if (!str(u, "searched").empty()) t += " (searched " + str(u, "searched") + ")";
  return t;
}

std::string upstream_html(const json& defect) {
  if (!defect.contains("upstream") || !defect["upstream"].is_object()) return "<span class=\"muted\">not searched</span>";
  const json& u = defect["upstream"];
  std::string h = "<strong>" + esc(str(u, "status")) + "</strong>";
  for (const json& r : arr(u, "refs"))
    if (r.is_string()) h += "<div><code>" + esc(r.get<std::string>()) + "</code></div>";
  if (!str(u, "note").empty()) h += "<div class=\"note\">" + esc(str(u, "note")) + "</div>";
  if (!str(u, "searched").empty()) h += "<div class=\"muted\">searched " + esc(str(u, "searched")) + "</div>";
  return h;
}

/// The standalone reproducer of a defect (REPORT-3): its file, language and the command that runs
/// it against the unmodified library.
std::string reproducer_html(const json& defect) {
  if (!defect.contains("reproducer") || !defect["reproducer"].is_object())
    return "<strong class=\"no\">none</strong>";
  const json& r = defect["reproducer"];
  return esc(str(r, "language")) + " <code>" + esc(str(r, "file")) + "</code><div class=\"note\"><code>" +
         esc(str(r, "run")) + "</code></div>";
}
}  // namespace


namespace {

constexpr const char* kTitle = "Third-party libraries (REPORT-3)";

struct Column {
  std::string library, scalar;
  const json* certificate;
};

/// One column per certificate of every certified library, in section order.
std::vector<Column> columns(const json& section) {
  std::vector<Column> cols;
  for (const json& lib : arr(section, "libraries"))
    for (const json& c : arr(lib, "certificates")) cols.push_back({str(lib, "name"), str(c, "scalar"), &c});
  return cols;
}

/// The clauses any certificate ran or claims, in the order they first appear (each certificate
/// lists them in spec order), NOT_SUPPORTED everywhere left out.
std::vector<std::string> matrix_rows(const std::vector<Column>& cols) {
  std::vector<std::string> rows;
  for (const Column& c : cols)
    for (const json& r : arr(*c.certificate, "clauses")) {
      if (str(r, "outcome") == "NOT_SUPPORTED") continue;
      if (std::find(rows.begin(), rows.end(), str(r, "id")) == rows.end()) rows.push_back(str(r, "id"));
    }
  return rows;
}

std::string worst_text(const json& worst) {
  if (!worst.is_object()) return "";
  std::string s = str(worst, "op");
  if (!str(worst, "label").empty()) s += (s.empty() ? "" : ", ") + str(worst, "label");
  return s;
}

std::string package_text(const json& lib) {
  const json& p = obj_at(lib, "package");
  return str(p, "registry") + " " + str(p, "name") + " " + str(p, "version");
}

std::string claims_text(const json& lib) {
  std::vector<std::string> claims;
  for (const json& c : arr(lib, "certificates")) claims.push_back(str(c, "claim"));
  return join(claims, "; ");
}

std::string expected_text(const json& lib) {
  if (str(lib, "status") != "certified") return "\u2014";
  if (lib.contains("against_pin")) return "\u2014 (another version)";
  return str(lib, "as_expected") == "true" ? "yes" : "NO";
}

std::string defects_count(const json& lib) {
  std::size_t known = 0, fresh = 0;
  for (const json& d : arr(lib, "defects")) (str(d, "known") == "true" ? known : fresh) += 1;
  if (str(lib, "status") != "certified") return "\u2014";
  return std::to_string(known + fresh) + (fresh ? " (" + std::to_string(fresh) + " not listed)" : "");
}

/// Whether dotted version a is older than b (numeric fields compared in order; "3.16.0" < "3.17.0").
bool older(const std::string& a, const std::string& b) {
  std::size_t i = 0, j = 0;
  while (i < a.size() || j < b.size()) {
    std::size_t ni = a.find('.', i), nj = b.find('.', j);
    const std::string fa = a.substr(i, ni == std::string::npos ? std::string::npos : ni - i);
    const std::string fb = b.substr(j, nj == std::string::npos ? std::string::npos : nj - j);
    const long va = std::strtol(fa.c_str(), nullptr, 10), vb = std::strtol(fb.c_str(), nullptr, 10);
    if (va != vb) return va < vb;
    i = ni == std::string::npos ? a.size() : ni + 1;
    j = nj == std::string::npos ? b.size() : nj + 1;
  }
  return false;
}

/// Another version than the pin: what changed against the pin's known defects and errors, said
/// in the direction of time (an older release's extra FAIL is a defect the pin fixed).
std::string against_pin_text(const json& lib) {
  if (!lib.contains("against_pin")) return "";
  const json& a = lib["against_pin"];
  const bool before = older(str(lib, "requested_version"), str(lib, "pinned_version"));
  std::vector<std::string> items;
  for (const json& f : arr(a, "fixed"))
    items.push_back((before ? "passes here, FAILs at the pin: " : "fixed since the pin: ") + str(f, "clause") + " " +
                    str(f, "scalar"));
  for (const json& f : arr(a, "appeared"))
    items.push_back((before ? "FAILs here, fixed by the pin: " : "new since the pin: ") + str(f, "clause") + " " +
                    str(f, "scalar"));
  for (const json& m : arr(a, "worst_error_moved"))
    items.push_back(str(m, "clause") + " " + str(m, "scalar") + " worst error " + error_eps_text(m.value("error_eps", json())) +
                    " eps here, " + error_eps_text(m.value("pin_error_eps", json())) + " eps at the pin");
  return "version " + str(lib, "requested_version") + " against the pin " + str(lib, "pinned_version") + ": " +
         (items.empty() ? "the same defects" : join(items, "; "));
}

/// Listed defects a run with fewer cases than they were found with did not reach.
std::string not_reproduced_text(const json& lib) {
  std::vector<std::string> items;
  for (const json& n : arr(lib, "not_reproduced")) items.push_back(str(n, "clause") + " (" + str(n, "scalar") + ")");
  return items.empty() ? "" : "listed defects not reached with this run's cases: " + join(items, ", ");
}

/// "1.05" from a ratio (2 decimals below 10, 1 above).
std::string ratio_text(const json& v) {
  if (!v.is_number()) return "";
  char b[32];
  const double r = v.get<double>();
  std::snprintf(b, sizeof b, r < 10 ? "%.2f" : "%.1f", r);
  return b;
}

/// The speed column: per table the median ratio to the baseline's same ops (section.speed).
std::string speed_text(const json& lib, const std::string& baseline) {
  std::vector<std::string> parts;
  for (const json& t : arr(lib, "speed"))
    if (t.contains("median_ratio"))
      parts.push_back(str(t, "scalar") + ": " + ratio_text(t["median_ratio"]) + "\u00d7 " + baseline + " (median of " +
                      str(t, "ops_compared") + " ops)");
  if (!parts.empty()) return join(parts, "; ");
  return str(lib, "route") == "abi" ? "not timed" : "\u2014 (not native)";
}

}  // namespace

void render_third_party_html(std::ostream& out, const json& section) {
  out << "<section class=\"third-party\" id=\"section-third_party\">\n<h2>" << kTitle << "</h2>\n";
  if (!section.contains("libraries")) {
    out << "<p class=\"muted\">" << esc(str(section, "note")) << "</p>\n</section>\n";
    return;
  }
  out << "<p class=\"muted\">Libraries nobody here wrote, certified through their adapters (<code>"
      << esc(str(section, "adapters_dir")) << "</code>): C-ABI tables in process, other languages through the JSON "
      << "test vectors (seed " << esc(str(section, "seed")) << ", " << esc(str(section, "cases_per_family"))
      << " cases per family). Adapters map conventions and never patch behaviour: every defect below is the "
         "library's. Each library's known defects are listed beside its adapter; <em>as expected</em> means exactly "
         "those FAIL. How to certify your own: <code>conformance/CERTIFY.md</code>.</p>\n<p><strong>"
      << esc(str(section, "certified")) << " certified</strong>, " << esc(str(section, "not_run")) << " not run, "
      << esc(str(section, "errors")) << " failed to run.</p>\n";

  out << "<div class=\"scroll\">\n<table class=\"third-party\">\n<thead><tr><th>Library</th><th>Version</th><th>Package</th>"
         "<th>Route</th><th>Status</th><th>Claim</th><th>Defects</th><th>As expected</th><th>Speed</th><th>Reproduce</th></tr></thead>\n<tbody>\n";
  const json& speed = obj_at(section, "speed");
  const std::string baseline = str(speed, "baseline").empty() ? "GLM" : str(speed, "baseline");
  for (const json& lib : arr(section, "libraries")) {
    const std::string status = str(lib, "status");
    out << "<tr data-library=\"" << esc(str(lib, "name")) << "\" data-status=\"" << esc(status) << "\"><td>";
    // The homepage as text, not a link: the report loads and links nothing outside itself.
    out << "<strong>" << esc(str(lib, "library")) << "</strong>";
    if (!str(lib, "homepage").empty()) out << " <span class=\"muted\">" << esc(str(lib, "homepage")) << "</span>";
    out << "<div class=\"muted\">" << esc(str(lib, "description")) << "</div></td><td>"
        << esc(lib.contains("version") && lib["version"].is_array() ? join(lib["version"], ", ") : str(lib, "version"))
        << "</td><td>" << esc(package_text(lib)) << "</td><td>" << esc(str(lib, "route")) << " (" << esc(str(lib, "language"))
        << ")</td><td>" << esc(status);
    if (!str(lib, "reason").empty()) out << "<div class=\"error\">" << esc(str(lib, "reason")) << "</div>";
    if (!against_pin_text(lib).empty()) out << "<div class=\"against-pin\">" << esc(against_pin_text(lib)) << "</div>";
    else if (!not_reproduced_text(lib).empty()) out << "<div class=\"muted\">" << esc(not_reproduced_text(lib)) << "</div>";
    out << "</td><td>" << esc(claims_text(lib)) << "</td><td>" << esc(defects_count(lib)) << "</td><td class=\""
        << (expected_text(lib) == "NO" ? "no" : "yes") << "\">" << expected_text(lib) << "</td><td>"
        << esc(speed.contains("baseline") ? speed_text(lib, baseline) : "") << "</td><td><code>"
        << esc(str(lib, "reproduce")) << "</code></td></tr>\n";
  }
  out << "</tbody>\n</table>\n</div>\n";
  if (!str(speed, "note").empty()) out << "<p class=\"muted\">Speed: " << esc(str(speed, "note"))
                                      << (str(speed, "cpu").empty() ? "" : "; CPU " + esc(str(speed, "cpu"))) << ".</p>\n";
  bool timed = false;
  for (const json& lib : arr(section, "libraries")) timed = timed || !arr(lib, "speed").empty();
  if (timed) {
    out << "<details><summary>Speed per op of the native libraries (ns per element, ratio to " << esc(baseline)
        << ")</summary>\n<div class=\"scroll\">\n<table class=\"third-party-speed\">\n<thead><tr><th>Library</th><th>Table</th>"
           "<th>Op</th><th>ns / element</th><th>"
        << esc(baseline) << " ns / element</th><th>Ratio</th></tr></thead>\n<tbody>\n";
    for (const json& lib : arr(section, "libraries"))
      for (const json& t : arr(lib, "speed"))
        for (const json& o : arr(t, "ops"))
          out << "<tr data-library=\"" << esc(str(lib, "name")) << "\"><td>" << esc(str(lib, "name")) << "</td><td>"
              << esc(str(t, "table")) << " <span class=\"muted\">" << esc(str(t, "scalar")) << "</span></td><td><code>"
              << esc(str(o, "op")) << "</code></td><td>" << esc(ratio_text(o.value("ns_per_element", json()))) << "</td><td>"
              << esc(ratio_text(o.value("baseline_ns_per_element", json()))) << "</td><td>" << esc(ratio_text(o.value("ratio", json())))
              << "</td></tr>\n";
    out << "</tbody>\n</table>\n</div>\n</details>\n";
  }

  const std::vector<Column> cols = columns(section);
  if (!cols.empty()) {
    out << "<h3>Per clause, per library</h3>\n<p class=\"muted\">Clauses some library supports; the tooltip gives the "
           "worst input. Blank: not supported.</p>\n<div class=\"scroll\">\n<table class=\"third-party-matrix\">\n<thead><tr><th>Clause</th>";
    for (const Column& c : cols) out << "<th>" << esc(c.library) << "<br><span class=\"muted\">" << esc(c.scalar) << "</span></th>";
    out << "</tr></thead>\n<tbody>\n";
    for (const std::string& id : matrix_rows(cols)) {
      out << "<tr><td><code>" << esc(id) << "</code></td>";
      for (const Column& c : cols) {
        const json* r = find_clause(*c.certificate, id);
        const std::string oc = r ? str(*r, "outcome") : "";
        if (oc.empty() || oc == "NOT_SUPPORTED") {
          out << "<td></td>";
          continue;
        }
        const json& worst = r->contains("worst") ? (*r)["worst"] : json();
        out << "<td><span class=\"badge oc-" << esc(oc) << "\" title=\"" << esc(worst_text(worst) + " " + str(worst, "input"))
            << "\">" << esc(outcome_abbrev(oc)) << "</span>" << (str(*r, "expected_failure").empty() ? "" : " <span class=\"muted\">known</span>")
            << "</td>";
      }
      out << "</tr>\n";
    }
    out << "</tbody>\n</table>\n</div>\n";
  }

  out << "<h3>Defects</h3>\n";
  bool any = false;
  for (const json& lib : arr(section, "libraries")) any = any || !arr(lib, "defects").empty();
  if (!any) {
    out << "<p class=\"muted\">None found.</p>\n";
  } else {
    out << "<div class=\"scroll\">\n<table class=\"third-party-defects\">\n<thead><tr><th>Library</th><th>Clause</th><th>Outcome</th>"
           "<th>Worst input (hexfloat)</th><th>Error</th><th>What</th><th>Known defect</th><th>The library's tracker</th><th>Reproducer (the library's own language)</th><th>Reproduce the certificate</th></tr></thead>\n<tbody>\n";
    for (const json& lib : arr(section, "libraries"))
      for (const json& d : arr(lib, "defects")) {
        const json& worst = d.contains("worst") ? d["worst"] : json();
        out << "<tr data-library=\"" << esc(str(lib, "name")) << "\" data-clause=\"" << esc(str(d, "clause")) << "\"><td>"
            << esc(str(lib, "name")) << " <span class=\"muted\">" << esc(str(d, "scalar")) << "</span></td><td><code>"
            << esc(str(d, "clause")) << "</code></td><td><span class=\"badge oc-" << esc(str(d, "outcome")) << "\">"
            << esc(str(d, "outcome")) << "</span></td><td><code>" << esc(str(worst, "input")) << "</code></td><td>"
            << esc(error_eps_text(worst.is_object() && worst.contains("error_eps") ? worst["error_eps"] : json())) << " " << kEps
            << "</td><td>" << esc(worst_text(worst)) << (str(worst, "detail").empty() ? "" : ": " + esc(str(worst, "detail")))
            << "</td><td>" << (str(d, "known") == "true" ? esc(str(d, "why")) : "<strong class=\"no\">not listed</strong>")
            << "</td><td>" << (str(d, "known") == "true" ? upstream_html(d) : "") << "</td><td>" << reproducer_html(d) << "</td><td><code>" << esc(str(d, "reproduce")) << "</code></td></tr>\n";
      }
    out << "</tbody>\n</table>\n</div>\n";
  }

  out << "<h3>Conventions each adapter maps</h3>\n";
  for (const json& lib : arr(section, "libraries")) {
    out << "<details><summary>" << esc(str(lib, "library")) << " <span class=\"muted\">(<code>" << esc(str(lib, "adapter"))
        << "</code>)</span></summary>\n<ul>\n";
    for (const json& c : arr(lib, "conventions")) out << "<li>" << esc(c.is_string() ? c.get<std::string>() : dump(c)) << "</li>\n";
    out << "</ul>\n<table>\n<thead><tr><th>ABI op</th><th>Library call</th></tr></thead>\n<tbody>\n";
    for (const auto& [op, call] : obj_at(lib, "ops").items())
      out << "<tr><td><code>" << esc(op) << "</code></td><td>" << esc(call.is_string() ? call.get<std::string>() : dump(call)) << "</td></tr>\n";
    for (const auto& [op, why] : obj_at(lib, "unsupported").items())
      out << "<tr><td><code>" << esc(op) << "</code></td><td class=\"muted\">not supported: "
          << esc(why.is_string() ? why.get<std::string>() : dump(why)) << "</td></tr>\n";
    out << "</tbody>\n</table>\n</details>\n";
  }
  out << "</section>\n";
}

void render_third_party_markdown(std::ostream& out, const json& section) {
  out << "## " << kTitle << "\n\n";
  if (!section.contains("libraries")) {
    out << cell(str(section, "note")) << "\n\n";
    return;
  }
  out << "Adapters in `" << str(section, "adapters_dir") << "`; vectors of seed " << str(section, "seed") << ", "
      << str(section, "cases_per_family") << " cases per family. " << str(section, "certified") << " certified, "
      << str(section, "not_run") << " not run, " << str(section, "errors")
      << " failed to run. Guide: `conformance/CERTIFY.md`.\n\n";
  const json& speed = obj_at(section, "speed");
  const std::string baseline = str(speed, "baseline").empty() ? "GLM" : str(speed, "baseline");
  header(out, {"library", "version", "package", "route", "status", "claim", "defects", "as expected", "speed", "reproduce"});
  for (const json& lib : arr(section, "libraries")) {
    std::string status = str(lib, "status") + (str(lib, "reason").empty() ? "" : ": " + str(lib, "reason"));
    if (!against_pin_text(lib).empty()) status += "; " + against_pin_text(lib);
    else if (!not_reproduced_text(lib).empty()) status += "; " + not_reproduced_text(lib);
    row(out, {cell(str(lib, "library")),
              cell(lib.contains("version") && lib["version"].is_array() ? join(lib["version"], ", ") : str(lib, "version")),
              cell(package_text(lib)), cell(str(lib, "route")), cell(status), cell(claims_text(lib)), cell(defects_count(lib)),
              expected_text(lib), cell(speed.contains("baseline") ? speed_text(lib, baseline) : ""), code(str(lib, "reproduce"))});
  }
  out << '\n';
  if (!str(speed, "note").empty())
    out << "Speed: " << cell(str(speed, "note")) << (str(speed, "cpu").empty() ? "" : "; CPU " + cell(str(speed, "cpu"))) << ".\n\n";
  const std::vector<Column> cols = columns(section);
  if (!cols.empty()) {
    out << "### Per clause, per library\n\n";
    std::vector<std::string> head = {"clause"};
    for (const Column& c : cols) head.push_back(cell(c.library + " " + c.scalar));
    header(out, head);
    for (const std::string& id : matrix_rows(cols)) {
      std::vector<std::string> cells = {code(id)};
      for (const Column& c : cols) {
        const json* r = find_clause(*c.certificate, id);
        const std::string oc = r ? str(*r, "outcome") : "";
        cells.push_back(oc.empty() || oc == "NOT_SUPPORTED" ? "" : outcome_abbrev(oc));
      }
      row(out, cells);
    }
    out << '\n';
  }
  out << "### Defects\n\n";
  bool any = false;
  for (const json& lib : arr(section, "libraries"))
    for (const json& d : arr(lib, "defects")) {
      if (!any)
        header(out, {"library", "clause", "outcome", "worst input", "error (eps)", "what", "known defect",
                     "the library's tracker", "reproducer", "reproduce the certificate"});
      any = true;
      const json& worst = d.contains("worst") ? d["worst"] : json();
      row(out, {cell(str(lib, "name") + " " + str(d, "scalar")), code(str(d, "clause")), str(d, "outcome"), code(str(worst, "input")),
                error_eps_text(worst.is_object() && worst.contains("error_eps") ? worst["error_eps"] : json()),
                cell(worst_text(worst) + (str(worst, "detail").empty() ? "" : ": " + str(worst, "detail"))),
                cell(str(d, "known") == "true" ? str(d, "why") : "NOT LISTED"),
                cell(str(d, "known") == "true" ? upstream_text(d) : ""),
                d.contains("reproducer") && d["reproducer"].is_object()
                    ? cell(str(d["reproducer"], "language") + ": ") + code(str(d["reproducer"], "run"))
                    : "none",
                code(str(d, "reproduce"))});
    }
  out << (any ? "\n" : "None found.\n\n");
}

}  // namespace rotorcert::report::detail
