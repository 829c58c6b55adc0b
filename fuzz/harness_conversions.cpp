// libFuzzer harness: normalize, inverse, to_matrix, from_matrix, to_axis_angle, from_axis_angle (NORM-1, INV-1, MAT-*, AXANG-*).
// Input layout: fuzz/decode.hpp; oracle and eligible tables: fuzz/oracle.hpp, fuzz/README.md.
#include "op_harness.hpp"

ROTORCERT_OP_HARNESS("conversions")
