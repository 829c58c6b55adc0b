// libFuzzer harness: the parser of test-vector files (`rotorcert vectors check` reads them):
// vectors::parse_vector_file must succeed or throw VectorsError, never crash, hang or throw
// anything else. A file it accepts must render (vectors::render) to a file it accepts again and
// that renders identically: what `vectors export` writes, `vectors check` reads back unchanged.
#include <cstdint>

#include <rotorcert/vectors/error.hpp>
#include <rotorcert/vectors/vector_file.hpp>

#include "oracle.hpp"
#include "parser_harness.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace rotorcert;
  fuzz::init();
  const auto j = fuzz::parse_json("vectors_file", data, size);
  if (!j) return 0;
  const spec::Spec& spec = fuzz::embedded_spec();
  fuzz::expect_only<vectors::VectorsError>("vectors_file", "parse_vector_file", [&] {
    const vectors::VectorFile f = vectors::parse_vector_file(spec, *j, "fuzz-input.json");
    const std::string text = vectors::render(spec, f);
    std::string again;
    try {
      again = vectors::render(spec, vectors::parse_vector_file(spec, nlohmann::json::parse(text), "rendered.json"));
    } catch (const std::exception& e) {
      fuzz::parser_finding("vectors_file", std::string("an accepted file, rendered, is rejected: ") + e.what());
    }
    if (again != text) fuzz::parser_finding("vectors_file", "render(parse(render(f))) != render(f)");
  });
  return 0;
}
