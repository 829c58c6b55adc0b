// rotorcert adapter for nalgebra (https://nalgebra.rs), the crate version pinned in Cargo.toml /
// Cargo.lock, built with its default features (std, macros).
//
// A cdylib exporting rotorcert_impl_entry (impls/include/rotorcert/impl_abi.h, ABI version 4) with
// two tables named "nalgebra": index 0 binary32 (UnitQuaternion<f32>, Quaternion<f32>,
// UnitDualQuaternion<f32>, Isometry3<f32>), index 1 binary64 (the same types over f64).
// scripts/setup-adapters builds it with `cargo build --release --locked` into the adapter's
// environment; `rotorcert thirdparty` loads it from there. The ops are in ops.rs, the ABI and the
// panic boundary in abi.rs; every convention mapping and declaration is stated in adapter.json.

#[path = "../../rust_abi/abi.rs"]
mod abi;

use abi::*;

pub mod f32 {
    pub type S = f32;
    include!("ops.rs");
}

pub mod f64 {
    pub type S = f64;
    include!("ops.rs");
}

/// Clauses whose operations nalgebra has (no bivectors or trivectors, no blends, no dual-quaternion
/// blending, no skinning, no dual-quaternion log/exp: DQ-8, DQ-9).
static CLAUSES: StrList<42> = str_list![
    // Core (APPLY-2, APPLY-3: nalgebra has no bivectors or trivectors)
    "QUAT-2", "NORM-1", "COMPOSE-1", "INV-1", "APPLY-1", "MAT-1", "MAT-2", "AXANG-1", "AXANG-2",
    // Extended
    "AXANG-3", "AXANG-4", "SQRT-1", "DQ-7", "RIGID-1", "RIGID-2", "RIGID-3",
    // Interp
    "LOG-1", "LOG-2", "EXP-1", "EXP-2", "SLERP-1", "SLERP-2", "SLERP-3", "SLERP-4", "SLERP-5", "NLERP-1",
    // Rigid (DQ-6: no dual-quaternion blending)
    "DQ-1", "DQ-2", "DQ-3", "DQ-4", "DQ-5", "AXIS-1",
    // Robust (EDGE-9 judges weighted ops only)
    "MAT-3", "EDGE-1", "EDGE-2", "EDGE-3", "EDGE-4", "EDGE-5", "EDGE-6", "EDGE-7", "EDGE-8",
];

/// DECL-1, nalgebra's documentation (citations in adapter.json).
static PRECONDITIONS: StrList<7> = str_list![
    "from_axis_angle:unit_axis",
    "rotate_about_axis:unit_axis",
    "from_matrix:rotation_matrix",
    "slerp:t_in_unit_interval",
    "dq_sclerp:t_in_unit_interval",
    "dq_sclerp:not_half_turn_apart",
];

/// Conventions nalgebra chose where the spec allows several answers (citations in adapter.json).
static CONVENTIONS: StrList<9> = str_list![
    "from_matrix:sign",
    "to_axis_angle:angle_range",
    "to_axis_angle:identity_axis",
    "to_angle:angle_range",
    "to_axis:angle_range",
    "to_axis:identity_axis",
    "log:shorter_arc",
    "nlerp:oriented",
];

const LEVELS: u32 = RC_LEVEL_CORE | RC_LEVEL_INTERP | RC_LEVEL_RIGID | RC_LEVEL_ROBUST;

/// The version string of both tables: the pinned crate and how it is built.
macro_rules! version {
    () => {
        "nalgebra 0.35.0 (default features: std, macros)"
    };
}

static TABLE_F32: Impl = Impl {
    abi_version: RC_ABI_VERSION,
    name: cstr!("nalgebra"),
    version: cstr!(version!()),
    description: cstr!("nalgebra 0.35.0 UnitQuaternion<f32>, Quaternion<f32>, UnitDualQuaternion<f32>, Isometry3<f32>; see adapter.json"),
    scalar: RC_SCALAR_FLOAT32,
    levels: LEVELS,
    clauses: CLAUSES.0.as_ptr(),
    f32: &f32::OPS,
    f64: std::ptr::null(),
    simd_targets: std::ptr::null(),
    select_target: None,
    current_target: None,
    preconditions: PRECONDITIONS.0.as_ptr(),
    conventions: CONVENTIONS.0.as_ptr(),
    f32_v3: &f32::OPS3,
    f64_v3: std::ptr::null(),
    f32_v4: &f32::OPS4,
    f64_v4: std::ptr::null(),
};

static TABLE_F64: Impl = Impl {
    abi_version: RC_ABI_VERSION,
    name: cstr!("nalgebra"),
    version: cstr!(version!()),
    description: cstr!("nalgebra 0.35.0 UnitQuaternion<f64>, Quaternion<f64>, UnitDualQuaternion<f64>, Isometry3<f64>; see adapter.json"),
    scalar: RC_SCALAR_FLOAT64,
    levels: LEVELS,
    clauses: CLAUSES.0.as_ptr(),
    f32: std::ptr::null(),
    f64: &f64::OPS,
    simd_targets: std::ptr::null(),
    select_target: None,
    current_target: None,
    preconditions: PRECONDITIONS.0.as_ptr(),
    conventions: CONVENTIONS.0.as_ptr(),
    f32_v3: std::ptr::null(),
    f64_v3: &f64::OPS3,
    f32_v4: std::ptr::null(),
    f64_v4: &f64::OPS4,
};

/// The entry point a rotorcert plugin exports (RC_IMPL_ENTRY_SYMBOL).
#[no_mangle]
pub extern "C" fn rotorcert_impl_entry(abi_version: u32, index: u32) -> *const Impl {
    entry(abi_version, index, &[&TABLE_F32, &TABLE_F64])
}
