// The table of the report's sections (sections.hpp).
#include "sections.hpp"

#include <algorithm>

namespace rotorcert::report::detail {

namespace {

constexpr Section kSections[] = {
    {"mutants", "Mutants", &render_mutants_html, &render_mutants_markdown},
    {"render", "Render check", &render_render_check_html, &render_render_check_markdown},
    {"speed", "Speed", &render_speed_html, &render_speed_markdown},
    {"third_party", "Third-party libraries", &render_third_party_html, &render_third_party_markdown},
};

}  // namespace

std::span<const Section> sections() { return kSections; }

const Section* find_section(std::string_view key) {
  const auto it = std::find_if(std::begin(kSections), std::end(kSections), [&](const Section& s) { return s.key == key; });
  return it == std::end(kSections) ? nullptr : &*it;
}

}  // namespace rotorcert::report::detail
