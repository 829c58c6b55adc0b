// sections.render (`rotorcert report --render DIR`, VIS-1..3) in HTML and Markdown: the Figure 1
// and candy-wrapper strips and the error table, one row per scene and method.
#include "common.hpp"
#include "markup.hpp"
#include "sections.hpp"

namespace rotorcert::report::detail {

namespace {

/// obj[key], or null when obj is not an object or has no such key (renderers never throw).
json field(const json& obj, const char* key) { return obj.is_object() && obj.contains(key) ? obj[key] : json(); }
/// PSNR: null in render.json means identical frames (infinite PSNR).
std::string psnr_text(const json& row) {
  return row.is_object() && row.contains("psnr_db") && row["psnr_db"].is_null() ? "\u221e" : stat_text(field(row, "psnr_db"));
}

constexpr const char* kRenderTitle = "Render check: visual equivalence (VIS-1, VIS-2, VIS-3)";

/// sections.render (`rotorcert report --render DIR`): the Figure 1 and candy-wrapper strips, embedded
/// (only data:image/png;base64 URIs are used, so the page still loads nothing from elsewhere), and
/// the error table, one row per scene and method.
void render_render(std::ostream& out, const json& section) {
  if (!str(section, "note").empty()) {
    out << "<section class=\"render\" id=\"section-render\">\n<h2>" << kRenderTitle << "</h2>\n<p class=\"muted\">"
        << esc(str(section, "note")) << "</p>\n</section>\n";
    return;
  }
  out << "<section class=\"render\" id=\"section-render\">\n<h2>" << kRenderTitle << "</h2>\n<p class=\"muted\">From <code>"
      << esc(str(section, "source")) << "</code>; renderer " << esc(str(section, "renderer")) << ". Results "
      << (str(section, "as_expected") == "true" ? "match" : "<strong class=\"no\">DO NOT match</strong>")
      << " expectations (" << esc(counts_text(obj_at(section, "counts")))
      << " over VIS-1 and VIS-2). Vertex errors in mm against the MPFR reference of the same technique; images against "
         "the reference frame of the same renderer.</p>\n";
  for (const json& f : arr(section, "figures")) {
    const std::string uri = str(f, "data_uri");
    const bool figure1 = str(f, "kind") == "figure1";
    std::string caption = std::string(figure1 ? "Figure 1 strip (QLB, DQB, GA rotor)" : "Candy-wrapper strip") + ", " +
                          str(f, "scene") + ", clip " + str(f, "clip") + ", last frame; left to right: " +
                          join(arr(f, "panels"), ", ");
    if (!figure1) {
      std::vector<std::string> v;
      for (const auto& [name, pct] : obj_at(f, "volume_pct").items()) v.push_back(name + " " + stat_text(pct) + " %");
      if (!v.empty()) caption += ". Volume change (VIS-3): " + join(v, ", ");
    }
    out << "<figure>";
    if (uri.rfind("data:image/png;base64,", 0) == 0)
      out << "<img style=\"max-width:100%\" alt=\"" << esc(caption) << "\" src=\"" << esc(uri) << "\">";
    out << "<figcaption>" << esc(caption) << "</figcaption></figure>\n";
  }
  out << "<div class=\"scroll\">\n<table class=\"render\">\n<thead><tr><th>Scene</th><th>Method</th><th>Expected</th>"
         "<th>VIS-1</th><th>max mm</th><th>mean mm</th><th>virtual mm</th><th>normal rad</th><th>VIS-2</th>"
         "<th>max diff</th><th>share &gt; 1 level</th><th>PSNR dB</th></tr></thead>\n<tbody>\n";
  for (const json& r : arr(section, "rows")) {
    const bool ok = str(r, "as_expected") == "true";
    out << "<tr class=\"" << (ok ? "as-expected" : "not-as-expected") << "\"><td>" << esc(str(r, "scene")) << "</td><td><code>"
        << esc(str(r, "method")) << "</code>";
    if (!str(r, "failure").empty()) out << "<div class=\"error\">" << esc(str(r, "failure")) << "</div>";
    out << "</td><td>" << esc(str(r, "expected").empty() ? "\u2014" : str(r, "expected"))
        << (ok ? "" : " <strong class=\"no\">(not met)</strong>") << "</td><td><span class=\"badge oc-" << esc(str(r, "vis1"))
        << "\">" << esc(str(r, "vis1")) << "</span></td><td>" << stat_text(field(r, "max_mm")) << "</td><td>"
        << stat_text(field(r, "mean_mm")) << "</td><td>" << stat_text(field(r, "virtual_max_mm")) << "</td><td>"
        << stat_text(field(r, "normal_max_rad")) << "</td><td><span class=\"badge oc-" << esc(str(r, "vis2")) << "\">"
        << esc(str(r, "vis2")) << "</span></td><td>" << esc(str(r, "max_channel_diff")) << "</td><td>"
        << stat_text(field(r, "share_over")) << "</td><td>" << psnr_text(r) << "</td></tr>\n";
  }
  out << "</tbody>\n</table>\n</div>\n</section>\n";
}
}  // namespace

void render_render_check_html(std::ostream& out, const json& section) { render_render(out, section); }

namespace markdown {
namespace {
/// sections.render (`rotorcert report --render DIR`): the figure strips as image links to the PNG
/// files `rotorcert render` wrote (Markdown viewers differ on data: URIs), and the error table.
void render_render(std::ostream& out, const json& section) {
  out << "## Render check: visual equivalence (VIS-1, VIS-2, VIS-3) <a id=\"section-render\"></a>\n\n";
  if (!str(section, "note").empty()) {
    out << cell(str(section, "note")) << "\n\n";
    return;
  }
  out
      << "From " << code(str(section, "source")) << "; renderer " << cell(str(section, "renderer")) << ". Results "
      << (str(section, "as_expected") == "true" ? "match" : "**DO NOT match**") << " expectations ("
      << cell(counts_text(obj_at(section, "counts"))) << " over VIS-1 and VIS-2).\n\n";
  for (const json& f : arr(section, "figures")) {
    const bool figure1 = str(f, "kind") == "figure1";
    std::string caption = std::string(figure1 ? "Figure 1 strip (QLB, DQB, GA rotor)" : "Candy-wrapper strip") + ", " +
                          str(f, "scene") + ", clip " + str(f, "clip") + "; left to right: " + join(arr(f, "panels"), ", ");
    if (!figure1) {
      std::vector<std::string> v;
      for (const auto& [name, pct] : obj_at(f, "volume_pct").items()) v.push_back(name + " " + stat_text(pct) + " %");
      if (!v.empty()) caption += ". Volume change (VIS-3): " + join(v, ", ");
    }
    // Characters that would end the link target early are replaced.
    std::string file = str(f, "file");
    for (char& c : file)
      if (c == ' ' || c == '(' || c == ')' || c == '<' || c == '>') c = '_';
    out << "![" << (figure1 ? "Figure 1 strip" : "Candy-wrapper strip") << "](" << file << ")\n\n" << cell(caption) << "\n\n";
  }
  header(out, {"Scene", "Method", "Expected", "VIS-1", "max mm", "mean mm", "virtual mm", "normal rad", "VIS-2", "max diff",
               "share > 1 level", "PSNR dB"});
  for (const json& r : arr(section, "rows")) {
    const bool ok = str(r, "as_expected") == "true";
    std::string method = code(str(r, "method"));
    if (!str(r, "failure").empty()) method += "<br>" + cell(str(r, "failure"));
    row(out, {cell(str(r, "scene")), method,
              cell(str(r, "expected").empty() ? "\u2014" : str(r, "expected")) + (ok ? "" : " **(not met)**"),
              cell(str(r, "vis1")), stat_text(field(r, "max_mm")), stat_text(field(r, "mean_mm")),
              stat_text(field(r, "virtual_max_mm")), stat_text(field(r, "normal_max_rad")), cell(str(r, "vis2")),
              cell(str(r, "max_channel_diff")), stat_text(field(r, "share_over")), psnr_text(r)});
  }
  out << "\n";
}
}  // namespace
}  // namespace markdown

void render_render_check_markdown(std::ostream& out, const json& section) { markdown::render_render(out, section); }

}  // namespace rotorcert::report::detail
