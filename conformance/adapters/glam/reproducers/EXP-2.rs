//! rotorcert reproducer: glam 0.34.3 (the version pinned in ../Cargo.lock), clause EXP-2.
//!
//! EXP-2 (spec/SPEC.md 8.2, eps16, METRIC-1): exp(log q) = q for every unit q. With glam's
//! rotation-vector pair, from_scaled_axis(to_scaled_axis(q)) must give back the rotation of q.
//! DQuat::to_scaled_axis goes through to_axis_angle, which returns (X, 0) whenever |v| < 1e-8
//! (`const EPSILON: f64 = 1.0e-8;`, src/f64/dquat.rs:407, :415), so every rotation below 2e-8 rad
//! round-trips to the identity.
//! Upstream: no matching issue found in bitshifter/glam-rs.
//! Run: cargo run --release --manifest-path conformance/adapters/glam/Cargo.toml
//!      --target-dir build/adapters/glam/target --example EXP-2
//! Exit 0: defect shown; 1: not shown (glam changed: update expected_failures.json).
#![allow(dead_code)]
use glam::DQuat;

fn main() {
    // The suite's worst input: a unit quaternion of a 2e-8 rad rotation.
    let q = [hexf("-0x1.36fcf1802e40dp-28"), hexf("0x1.2f707e1ffa366p-27"), hexf("-0x1.1cb3cb73f6cb6p-30"), hexf("0x1p+0")];
    let back = DQuat::from_scaled_axis(DQuat::from_xyzw(q[0], q[1], q[2], q[3]).to_scaled_axis()).to_array();
    let err = metric1(&back, &q) / f64::EPSILON;

    println!("rotorcert reproducer: glam 0.34.3 EXP-2: DQuat::from_scaled_axis(q.to_scaled_axis()) is the identity for every rotation below 2e-8 rad, {err:.3e} eps");
    println!("call:    DQuat::from_scaled_axis(DQuat::from_xyzw(x, y, z, w).to_scaled_axis())");
    println!("input:   q [x, y, z, w] = {}", hxs(&q));
    println!("library: {}", hxs(&back));
    println!("correct: q itself (up to sign)");
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
