"""The operations of the rotorcert ABI as the vectors name them, and the output arrays of each."""

# Output arrays of each ABI op, in the order the op writes them, with their strides
# (the op list impls/include/rotorcert/abi_op_list.h; layouts of LAYOUT-1; ctest
# conformance_abi_tables_match checks this table against it). `log_exp_round_trip` is EXP-2's
# round trip: exp of what log returned, not an ABI op of its own.
OUTPUTS = {
    "normalize": (("out_q", 4),), "compose": (("out_q", 4),), "inverse": (("out_q", 4),),
    "apply_vector": (("out_v", 3),), "apply_bivector": (("out_b", 3),), "apply_trivector": (("out_s", 1),),
    "to_matrix": (("out_m", 9),), "from_matrix": (("out_q", 4),),
    "to_axis_angle": (("out_angle", 1), ("out_axis", 3)), "from_axis_angle": (("out_q", 4),),
    "log": (("out_v", 3),), "exp": (("out_q", 4),), "slerp": (("out_q", 4),), "nlerp": (("out_q", 4),),
    "blend_qlb": (("out_q", 4),), "blend_log": (("out_q", 4),),
    "dq_from_rotation_translation": (("out_d", 8),), "dq_compose": (("out_d", 8),),
    "dq_apply_point": (("out_p", 3),), "dq_normalize": (("out_d", 8),), "dq_sclerp": (("out_d", 8),),
    "dq_blend": (("out_d", 8),), "rotate_about_axis": (("out_p", 3),),
    "skin_linear": (("out_v", 3),), "skin_dual_quaternion": (("out_v", 3),),
    # ABI version 3
    "to_angle": (("out_angle", 1),), "to_axis": (("out_axis", 3),), "sqrt": (("out_q", 4),),
    "dq_to_rotation_translation": (("out_q", 4), ("out_t", 3)),
    # ABI version 4
    "dq_log": (("out_xi", 6),), "dq_exp": (("out_d", 8),),
    "rigid_compose": (("out_q", 4), ("out_t", 3)), "rigid_apply": (("out_p", 3),),
    "rigid_inverse": (("out_q", 4), ("out_t", 3)),
    "log_exp_round_trip": (("out_q", 4),),
}

ROUND_TRIP = "log_exp_round_trip"

# The ABI's operations: what a results file may declare in `unsupported_ops` (RESULT-1).
ABI_OPS = tuple(op for op in OUTPUTS if op != ROUND_TRIP)

NUMBER_FORMATS = {"float": "binary32", "double": "binary64"}
