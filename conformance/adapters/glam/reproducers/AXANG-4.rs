//! rotorcert reproducer: glam 0.34.3 (the version pinned in ../Cargo.lock), clause AXANG-4.
//!
//! AXANG-4 (spec/SPEC.md 6, level Extended, tolerance eps16, METRIC-3 with s = 1): the axis alone,
//! u = v/|v|; any unit axis only for the identity (v = 0, ACC-1 identity_axis), and -u is
//! ACCEPTABLE where w < 0 (ACC-1 angle_range). glam has no axis-only query: its axis is
//! Quat::to_axis_angle().0 / DQuat::to_axis_angle().0 (src/f32/sse2/quat.rs:427-441,
//! src/f64/dquat.rs:404-417), which returns Vec3::X whenever |v| < EPSILON = 1e-8 (both types):
//! for every rotation within 2e-8 rad of the identity or of a full turn the axis is x, although
//! v/|v| is exact there (in binary32 too: w rounds to +-1 but x, y, z keep the axis). As a rotation
//! (to_axis_angle, AXANG-1) the binary32 answer is within the bars; the axis alone is not.
//! Upstream: no matching issue found in bitshifter/glam-rs.
//! Run: cargo run --release --manifest-path conformance/adapters/glam/Cargo.toml
//!      --target-dir build/adapters/glam/target --example AXANG-4
//! Exit 0: defect shown; 1: not shown (glam changed: update expected_failures.json).
#![allow(dead_code)]
use glam::{DQuat, Quat};

/// The axis error (METRIC-3) of `got` against v/|v| of q, and against -v/|v| (acceptable, w < 0).
fn errs(q: &[f64; 4], got: &[f64; 3]) -> (f64, f64) {
    let nv = (q[0] * q[0] + q[1] * q[1] + q[2] * q[2]).sqrt();
    let e = (0..3).map(|i| (got[i] - q[i] / nv).powi(2)).sum::<f64>().sqrt();
    let f = (0..3).map(|i| (got[i] + q[i] / nv).powi(2)).sum::<f64>().sqrt();
    (e, f)
}

fn main() {
    println!("rotorcert reproducer: glam 0.34.3 AXANG-4: Quat/DQuat::to_axis_angle().0 is x for every rotation within 2e-8 rad of a full turn or of the identity (|v| < 1e-8)");
    // The suite's worst inputs (worst-case search from near a full turn), binary64 and binary32.
    let q = [hexf("-0x1.3292a6807a3c9p-30"), hexf("-0x1.c973b08ee3e11p-34"), hexf("-0x1.2d52a5d7c1a42p-33"), hexf("-0x1p+0")];
    let axis = DQuat::from_xyzw(q[0], q[1], q[2], q[3]).to_axis_angle().0.to_array();
    let (e64, m64) = errs(&q, &axis);
    let q32 = [hexf("-0x1.32abdap-30") as f32, hexf("-0x1.c96a3ep-34") as f32, hexf("-0x1.2d425cp-33") as f32, hexf("-0x1p+0") as f32];
    let a32 = Quat::from_xyzw(q32[0], q32[1], q32[2], q32[3]).to_axis_angle().0.to_array();
    let q32d = q32.map(|x| x as f64);
    let a32d = a32.map(|x| x as f64);
    let (e32, m32) = errs(&q32d, &a32d);
    let nv = |q: &[f64; 4]| (q[0] * q[0] + q[1] * q[1] + q[2] * q[2]).sqrt();
    let u = |q: &[f64; 4]| [q[0] / nv(q), q[1] / nv(q), q[2] / nv(q)];
    println!("call:    DQuat::from_xyzw(x, y, z, w).to_axis_angle().0 (binary64), Quat::... (binary32)");
    println!("input:   q [x, y, z, w] = {} (binary64, |v| = {:.3e})", hxs(&q), nv(&q));
    println!("library: axis = {}", hxs(&axis));
    println!("correct: axis = v/|v| = {} {}", hxs(&u(&q)), dec(&u(&q)));
    println!("error:   {:.3e} eps (METRIC-3; eps = 2^-52; loose bar 256 eps); {:.3e} eps against -u (acceptable, w < 0)", e64 / f64::EPSILON, m64 / f64::EPSILON);
    println!("input:   q [x, y, z, w] = {} (binary32, |v| = {:.3e})", hxs(&q32d), nv(&q32d));
    println!("library: axis = {}", hxs(&a32d));
    println!("correct: axis = v/|v| = {} {}", hxs(&u(&q32d)), dec(&u(&q32d)));
    println!("error:   {:.3e} eps (METRIC-3; eps = 2^-23; loose bar 256 eps); {:.3e} eps against -u", e32 / f32::EPSILON as f64, m32 / f32::EPSILON as f64);
    if m64.min(e64) / f64::EPSILON <= 256.0 || m32.min(e32) / (f32::EPSILON as f64) <= 256.0 {
        println!("DEFECT NOT SHOWN");
        std::process::exit(1);
    }
    println!("DEFECT SHOWN");
}

// ---- helpers: exact hexfloat input and output, the spec's metrics (each reproducer is standalone) ----

/// The exact value of a C99 hexfloat literal such as "-0x1.8p-999" or "0x0.0000000000001p-1022".
fn hexf(s: &str) -> f64 {
    let (neg, body) = match s.strip_prefix('-') {
        Some(r) => (true, r),
        None => (false, s),
    };
    let v = match body {
        "inf" => f64::INFINITY,
        "nan" => f64::NAN,
        _ => {
            let body = body.strip_prefix("0x").expect("a hexfloat starts with 0x");
            let (mant, exp) = body.split_once('p').expect("a hexfloat has an exponent");
            let (int, frac) = mant.split_once('.').unwrap_or((mant, ""));
            let mut m: u64 = 0;
            for c in int.chars().chain(frac.chars()) {
                m = m * 16 + c.to_digit(16).expect("hex digit") as u64;
            }
            let mut e: i32 = exp.parse::<i32>().expect("exponent") - 4 * frac.len() as i32;
            let mut v = m as f64; // exact: the literals here have at most 53 significant bits
            while e > 0 {
                let k = e.min(1000);
                v *= 2f64.powi(k);
                e -= k;
            }
            while e < 0 {
                let k = (-e).min(1000);
                v /= 2f64.powi(k); // exact until the last step, which rounds once (subnormals)
                e += k;
            }
            v
        }
    };
    if neg {
        -v
    } else {
        v
    }
}

/// C99 %a of a binary64 value (a binary32 value converted exactly prints the same digits).
fn hx(x: f64) -> String {
    if x.is_nan() {
        return "nan".into();
    }
    let sign = if x.is_sign_negative() { "-" } else { "" };
    if x.is_infinite() {
        return format!("{sign}inf");
    }
    let bits = x.to_bits();
    let (e, m) = (((bits >> 52) & 0x7ff) as i32, bits & ((1u64 << 52) - 1));
    if e == 0 && m == 0 {
        return format!("{sign}0x0p+0");
    }
    let (lead, exp) = if e == 0 { (0, -1022) } else { (1, e - 1023) };
    let frac = format!("{m:013x}");
    let frac = frac.trim_end_matches('0');
    let dot = if frac.is_empty() { String::new() } else { format!(".{frac}") };
    format!("{sign}0x{lead}{dot}p{exp:+}")
}

fn hxs(v: &[f64]) -> String {
    format!("[{}]", v.iter().map(|&x| hx(x)).collect::<Vec<_>>().join(", "))
}

fn dec(v: &[f64]) -> String {
    format!("[{}]", v.iter().map(|x| format!("{x:.12}")).collect::<Vec<_>>().join(", "))
}
