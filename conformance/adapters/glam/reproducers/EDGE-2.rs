//! rotorcert reproducer: glam 0.34.3 (the version pinned in ../Cargo.lock), clause EDGE-2.
//!
//! EDGE-2 (spec/SPEC.md 9): rotation angles from 1e-9 to 1e-3 rad must be handled within the
//! operation's own class (eps16 for to_axis_angle), with no 0/0. DQuat::to_axis_angle
//! (src/f64/dquat.rs:404-417) returns (DVec3::X, 0.0) whenever |v| < 1e-8 (`const EPSILON: f64 =
//! 1.0e-8;`, :407): every rotation below 2e-8 rad comes back as angle 0 about x, although
//! atan2(|v|, w) and v/|v| are exact enough there (binary64 holds |v| ~ 1e-9 to full precision).
//! to_scaled_axis() (:422-425), hence the adapter's log, inherits it. The binary32 Quat uses the
//! same 1e-8, which is below its eps and harmless there.
//! Upstream: no matching issue found in bitshifter/glam-rs.
//! Run: cargo run --release --manifest-path conformance/adapters/glam/Cargo.toml
//!      --target-dir build/adapters/glam/target --example EDGE-2
//! Exit 0: defect shown; 1: not shown (glam changed: update expected_failures.json).
#![allow(dead_code)]
use glam::DQuat;

fn main() {
    // The suite's worst input (angles 1e-9 .. 1e-3): a rotation by 1.29e-8 rad.
    let q = [hexf("-0x1.b808e5366b4d2p-28"), hexf("-0x1.f26fb669108d1p-32"), hexf("-0x1.6e41cb8834c9ep-32"), hexf("0x1p+0")];
    let (axis, angle) = DQuat::from_xyzw(q[0], q[1], q[2], q[3]).to_axis_angle();
    let scaled = DQuat::from_xyzw(q[0], q[1], q[2], q[3]).to_scaled_axis();

    // Closed form in binary64 (well-conditioned: a few ulp).
    let nv = (q[0] * q[0] + q[1] * q[1] + q[2] * q[2]).sqrt();
    let theta = 2.0 * nv.atan2(q[3]);
    let u = [q[0] / nv, q[1] / nv, q[2] / nv];
    let eps = f64::EPSILON;
    let angle_err = (angle - theta).abs() / eps;
    let axis_err = (0..3).map(|i| (axis.to_array()[i] - u[i]).powi(2)).sum::<f64>().sqrt() / eps;

    println!("rotorcert reproducer: glam 0.34.3 EDGE-2: DQuat::to_axis_angle reports every rotation below 2e-8 rad as angle 0 about x (|v| < 1e-8), {angle_err:.3e} eps in the angle");
    println!("call:    DQuat::from_xyzw(x, y, z, w).to_axis_angle() (and .to_scaled_axis())");
    println!("input:   q [x, y, z, w] = {}   (|v| = {nv:.3e})", hxs(&q));
    println!("library: axis = {}, angle = {}; to_scaled_axis = {}", hxs(&axis.to_array()), hx(angle), hxs(&scaled.to_array()));
    println!("correct: axis = {} {}, angle = 2 atan2(|v|, w) = {} ({theta:.6e}); scaled axis = angle * axis", hxs(&u), dec(&u), hx(theta));
    println!("error:   angle {angle_err:.3e} eps, axis {axis_err:.3e} eps (eps = 2^-52; loose bar 256 eps)");
    if angle_err <= 256.0 && axis_err <= 256.0 {
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
