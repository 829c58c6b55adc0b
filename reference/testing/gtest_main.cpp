// gtest main for every rotorcert test: sets the reference precision (NUM-2) before any test
// creates an MPFR number.
#include <gtest/gtest.h>

#include <rotorcert/reference/scalar.hpp>

int main(int argc, char** argv) {
  rotorcert::ref::use_reference_precision();
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
