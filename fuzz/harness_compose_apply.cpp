// libFuzzer harness: compose, apply_vector, apply_bivector, apply_trivector (COMPOSE-1, QUAT-2, APPLY-*).
// Input layout: fuzz/decode.hpp; oracle and eligible tables: fuzz/oracle.hpp, fuzz/README.md.
#include "op_harness.hpp"

ROTORCERT_OP_HARNESS("compose_apply")
