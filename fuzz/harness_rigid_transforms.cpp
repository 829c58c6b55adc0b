// libFuzzer harness: rigid transforms in their other forms: dq_to_rotation_translation, dq_log,
// dq_exp, rigid_compose, rigid_apply, rigid_inverse (DQ-7, DQ-8, DQ-9, RIGID-1..3).
// Input layout: fuzz/decode.hpp; oracle and eligible tables: fuzz/oracle.hpp, fuzz/README.md.
#include "op_harness.hpp"

ROTORCERT_OP_HARNESS("rigid_transforms")
