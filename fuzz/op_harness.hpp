// The body shared by the operation harnesses (harness_<family>.cpp): decode, run, judge.
#pragma once

#include <cstddef>
#include <cstdint>

#include "decode.hpp"
#include "families.hpp"
#include "oracle.hpp"

namespace rotorcert::fuzz {

inline int run_family(const char* family, const std::uint8_t* data, std::size_t size) {
  init();
  Decoded d;
  if (decode(data, size, families().at(family), d)) (void)check(d);
  return 0;
}

}  // namespace rotorcert::fuzz

#define ROTORCERT_OP_HARNESS(family)                                                  \
  extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) { \
    return rotorcert::fuzz::run_family(family, data, size);                           \
  }
