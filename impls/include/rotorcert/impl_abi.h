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

#include "abi_op_list.h"

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

/* The operations, for one scalar type S: one function pointer per row of abi_op_list.h, in its
 * order, with the signature that row gives (the list names the clause each operation answers to).
 * Every function returns 0, or a nonzero value when the call as a whole could not run (for
 * example an allocation failed); per-element outcomes go to status[].
 *
 * rc_ops_f32 / rc_ops_f64 hold ABI version 1's operations (RC_ABI_OPS_V1); the operations added
 * later live in structs of their own, appended to rc_impl, so that no struct ever changes layout:
 * rc_ops3_* (RC_ABI_OPS_V3), read only from a table whose abi_version is >= 3, and rc_ops4_*
 * (RC_ABI_OPS_V4), read only from one whose abi_version is >= 4. (C with <tgmath.h>: call the
 * square root slot as (ops->sqrt)(...).) */
typedef struct rc_ops_f32 { RC_ABI_OPS_V1(RC_ABI_SLOT, float) } rc_ops_f32;
typedef struct rc_ops_f64 { RC_ABI_OPS_V1(RC_ABI_SLOT, double) } rc_ops_f64;
typedef struct rc_ops3_f32 { RC_ABI_OPS_V3(RC_ABI_SLOT, float) } rc_ops3_f32;
typedef struct rc_ops3_f64 { RC_ABI_OPS_V3(RC_ABI_SLOT, double) } rc_ops3_f64;
typedef struct rc_ops4_f32 { RC_ABI_OPS_V4(RC_ABI_SLOT, float) } rc_ops4_f32;
typedef struct rc_ops4_f64 { RC_ABI_OPS_V4(RC_ABI_SLOT, double) } rc_ops4_f64;

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
