// libFuzzer harness: log and exp (LOG-*, EXP-1), and the round trip exp(log q) = q through the implementation (EXP-2).
// Input layout: fuzz/decode.hpp; oracle and eligible tables: fuzz/oracle.hpp, fuzz/README.md.
#include "op_harness.hpp"

ROTORCERT_OP_HARNESS("log_exp")
