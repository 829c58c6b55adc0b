// libFuzzer harness: n-way blends: blend_qlb, blend_log, dq_blend (QLB-1, LOGBLEND-1, DQ-6, EDGE-9), k = 0..8 influences.
// Input layout: fuzz/decode.hpp; oracle and eligible tables: fuzz/oracle.hpp, fuzz/README.md.
#include "op_harness.hpp"

ROTORCERT_OP_HARNESS("blending")
