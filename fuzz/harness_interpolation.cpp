// libFuzzer harness: slerp and nlerp (SLERP-*, NLERP-1), t anywhere, ties and antipodes.
// Input layout: fuzz/decode.hpp; oracle and eligible tables: fuzz/oracle.hpp, fuzz/README.md.
#include "op_harness.hpp"

ROTORCERT_OP_HARNESS("interpolation")
