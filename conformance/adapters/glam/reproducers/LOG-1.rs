//! rotorcert reproducer: glam 0.34.3 (the version pinned in ../Cargo.lock), clause LOG-1.
//!
//! LOG-1 (spec/SPEC.md 8.2, eps16, METRIC-5 in radians): log q = atan2(|v|, w) v/|v| (principal
//! branch; the log of -q, of norm <= pi/2, is ACCEPTABLE by ACC-1 shorter_arc). glam has no
//! quaternion log; its rotation vector DQuat::to_scaled_axis() = axis * angle (src/f64/dquat.rs:
//! 422-425) is 2 log q, and it goes through to_axis_angle, which returns (X, 0) whenever
//! |v| < 1e-8 (`const EPSILON: f64 = 1.0e-8;`, :407, :415). So the rotation vector of a rotation
//! within 2e-8 rad of a full turn (w ~ -1) or of the identity is the zero vector: neither
//! theta u (|.| ~ 2 pi) nor the other representative's 2|v| u.
//! Upstream: no matching issue found in bitshifter/glam-rs.
//! Run: cargo run --release --manifest-path conformance/adapters/glam/Cargo.toml
//!      --target-dir build/adapters/glam/target --example LOG-1
//! Exit 0: defect shown; 1: not shown (glam changed: update expected_failures.json).
#![allow(dead_code)]
use glam::DQuat;

fn main() {
    // The suite's worst input: w = -1, |v| = 5.6e-10 (a rotation by 2 pi - 1.1e-9).
    let q = [hexf("-0x1.685bf6e4deae8p-37"), hexf("0x1.fd23b69d7c146p-32"), hexf("0x1.f2f770a6c1c52p-33"), hexf("-0x1p+0")];
    let rv = DQuat::from_xyzw(q[0], q[1], q[2], q[3]).to_scaled_axis().to_array();
    let log = [rv[0] * 0.5, rv[1] * 0.5, rv[2] * 0.5]; // the documented theta u -> (theta/2) u

    // Closed form in binary64 (well-conditioned): principal log and the log of -q.
    let nv = (q[0] * q[0] + q[1] * q[1] + q[2] * q[2]).sqrt();
    let half = nv.atan2(q[3]);
    let want: Vec<f64> = (0..3).map(|i| half * q[i] / nv).collect();
    let half_neg = nv.atan2(-q[3]);
    let want_neg: Vec<f64> = (0..3).map(|i| -half_neg * q[i] / nv).collect();
    let dist = |a: &[f64], b: &[f64]| (0..3).map(|i| (a[i] - b[i]).powi(2)).sum::<f64>().sqrt();
    let eps = f64::EPSILON;
    let (err, err_neg) = (dist(&log, &want) / eps, dist(&log, &want_neg) / eps);

    println!("rotorcert reproducer: glam 0.34.3 LOG-1: DQuat::to_scaled_axis is the zero vector for every rotation within 2e-8 rad of a full turn (to_axis_angle's |v| < 1e-8 cut), {err:.3e} eps");
    println!("call:    DQuat::from_xyzw(x, y, z, w).to_scaled_axis() * 0.5   (glam's rotation vector is theta u = 2 log q)");
    println!("input:   q [x, y, z, w] = {}   (|v| = {nv:.3e})", hxs(&q));
    println!("library: to_scaled_axis = {}, so log = {}", hxs(&rv), hxs(&log));
    println!("correct: log q = atan2(|v|, w) v/|v| = {} {}; log(-q) = {} (ACC-1 shorter_arc)", hxs(&want), dec(&want), hxs(&want_neg));
    println!("error:   {err:.3e} eps against log q, {err_neg:.3e} eps against log(-q) (METRIC-5; eps = 2^-52; loose bar 256 eps)");
    if err.min(err_neg) <= 256.0 {
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
