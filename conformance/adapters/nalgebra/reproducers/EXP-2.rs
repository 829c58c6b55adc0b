//! rotorcert reproducer: nalgebra 0.35.0 (the version pinned in ../Cargo.lock), clause EXP-2.
//!
//! EXP-2 (spec/SPEC.md 8.2, eps16, METRIC-1): exp(log q) = q for every unit q. With nalgebra's
//! own pair, UnitQuaternion::ln (src/geometry/quaternion.rs:1382-1389) and Quaternion::exp
//! (:518-558), exp(q.ln()) is q^2: ln returns axis() * angle() = theta u, twice the logarithm
//! (theta/2) u, as LOG-1 shows.
//! Upstream: known, https://github.com/dimforge/nalgebra/issues/1363 ("Unit Quaternion logarithm
//! inconsistent with exp", open: `p.ln().exp()` differs from `p`).
//! Run: cargo run --release --manifest-path conformance/adapters/nalgebra/Cargo.toml
//!      --target-dir build/adapters/nalgebra/target --example EXP-2
//! Exit 0: defect shown; 1: not shown (nalgebra changed: update expected_failures.json).
#![allow(dead_code)]
use nalgebra::{Quaternion, UnitQuaternion};

fn main() {
    // The suite's worst input (binary64).
    let q = [hexf("-0x1.5df13ed103f78p-6"), hexf("0x1.8dd5d87314e92p-1"), hexf("0x1.421acb4b7eb37p-1"), hexf("-0x1.a6a6fc2e90931p-12")];
    let unit = UnitQuaternion::from_quaternion(Quaternion::new(q[3], q[0], q[1], q[2]));
    let back = unit.ln().exp();
    let got = [back.i, back.j, back.k, back.w];
    let sq = unit.quaternion() * unit.quaternion();
    let q2 = [sq.i, sq.j, sq.k, sq.w];
    let err = metric1(&got, &q) / f64::EPSILON;

    println!("rotorcert reproducer: nalgebra 0.35.0 EXP-2: exp(q.ln()) is q^2, not q (UnitQuaternion::ln is twice the logarithm), {err:.3e} eps");
    println!("call:    UnitQuaternion::from_quaternion(Quaternion::new(w, x, y, z)).ln().exp()");
    println!("input:   q [x, y, z, w] = {}", hxs(&q));
    println!("library: {} {}", hxs(&got), dec(&got));
    println!("correct: q itself (up to sign); q^2 = {} for comparison", dec(&q2));
    println!("error:   {err:.3e} eps (METRIC-1; eps = 2^-52; loose bar 256 eps)");
    if err <= 256.0 {
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
