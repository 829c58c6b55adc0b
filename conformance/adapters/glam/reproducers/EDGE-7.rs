//! rotorcert reproducer: glam 0.34.3 (the version pinned in ../Cargo.lock), clause EDGE-7.
//!
//! EDGE-7 (spec/SPEC.md 9, class outcome): NaN or +-Inf in an input is DOMAIN_ERROR, every output
//! NaN (a library without a status channel: all outputs NaN, RESULT-2). glam has no finiteness
//! check in the calls that document no precondition: Quat::normalize (self * length_recip(),
//! src/f64/dvec4.rs:682-686) of (0, Inf, 0, 1) is (0, NaN, 0, 0), finite components and all;
//! to_axis_angle (src/f64/dquat.rs:404-417) of a NaN quaternion fails its `length >= EPSILON` test
//! and returns the identity (X, 0.0); Quat * Quat (mul_quat, :769-777) with an infinite factor
//! gives infinities. (Ops with a documented precondition, unit or finite input, are not judged on
//! non-finite input.)
//! Upstream: no matching issue found in bitshifter/glam-rs.
//! Run: cargo run --release --manifest-path conformance/adapters/glam/Cargo.toml
//!      --target-dir build/adapters/glam/target --example EDGE-7
//! Exit 0: defect shown; 1: not shown (glam changed: update expected_failures.json).
#![allow(dead_code)]
use glam::{DQuat, Quat};

fn all_nan(v: &[f64]) -> bool {
    v.iter().all(|x| x.is_nan())
}

fn main() {
    println!("rotorcert reproducer: glam 0.34.3 EDGE-7: non-finite input gives partly finite output with no error (normalize, to_axis_angle, mul_quat)");
    let mut shown = false;
    let inf = f64::INFINITY;
    let nan = f64::NAN;

    // EX-EDGE-7-b: normalize((0, Inf, 0, 1)), binary64 and binary32.
    let q = [0.0, inf, 0.0, 1.0];
    let got = DQuat::from_array(q).normalize().to_array();
    let got32: Vec<f64> = Quat::from_xyzw(0.0, f32::INFINITY, 0.0, 1.0).normalize().to_array().iter().map(|&x| x as f64).collect();
    shown |= !all_nan(&got) || !all_nan(&got32);
    println!("call:    DQuat::from_xyzw(x, y, z, w).normalize() (and Quat, binary32)");
    println!("input:   q = {}", hxs(&q));
    println!("library: {} (binary32: {}){}", hxs(&got), hxs(&got32), if !all_nan(&got) { "  <-- not all NaN: status OK" } else { "" });

    // to_axis_angle of a NaN quaternion: the identity.
    let q = [nan, 0.0, 0.0, 1.0];
    let (axis, angle) = DQuat::from_array(q).to_axis_angle();
    let out = [angle, axis.x, axis.y, axis.z];
    shown |= !all_nan(&out);
    println!("call:    DQuat::from_xyzw(x, y, z, w).to_axis_angle()");
    println!("input:   q = {}", hxs(&q));
    println!("library: axis = {}, angle = {}{}", hxs(&axis.to_array()), hx(angle), if !all_nan(&out) { "  <-- a finite answer" } else { "" });

    // compose with an infinite factor.
    let a = [0.0, inf, 0.0, 1.0];
    let b = [0.1, 0.2, 0.3, 0.9];
    let got = (DQuat::from_array(a) * DQuat::from_array(b)).to_array();
    shown |= !all_nan(&got);
    println!("call:    DQuat::from_xyzw(a) * DQuat::from_xyzw(b)");
    println!("input:   a = {}, b = {}", hxs(&a), hxs(&b));
    println!("library: {}{}", hxs(&got), if !all_nan(&got) { "  <-- not all NaN: status OK" } else { "" });

    println!("correct: DOMAIN_ERROR: every output NaN (EDGE-7; glam has no error channel)");
    println!("{}", if shown { "DEFECT SHOWN" } else { "DEFECT NOT SHOWN" });
    std::process::exit(if shown { 0 } else { 1 });
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
