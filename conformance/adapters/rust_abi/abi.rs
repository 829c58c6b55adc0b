// The rotorcert C ABI, version 4 (impls/include/rotorcert/impl_abi.h), written out in Rust for a
// Rust adapter: the table structs with the header's field order, the batch loop with the status
// rule of RESULT-2, and the panic boundary. One file for every Rust adapter: each crate includes it
// with `#[path = "../../rust_abi/abi.rs"] mod abi;` (conformance/adapters/rust_abi/, installed and
// fingerprinted with the crates by scripts/setup-adapters).
//
// Layouts (LAYOUT-1): quaternion [x, y, z, w], vector [x, y, z], dual quaternion [real xyzw, dual
// xyzw], 3x3 matrix column-major m[c*3 + r], scalars one value. Element i of an input or output of
// width w starts at i * w.
//
// Status (RESULT-2): DOMAIN_ERROR when the library refuses the input (an Option it documents as
// None, a panic its documentation announces for that input) or when every output component is NaN;
// otherwise OK with the outputs as the library computed them. On DOMAIN_ERROR every output
// component is set to a quiet NaN, the outcome the ABI defines.
//
// Panics never cross the C ABI: every element runs inside catch_unwind. A panic the library does
// not document as its answer for that input is reported as what it is, a failure of the call, by
// the status byte PANICKED (255, neither OK nor DOMAIN_ERROR: the suite grades the element FAIL
// and names its input, as the scipy adapter does for a call that never returns), with the panic
// message on stderr. A build with panic = "abort" would turn every panic into a crash of the whole
// clause; Cargo.toml keeps the default unwinding.
#![allow(dead_code)]

use std::cell::RefCell;
use std::ffi::{c_char, c_int};
use std::panic::{self, AssertUnwindSafe};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Once;

pub const RC_ABI_VERSION: u32 = 4;
pub const RC_ABI_VERSION_MIN: u32 = 1;
pub const RC_OK: u8 = 0;
pub const RC_DOMAIN_ERROR: u8 = 1;
/// Not an ABI status: the library panicked where its documentation promises an answer.
pub const PANICKED: u8 = 255;
pub const RC_SCALAR_FLOAT32: u32 = 1;
pub const RC_SCALAR_FLOAT64: u32 = 2;
pub const RC_LEVEL_CORE: u32 = 1 << 0;
pub const RC_LEVEL_INTERP: u32 = 1 << 1;
pub const RC_LEVEL_BLEND: u32 = 1 << 2;
pub const RC_LEVEL_RIGID: u32 = 1 << 3;
pub const RC_LEVEL_SKINNING: u32 = 1 << 4;
pub const RC_LEVEL_ROBUST: u32 = 1 << 5;

pub type Fn1<S> = unsafe extern "C" fn(usize, *const S, *mut S, *mut u8) -> c_int;
pub type Fn2<S> = unsafe extern "C" fn(usize, *const S, *const S, *mut S, *mut u8) -> c_int;
pub type Fn1x2<S> = unsafe extern "C" fn(usize, *const S, *mut S, *mut S, *mut u8) -> c_int;
pub type Fn3<S> = unsafe extern "C" fn(usize, *const S, *const S, *const S, *mut S, *mut u8) -> c_int;
pub type Fn4<S> = unsafe extern "C" fn(usize, *const S, *const S, *const S, *const S, *mut S, *mut u8) -> c_int;
pub type Fn2x2<S> = unsafe extern "C" fn(usize, *const S, *const S, *mut S, *mut S, *mut u8) -> c_int;
pub type Fn4x2<S> =
    unsafe extern "C" fn(usize, *const S, *const S, *const S, *const S, *mut S, *mut S, *mut u8) -> c_int;
pub type FnBlend<S> = unsafe extern "C" fn(usize, usize, *const S, *const S, *mut S, *mut u8) -> c_int;
pub type FnSkin<S> =
    unsafe extern "C" fn(usize, usize, *const S, *const S, *const S, *const S, *mut S, *mut u8) -> c_int;

/// RC_ABI_OPS_V1 of abi_op_list.h, field for field (None is the NULL of NOT_SUPPORTED).
#[repr(C)]
pub struct Ops<S: 'static> {
    pub normalize: Option<Fn1<S>>,
    pub compose: Option<Fn2<S>>,
    pub inverse: Option<Fn1<S>>,
    pub apply_vector: Option<Fn2<S>>,
    pub apply_bivector: Option<Fn2<S>>,
    pub apply_trivector: Option<Fn2<S>>,
    pub to_matrix: Option<Fn1<S>>,
    pub from_matrix: Option<Fn1<S>>,
    pub to_axis_angle: Option<Fn1x2<S>>,
    pub from_axis_angle: Option<Fn2<S>>,
    pub log: Option<Fn1<S>>,
    pub exp: Option<Fn1<S>>,
    pub slerp: Option<Fn3<S>>,
    pub nlerp: Option<Fn3<S>>,
    pub blend_qlb: Option<FnBlend<S>>,
    pub blend_log: Option<FnBlend<S>>,
    pub dq_from_rotation_translation: Option<Fn2<S>>,
    pub dq_compose: Option<Fn2<S>>,
    pub dq_apply_point: Option<Fn2<S>>,
    pub dq_normalize: Option<Fn1<S>>,
    pub dq_sclerp: Option<Fn3<S>>,
    pub dq_blend: Option<FnBlend<S>>,
    pub rotate_about_axis: Option<Fn4<S>>,
    pub skin_linear: Option<FnSkin<S>>,
    pub skin_dual_quaternion: Option<FnSkin<S>>,
}

impl<S: 'static> Ops<S> {
    /// Every operation NOT_SUPPORTED; tables fill in what the library has (`..Ops::NONE`).
    pub const NONE: Self = Ops {
        normalize: None,
        compose: None,
        inverse: None,
        apply_vector: None,
        apply_bivector: None,
        apply_trivector: None,
        to_matrix: None,
        from_matrix: None,
        to_axis_angle: None,
        from_axis_angle: None,
        log: None,
        exp: None,
        slerp: None,
        nlerp: None,
        blend_qlb: None,
        blend_log: None,
        dq_from_rotation_translation: None,
        dq_compose: None,
        dq_apply_point: None,
        dq_normalize: None,
        dq_sclerp: None,
        dq_blend: None,
        rotate_about_axis: None,
        skin_linear: None,
        skin_dual_quaternion: None,
    };
}

/// RC_ABI_OPS_V3 of abi_op_list.h (ABI version 3), field for field: the operations read only from a
/// table whose abi_version is >= 3, in their own struct (rc_impl.f32_v3 / f64_v3).
#[repr(C)]
pub struct Ops3<S: 'static> {
    pub to_angle: Option<Fn1<S>>,
    pub to_axis: Option<Fn1<S>>,
    pub sqrt: Option<Fn1<S>>,
    pub dq_to_rotation_translation: Option<Fn1x2<S>>,
}

impl<S: 'static> Ops3<S> {
    /// Every version-3 operation NOT_SUPPORTED (`..Ops3::NONE`).
    pub const NONE: Self = Ops3 { to_angle: None, to_axis: None, sqrt: None, dq_to_rotation_translation: None };
}

/// RC_ABI_OPS_V4 of abi_op_list.h (ABI version 4), field for field: the operations read only from a
/// table whose abi_version is >= 4, in their own struct (rc_impl.f32_v4 / f64_v4). Layouts: a dual
/// vector [xi_r xyz, xi_d xyz] (6 scalars); a rigid transform as a quaternion q and a vector t.
#[repr(C)]
pub struct Ops4<S: 'static> {
    /// DQ-8: (d, out_xi)
    pub dq_log: Option<Fn1<S>>,
    /// DQ-9: (xi, out_d)
    pub dq_exp: Option<Fn1<S>>,
    /// RIGID-1: (qa, ta, qb, tb, out_q, out_t)
    pub rigid_compose: Option<Fn4x2<S>>,
    /// RIGID-2: (q, t, p, out_p)
    pub rigid_apply: Option<Fn3<S>>,
    /// RIGID-3: (q, t, out_q, out_t)
    pub rigid_inverse: Option<Fn2x2<S>>,
}

impl<S: 'static> Ops4<S> {
    /// Every version-4 operation NOT_SUPPORTED (`..Ops4::NONE`).
    pub const NONE: Self =
        Ops4 { dq_log: None, dq_exp: None, rigid_compose: None, rigid_apply: None, rigid_inverse: None };
}

/// A NULL-terminated list of C strings (clauses, preconditions, conventions).
#[repr(transparent)]
pub struct StrList<const N: usize>(pub [*const c_char; N]);
// SAFETY: the pointers are to 'static, immutable string literals.
unsafe impl<const N: usize> Sync for StrList<N> {}

/// `str_list!["NORM-1", "COMPOSE-1"]`: a StrList with the terminating NULL.
#[macro_export]
macro_rules! str_list {
    ($($s:expr),* $(,)?) => {
        $crate::abi::StrList([$(concat!($s, "\0").as_ptr() as *const ::std::ffi::c_char,)* ::std::ptr::null()])
    };
}

/// `cstr!("text")`: a pointer to a 'static NUL-terminated literal.
#[macro_export]
macro_rules! cstr {
    ($s:expr) => {
        concat!($s, "\0").as_ptr() as *const ::std::ffi::c_char
    };
}

/// rc_impl of impl_abi.h (version 4 layout: the version-2 fields, then f32_v3 / f64_v3, then
/// f32_v4 / f64_v4, of each pair at most the one of `scalar` is set).
#[repr(C)]
pub struct Impl {
    pub abi_version: u32,
    pub name: *const c_char,
    pub version: *const c_char,
    pub description: *const c_char,
    pub scalar: u32,
    pub levels: u32,
    pub clauses: *const *const c_char,
    pub f32: *const Ops<f32>,
    pub f64: *const Ops<f64>,
    pub simd_targets: *const *const c_char,
    pub select_target: Option<unsafe extern "C" fn(*const c_char) -> c_int>,
    pub current_target: Option<unsafe extern "C" fn() -> *const c_char>,
    pub preconditions: *const *const c_char,
    pub conventions: *const *const c_char,
    pub f32_v3: *const Ops3<f32>,
    pub f64_v3: *const Ops3<f64>,
    pub f32_v4: *const Ops4<f32>,
    pub f64_v4: *const Ops4<f64>,
}
// SAFETY: a table is immutable and points only to 'static data.
unsafe impl Sync for Impl {}

/// The body of rotorcert_impl_entry: the index-th table for a supported ABI version (a newer table
/// is an older one with fields appended: a host asking for version 1 or 2 reads its prefix).
pub fn entry(abi_version: u32, index: u32, tables: &[&'static Impl]) -> *const Impl {
    if !(RC_ABI_VERSION_MIN..=RC_ABI_VERSION).contains(&abi_version) {
        return std::ptr::null();
    }
    install_panic_hook();
    match tables.get(index as usize) {
        Some(t) => *t as *const Impl,
        None => std::ptr::null(),
    }
}

pub trait Real: Copy + 'static {
    const NAN: Self;
    const ZERO: Self;
    fn is_nan_(self) -> bool;
    fn hex(self) -> String;
}

impl Real for f32 {
    const NAN: Self = f32::NAN;
    const ZERO: Self = 0.0;
    fn is_nan_(self) -> bool {
        self.is_nan()
    }
    fn hex(self) -> String {
        hexfloat(self as f64, 126)
    }
}

impl Real for f64 {
    const NAN: Self = f64::NAN;
    const ZERO: Self = 0.0;
    fn is_nan_(self) -> bool {
        self.is_nan()
    }
    fn hex(self) -> String {
        hexfloat(self, 1022)
    }
}

/// C99 %a-style hexfloat of a value of a format whose smallest normal exponent is -emin (for the
/// panic report).
fn hexfloat(x: f64, emin: i32) -> String {
    if x.is_nan() {
        return "nan".into();
    }
    if x.is_infinite() {
        return if x < 0.0 { "-inf".into() } else { "inf".into() };
    }
    let sign = if x.is_sign_negative() { "-" } else { "" };
    if x == 0.0 {
        return format!("{sign}0x0p+0");
    }
    let bits = x.abs().to_bits();
    let (mut e, mut m) = (((bits >> 52) & 0x7ff) as i32 - 1023, bits & ((1u64 << 52) - 1));
    let mut lead = 1;
    if e == -1023 {
        e = -1022;
        lead = 0;
    }
    if lead == 1 && e < -emin {
        // a subnormal of the narrower format: print it as that format does
        let shift = (-emin - e) as u32;
        m = ((1u64 << 52) | m) >> shift;
        e = -emin;
        lead = 0;
    }
    let mut frac = format!("{m:013x}");
    while frac.ends_with('0') {
        frac.pop();
    }
    let dot = if frac.is_empty() { String::new() } else { format!(".{frac}") };
    format!("{sign}0x{lead}{dot}p{e:+}")
}

/// What a library call answered for one element.
pub enum Answer {
    /// Outputs written (the status rule still makes an all-NaN answer DOMAIN_ERROR).
    Value,
    /// The library refused the input through its API (None of a try_ function): DOMAIN_ERROR.
    Refused,
}

/// How a panic of the library is graded for an operation.
#[derive(Clone, Copy)]
pub enum Panics {
    /// Its documentation announces the panic for inputs it does not interpolate or convert
    /// (e.g. nalgebra's slerp "Panics if the angle between both quaternion is 180 degrees"):
    /// DOMAIN_ERROR, the library's refusal.
    Refusal,
    /// Not documented for any input: a defect, reported with status PANICKED.
    Defect,
}

thread_local! {
    static LAST_PANIC: RefCell<String> = const { RefCell::new(String::new()) };
}
static HOOK: Once = Once::new();
static REPORTED: AtomicUsize = AtomicUsize::new(0);

/// The panic hook of this library: the message is kept for the batch loop, which decides whether
/// it is a refusal (silent) or a defect (reported); nothing is printed from inside the hook.
fn install_panic_hook() {
    HOOK.call_once(|| {
        panic::set_hook(Box::new(|info| {
            let msg = if let Some(s) = info.payload().downcast_ref::<&str>() {
                (*s).to_string()
            } else if let Some(s) = info.payload().downcast_ref::<String>() {
                s.clone()
            } else {
                "(non-string panic payload)".to_string()
            };
            let at = info.location().map(|l| format!(" at {}:{}", l.file(), l.line())).unwrap_or_default();
            LAST_PANIC.with(|p| *p.borrow_mut() = format!("{msg}{at}"));
        }));
    });
}

pub const MAX_WIDTH: usize = 9;

/// The batch loop of every operation: element i of each input (pointer, width) is copied out, the
/// element function called inside catch_unwind, the status decided (RESULT-2) and the outputs
/// written, all NaN on DOMAIN_ERROR or PANICKED.
///
/// # Safety
/// The pointers are those the suite passes: n elements of each width, outputs not overlapping
/// inputs of the same element in a way that matters (inputs are copied before any output is
/// written).
pub unsafe fn run<S: Real, const NI: usize, const NO: usize>(
    lib: &str,
    op: &str,
    n: usize,
    ins: [(*const S, usize); NI],
    outs: [(*mut S, usize); NO],
    status: *mut u8,
    panics: Panics,
    f: impl Fn(&[[S; MAX_WIDTH]; NI], &mut [[S; MAX_WIDTH]; NO]) -> Answer,
) -> c_int {
    if n > 0 && status.is_null() {
        return 1;
    }
    for i in 0..n {
        let mut input = [[S::ZERO; MAX_WIDTH]; NI];
        for (a, &(p, w)) in ins.iter().enumerate() {
            input[a][..w].copy_from_slice(std::slice::from_raw_parts(p.add(i * w), w));
        }
        let mut output = [[S::NAN; MAX_WIDTH]; NO];
        let answer = panic::catch_unwind(AssertUnwindSafe(|| f(&input, &mut output)));
        let st = match answer {
            Ok(Answer::Refused) => RC_DOMAIN_ERROR,
            Ok(Answer::Value) => {
                let all_nan = outs.iter().enumerate().all(|(a, &(_, w))| output[a][..w].iter().all(|x| x.is_nan_()));
                if all_nan {
                    RC_DOMAIN_ERROR
                } else {
                    RC_OK
                }
            }
            Err(_) => match panics {
                Panics::Refusal => RC_DOMAIN_ERROR,
                Panics::Defect => {
                    if REPORTED.fetch_add(1, Ordering::Relaxed) < 20 {
                        let msg = LAST_PANIC.with(|p| p.borrow().clone());
                        let args: Vec<String> = ins
                            .iter()
                            .enumerate()
                            .map(|(a, &(_, w))| {
                                let v: Vec<String> = input[a][..w].iter().map(|x| x.hex()).collect();
                                format!("[{}]", v.join(", "))
                            })
                            .collect();
                        eprintln!(
                            "rotorcert adapter {lib}: {op} panicked (status {PANICKED}, FAIL) on {}: {msg}",
                            args.join(" ")
                        );
                    }
                    PANICKED
                }
            },
        };
        if st != RC_OK {
            for o in output.iter_mut() {
                o.fill(S::NAN);
            }
        }
        for (a, &(p, w)) in outs.iter().enumerate() {
            std::slice::from_raw_parts_mut(p.add(i * w), w).copy_from_slice(&output[a][..w]);
        }
        *status.add(i) = st;
    }
    0
}
