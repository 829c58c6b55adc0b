//! rotorcert reproducer: glam 0.34.3 (the version pinned in ../Cargo.lock), clause AXANG-1.
//!
//! AXANG-1 (spec/SPEC.md 8.1, tolerance eps16; the angle is judged by its absolute error in
//! radians): to_axis_angle(q) = (theta, u) with theta = 2 atan2(|v|, w) in [0, 2 pi] and
//! u = v/|v|; another (theta', u') of the same rotation is ACCEPTABLE (ACC-1 angle_range), a
//! different rotation never is. DQuat::to_axis_angle (src/f64/dquat.rs:404-417) returns
//! (DVec3::X, 0.0) whenever |v| < EPSILON with `const EPSILON: f64 = 1.0e-8;` (:407, :415), a
//! threshold of the binary32 template that binary64 inherits: every unit quaternion within
//! 1e-8 of +-1 is reported as the identity. Near w = -1 the rotation is by 2 pi - 2|v|, i.e. by
//! 2|v| (up to 2e-8 rad) in the other direction, and angle 0 is not that rotation either.
//! Upstream: no matching issue found in bitshifter/glam-rs (the atan2 form came with PR #387,
//! "Calculate Quat::to_axis_angle in a more numerically stable way").
//! Run: cargo run --release --manifest-path conformance/adapters/glam/Cargo.toml
//!      --target-dir build/adapters/glam/target --example AXANG-1
//! Exit 0: defect shown; 1: not shown (glam changed: update expected_failures.json).
#![allow(dead_code)]
use glam::DQuat;

fn main() {
    // The suite's worst input (rotations 1e-9 .. 1e-1 short of a full turn): |v| = 5.7e-10, w = -1.
    let q = [hexf("0x1.fea4c0a53598ap-32"), hexf("0x1.a6366a866bb4ep-33"), hexf("0x1.03098b837ee94p-34"), hexf("-0x1p+0")];
    let (axis, angle) = DQuat::from_xyzw(q[0], q[1], q[2], q[3]).to_axis_angle();

    // Closed form in binary64: |v| and atan2 are well-conditioned here (a few ulp).
    let nv = (q[0] * q[0] + q[1] * q[1] + q[2] * q[2]).sqrt();
    let theta = 2.0 * nv.atan2(q[3]);
    let u = [q[0] / nv, q[1] / nv, q[2] / nv];
    let eps = f64::EPSILON;
    let angle_err = (angle - theta).abs() / eps;
    // Even read as another description of a rotation (ACC-1 angle_range), (0, x) is the identity,
    // 2 pi - theta = 2|v| away from the rotation of q.
    let rotation_err = (2.0 * std::f64::consts::PI - theta).abs().min(theta) / eps;

    println!("rotorcert reproducer: glam 0.34.3 AXANG-1: DQuat::to_axis_angle returns angle 0 about x for every rotation within 2e-8 rad of a full turn or of the identity (|v| < 1e-8), {angle_err:.3e} eps");
    println!("call:    DQuat::from_xyzw(x, y, z, w).to_axis_angle()");
    println!("input:   q [x, y, z, w] = {}   (|v| = {nv:.3e})", hxs(&q));
    println!("library: axis = {}, angle = {}", hxs(&axis.to_array()), hx(angle));
    println!("correct: axis = {} {}, angle = 2 atan2(|v|, w) = {} ({theta:.12})", hxs(&u), dec(&u), hx(theta));
    println!("error:   angle {angle_err:.3e} eps (absolute, AXANG-1); as a rotation {rotation_err:.3e} eps (eps = 2^-52; loose bar 256 eps)");
    if angle_err <= 256.0 && rotation_err <= 256.0 {
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
