// libFuzzer harness: results files (`rotorcert vectors check RESULTS.json`): the structure parser
// vectors::parse_results, then the grading of an accepted file against a small fixed set of
// vectors (vectors::grade decodes every value against the vector it answers). Both must succeed
// or throw VectorsError, never crash, hang or throw anything else.
#include <cstdint>

#include <rotorcert/vectors/check.hpp>
#include <rotorcert/vectors/error.hpp>
#include <rotorcert/vectors/results.hpp>
#include <rotorcert/vectors/vector_set.hpp>

#include "oracle.hpp"
#include "parser_harness.hpp"
#include "results_set.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace rotorcert;
  fuzz::init();
  const auto j = fuzz::parse_json("results_file", data, size);
  if (!j) return 0;
  const spec::Spec& spec = fuzz::embedded_spec();
  fuzz::expect_only<vectors::VectorsError>("results_file", "parse_results/grade", [&] {
    const vectors::ResultsFile r = vectors::parse_results(*j, "fuzz-results.json");
    (void)vectors::grade(spec, fuzz::results_vector_set(r.format()), r);
  });
  return 0;
}
