// Shared by the parser harnesses: bytes -> JSON (a syntax error is what read_json_file() turns
// into VectorsError, so it is an expected outcome) -> the parser under test, which must succeed
// or throw its own error type. Any other exception is a finding: printed, then abort().
#pragma once

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <optional>
#include <string>
#include <string_view>
#include <typeinfo>

#include <nlohmann/json.hpp>

#include <rotorcert/vectors/error.hpp>
#include <rotorcert/vectors/vector_set.hpp>

namespace rotorcert::fuzz {

[[noreturn]] inline void parser_finding(const char* harness, const std::string& what) {
  std::fprintf(stderr, "\n==== rotorcert fuzz finding (%s) ====\n%s\n================================\n", harness,
               what.c_str());
  std::abort();
}

/// Runs f(); returns normally if it returns or throws Expected; any other exception is a finding.
template <class Expected, class F>
void expect_only(const char* harness, const char* stage, F&& f) {
  try {
    f();
  } catch (const Expected&) {
  } catch (const std::exception& e) {
    parser_finding(harness, std::string(stage) + " threw " + typeid(e).name() + " instead of its error type: " + e.what());
  } catch (...) {
    parser_finding(harness, std::string(stage) + " threw a non-std exception");
  }
}

/// The document, or nullopt for bytes that vectors::parse_json_text() (the parser behind every
/// file `rotorcert vectors` reads) rejects with VectorsError; any other exception escaping it is
/// a finding (it was: out_of_range 406 for a number such as 7e824 that overflows a double).
inline std::optional<nlohmann::json> parse_json(const char* harness, const std::uint8_t* data, std::size_t size) {
  std::optional<nlohmann::json> doc;
  expect_only<vectors::VectorsError>(harness, "vectors::parse_json_text", [&] {
    doc = vectors::parse_json_text(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz-input.json");
  });
  return doc;
}

}  // namespace rotorcert::fuzz
