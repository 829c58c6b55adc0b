// rotorcert adapter for glam (https://github.com/bitshifter/glam-rs), the crate version pinned in
// Cargo.toml / Cargo.lock, built with its default features (std, all-types; not `glam-assert`, so
// the documented "Will panic if ... is not normalized when glam_assert is enabled" assertions are
// compiled out, as in every default build of a glam user).
//
// A cdylib exporting rotorcert_impl_entry (impls/include/rotorcert/impl_abi.h, ABI version 4) with
// two tables named "glam": index 0 binary32 (glam::Quat, Vec3, Mat3; Quat is glam's SSE2 type on
// x86_64), index 1 binary64 (glam::DQuat, DVec3, DMat3). scripts/setup-adapters builds it with
// `cargo build --release --locked` into the adapter's environment; `rotorcert thirdparty` loads
// it from there. The ops are in ops.rs, the ABI and the panic boundary in abi.rs; every convention
// mapping and declaration is stated in adapter.json.

#[path = "../../rust_abi/abi.rs"]
mod abi;

use abi::*;

pub mod f32 {
    pub type S = f32;
    pub type Q = glam::Quat;
    pub type V = glam::Vec3;
    pub type M = glam::Mat3;
    pub type A = glam::Affine3A;
    include!("ops.rs");
}

pub mod f64 {
    pub type S = f64;
    pub type Q = glam::DQuat;
    pub type V = glam::DVec3;
    pub type M = glam::DMat3;
    pub type A = glam::DAffine3;
    include!("ops.rs");
}

/// Clauses whose operations glam has (no bivectors, trivectors, blends, dual quaternions or
/// skinning: those levels are not claimed).
static CLAUSES: StrList<34> = str_list![
    // Core (APPLY-2, APPLY-3: glam has no bivectors or trivectors)
    "QUAT-2", "NORM-1", "COMPOSE-1", "INV-1", "APPLY-1", "MAT-1", "MAT-2", "AXANG-1", "AXANG-2",
    // Extended (no SQRT-1, DQ-7, DQ-8, DQ-9: glam has no square root and no dual quaternions;
    // RIGID-1..3: Affine3A / DAffine3 from_rotation_translation)
    "AXANG-3", "AXANG-4", "RIGID-1", "RIGID-2", "RIGID-3",
    // Interp
    "LOG-1", "LOG-2", "EXP-1", "EXP-2", "SLERP-1", "SLERP-2", "SLERP-3", "SLERP-4", "SLERP-5", "NLERP-1",
    // Robust (EDGE-9 judges weighted ops only)
    "MAT-3", "EDGE-1", "EDGE-2", "EDGE-3", "EDGE-4", "EDGE-5", "EDGE-6", "EDGE-7", "EDGE-8",
];

/// DECL-1, glam's documentation (doc comments of src/f32/sse2/quat.rs and src/f64/dquat.rs, the
/// same text; citations in adapter.json).
static PRECONDITIONS: StrList<12> = str_list![
    "inverse:unit_quaternion",
    "rigid_compose:unit_quaternion",
    "rigid_apply:unit_quaternion",
    "rigid_inverse:unit_quaternion",
    "apply_vector:unit_quaternion",
    "to_matrix:unit_quaternion",
    "from_matrix:rotation_matrix",
    "from_axis_angle:unit_axis",
    "slerp:unit_quaternion",
    "nlerp:unit_quaternion",
    "exp:finite",
];

/// Conventions glam chose where the spec allows several answers (citations in adapter.json).
/// to_angle and to_axis are the two outputs of to_axis_angle, glam's one call for either: EDGE-7
/// judges that call whole (ACC-1 output_of_to_axis_angle).
static CONVENTIONS: StrList<6> = str_list![
    "from_matrix:sign",
    "to_axis_angle:identity_axis",
    "to_axis:identity_axis",
    "to_angle:output_of_to_axis_angle",
    "to_axis:output_of_to_axis_angle",
];

const LEVELS: u32 = RC_LEVEL_CORE | RC_LEVEL_INTERP | RC_LEVEL_ROBUST;
/// The version string of both tables: the pinned crate and how it is built.
macro_rules! version {
    () => {
        "glam 0.34.3 (default features: std, all-types; no glam-assert)"
    };
}

static TABLE_F32: Impl = Impl {
    abi_version: RC_ABI_VERSION,
    name: cstr!("glam"),
    version: cstr!(version!()),
    description: cstr!("glam 0.34.3 glam::Quat (binary32, SSE2 on x86_64), Vec3, Mat3; see adapter.json"),
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
    name: cstr!("glam"),
    version: cstr!(version!()),
    description: cstr!("glam 0.34.3 glam::DQuat (binary64), DVec3, DMat3; see adapter.json"),
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
