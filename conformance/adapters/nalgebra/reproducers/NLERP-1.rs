//! rotorcert reproducer: nalgebra 0.35.0 (the version pinned in ../Cargo.lock), clause NLERP-1.
//!
//! NLERP-1 (spec/SPEC.md 8.2, eps16): nlerp(a, b, t) = normalize((1 - t) a + t b') with b' = -b when
//! a.b < 0, so the sum never vanishes. UnitQuaternion::nlerp (src/geometry/quaternion.rs:1192-1197)
//! is documented as lerp then normalize, lerp = "self * (1 - t) + other * t" (:1162-1175), with no
//! hemisphere flip (declared nlerp:oriented, ACC-1: the long arc is accepted where the table
//! declares it, its error measured times the chord's length |s|, but s = 0 stays undefined, hence
//! FAIL). q and -q are the same rotation, and nlerp(q, -q, 1/2) is 0/0: NaN.
//! UnitQuaternion::slerp of the same pair flips and returns q.
//! Upstream: no matching issue found in dimforge/nalgebra.
//! Run: cargo run --release --manifest-path conformance/adapters/nalgebra/Cargo.toml
//!      --target-dir build/adapters/nalgebra/target --example NLERP-1
//! Exit 0: defect shown; 1: not shown (nalgebra changed: update expected_failures.json).
#![allow(dead_code)]
use nalgebra::{Quaternion, UnitQuaternion};

fn main() {
    println!("rotorcert reproducer: nalgebra 0.35.0 NLERP-1: UnitQuaternion::nlerp(q, -q, 1/2) is NaN (no hemisphere flip), though q and -q are one rotation");
    let mut shown = false;
    // EX-NLERP-1-d: a = 1, b = -1, t = 1/2.
    let (a, b, t): ([f64; 4], [f64; 4], f64) = ([0.0, 0.0, 0.0, 1.0], [0.0, 0.0, 0.0, -1.0], 0.5);
    let ua = UnitQuaternion::from_quaternion(Quaternion::new(a[3], a[0], a[1], a[2]));
    let ub = UnitQuaternion::from_quaternion(Quaternion::new(b[3], b[0], b[1], b[2]));
    let r = ua.nlerp(&ub, t);
    let got = [r.i, r.j, r.k, r.w];
    let s = ua.slerp(&ub, t);
    shown |= got.iter().any(|x| x.is_nan());
    println!("call:    UnitQuaternion::from_quaternion(a).nlerp(&UnitQuaternion::from_quaternion(b), t)   (f64; f32 alike)");
    println!("input:   a = {}, b = {}, t = {}   (EX-NLERP-1-d)", hxs(&a), hxs(&b), hx(t));
    println!("library: {}   (slerp of the same pair: {})", hxs(&got), hxs(&[s.i, s.j, s.k, s.w]));
    println!("correct: [0x0p+0, 0x0p+0, 0x0p+0, 0x1p+0] (b' = -b = a, the interpolation is constant)");

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

/// METRIC-1: the angle of the rotation separating a and b (each normalised first), sign-blind.
fn metric1(a: &[f64], b: &[f64]) -> f64 {
    let na = a.iter().map(|x| x * x).sum::<f64>().sqrt();
    let nb = b.iter().map(|x| x * x).sum::<f64>().sqrt();
    let (mut dm, mut dp) = (0.0, 0.0);
    for i in 0..4 {
        let (x, y) = (a[i] / na, b[i] / nb);
        dm += (x - y) * (x - y);
        dp += (x + y) * (x + y);
    }
    let (dm, dp) = (dm.sqrt(), dp.sqrt());
    4.0 * dm.min(dp).atan2(dm.max(dp))
}
