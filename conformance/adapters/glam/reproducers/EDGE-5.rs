//! rotorcert reproducer: glam 0.34.3 (the version pinned in ../Cargo.lock), clause EDGE-5.
//!
//! EDGE-5 (spec/SPEC.md 9, eps16): a finite nonzero q means the rotation q/|q| at every scale the
//! format holds; NORM-1 asks for normalisation without intermediate overflow or underflow
//! (scaling by a power of two first). Quat::normalize / DQuat::normalize are
//! self * length_recip() with length = sqrt(dot(self, self)) (src/f64/dvec4.rs:601-603,
//! :626-628, :682-686; src/f32/sse2/vec4.rs:592-596, :651): the sum of squares overflows above
//! ~2^511 (binary64) / 2^63 (binary32) and underflows below ~2^-538 / 2^-75, giving zeros, Inf
//! or NaN. to_axis_angle and to_scaled_axis test |v| < 1e-8 (src/f64/dquat.rs:407,
//! src/f32/sse2/quat.rs:431) without normalising, so any small-scale q (|q| ~ 2^-100) is taken
//! for the identity whatever its rotation.
//! Upstream: no matching issue found in bitshifter/glam-rs (glam documents normalize as "For
//! valid results, self must _not_ be of length zero", nothing on scale).
//! Run: cargo run --release --manifest-path conformance/adapters/glam/Cargo.toml
//!      --target-dir build/adapters/glam/target --example EDGE-5
//! Exit 0: defect shown; 1: not shown (glam changed: update expected_failures.json).
#![allow(dead_code)]
use glam::{DQuat, Quat};

fn main() {
    println!("rotorcert reproducer: glam 0.34.3 EDGE-5: normalize overflows/underflows outside ~2^-75..2^63 (binary32) and ~2^-538..2^511 (binary64); to_axis_angle takes every small-scale q for the identity");
    let mut shown = false;

    // 1. binary32 normalize at scale 2^-100 (the suite's worst input): the sum of squares underflows to 0.
    let q: Vec<f64> = ["0x1.b8f03cp-102", "0x1.875a4cp-111", "-0x1.b04b1ep-104", "0x1.fa16f6p-101"].iter().map(|s| hexf(s)).collect();
    let got = Quat::from_xyzw(q[0] as f32, q[1] as f32, q[2] as f32, q[3] as f32).normalize().to_array();
    let got: Vec<f64> = got.iter().map(|&x| x as f64).collect();
    let n = q.iter().map(|x| (x * 2f64.powi(100)).powi(2)).sum::<f64>().sqrt() / 2f64.powi(100);
    let want: Vec<f64> = q.iter().map(|x| x / n).collect();
    let bad = got.iter().any(|x| !x.is_finite());
    shown |= bad;
    println!("call:    Quat::from_xyzw(x, y, z, w).normalize()   (binary32)");
    println!("input:   q = {}", hxs(&q));
    println!("library: {}{}", hxs(&got), if bad { "  <-- DEFECT" } else { "" });
    println!("correct: {} {}   (q/|q|, |q| computed in binary64 after scaling by 2^100)", hxs(&want), dec(&want));

    // 2. binary64 normalize of EX-NORM-1-f (components 2^1023): the sum of squares overflows.
    let q = [hexf("0x1p+1023"); 4];
    let got = DQuat::from_array(q).normalize().to_array();
    let bad = got.iter().any(|&x| (x - 0.5).abs() > 1e-15);
    shown |= bad;
    println!("call:    DQuat::from_xyzw(x, y, z, w).normalize()   (binary64, EX-NORM-1-f)");
    println!("input:   q = {}", hxs(&q));
    println!("library: {}{}", hxs(&got), if bad { "  <-- DEFECT" } else { "" });
    println!("correct: [0x1p-1, 0x1p-1, 0x1p-1, 0x1p-1]");

    // 3. binary64 to_axis_angle of a rotation by 5.82 rad given at scale 2^-900 (the suite's worst).
    let q: Vec<f64> = ["-0x1.7ea1c4e7c3393p-903", "-0x1.17c24d741ee46p-909", "-0x1.2f3e59d4968a2p-902", "-0x1.7b794964a3d49p-900"].iter().map(|s| hexf(s)).collect();
    let (axis, angle) = DQuat::from_xyzw(q[0], q[1], q[2], q[3]).to_axis_angle();
    let nv = q[..3].iter().map(|x| (x * 2f64.powi(900)).powi(2)).sum::<f64>().sqrt() / 2f64.powi(900);
    let theta = 2.0 * nv.atan2(q[3]);
    let u: Vec<f64> = q[..3].iter().map(|x| x / nv).collect();
    let bad = (angle - theta).abs() > 256.0 * f64::EPSILON;
    shown |= bad;
    println!("call:    DQuat::from_xyzw(x, y, z, w).to_axis_angle()   (binary64, |q| ~ 2^-900)");
    println!("input:   q = {}", hxs(&q));
    println!("library: axis = {}, angle = {}{}", hxs(&axis.to_array()), hx(angle), if bad { "  <-- DEFECT" } else { "" });
    println!("correct: axis = {} {}, angle = {} ({theta:.12})", hxs(&u), dec(&u), hx(theta));

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
