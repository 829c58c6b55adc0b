//! rotorcert reproducer: nalgebra 0.35.0 (the version pinned in ../Cargo.lock), clause EDGE-8.
//!
//! EDGE-8 (spec/SPEC.md 9, eps4): subnormal components are ordinary nonzero values:
//! normalize((2^-1074, -0, 0, 0)) = (1, -0, 0, 0). Quaternion::normalize and
//! UnitQuaternion::from_quaternion divide by sqrt(norm_squared()) (src/base/norm.rs:257-262): the
//! squares of subnormals underflow to 0, the division gives Inf and NaN, and every op on a
//! UnitQuaternion made from such a quaternion (apply, to_matrix, slerp) returns NaN.
//! Upstream: no matching issue found in dimforge/nalgebra.
//! Run: cargo run --release --manifest-path conformance/adapters/nalgebra/Cargo.toml
//!      --target-dir build/adapters/nalgebra/target --example EDGE-8
//! Exit 0: defect shown; 1: not shown (nalgebra changed: update expected_failures.json).
#![allow(dead_code)]
use nalgebra::{Quaternion, UnitQuaternion, Vector3};

fn main() {
    println!("rotorcert reproducer: nalgebra 0.35.0 EDGE-8: normalize of subnormal quaternions gives Inf and NaN; rotations built from them are NaN");
    let mut shown = false;
    // EX-EDGE-8-a.
    let q = [hexf("0x0.0000000000001p-1022"), hexf("-0x0p+0"), 0.0, 0.0];
    let n = Quaternion::new(q[3], q[0], q[1], q[2]).normalize();
    let got = [n.i, n.j, n.k, n.w];
    let bad = got.iter().any(|x| !x.is_finite());
    shown |= bad;
    println!("call:    Quaternion::new(w, x, y, z).normalize()   (f64, EX-EDGE-8-a)");
    println!("input:   q [x, y, z, w] = {}", hxs(&q));
    println!("library: {}{}", hxs(&got), if bad { "  <-- DEFECT" } else { "" });
    println!("correct: [0x1p+0, -0x0p+0, 0x0p+0, 0x0p+0]");
    // EX-EDGE-8-f: apply a subnormal quaternion (a half turn about (0, 0, 1)/... scaled by 2^-1074).
    let q = [0.0, 0.0, hexf("0x0.0000000000001p-1022"), hexf("0x0.0000000000001p-1022")];
    let v = [1.0, 0.0, 0.0];
    let r = UnitQuaternion::from_quaternion(Quaternion::new(q[3], q[0], q[1], q[2])) * Vector3::new(v[0], v[1], v[2]);
    let got = [r.x, r.y, r.z];
    let bad = got.iter().any(|x| !x.is_finite());
    shown |= bad;
    println!("call:    UnitQuaternion::from_quaternion(Quaternion::new(w, x, y, z)) * Vector3::new(1, 0, 0)   (f64, EX-EDGE-8-f)");
    println!("input:   q [x, y, z, w] = {}, v = {}", hxs(&q), hxs(&v));
    println!("library: {}{}", hxs(&got), if bad { "  <-- DEFECT" } else { "" });
    println!("correct: [0x0p+0, 0x1p+0, 0x0p+0] (q/|q| = (0, 0, 1, 1)/sqrt 2, a quarter turn about z)");
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
