// libFuzzer harness: the rotation's parts: to_angle, to_axis, sqrt (AXANG-3, AXANG-4, SQRT-1).
// Input layout: fuzz/decode.hpp; oracle and eligible tables: fuzz/oracle.hpp, fuzz/README.md.
#include "op_harness.hpp"

ROTORCERT_OP_HARNESS("rotation_parts")
