/* The batch operations of the rotorcert ABI: the one list every table of operations is made from.
 *
 * Each ABI version that added operations has a list macro taking X and the scalar type S:
 *
 *     RC_ABI_OPS_V1(X, S)   the operations of rc_ops_f32 / rc_ops_f64 (ABI version 1)
 *     RC_ABI_OPS_V3(X, S)   those of rc_ops3_f32 / rc_ops3_f64 (added in version 3)
 *     RC_ABI_OPS_V4(X, S)   those of rc_ops4_f32 / rc_ops4_f64 (added in version 4)
 *     RC_ABI_OPS(X, S)      all of them, in that order
 *
 * and expands X once per operation, in table order:
 *
 *     X(name, since, level, clauses, kind, (inputs), (outputs))
 *
 *   name     the slot of the table (a C identifier; `sqrt`, `log` and `exp` are never followed by
 *            a parenthesis here, so <tgmath.h>'s macros do not touch them)
 *   since    the ABI version whose struct holds the slot: 1, 3 or 4
 *   level    the level of its main clause, the first of `clauses` (LEVEL-1): CORE, INTERP, BLEND,
 *            RIGID, SKINNING or EXTENDED, the spec's level name in capitals
 *   clauses  the spec clauses that define it, a string of IDs separated by spaces
 *   kind     ELEM (n elements), BLEND (n blends of k influences), SKIN (n vertices of k
 *            influences); RC_ABI_K_<kind> is the parameter that kind adds after n
 *   inputs   the input arrays, `const S* name` each, in call order (layouts: impl_abi.h, LAYOUT-1)
 *   outputs  the output arrays, `S* name` each
 *
 * Every slot's C signature is
 *     int name(size_t n, RC_ABI_K_<kind> inputs..., outputs..., uint8_t* status)
 * (RC_ABI_SLOT below). Only mechanical facts live here; what an operation means is its clause
 * (spec/SPEC.md) and its reference (reference/), how its arrays are compared is the engine's
 * AbiOp. Appending an operation: a row at the end of a new version's list (a table's layout never
 * changes), then its clause, reference and AbiOp (ARCHITECTURE.md, "Adding an operation"). */
#ifndef ROTORCERT_ABI_OP_LIST_H
#define ROTORCERT_ABI_OP_LIST_H

#define RC_ABI_OPS_V1(X, S)                                                                                \
  X(normalize, 1, CORE, "NORM-1", ELEM, (const S* q), (S* out_q))                                          \
  X(compose, 1, CORE, "COMPOSE-1", ELEM, (const S* a, const S* b), (S* out_q))                             \
  X(inverse, 1, CORE, "INV-1", ELEM, (const S* q), (S* out_q))                                             \
  X(apply_vector, 1, CORE, "APPLY-1", ELEM, (const S* q, const S* v), (S* out_v))                          \
  X(apply_bivector, 1, CORE, "APPLY-2", ELEM, (const S* q, const S* b), (S* out_b))                        \
  X(apply_trivector, 1, CORE, "APPLY-3", ELEM, (const S* q, const S* s), (S* out_s))                       \
  X(to_matrix, 1, CORE, "MAT-1", ELEM, (const S* q), (S* out_m))                                           \
  X(from_matrix, 1, CORE, "MAT-2 MAT-3", ELEM, (const S* m), (S* out_q))                                   \
  X(to_axis_angle, 1, CORE, "AXANG-1", ELEM, (const S* q), (S* out_angle, S* out_axis))                    \
  X(from_axis_angle, 1, CORE, "AXANG-2", ELEM, (const S* angle, const S* axis), (S* out_q))                \
  X(log, 1, INTERP, "LOG-1 LOG-2", ELEM, (const S* q), (S* out_v))                                         \
  X(exp, 1, INTERP, "EXP-1", ELEM, (const S* v), (S* out_q))                                               \
  X(slerp, 1, INTERP, "SLERP-1", ELEM, (const S* a, const S* b, const S* t), (S* out_q))                   \
  X(nlerp, 1, INTERP, "NLERP-1", ELEM, (const S* a, const S* b, const S* t), (S* out_q))                   \
  X(blend_qlb, 1, BLEND, "QLB-1", BLEND, (const S* q, const S* w), (S* out_q))                             \
  X(blend_log, 1, BLEND, "LOGBLEND-1", BLEND, (const S* q, const S* w), (S* out_q))                        \
  X(dq_from_rotation_translation, 1, RIGID, "DQ-1", ELEM, (const S* q, const S* t), (S* out_d))           \
  X(dq_compose, 1, RIGID, "DQ-2", ELEM, (const S* a, const S* b), (S* out_d))                              \
  X(dq_apply_point, 1, RIGID, "DQ-3", ELEM, (const S* d, const S* p), (S* out_p))                          \
  X(dq_normalize, 1, RIGID, "DQ-4", ELEM, (const S* d), (S* out_d))                                        \
  X(dq_sclerp, 1, RIGID, "DQ-5", ELEM, (const S* a, const S* b, const S* t), (S* out_d))                   \
  X(dq_blend, 1, RIGID, "DQ-6", BLEND, (const S* d, const S* w), (S* out_d))                               \
  X(rotate_about_axis, 1, RIGID, "AXIS-1", ELEM, (const S* c, const S* u, const S* angle, const S* p),     \
    (S* out_p))                                                                                            \
  X(skin_linear, 1, SKINNING, "SKIN-1", SKIN, (const S* q, const S* t, const S* w, const S* v), (S* out_v)) \
  X(skin_dual_quaternion, 1, SKINNING, "SKIN-2", SKIN, (const S* q, const S* t, const S* w, const S* v),   \
    (S* out_v))

/* Version 3: the two halves of to_axis_angle, for APIs that offer them apart; the rotor square
 * root (half the rotation); the inverse of dq_from_rotation_translation. */
#define RC_ABI_OPS_V3(X, S)                                                                                \
  X(to_angle, 3, EXTENDED, "AXANG-3", ELEM, (const S* q), (S* out_angle))                                      \
  X(to_axis, 3, EXTENDED, "AXANG-4", ELEM, (const S* q), (S* out_axis))                                        \
  X(sqrt, 3, EXTENDED, "SQRT-1", ELEM, (const S* q), (S* out_q))                                             \
  X(dq_to_rotation_translation, 3, EXTENDED, "DQ-7", ELEM, (const S* d), (S* out_q, S* out_t))

/* Version 4: the motor logarithm and exponential in dual-quaternion coordinates (a dual vector
 * xi is 6 scalars [xi_r x, y, z, xi_d x, y, z]); rigid transforms held as rotation quaternion q
 * [x, y, z, w] + translation t [x, y, z] (x -> R x + t: Isometry3, btTransform, ...). */
#define RC_ABI_OPS_V4(X, S)                                                                                \
  X(dq_log, 4, EXTENDED, "DQ-8", ELEM, (const S* d), (S* out_xi))                                             \
  X(dq_exp, 4, EXTENDED, "DQ-9", ELEM, (const S* xi), (S* out_d))                                             \
  X(rigid_compose, 4, EXTENDED, "RIGID-1", ELEM, (const S* qa, const S* ta, const S* qb, const S* tb),        \
    (S* out_q, S* out_t))                                                                                  \
  X(rigid_apply, 4, EXTENDED, "RIGID-2", ELEM, (const S* q, const S* t, const S* p), (S* out_p))              \
  X(rigid_inverse, 4, EXTENDED, "RIGID-3", ELEM, (const S* q, const S* t), (S* out_q, S* out_t))

#define RC_ABI_OPS(X, S) RC_ABI_OPS_V1(X, S) RC_ABI_OPS_V3(X, S) RC_ABI_OPS_V4(X, S)

/* The parameter each kind adds after n. */
#define RC_ABI_K_ELEM
#define RC_ABI_K_BLEND size_t k,
#define RC_ABI_K_SKIN size_t k,

#define RC_ABI_UNPAREN(...) __VA_ARGS__

/* One table field: the slot's function pointer, declared from its row. */
#define RC_ABI_SLOT(name, since, level, clauses, kind, inputs, outputs) \
  int (*name)(size_t n, RC_ABI_K_##kind RC_ABI_UNPAREN inputs, RC_ABI_UNPAREN outputs, uint8_t * status);

#endif /* ROTORCERT_ABI_OP_LIST_H */
