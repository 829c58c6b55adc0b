// libFuzzer harness: rigid transforms: dq_from_rotation_translation, dq_compose, dq_apply_point, dq_normalize, dq_sclerp, rotate_about_axis (DQ-1..5, AXIS-1).
// Input layout: fuzz/decode.hpp; oracle and eligible tables: fuzz/oracle.hpp, fuzz/README.md.
#include "op_harness.hpp"

ROTORCERT_OP_HARNESS("rigid")
