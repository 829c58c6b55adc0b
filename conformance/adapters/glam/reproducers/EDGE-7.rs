//! rotorcert reproducer: glam 0.34.3 (the version pinned in ../Cargo.lock), clause EDGE-7.
//!
//! EDGE-7 (spec/SPEC.md 9, class outcome): NaN or +-Inf in an input is DOMAIN_ERROR, every output
//! NaN (a library without a status channel: all outputs NaN, RESULT-2); status OK with some output
//! NaN or +-Inf is ACCEPTABLE (ACC-1 nonfinite_propagation): glam's normalize of (0, Inf, 0, 1) =
//! (0, NaN, 0, 0) and products with an infinite factor are. An all-finite answer to a non-finite
//! input stays a FAIL. DQuat::to_axis_angle (src/f64/dquat.rs:404-417; Quat: src/f32/sse2/quat.rs:
//! 427-441) tests `if length >= EPSILON` on |(x, y, z)|: a NaN there fails the test and the else
//! branch returns (DVec3::X, 0.0), the identity's answer, with no NaN left in it; to_scaled_axis
//! (:422, axis * angle, the adapter's log) returns 0 for it. The suite's worst input: to_angle
//! (to_axis_angle().1, glam has no angle-only query) of q with a NaN y. (For +-Inf in x, y or z the
//! angle is 2 atan2(Inf, w) = pi, and for w = +-Inf the pair is (v/|v|, 0 or 2 pi): the answers for
//! the rotation q/|q| tends to, ACCEPTABLE under ACC-1 nonfinite_limit since spec 2.7.0.)
//! glam documents no finiteness precondition on to_axis_angle; glam#512 / #527 only made
//! Vec*::normalize say "self must be finite".
//! Upstream: no matching issue found in bitshifter/glam-rs.
//! Run: cargo run --release --manifest-path conformance/adapters/glam/Cargo.toml
//!      --target-dir build/adapters/glam/target --example EDGE-7
//! Exit 0: defect shown; 1: not shown (glam changed: update expected_failures.json).
#![allow(dead_code)]
use glam::{DQuat, Quat};

fn finite(v: &[f64]) -> bool {
    v.iter().all(|x| x.is_finite())
}

fn main() {
    println!("rotorcert reproducer: glam 0.34.3 EDGE-7: to_axis_angle of a quaternion with a NaN component returns the identity's (X, 0), all finite");
    // The suite's worst input (to_angle, "NaN in q"), [x, y, z, w] as the report prints it, binary64
    // and binary32.
    let q = [hexf("-0x1.23e64e6838673p-1"), hexf("-nan"), hexf("-0x1.04e99a3543728p-2"), hexf("-0x1.5803222154743p-2")];
    let q32 = [hexf("-0x1.23e64ep-1"), hexf("-nan"), hexf("-0x1.04e99ap-2"), hexf("-0x1.580322p-2")];

    let (axis, angle) = DQuat::from_array(q).to_axis_angle();
    let scaled = DQuat::from_array(q).to_scaled_axis().to_array();
    let out = [axis.x, axis.y, axis.z, angle];
    let f = q32.map(|x| x as f32);
    let (axis32, angle32) = Quat::from_xyzw(f[0], f[1], f[2], f[3]).to_axis_angle();
    let out32 = [axis32.x as f64, axis32.y as f64, axis32.z as f64, angle32 as f64];

    let shown = !finite(&q) && (finite(&out) || finite(&scaled));
    let shown32 = !finite(&q32) && finite(&out32);
    println!("call:    DQuat::from_xyzw(x, y, z, w).to_axis_angle(), .to_scaled_axis() (and Quat, binary32)");
    println!("input:   q [x, y, z, w] = {}   (binary32: {})", hxs(&q), hxs(&q32));
    println!("library: axis = {}, angle = {}{}", hxs(&axis.to_array()), hx(angle), if finite(&out) { "  <-- the identity's answer: all finite" } else { "" });
    println!("         to_scaled_axis = {}{}", hxs(&scaled), if finite(&scaled) { "  <-- zero: the log of the identity" } else { "" });
    println!("         binary32: axis = {}, angle = {}", hxs(&out32[..3]), hx(out32[3]));
    println!("correct: DOMAIN_ERROR: angle NaN, axis [nan, nan, nan] (EDGE-7), or some output NaN/Inf (ACC-1 nonfinite_propagation)");
    if !(shown || shown32) {
        println!("DEFECT NOT SHOWN");
        std::process::exit(1);
    }
    println!("error:   an all-finite answer to a non-finite input: the NaN no longer reaches the caller");
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
