//! rotorcert reproducer: glam 0.34.3 (the version pinned in ../Cargo.lock), clause EDGE-8.
//!
//! EDGE-8 (spec/SPEC.md 9, eps4): subnormal components are ordinary nonzero values:
//! normalize((2^-1074, -0, 0, 0)) = (1, -0, 0, 0). Quat::normalize / DQuat::normalize compute
//! self * (1 / sqrt(dot(self, self))) (src/f64/dvec4.rs:601-603, :626-628, :682-686;
//! src/f32/sse2/vec4.rs:592-596, :651): the squares of subnormals underflow to 0, 1/0 = Inf and
//! Inf * 0 = NaN. to_scaled_axis (via to_axis_angle's |v| < 1e-8 test, src/f64/dquat.rs:407)
//! returns the zero vector for a quaternion whose vector part is subnormal but whose rotation is a
//! half turn or more.
//! Upstream: no matching issue found in bitshifter/glam-rs.
//! Run: cargo run --release --manifest-path conformance/adapters/glam/Cargo.toml
//!      --target-dir build/adapters/glam/target --example EDGE-8
//! Exit 0: defect shown; 1: not shown (glam changed: update expected_failures.json).
#![allow(dead_code)]
use glam::{DQuat, Quat};

fn main() {
    println!("rotorcert reproducer: glam 0.34.3 EDGE-8: normalize of subnormal quaternions gives Inf and NaN; to_scaled_axis of a subnormal vector part is 0");
    let mut shown = false;

    // EX-EDGE-8-a, binary64.
    let q = [hexf("0x0.0000000000001p-1022"), hexf("-0x0p+0"), 0.0, 0.0];
    let got = DQuat::from_array(q).normalize().to_array();
    let bad = got.iter().any(|x| !x.is_finite());
    shown |= bad;
    println!("call:    DQuat::from_xyzw(x, y, z, w).normalize()   (binary64, EX-EDGE-8-a)");
    println!("input:   q = {}", hxs(&q));
    println!("library: {}{}", hxs(&got), if bad { "  <-- DEFECT" } else { "" });
    println!("correct: [0x1p+0, -0x0p+0, 0x0p+0, 0x0p+0]");

    // EX-NORM-1-i in binary32: (0, 0, 1.5 2^-140, 2^-139) = 2^-140 (0, 0, 1.5, 2).
    let q = [0.0, 0.0, hexf("0x1.8p-140"), hexf("0x1p-139")];
    let got: Vec<f64> = Quat::from_xyzw(0.0, 0.0, q[2] as f32, q[3] as f32).normalize().to_array().iter().map(|&x| x as f64).collect();
    let bad = got.iter().any(|x| !x.is_finite());
    shown |= bad;
    println!("call:    Quat::from_xyzw(x, y, z, w).normalize()   (binary32, EX-NORM-1-i)");
    println!("input:   q = {}", hxs(&q));
    println!("library: {}{}", hxs(&got), if bad { "  <-- DEFECT" } else { "" });
    println!("correct: [0x0p+0, 0x0p+0, 0x1.3333333333333p-1, 0x1.999999999999ap-1] (0, 0, 0.6, 0.8)");

    // to_scaled_axis of a quarter-plus turn whose vector part is subnormal (w = -0).
    let q = [hexf("0x0.00000000008p-1022"), hexf("0x0.000000000001p-1022"), hexf("0x0.00000000000ap-1022"), hexf("-0x0p+0")];
    let rv = DQuat::from_array(q).to_scaled_axis().to_array();
    let nv = q[..3].iter().map(|x| (x * 2f64.powi(1000)).powi(2)).sum::<f64>().sqrt() / 2f64.powi(1000);
    let theta = 2.0 * nv.atan2(q[3]);
    let want: Vec<f64> = q[..3].iter().map(|x| theta * (x / nv)).collect();
    let bad = rv.iter().all(|&x| x == 0.0);
    shown |= bad;
    println!("call:    DQuat::from_xyzw(x, y, z, w).to_scaled_axis()   (binary64)");
    println!("input:   q = {}", hxs(&q));
    println!("library: {}{}", hxs(&rv), if bad { "  <-- DEFECT" } else { "" });
    println!("correct: theta u = {} {} (theta = {theta:.12}, a half turn)", hxs(&want), dec(&want));

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
