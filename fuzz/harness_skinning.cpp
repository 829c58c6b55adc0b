// libFuzzer harness: skinning of a vertex: skin_linear, skin_dual_quaternion (SKIN-*), k = 0..8 influences.
// Input layout: fuzz/decode.hpp; oracle and eligible tables: fuzz/oracle.hpp, fuzz/README.md.
#include "op_harness.hpp"

ROTORCERT_OP_HARNESS("skinning")
