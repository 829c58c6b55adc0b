/* rotorcert implementation ABI, version 4 (version 1, 2 and 3 tables still load: see below).
 *
 * An implementation under test (built in, or a third-party plugin loaded with dlopen) exports
 * one C entry point:
 *
 *     const rc_impl* rotorcert_impl_entry(uint32_t abi_version, uint32_t index);
 *
 * It returns its index-th table (one table per scalar type it offers, say a float and a double
 * table) or NULL past the last one, and NULL when it does not speak abi_version. Tables and
 * everything they point to live as long as the library is loaded.
 *
 * Versions: a version-2 table is a version-1 table with two fields appended (preconditions and
 * conventions, the declarations of spec clause DECL-1); a version-3 table is a version-2 table
 * with two more appended (f32_v3, f64_v3: the operations added in version 3, in a struct of their
 * own so that rc_ops_f32/f64 keep their version-1 layout); a version-4 table appends f32_v4 and
 * f64_v4 the same way. The suite asks for version 4 first, then 3, 2, 1, taking the first version
 * at which the library answers a table at index 0; it reads the appended fields only from a table
 * whose abi_version is at least the version that added them (an older table simply lacks the
 * newer operations: NOT_SUPPORTED).
 * A library built against this header answers every version from RC_ABI_VERSION_MIN to
 * RC_ABI_VERSION (an older host reads the prefix of its own version).
 *
 * Every operation is a batch over plain arrays of the table's scalar type (float or double,
 * see rc_impl.scalar), n elements per call, with one status byte per element. A NULL function
 * pointer means NOT_SUPPORTED. Functions must not keep pointers, must accept n = 0, and must be
 * callable from several threads on disjoint arrays.
 *
 * Array layouts (spec clause LAYOUT-1; element i starts at i * stride):
 *   quaternion  4 scalars  [x, y, z, w]                     (glTF order, GLM's storage order)
 *   vector      3 scalars  [x, y, z]
 *   bivector    3 scalars  [e23, e31, e12]; a rotation log is the pure quaternion [x, y, z] =
 *                          (angle/2) * axis (LOG-1)
 *   dual quat.  8 scalars  [real x, y, z, w, dual x, y, z, w], sigma = real + eps dual,
 *                          dual = 1/2 t real (DQ-1)
 *   matrix 3x3  9 scalars  column-major, m[c * 3 + r]
 *   scalar      1 scalar   angles in radians, interpolation parameters t
 *   weights     k scalars  per element (n-way operations take k influences per element,
 *                          element i's influences at i * k .. i * k + k - 1)
 *
 * Status bytes (RESULT-2): RC_OK, or RC_DOMAIN_ERROR when the input is outside the
 * operation's domain (EDGE-6, EDGE-7, EDGE-9, MAT-3); the spec then requires every output
 * component of that element to be a quiet NaN.
 *
 * Conventions fixed by the spec: Hamilton quaternions (ijk = -1), active right-handed
 * rotation v' = q v q*, compose(a, b) = a b applies b first, rotor R = w - x e23 - y e31 - z e12
 * (Q2R-1). An implementation that works otherwise inside converts at this boundary, and the
 * conversion is part of what is measured.
 */
#ifndef ROTORCERT_IMPL_ABI_H
#define ROTORCERT_IMPL_ABI_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define RC_ABI_VERSION 4u
#define RC_ABI_VERSION_MIN 1u /* the oldest version the suite still loads */

/* Element status (RESULT-2). */
enum { RC_OK = 0, RC_DOMAIN_ERROR = 1 };

/* Scalar type of a table's arrays (NUM-1). */
enum { RC_SCALAR_FLOAT32 = 1, RC_SCALAR_FLOAT64 = 2 };

/* Conformance levels (LEVEL-1), as bits of rc_impl.levels. */
enum {
  RC_LEVEL_CORE = 1u << 0,
  RC_LEVEL_INTERP = 1u << 1,
  RC_LEVEL_BLEND = 1u << 2,
  RC_LEVEL_RIGID = 1u << 3,
  RC_LEVEL_SKINNING = 1u << 4,
  RC_LEVEL_ROBUST = 1u << 5
};

/* The operations, for one scalar type S. Every function returns 0, or a nonzero value when
 * the call as a whole could not run (for example an allocation failed); per-element outcomes
 * go to status[]. The clause each operation answers to is named at its pointer. */
#define RC_DECLARE_OPS(NAME, S)                                                                              \
  typedef struct NAME {                                                                                      \
    /* Core */                                                                                               \
    int (*normalize)(size_t n, const S* q, S* out_q, uint8_t* status);                 /* NORM-1 */         \
    int (*compose)(size_t n, const S* a, const S* b, S* out_q, uint8_t* status);       /* COMPOSE-1 */      \
    int (*inverse)(size_t n, const S* q, S* out_q, uint8_t* status);                   /* INV-1 */          \
    int (*apply_vector)(size_t n, const S* q, const S* v, S* out_v, uint8_t* status);  /* APPLY-1 */        \
    int (*apply_bivector)(size_t n, const S* q, const S* b, S* out_b, uint8_t* status); /* APPLY-2 */       \
    int (*apply_trivector)(size_t n, const S* q, const S* s, S* out_s, uint8_t* status); /* APPLY-3 */      \
    int (*to_matrix)(size_t n, const S* q, S* out_m, uint8_t* status);                 /* MAT-1 */          \
    int (*from_matrix)(size_t n, const S* m, S* out_q, uint8_t* status);               /* MAT-2, MAT-3 */   \
    int (*to_axis_angle)(size_t n, const S* q, S* out_angle, S* out_axis, uint8_t* status); /* AXANG-1 */   \
    int (*from_axis_angle)(size_t n, const S* angle, const S* axis, S* out_q, uint8_t* status); /* AXANG-2 */ \
    /* Interp */                                                                                             \
    int (*log)(size_t n, const S* q, S* out_v, uint8_t* status);                       /* LOG-1, LOG-2 */   \
    int (*exp)(size_t n, const S* v, S* out_q, uint8_t* status);                       /* EXP-1 */          \
    int (*slerp)(size_t n, const S* a, const S* b, const S* t, S* out_q, uint8_t* status); /* SLERP-* */    \
    int (*nlerp)(size_t n, const S* a, const S* b, const S* t, S* out_q, uint8_t* status); /* NLERP-1 */    \
    /* Blend: n blends of k influences each */                                                               \
    int (*blend_qlb)(size_t n, size_t k, const S* q, const S* w, S* out_q, uint8_t* status); /* QLB-1 */    \
    int (*blend_log)(size_t n, size_t k, const S* q, const S* w, S* out_q, uint8_t* status); /* LOGBLEND-1 */ \
    /* Rigid */                                                                                              \
    int (*dq_from_rotation_translation)(size_t n, const S* q, const S* t, S* out_d, uint8_t* status); /* DQ-1 */ \
    int (*dq_compose)(size_t n, const S* a, const S* b, S* out_d, uint8_t* status);    /* DQ-2 */           \
    int (*dq_apply_point)(size_t n, const S* d, const S* p, S* out_p, uint8_t* status); /* DQ-3 */          \
    int (*dq_normalize)(size_t n, const S* d, S* out_d, uint8_t* status);              /* DQ-4 */           \
    int (*dq_sclerp)(size_t n, const S* a, const S* b, const S* t, S* out_d, uint8_t* status); /* DQ-5 */   \
    int (*dq_blend)(size_t n, size_t k, const S* d, const S* w, S* out_d, uint8_t* status); /* DQ-6 */      \
    int (*rotate_about_axis)(size_t n, const S* c, const S* u, const S* angle, const S* p, S* out_p,       \
                             uint8_t* status);                                          /* AXIS-1 */         \
    /* Skinning: n vertices with k influences each (rotation, translation, weight) */                       \
    int (*skin_linear)(size_t n, size_t k, const S* q, const S* t, const S* w, const S* v, S* out_v,       \
                       uint8_t* status);                                                /* SKIN-1 */         \
    int (*skin_dual_quaternion)(size_t n, size_t k, const S* q, const S* t, const S* w, const S* v,        \
                                S* out_v, uint8_t* status);                             /* SKIN-2 */         \
  } NAME

RC_DECLARE_OPS(rc_ops_f32, float);
RC_DECLARE_OPS(rc_ops_f64, double);

/* The operations added in ABI version 3, same conventions (batch, NULL = NOT_SUPPORTED). Read
 * only from a table whose abi_version is >= 3. */
#define RC_DECLARE_OPS3(NAME, S)                                                                             \
  typedef struct NAME {                                                                                      \
    /* Core: the two halves of to_axis_angle, for APIs that offer them apart */                             \
    int (*to_angle)(size_t n, const S* q, S* out_angle, uint8_t* status);              /* AXANG-3 */        \
    int (*to_axis)(size_t n, const S* q, S* out_axis, uint8_t* status);                /* AXANG-4 */        \
    /* Interp: the rotor square root, half the rotation (C with <tgmath.h>: call (ops->sqrt)(...)) */      \
    int (*sqrt)(size_t n, const S* q, S* out_q, uint8_t* status);                      /* SQRT-1 */         \
    /* Rigid: the inverse of dq_from_rotation_translation */                                                \
    int (*dq_to_rotation_translation)(size_t n, const S* d, S* out_q, S* out_t, uint8_t* status); /* DQ-7 */ \
  } NAME

RC_DECLARE_OPS3(rc_ops3_f32, float);
RC_DECLARE_OPS3(rc_ops3_f64, double);

/* The operations added in ABI version 4, same conventions. Read only from a table whose
 * abi_version is >= 4. Layouts (LAYOUT-1): a dual vector xi = xi_r + eps xi_d, the logarithm of a
 * unit dual quaternion, is 6 scalars [xi_r x, y, z, xi_d x, y, z]; a rigid transform as rotation +
 * translation is a quaternion q [x, y, z, w] (the rotation of q/|q|) and a vector t [x, y, z]
 * (x -> R x + t). */
#define RC_DECLARE_OPS4(NAME, S)                                                                             \
  typedef struct NAME {                                                                                      \
    /* Rigid: the motor logarithm and exponential in dual-quaternion coordinates */                         \
    int (*dq_log)(size_t n, const S* d, S* out_xi, uint8_t* status);                  /* DQ-8 */           \
    int (*dq_exp)(size_t n, const S* xi, S* out_d, uint8_t* status);                  /* DQ-9 */           \
    /* Rigid transforms held as rotation quaternion + translation (Isometry3, btTransform, ...) */          \
    int (*rigid_compose)(size_t n, const S* qa, const S* ta, const S* qb, const S* tb, S* out_q, S* out_t,  \
                         uint8_t* status);                                            /* RIGID-1 */        \
    int (*rigid_apply)(size_t n, const S* q, const S* t, const S* p, S* out_p, uint8_t* status); /* RIGID-2 */ \
    int (*rigid_inverse)(size_t n, const S* q, const S* t, S* out_q, S* out_t, uint8_t* status); /* RIGID-3 */ \
  } NAME

RC_DECLARE_OPS4(rc_ops4_f32, float);
RC_DECLARE_OPS4(rc_ops4_f64, double);

/* One implementation for one scalar type. */
typedef struct rc_impl {
  uint32_t abi_version;       /* RC_ABI_VERSION the table was built against */
  const char* name;           /* stable identifier, e.g. "glm_quat" */
  const char* version;        /* of the implementation, or of the library it adapts */
  const char* description;    /* one line */
  uint32_t scalar;            /* RC_SCALAR_FLOAT32 or RC_SCALAR_FLOAT64 */
  uint32_t levels;            /* RC_LEVEL_* bits it claims */
  const char* const* clauses; /* NULL-terminated list of clause IDs it claims */
  const rc_ops_f32* f32;      /* set iff scalar == RC_SCALAR_FLOAT32 */
  const rc_ops_f64* f64;      /* set iff scalar == RC_SCALAR_FLOAT64 */
  /* SIMD dispatch (optional, NULL if none): the targets it can run, NULL-terminated, best
   * last; select_target forces one by name (0 on success), NULL restores the default;
   * current_target names the one in use. */
  const char* const* simd_targets;
  int (*select_target)(const char* name);
  const char* (*current_target)(void);
  /* ---- ABI version 2 ---- */
  /* Declarations (DECL-1), each a NULL-terminated list of "op:id" strings, or NULL for none.
   * preconditions: documented preconditions of the library's calls, e.g. "from_axis_angle:unit_axis",
   *   "slerp:t_in_unit_interval", "from_matrix:rotation_matrix". An input outside a declared
   *   precondition is not held against the table at Core..Skinning; a Robust clause with such
   *   inputs is NOT_SUPPORTED (the table does not claim to handle them).
   * conventions: conventions the library chose where the spec allows several correct answers,
   *   e.g. "from_matrix:sign", "to_axis_angle:angle_range_0_pi", "log:shorter_arc"; an output that
   *   follows a declared convention passes, an undeclared one is reported as ACCEPTABLE.
   * Ids: spec/SPEC.md section 4a (DECL-1, ACC-1). */
  const char* const* preconditions;
  const char* const* conventions;
  /* ---- ABI version 3 ---- */
  /* The version-3 operations of the same scalar type: at most the one of rc_impl.scalar is set
   * (f32_v3 for RC_SCALAR_FLOAT32, f64_v3 for RC_SCALAR_FLOAT64); NULL means none of them. */
  const rc_ops3_f32* f32_v3;
  const rc_ops3_f64* f64_v3;
  /* ---- ABI version 4 ---- */
  /* The version-4 operations, same rule as f32_v3 / f64_v3. */
  const rc_ops4_f32* f32_v4;
  const rc_ops4_f64* f64_v4;
} rc_impl;

/* The entry point every implementation library exports. */
typedef const rc_impl* (*rc_impl_entry_fn)(uint32_t abi_version, uint32_t index);
#define RC_IMPL_ENTRY_SYMBOL "rotorcert_impl_entry"

#ifdef __cplusplus
} /* extern "C" */
#endif

#endif /* ROTORCERT_IMPL_ABI_H */
